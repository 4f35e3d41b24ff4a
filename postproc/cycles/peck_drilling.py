"""G73 high-speed peck and G83 deep-hole peck drilling."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

import math
from typing import Final

from postproc.errors import ProgramError

from .expansion import UNBOUNDED, CycleExpansion, ToolPath, level
from .section import CannedCycle

PECK_REMAINDER: Final = 1e-5
"""mm: a last peck shorter than this is the rounding of the written numbers, not a peck (a depth that is a
whole number of Q, written in inch to 8 decimals, stops some 1e-7 mm short of the bottom). Below the finest
least input increment a controller is given (IS-C, 0.0001 mm [K: Fanuc increment systems IS-B/IS-C]), and at most
a thousandth of the peck (``remainder_tolerance``), so a Q below it still counts every peck."""


def remainder_tolerance(q: float) -> float:
    """The last peck's length, mm, below which it is no peck (``PECK_REMAINDER``)."""
    return min(PECK_REMAINDER, q * 1e-3)


@mypyc_attr(allow_interpreted_subclasses=True)
class PeckDrillingExpansion(CycleExpansion):
    """G73: feed q, rapid back by d, feed q + d, ... (the tool stays in the hole).
    G83: feed q, rapid to R, rapid to d above the last bottom, feed q + d, ...

    Both end with a shorter last peck to the bottom and one rapid out. Depths are computed from R
    (R - k*q), not accumulated, so many pecks carry no float drift. The same rules hold for
    LinuxCNC, whose d is fixed (0.254 mm): its set-up should say so.
    """

    XNAME = "PeckDrillingSyntax"
    __slots__ = ()
    KINDS = frozenset(("peck_chip", "peck_deep"))
    ENDS_OVER_THE_SPOT = True

    def least_moves_per_hole(self, cycle: CannedCycle) -> int:
        """One cut per peck: depth / Q, counted before expanding (a tiny Q is refused at once)."""
        r, bottom, q = level(cycle, "r"), level(cycle, "bottom"), cycle.q
        if q is None or q <= 0 or r <= bottom:
            return 1
        pecks = (r - bottom) / q
        if not pecks < UNBOUNDED:
            return UNBOUNDED  # Q so small the count overflows
        return max(1, math.ceil(pecks - remainder_tolerance(q) / q))

    def hole_end(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        self.over_the_spot(path, cycle, a, b)
        peck_depth(cycle)

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        self.position(path, cycle, a, b)
        r, bottom = level(cycle, "r"), level(cycle, "bottom")
        q = peck_depth(cycle)
        d = cycle.clearance or 0.0
        feed = cycle.feed
        deep = cycle.kind == "peck_deep"
        k = 1
        depth = r - q
        last = bottom + remainder_tolerance(q)
        while depth > last:
            path.cut(depth, feed)
            if deep:
                path.rapid(level=r)
            path.rapid(level=depth + d)
            k += 1
            depth = r - k * q
        path.cut(bottom, feed)
        path.rapid(level=self.return_level(cycle))


def peck_depth(cycle: CannedCycle) -> float:
    """The cycle's Q; a peck cycle without a positive one makes no hole."""
    q = cycle.q
    if q is None or q <= 0:
        raise ProgramError(f"the {cycle.kind.replace('_', ' ')} cycle's peck depth must be positive")
    return q
