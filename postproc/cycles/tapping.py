"""G84 tapping and G74 left-hand tapping: the spindle reverses at the bottom."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from postproc.ir import SpindleControl
from postproc.ir.state import PLANE_AXES
from postproc.lowering.synchronised_tap import RigidTap

from .expansion import CycleExpansion, ToolPath, rules_of
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class TappingExpansion(CycleExpansion):
    """Fanuc: feed to the bottom, dwell P, reverse, feed back to R, (G98: rapid to the initial level),
    restore the direction. RS274 (LinuxCNC's interpreter): feed to the bottom, stop, reverse, dwell
    (0 without P), feed out to the clear level, stop, restore.

    The spindle is running the tapping direction already (M03 for G84, M04 for G74): entering the
    hole changes nothing.

    A rigid tap (``cycle.pitch``, ``postproc.cycles.rigid_tap``): position, then one ``RigidTap`` from the
    R level to the bottom and back, synchronised at the pitch, the dwell P at the bottom [K: Fanuc 0i-MF
    operator's manual, rigid tapping G84: rapid to R, tap to Z, dwell, spindle reversed, retract to R; G98
    then rapid to the initial level; [?] whether P also dwells at R after the return is not modelled]. The
    spindle turns the tapping direction (G84 clockwise, G74 counter-clockwise [K]): a spindle in the
    other is set to it first.
    """

    XNAME = "TappingSyntax"
    __slots__ = ()
    KINDS = frozenset(("tap", "tap_left"))
    ENDS_OVER_THE_SPOT = True

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        work, reverse = ("cw", "ccw") if cycle.kind == "tap" else ("ccw", "cw")
        self.position(path, cycle, a, b)
        if cycle.pitch is not None:
            if cycle.spindle != work and not any(isinstance(item, SpindleControl) for item in path.items):
                path.spindle(work)
            normal = PLANE_AXES[cycle.plane][2]
            path.add(RigidTap({normal: cycle.bottom}, cycle.pitch, cycle.dwell or None))  # type: ignore[dict-item]
            path.rapid(level=self.return_level(cycle))
            return
        path.cut(cycle.bottom, cycle.feed)  # type: ignore[arg-type]
        if rules_of(cycle).stops_to_reverse:
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
