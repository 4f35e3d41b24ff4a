"""G71: stock removal in turning (type I monotonic profiles and type II pockets)."""

from __future__ import annotations

from typing import Sequence

from .profile import Point, Seg, TurnMove
from .roughing import Roughing, rough


def rough_turning(start: Point, profile: Sequence[Seg], depth: float, retract: float,
                  u_diameter: float = 0.0, w: float = 0.0, feed: float | None = None,
                  type_ii: bool | None = None, limit: int = 100_000) -> list[TurnMove]:
    """``G71 U(Δd) R(e); G71 P(ns) Q(nf) U(Δu) W(Δw) F`` from ``start`` (A), ending back at A.

    ``profile``: the blocks ns..nf (radius, absolute), ns starting at A. ``depth``: Δd, the radius
    depth of each level (> 0). ``retract``: e (>= 0). ``u_diameter``: Δu as a DIAMETER value, signed
    (+ leaves stock outside, - inside); the profile is offset by Δu/2 in X. ``w``: Δw, signed. ``feed``:
    the cycle's F (F inside ns..nf is for the finishing cycle only). ``type_ii``: whether the ns block
    programs Z or W (type II, pockets allowed); None decides by the ns block's geometry (moves in Z).
    ``limit``: the most levels the cycle may cut (a located error above, never a hang).

    The tool infeeds in the direction the ns block moves in X, and cuts along Z in the direction the
    profile runs (ns end to nf end). Sequence (the seed's GSK G71 and DIALECTS.md 2.2 [V]; the exact
    retract and return moves [K]; LinuxCNC's conformance case g72-facing agrees on the levels and the
    45-degree retract):
    1. rapid A -> A' = A + (Δu/2, Δw);
    2. for each level A'x - k*Δd above the lowest point of the offset profile: the infeed to the
       level at A'z as the ns block moves (G00 rapid, G01 at F); feed along Z to the offset profile;
       rapid retract e at 45 degrees (out in X, back in Z); rapid back to A'z. Type II only: each
       further span of the level (a pocket) is reached at the clear X (the highest of A, A' and the
       profile), rapid down to the level above, fed in to the level, cut, and left straight out in X;
    3. the ns block's move to B' (rapid or F), the contour B'..C' offset by (Δu/2, Δw) at F;
    4. rapid out in X to the clear X, rapid in Z to A's Z, rapid in X to A (the controller's single
       rapid to A, taken as a dog-leg that cannot cross the part).

    The profile must be monotonic: type I in X and Z, type II in Z (arcs included). The seed's GSK
    makes that check only with K1; a profile breaking the rule has no defined roughing, so it is always
    refused here, naming the offending block's line.
    """
    return rough(Roughing("stock removal in turning", start, profile, depth, retract, (u_diameter / 2.0, w),
                          feed, type_ii, limit, "X"))
