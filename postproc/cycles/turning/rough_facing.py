"""G72: stock removal in facing, G71 with the roles of X and Z exchanged."""

from __future__ import annotations

from typing import Sequence

from .profile import Point, Seg, TurnMove
from .roughing import Roughing, rough


def rough_facing(start: Point, profile: Sequence[Seg], depth: float, retract: float,
                 u_diameter: float = 0.0, w: float = 0.0, feed: float | None = None,
                 type_ii: bool | None = None, limit: int = 100_000) -> list[TurnMove]:
    """``G72 W(Δd) R(e); G72 P(ns) Q(nf) U(Δu) W(Δw) F`` from ``start`` (A), ending back at A.

    Words as for ``rough_turning``, except that ``depth`` (Δd) and ``retract`` (e) are Z distances,
    the ns block of a type I profile moves only in Z (its direction is the infeed), and the levels
    are cut along X in the direction the profile runs. ``u_diameter`` is still the DIAMETER X
    allowance. The sequence is ``rough_turning``'s with X and Z exchanged (DIALECTS.md 2.2 [V]:
    "like G71, but the layers run parallel to X"): 45-degree retract e back in X and out in Z.
    The profile must be monotonic in X and Z (type I) or in X (type II), naming the offending line.
    """
    return rough(Roughing("stock removal in facing", start, profile, depth, retract, (u_diameter / 2.0, w),
                          feed, type_ii, limit, "Z"))
