"""G75: OD/ID grooving: G74 with X and Z exchanged (pecks along X, passes stepped along Z)."""

from __future__ import annotations

from .peck_face import peck_passes
from .profile import Frame, Point, TurnMove

NAME = "grooving cycle"


def groove(start: Point, x: float, z: float, peck: float, retract: float, step: float = 0.0,
           relief: float = 0.0, feed: float | None = None, limit: int = 100_000) -> list[TurnMove]:
    """``G75 R(e); G75 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F`` from ``start`` (A), ending back at A.

    ``x``: the groove's bottom (radius, absolute); ``z``: the last pass's Z (A's Z for one pass).
    ``peck``: Δi (P), the X depth of each peck (> 0); ``step``: Δk (Q), the Z step between passes;
    both already converted by the caller from least increments. ``retract``: e; ``relief``: Δd, the
    Z relief at the bottom against the step direction; ``feed``: F.

    Sequence: ``peck_face``'s with X and Z exchanged (DIALECTS.md 2.2 [V]: "same words with the
    roles of X and Z swapped"): for each pass at Z = A's Z, then a step further each time, the last
    at Z: feed Δi deeper in X, rapid back e, until the bottom; feed the relief; rapid X back to A's X;
    rapid to the next pass; at the end rapid to A.
    """
    return peck_passes(NAME, Frame(True, 1.0, 1.0), start, x, z, peck, retract, step, relief, feed, limit)
