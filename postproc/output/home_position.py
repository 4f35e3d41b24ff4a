"""Where a reference return goes, for a target that writes it as a move in machine coordinates.

Fanuc's ``G28`` ends at each named axis's reference position; ISG (``#SUPPRESS OFFSETS`` / ``G53``-style
moves), Fagor (``G53 G00``) and SINUMERIK (``G75 FP=1``) write it as a move to that position, which only the
set-up knows (``<Axes><Axis home>``), as the simulator takes it."""

from __future__ import annotations

from ..ir import Motion
from ..setup.machine_setup import MachineSetup
from ..ir.state import MM_PER_INCH


def home_position(setup: MachineSetup, axis: str, inch: bool) -> float | None:
    """The set-up's home of ``axis`` (machine coordinates) in program units, None where it gives none."""
    travel = setup.travel.get(axis)
    if travel is None or travel.home is None:
        return None
    return travel.home * setup.machine.mm() / (MM_PER_INCH if inch else 1.0)


def add_home(axis: str) -> str:
    """What to add to the set-up for an axis whose home it does not give."""
    return f"add <Axes><Axis name=\"{axis}\" home=\"..\"/>"


SECOND_RETURN = "a return to the second reference position"
"""What a writer that spells codes names with its code (``reference_problem``'s ``second``)."""


def reference_problem(setup: MachineSetup, motion: Motion, inch: bool, how: str,
                      second: str = SECOND_RETURN) -> str | None:
    """Why a reference return cannot be written as a move to the set-up's home (``how`` says how the target
    writes it), or None when it can."""
    if motion.mode != "home":
        return f"{second}: the set-up has no element for it (only each axis's home)"
    for axis in motion.axes:
        if home_position(setup, axis, inch) is None:
            return f"a reference return of axis {axis}: {how}, which the set-up does not give ({add_home(axis)})"
    return None


def reference_target(setup: MachineSetup, motion: Motion, inch: bool) -> dict[str, float]:
    """The home of each axis a reference return names, in program units (``reference_problem`` is None)."""
    return {axis: home for axis in motion.axes if (home := home_position(setup, axis, inch)) is not None}
