"""G76: multiple-pass threading (two-block form), single-edge infeed along the flank."""

from __future__ import annotations

import math

from postproc.errors import ProgramError

from .profile import Point, TurnMove, drop_still, finite, sign
from .single_threading import thread_end

NAME = "multiple threading cycle"


def thread_depths(height: float, first_depth: float, min_depth: float, allowance: float,
                  finish_passes: int, limit: int = 100_000) -> list[float]:
    """The cumulative depth of every pass, from the crest: Δd*sqrt(n), each step at least Δdmin, up to
    k - d; then ``finish_passes`` passes at k (the first of them removes the allowance d)."""
    rough_to = height - allowance
    depths: list[float] = []
    n = 0
    while rough_to > 0.0 and (not depths or depths[-1] < rough_to - 1e-12):
        n += 1
        depth = first_depth * math.sqrt(n)
        if depths:
            depth = max(depth, depths[-1] + min_depth)
        depths.append(min(depth, rough_to))
        if len(depths) > limit:
            raise ProgramError(f"{NAME}: more than {limit} passes (the first depth or the minimum depth is "
                               "too small for the thread height)")
    return depths + [height] * finish_passes


def threading(start: Point, x: float, z: float, lead: float, height: float, first_depth: float,
              finish_passes: int = 1, chamfer: int = 0, angle: float = 60.0, min_depth: float = 0.0,
              allowance: float = 0.0, r: float = 0.0, limit: int = 100_000) -> list[TurnMove]:
    """``G76 P(m)(r)(a) Q(Δdmin) R(d); G76 X(U) Z(W) R(i) P(k) Q(Δd) F(L)`` from ``start`` (A), back to A.

    ``x``, ``z``: the thread's root at its end (radius, absolute). ``lead``: F (L), the lead.
    ``height``: k, the thread height (radius). ``first_depth``: Δd, the first pass's depth (radius).
    ``min_depth``: Δdmin. ``allowance``: d, the finishing allowance. (k, Δd and Δdmin already converted
    by the caller from least increments.) ``finish_passes``: m (1-99). ``chamfer``: r, the pull-out in
    tenths of the lead (0-99), at 45 degrees. ``angle``: a, the tool's included angle in degrees
    (0-120; the infeed follows one flank at a/2). ``r``: i, the taper: the radius at the thread's
    start minus the radius at its end.

    Depths (DIALECTS.md 2.2 [V] words, [K] the sqrt(n) rule): pass n cuts to Δd*sqrt(n) from the
    crest, never less than Δdmin deeper than the pass before, up to k - d; then m passes at k.
    Each pass at depth D (the tool on the side of the root A lies on; the flank infeed moves the pass
    back toward A's Z by (k - D) * tan(a/2), so the full-depth passes run from A's Z to Z): rapid in Z
    to the pass's start Z, rapid in X onto the thread, thread to its end (with the chamfer as
    ``single_threading`` makes it), rapid out to A's X. At the end rapid to A.
    """
    x0, z0 = start
    finite(NAME, x0=x0, z0=z0, x=x, z=z, lead=lead, height=height, first_depth=first_depth,
           angle=angle, min_depth=min_depth, allowance=allowance, r=r)
    if lead <= 0.0:
        raise ProgramError(f"{NAME}: the lead F must be positive, not {lead:g}")
    if height <= 0.0 or first_depth <= 0.0:
        raise ProgramError(f"{NAME}: the thread height and the first depth must be positive")
    if min_depth < 0.0 or allowance < 0.0 or allowance > height:
        raise ProgramError(f"{NAME}: the minimum depth and the finishing allowance must be between 0 and "
                           "the thread height")
    if not 1 <= finish_passes <= 99:
        raise ProgramError(f"{NAME}: the number of finishing passes must be 1 to 99, not {finish_passes}")
    if not 0.0 <= angle < 180.0:
        raise ProgramError(f"{NAME}: the tool angle must be 0 to 180 degrees, not {angle:g}")
    out, sz = sign(x0 - (x + r)), sign(z - z0)
    if out == 0 or sign(x0 - x) != out:
        raise ProgramError(f"{NAME}: the start point must lie outside the thread in X, on one side of it")
    if sz == 0:
        raise ProgramError(f"{NAME}: the thread has no length in Z")
    if abs(x0 - x) < height - 1e-9 or abs(x0 - x - r) < height - 1e-9:
        raise ProgramError(f"{NAME}: the start point's X lies within the thread height")
    tan_half = math.tan(math.radians(angle / 2.0))
    moves: list[TurnMove] = []
    for depth in thread_depths(height, first_depth, min_depth, allowance, finish_passes, limit):
        above = out * (height - depth)
        back = -sz * (height - depth) * tan_half
        zs, ze = z0 + back, z + back
        xs, xe = x + r + above, x + above
        moves.append(TurnMove("rapid", x0, zs, note="shift"))
        moves.append(TurnMove("rapid", xs, zs, note="infeed"))
        moves += thread_end(NAME, xs, zs, xe, ze, x0, lead, chamfer)
        moves.append(TurnMove("rapid", x0, ze, note="pull out"))
    moves.append(TurnMove("rapid", x0, z0, note="return"))
    return drop_still(moves, start)
