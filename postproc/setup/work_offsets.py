"""What lies between the toolpath's frame and the machine's: the work offsets the frame does not hold.

The simulator's points are work coordinates (``postproc.simulate.toolpath``): a work offset the program sets
(G10 L2) shifts them, so the frame holds it; one the set-up gives (``<WorkOffsets>``) does not. A machine
position (a move in machine coordinates, a reference point) is therefore put in the frame by subtracting the
set-up's offset of the active work system, and the travel check adds the same value to carry a point to the
machine (``postproc.simulate.travel``): one function for both, and for the lowering that writes a programmed
point's machine position (``postproc.lowering.cutter_compensation``: the exit move in machine coordinates after a
cancel), which is why it stands with the set-up, below both.
"""

from __future__ import annotations

from ..ir.state import PLACED_AXES, SetUpPlaces
from .record import ROTARY_AXES
from .machine_setup import MachineSetup

_NONE: dict[str, float] = {}


def declared_offsets(setup: MachineSetup, axes: tuple[str, ...], diameter: bool) -> dict[int, dict[str, float]]:
    """The set-up's work offsets in simulator units (mm; degrees on a rotary axis; a diameter lathe's X as a
    radius, as the set-up gives X there as a diameter), by work system (1 = the first; 0 the external one)."""
    mm = setup.machine.mm()
    factor = {a: (1.0 if a in ROTARY_AXES else mm) * (0.5 if diameter and a == "X" else 1.0) for a in axes}
    return {int(n): {a: v * factor[a] for a, v in o.axes().items() if a in factor}
            for n, o in setup.work_offsets.items()}


def offset_beyond_frame(axis: str, system: int, programmed: dict[int, dict[str, float]],
                        declared: dict[int, dict[str, float]]) -> tuple[float | None, str]:
    """Machine minus frame position on ``axis`` from work offsets: the active ``system``'s and the external
    one's (0), each unless the program set it (``programmed``, a G10's values, which the frame holds), from
    the set-up (``declared``). None, and why, when neither gives the active system's; the external offset
    counts as zero when neither gives it."""
    total = 0.0
    for number, required in ((system, True), (0, False)):
        if axis in programmed.get(number, _NONE):
            continue
        value = declared.get(number, _NONE).get(axis)
        if value is None and required:
            return None, (f"the set-up gives work system {number} no offset for {axis} (<WorkOffsets><Offset "
                          f"number=\"{number}\" {axis.lower()}=...>) and the program sets none")
        total += value or 0.0
    return total, ""


def set_up_places(setup: MachineSetup) -> SetUpPlaces | None:
    """The set-up's homes and work offsets as a translation's reading follows them (``SetUpPlaces``), where it
    declares work offsets: every placed position needs the active system's (a home alone places nothing). Else
    None, and the reading pays nothing (the bench machine declares a Z home and no offsets)."""
    if not setup.work_offsets:
        return None
    mm = setup.machine.mm()
    homes = {a: t.home * mm for a, t in setup.travel.items() if a in PLACED_AXES and t.home is not None}
    declared = declared_offsets(setup, PLACED_AXES, False)
    offsets: dict[int, dict[str, float]] = {}
    for system in declared:
        offsets[system] = {}
        for axis in PLACED_AXES:
            offset = offset_beyond_frame(axis, system, {}, declared)[0]
            if offset is not None:
                offsets[system][axis] = offset
    return SetUpPlaces(homes, offsets)
