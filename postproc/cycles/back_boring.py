"""G87 back boring: enter the hole oriented and shifted, cut upward, leave the same way."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from postproc.ir.state import PLANE_AXES

from .expansion import EPS, CycleExpansion, ToolPath, level
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class BackBoringExpansion(CycleExpansion):
    """G87 back boring (Fanuc). Supports modal repetition. Reads absolute levels from the cycle
    section resolved by CannedCycleResolveSyntax: the cut starts at ``bottom`` and goes up to ``top``.

    With the seed's levels (Z the bottom, R the top; the default) the eleven items per hole are:
    oriented stop where the tool stands; rapid, shifted by Q, to the initial level; rapid down to the
    bottom; shift back; spindle CW; feed up to the top; oriented stop; shift; rapid to the initial
    level; shift back; spindle CW. With the manual's levels (R the bottom, Z the top) the tool first
    positions on the hole at the initial level and orients there, as the Fanuc manual draws it. A dwell
    P, when programmed, comes after the cut. The return is always to the initial level.
    """

    XNAME = "BackBoringSyntax"
    __slots__ = ()
    KINDS = frozenset(("back_bore",))

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        first, second, _ = PLANE_AXES[cycle.plane]
        shift = cycle.shift or {}
        sa, sb = a + shift.get(first, 0.0), b + shift.get(second, 0.0)
        initial, bottom, top = level(cycle, "initial"), level(cycle, "bottom"), level(cycle, "top")
        if abs(level(cycle, "r") - bottom) < EPS:
            path.rapid(a, b)
        path.orient(cycle.orient)
        path.rapid(sa, sb, initial)
        path.rapid(level=bottom)
        path.rapid(a, b)
        path.spindle("cw")
        path.cut(top, cycle.feed)
        path.dwell(cycle.dwell)
        path.orient(cycle.orient)
        path.rapid(sa, sb)
        path.rapid(level=initial)
        path.rapid(a, b)
        path.spindle("cw")
