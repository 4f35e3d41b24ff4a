"""G81 drilling and G82 spot drilling: feed to the bottom, (dwell,) rapid out."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from .expansion import CycleExpansion, ToolPath, rules_of
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class DrillingExpansion(CycleExpansion):
    """G81/G82. The rapid out goes straight from the bottom to the return level, not through R."""

    XNAME = "DrillingSyntax"
    __slots__ = ()
    KINDS = frozenset(("drill", "drill_dwell"))
    ENDS_OVER_THE_SPOT = True

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        self.position(path, cycle, a, b)
        path.cut(cycle.bottom, cycle.feed)  # type: ignore[arg-type]
        if cycle.kind == "drill_dwell":
            path.dwell(cycle.dwell, always=rules_of(cycle).dwell_always)
        path.rapid(level=self.return_level(cycle))
