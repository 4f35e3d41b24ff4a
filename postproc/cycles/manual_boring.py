"""G88 boring with a manual retract: the program stops at the bottom for the operator."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from .expansion import CycleExpansion, ToolPath, rules_of
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class ManualBoringExpansion(CycleExpansion):
    """Fanuc: feed to the bottom, dwell P, spindle stop, program stop; on cycle start the tool (taken
    as still at the bottom: the operator's hand moves are not simulated) rapids to the return level
    and the spindle restarts CW.

    RS274 (LinuxCNC's interpreter): feed, dwell, stop, program stop, spindle restarted in its previous
    direction, and no retract move: the interpreter takes the tool to be at the clear level afterwards,
    so the next positioning starts there.
    """

    XNAME = "ManualBoringSyntax"
    __slots__ = ()
    KINDS = frozenset(("bore_manual",))

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        rules = rules_of(cycle)
        self.position(path, cycle, a, b)
        path.cut(cycle.bottom, cycle.feed)  # type: ignore[arg-type]
        path.dwell(cycle.dwell, always=rules.dwell_always)
        path.spindle("stop")
        path.program_stop()
        if not rules.manual_retracts:
            path.spindle(cycle.spindle if rules.spindle_resumes and cycle.spindle in ("cw", "ccw") else "cw")
            path.set_level(self.return_level(cycle))
            return
        path.rapid(level=self.return_level(cycle))
        path.spindle("cw")
