"""G73: pattern repeating, the profile traced d times, each pass shifted less toward the stock."""

from __future__ import annotations

import math
from typing import Sequence

from postproc.errors import ProgramError

from .profile import (Frame, Point, Seg, TurnMove, arc_contains, arc_radius, check_chain, contour_moves,
                      drop_still, finite, shifted, sign)

NAME = "pattern repeating cycle"


def pattern_repeat(start: Point, profile: Sequence[Seg], relief_x: float, relief_z: float, passes: int,
                   u_diameter: float = 0.0, w: float = 0.0, feed: float | None = None) -> list[TurnMove]:
    """``G73 U(Δi) W(Δk) R(d); G73 P(ns) Q(nf) U(Δu) W(Δw) F`` from ``start`` (A), ending back at A.

    ``profile``: ns..nf (radius, absolute), ns starting at A. ``relief_x``: Δi, the total X relief
    (radius, signed); ``relief_z``: Δk, the total Z relief (signed); ``passes``: d, the number of
    passes (>= 1). ``u_diameter``: Δu as a DIAMETER value, signed; ``w``: Δw, signed. ``feed``: the
    cycle's F (the profile's own F is for the finishing cycle).

    Sequence (DIALECTS.md 2.2 [V] for the words; the pass spacing [K]): pass n = 1..d traces the
    profile shifted by (Δu/2 + Δi*(d-n)/(d-1), Δw + Δk*(d-n)/(d-1)) (only the allowance when d = 1):
    the first pass escapes by Δi + Δu/2 and Δk + Δw, the last lies on the profile offset by the
    allowance. Each pass: rapid to its shifted A, the ns block as programmed (G00 rapid, else at F),
    the rest at F. Between passes and at the end the tool returns by rapid, out in X to the clear X
    (beyond A and every pass, on the side the ns block comes from), along Z, then in X: the
    controller's rapid to the next pass, taken as a dog-leg that cannot cross the part.
    """
    finite(NAME, x0=start[0], z0=start[1], relief_x=relief_x, relief_z=relief_z, u=u_diameter, w=w, feed=feed)
    check_chain(profile, start, NAME)
    if passes < 1:
        raise ProgramError(f"{NAME}: the number of passes must be at least 1, not {passes}")
    if passes > 10_000:
        raise ProgramError(f"{NAME}: {passes} passes exceed the limit of 10000")
    u = u_diameter / 2.0
    ns = profile[0]
    out = -sign(ns.x1 - ns.x0) or sign(relief_x + u) or 1.0
    frame = Frame(False, out, 1.0)
    shifts = []
    for n in range(1, passes + 1):
        f = (passes - n) / (passes - 1) if passes > 1 else 0.0
        shifts.append((u + relief_x * f, w + relief_z * f))
    top = max([frame.point(*start)[0]] + [_highest(frame.seg(shifted(s, dx, dz))) for dx, dz in shifts
                                          for s in profile])
    moves: list[TurnMove] = []
    for dx, dz in shifts:
        path = [shifted(s, dx, dz) for s in profile]
        moves += _rapid_to(frame, moves, start, top, (path[0].x0, path[0].z0))
        moves += contour_moves(path, feed, "pass")
    moves += _rapid_to(frame, moves, start, top, start)
    return drop_still(moves, start)


def _rapid_to(frame: Frame, moves: list[TurnMove], start: Point, top: float, to: Point) -> list[TurnMove]:
    """Out to the clear X, along Z, in to ``to`` (from A itself, straight)."""
    if not moves:
        return [TurnMove("rapid", to[0], to[1], note="approach")]
    here = moves[-1]
    clear_here = frame.back(top, frame.point(here.x, here.z)[1])
    clear_there = frame.back(top, frame.point(*to)[1])
    return [TurnMove("rapid", clear_here[0], clear_here[1], note="return"),
            TurnMove("rapid", clear_there[0], clear_there[1], note="return"),
            TurnMove("rapid", to[0], to[1], note="return")]


def _highest(seg: Seg) -> float:
    high = max(seg.x0, seg.x1)
    if seg.kind != "line" and arc_contains(seg, math.pi / 2.0, strict=False):
        assert seg.cx is not None
        high = max(high, seg.cx + arc_radius(seg))
    return high
