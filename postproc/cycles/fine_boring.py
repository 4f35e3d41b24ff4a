"""G76 fine boring: oriented stop and a shift off the wall before the rapid out."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from postproc.ir.state import PLANE_AXES

from .expansion import CycleExpansion, ToolPath
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class FineBoringExpansion(CycleExpansion):
    """Feed to the bottom, dwell P, oriented stop, rapid shift by Q (direction from the set-up),
    rapid out to the return level still shifted, shift back, spindle CW. No orientation on the way in.
    """

    XNAME = "FineBoringSyntax"
    __slots__ = ()
    KINDS = frozenset(("fine_bore",))

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        first, second, _ = PLANE_AXES[cycle.plane]
        shift = cycle.shift or {}
        self.position(path, cycle, a, b)
        path.cut(cycle.bottom, cycle.feed)  # type: ignore[arg-type]
        path.dwell(cycle.dwell)
        path.orient(cycle.orient)
        path.rapid(a + shift.get(first, 0.0), b + shift.get(second, 0.0))
        path.rapid(level=self.return_level(cycle))
        path.rapid(a, b)
        path.spindle("cw")
