"""G84 tapping and G74 left-hand tapping: the spindle reverses at the bottom."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from .expansion import CycleExpansion, ToolPath
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class TappingSyntax(CycleExpansion):
    """Fanuc: feed to the bottom, dwell P, reverse, feed back to R, (G98: rapid to the initial level),
    restore the direction. RS274 (LinuxCNC's interpreter): feed to the bottom, stop, reverse, dwell
    (0 without P), feed out to the clear level, stop, restore.

    The spindle is running the tapping direction already (M03 for G84, M04 for G74): entering the
    hole changes nothing.
    """

    XNAME = "TappingSyntax"
    __slots__ = ()
    KINDS = frozenset(("tap", "tap_left"))
    ENDS_OVER_THE_SPOT = True

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        work, reverse = ("cw", "ccw") if cycle.kind == "tap" else ("ccw", "cw")
        self.position(path, cycle, a, b)
        path.cut(cycle.bottom, cycle.feed)  # type: ignore[arg-type]
        if cycle.semantics == "rs274":
            path.spindle("stop")
            path.spindle(reverse)
            path.dwell(cycle.dwell, always=True)
            path.cut(self.return_level(cycle), cycle.feed)
            path.spindle("stop")
            path.spindle(work)
            return
        path.dwell(cycle.dwell)
        path.spindle(reverse)
        path.cut(cycle.r, cycle.feed)  # type: ignore[arg-type]
        path.rapid(level=self.return_level(cycle))
        path.spindle(work)
