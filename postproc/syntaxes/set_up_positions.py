"""Where the set-up puts the tool after a move the program text does not place, for a translation's reading.

A reference return (``G28``), a move in machine coordinates (``G53``) and a change of work system (``G55``) leave
the reading's position unknown (``postproc.syntaxes.modal_state``): the work position then depends on the machine's
reference positions and work offsets. A translation to another dialect refuses an arc whose shape depends on such an
unknown start (``modal_state._refuse_unknown_start``): its controller checks the radius from wherever the machine
stands. Where the set-up declares those values (``<Axes><Axis home>``, ``<WorkOffsets>``), the simulator takes the
tool there (``postproc.simulate.simulator``: ``machine_to_frame``), and so does this reading:

    work position = machine position - (offset of the active work system + external offset)

with the machine position the declared home (a first reference return), the block's machine word (a move in machine
coordinates under absolute distance), or the work position before a change of work system plus the old offsets.
Only declared values count, as in ``postproc.lowering.machine_positions`` (issue 26: a guess cannot be seen by
``verify``, whose two sides would share it). What the set-up does not give, a tool length offset in force on the
axis (the programmed point is the controlled point less the length), a second reference return, and any offset or
frame the program sets (``G10``, ``G92``, a frame command: values the run holds) leave the axis unknown, as before.
A lathe (diameters, U/W increments, tool offsets) is not followed here.

Installed by ``translate`` for a translation to another dialect, as ``ModalState.extra[KEY]``; interpreted: it runs
only at the rare blocks that change the work system or leave the program's frame.
"""

from __future__ import annotations

from typing import Final, Mapping

from postproc.context import Context
from postproc.ir import Motion
from postproc.ir.state import MM_PER_INCH, ModalState
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.work_offsets import declared_offsets, offset_beyond_frame

KEY: Final = "set_up_positions"
"""``ModalState.extra`` key of the run's ``SetUpPositions``."""
AXES: Final = ("X", "Y", "Z")
"""The linear axes followed (an arc's plane is two of them)."""
LENGTH_AXIS: Final = "Z"
"""The axis a tool length offset acts on (a mill's)."""
PROGRAM_SET: Final = frozenset(("CoordinateSet", "FrameChange"))
"""Sections after which the frame holds values only the run knows: nothing more is followed (and a ``DataSetting``
of a work offset, ``G10 L2``/``L20``; a tool table's entry changes no work position)."""


def install(ctx: Context, setup: MachineSetup) -> None:
    """Follow the set-up's positions in this reading when it declares work offsets: every placed position needs the
    active system's (a home alone places nothing). Else, and on a lathe, nothing is installed and the reading pays
    nothing (the bench machine declares a Z home and no offsets: an interpreted call at every block that changes
    a mode cost the grbl row ~70 instructions a block, callgrind)."""
    if setup.work_offsets and not ctx.lathe:
        ctx.state.extra[KEY] = SetUpPositions(setup)


class SetUpPositions:
    """The set-up's homes and work offsets, read by the reading's modal step at the blocks that need them."""

    def __init__(self, setup: MachineSetup) -> None:
        self.mm = setup.machine.mm()
        """Millimetres per set-up unit."""
        self.homes = {a: t.home * self.mm for a, t in setup.travel.items() if a in AXES and t.home is not None}
        """Each axis's reference position (machine coordinates, mm), where the set-up gives one."""
        self.declared = declared_offsets(setup, AXES, False)
        """The set-up's work offsets (mm), by work system."""

    def offset(self, axis: str, system: int) -> float | None:
        """Machine minus work position on ``axis`` under work ``system`` (mm), None where the set-up does not say."""
        return offset_beyond_frame(axis, system, {}, self.declared)[0]

    def apply(self, state: ModalState, sections: Mapping[str, object], ctx: Context) -> None:
        """``state.apply(sections)``, with the work position after a change of work system taken from the old one
        and the two systems' offsets where they are declared. A section the program sets the frame with ends the
        following (the key leaves ``state.extra``)."""
        setting = sections.get("DataSetting")
        if ctx.lathe or not PROGRAM_SET.isdisjoint(sections) or (
                setting is not None and str(getattr(setting, "table", "")).startswith("work_offset")):
            del state.extra[KEY]
            state.apply(sections)
            return
        work = sections.get("WorkOffset")
        index = getattr(work, "index", None)
        if not isinstance(index, int) or index == state.work_offset:
            state.apply(sections)
            return
        scale = MM_PER_INCH if state.units == "inch" else 1.0
        machine: dict[str, float] = {}
        for axis in AXES:
            here = state.position.get(axis)
            offset = self.offset(axis, state.work_offset)
            if here is not None and offset is not None:
                machine[axis] = here * scale + offset
        state.apply(sections)
        self._place(state, machine, state.work_offset)

    def moved(self, state: ModalState, motion: Motion, machine_coordinates: bool, ctx: Context) -> None:
        """After a reference return or a move in machine coordinates (the reading has left ``motion``'s axes
        unknown): the work position of each axis the set-up places."""
        if ctx.lathe or ctx.increments:
            return
        ends: dict[str, float] = {}
        scale = MM_PER_INCH if state.units == "inch" else 1.0
        for axis, value in motion.axes.items():
            if axis not in AXES or axis == LENGTH_AXIS and state.length != "cancel":
                continue  # (the programmed point is the controlled point less a length only the run may know)
            if machine_coordinates:
                if state.distance != "incremental" and type(value) is float:
                    ends[axis] = value * scale
            elif motion.mode == "home" and axis in self.homes:
                ends[axis] = self.homes[axis]
        self._place(state, ends, state.work_offset)

    def _place(self, state: ModalState, machine: dict[str, float], system: int) -> None:
        """Put each machine position (mm) in the work frame of ``system``, in program units."""
        scale = MM_PER_INCH if state.units == "inch" else 1.0
        position = state.position
        for axis, value in machine.items():
            offset = self.offset(axis, system)
            if offset is not None and position.get(axis, 0.0) is None:
                position[axis] = round((value - offset) / scale, 12) + 0.0
