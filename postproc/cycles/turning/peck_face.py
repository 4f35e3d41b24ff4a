"""G74: face peck drilling / face grooving: pecks along Z, columns stepped along X."""

from __future__ import annotations

import math

from postproc.errors import ProgramError

from .profile import Frame, Point, TurnMove, drop_still, finite, sign

NAME = "face peck cycle"


def peck_face(start: Point, x: float, z: float, peck: float, retract: float, step: float = 0.0,
              relief: float = 0.0, feed: float | None = None, limit: int = 100_000) -> list[TurnMove]:
    """``G74 R(e); G74 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F`` from ``start`` (A), ending back at A.

    ``x``, ``z``: the last column's X and the bottom (radius, absolute; X = A's X for a drill on
    the axis). ``peck``: Δk, the Z depth of each peck (> 0). ``step``: Δi, the X step between
    columns (> 0 when X differs from A's). Both already converted by the caller from least
    increments. ``retract``: e, the back-off after each peck. ``relief``: Δd, the X relief at the
    bottom, made against the step direction (signed when there is one column only). ``feed``: F.

    Sequence (DIALECTS.md 2.2 [V] for the words; the motion [K], the relief's feed rate [?]): for each
    column X = A's X, then a step further each time, the last at X: feed Δk deeper, rapid back e,
    and again until the bottom; at the bottom feed the relief; rapid Z back to A's Z; rapid to the next
    column. At the end rapid to A.
    """
    return peck_passes(NAME, Frame(False, 1.0, 1.0), start, x, z, peck, retract, step, relief, feed, limit)


def peck_passes(name: str, frame: Frame, start: Point, x: float, z: float, peck: float, retract: float,
           step: float, relief: float, feed: float | None, limit: int) -> list[TurnMove]:
    """Pecks along the frame's z, columns along its x (G74 as is; G75 through a swapped frame)."""
    finite(name, x0=start[0], z0=start[1], x=x, z=z, peck=peck, retract=retract, step=step,
           relief=relief, feed=feed)
    x0, z0 = frame.point(*start)
    x1, z1 = frame.point(x, z)
    if peck <= 0.0 and abs(z1 - z0) > 0.0:
        raise ProgramError(f"{name}: the peck depth must be positive, not {peck:g}")
    if retract < 0.0:
        raise ProgramError(f"{name}: the retract amount must not be negative, not {retract:g}")
    span = abs(x1 - x0)
    if span > 0.0 and step <= 0.0:
        raise ProgramError(f"{name}: the step between passes must be positive, not {step:g}")
    columns = 1 + (max(1, math.ceil(span / step - 1e-9)) if span > 0.0 else 0)
    pecks = math.ceil(abs(z1 - z0) / peck - 1e-9) if abs(z1 - z0) > 0.0 else 0
    if columns * (2 * pecks + 4) > limit:
        raise ProgramError(f"{name}: {columns} passes of {pecks} pecks exceed the limit of {limit} moves")
    sx, sz = sign(x1 - x0), sign(z1 - z0)
    back = -sx if sx else (sign(relief) or 1.0)
    moves: list[TurnMove] = []
    for c in range(columns):
        xc = x1 if c == columns - 1 else x0 + sx * step * c
        moves.append(TurnMove("rapid", xc, z0, note="position"))
        for j in range(1, pecks + 1):
            zj = z1 if j == pecks else z0 + sz * peck * j
            moves.append(TurnMove("feed", xc, zj, feed=feed, note="peck"))
            if j < pecks:
                moves.append(TurnMove("rapid", xc, zj - sz * retract, note="retract"))
        moves.append(TurnMove("feed", xc + back * abs(relief), z1, feed=feed, note="relief"))
        moves.append(TurnMove("rapid", xc + back * abs(relief), z0, note="return"))
    moves.append(TurnMove("rapid", x0, z0, note="return"))
    return drop_still([frame.move(m) for m in moves], start)
