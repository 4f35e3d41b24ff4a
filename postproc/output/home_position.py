"""Where a reference return goes, for a target that writes it as a move in machine coordinates.

Fanuc's ``G28`` ends at each named axis's reference position; ISG (``#SUPPRESS OFFSETS`` / ``G53``-style
moves), Fagor (``G53 G00``) and SINUMERIK (``G75 FP=1``) write it as a move to that position, which only the
set-up knows (``<Axes><Axis home>``), as the simulator takes it."""

from __future__ import annotations

from ..setup.machine_setup import MachineSetup
from ..state import MM_PER_INCH


def home_position(setup: MachineSetup, axis: str, inch: bool) -> float | None:
    """The set-up's home of ``axis`` (machine coordinates) in program units, None where it gives none."""
    travel = setup.travel.get(axis)
    if travel is None or travel.home is None:
        return None
    return travel.home * setup.machine.mm() / (MM_PER_INCH if inch else 1.0)


def add_home(axis: str) -> str:
    """What to add to the set-up for an axis whose home it does not give."""
    return f"add <Axes><Axis name=\"{axis}\" home=\"..\"/>"
