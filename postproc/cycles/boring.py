"""G85 and G89 boring (feed out) and G86 boring (spindle stop, rapid out)."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from .expansion import CycleExpansion, ToolPath, rules_of
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class BoringExpansion(CycleExpansion):
    """Fanuc (``Semantics`` of the RS274 family base): G85 feed to the bottom, feed to R, (G98: rapid to the initial level); G89 the same with a
    dwell P at the bottom; G86 feed, spindle stop, rapid out, spindle CW (no dwell).

    RS274 (LinuxCNC's interpreter): G85 feeds to R and rapids to the clear level; G89 dwells and feeds
    straight out to the clear level; G86 dwells before the stop and restarts the spindle in the
    direction it had.
    """

    XNAME = "BoringSyntax"
    __slots__ = ()
    KINDS = frozenset(("bore_feed", "bore_stop", "bore_dwell_feed"))
    ENDS_OVER_THE_SPOT = True

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        rules = rules_of(cycle)
        out = self.return_level(cycle)
        self.position(path, cycle, a, b)
        path.cut(cycle.bottom, cycle.feed)  # type: ignore[arg-type]
        if cycle.kind == "bore_stop":
            if rules.dwell_always:
                path.dwell(cycle.dwell, always=True)
            path.spindle("stop")
            path.rapid(level=out)
            path.spindle(cycle.spindle if rules.spindle_resumes and cycle.spindle in ("cw", "ccw") else "cw")
            return
        if cycle.kind == "bore_dwell_feed":
            path.dwell(cycle.dwell, always=rules.dwell_always)
            if rules.feeds_out_to_clear:
                path.cut(out, cycle.feed)
                return
        path.cut(cycle.r, cycle.feed)  # type: ignore[arg-type]
        path.rapid(level=out)
