"""Moves in machine coordinates resolved into work coordinates, for a target that has no such move (a lowering
step of the target that needs it: GSK).

A move in machine coordinates (Fanuc ``G53 X0 Z0``) goes to where the machine's controlled point stands at those
machine positions, whatever the work offset and the tool offset in force. The simulation puts it in the work
frame by subtracting both (``postproc.simulate.simulator.Simulator._machine_coordinates`` and ``machine_to_frame``:
the set-up's offset of the active work system and the external one, ``postproc.setup.work_offsets``, and the
lathe tool offset the T code selected, ``postproc.compensation.tool_table.ToolTable.lathe``). This step writes the
same point as a move in work coordinates, which every target has, so ``verify`` compares the same path and the
machine goes where the source's went:

    programmed = machine - (work offset of the active system + external offset) - tool offset in force

Only offsets the set-up declares count (the simulation takes a set-up without ``<WorkOffsets>`` as zero on both
sides of ``verify``, so it could not see a wrong guess; issue 26: writing a machine's Z0 as the program's Z0
sent a Haas program's first rapid down to the part's zero). Where the active system's offset, the tool's
``<Tool x z>``, or the frame itself is not known (a ``G10`` work offset, a coordinate setting ``G50``/``G92``, a
frame change earlier in the program: values only the run knows here), the move is a located error that names
what to add to the set-up. A move in machine coordinates under incremental distance stays a located error too
(its other words would read the increment). Lathe X is written as the program writes it (a diameter where X is).
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..compensation.tool_table import ToolTable
from ..context import Context
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir.expr import Expr
from ..ir import Block, DataSetting, Motion, ToolLengthOffset, ToolSelect, WorkOffset
from ..setup.work_offsets import declared_offsets, offset_beyond_frame
from .lower import BlockStep, LoweringStep
from .units_and_distance import UnitsAndDistance

FRAME_UNKNOWN: Final = frozenset(("CoordinateSet", "FrameChange"))
"""Sections after which the frame holds values only the run knows."""
AXES: Final = ("X", "Y", "Z", "A", "B", "C")
"""The axes whose declared offsets are read (a machine move names no other)."""
WATCHED: Final = frozenset(("MachineCoordinates", "Units", "WorkOffset", "DistanceMode", "ToolSelect", "ToolChange",
                            "ToolLengthOffset", "DataSetting", *FRAME_UNKNOWN))
"""The sections this step reads; a block with none of them passes untouched."""


class ResolveMachineMoves(LoweringStep):
    """Lowering step: see the module docstring."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _Resolve(ctx, target.NAME, not target.TOOL_CHANGER)


resolve_machine_moves = ResolveMachineMoves()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Resolve(BlockStep):
    """One run: the units, distance mode, work system and lathe tool offset register in force, and whether the
    frame is still the set-up's. A block that is only a move changes none of them and is no machine move."""

    def __init__(self, ctx: Context, target: str, turret: bool) -> None:
        super().__init__()
        self.turret = turret and ctx.lathe
        """The target indexes a turret lathe's tool with its offset (GSK ``T0202``): the stream reaching this step is
        written for it, so a T word there selects offset register ``T % 100`` whatever the source did (a LinuxCNC
        ``T2 M6 G43 H2`` has become ``T0202`` before this step)."""
        self.moves = False
        self.ctx = ctx
        self.target = target
        self.declared = declared_offsets(ctx.setup, AXES, ctx.diameter)
        self.table = ToolTable(ctx.setup)
        self.modes = UnitsAndDistance()
        self.system = 1  # G54 (or the dialect's first system) at power-on [K: DIALECTS.md, modal defaults]
        self.register: int | str = 0
        """The lathe tool offset register in force (0: none), or why it is not known."""
        self.selected: int | None = None
        """The tool the last T word selected (an M6 lathe's next tool), None where computed or none."""
        self.spindle_tool: int | None = None
        """The tool an M6 put in the spindle (what ``G43`` without H offsets by)."""
        self.unknown = ""
        """Why the frame is no longer the set-up's ('' while it is)."""

    def take(self, block: Block) -> list[Block] | None:
        s = block.sections
        if WATCHED.isdisjoint(s):
            return None
        self.modes.follow(s)
        work = s.get("WorkOffset")
        if isinstance(work, WorkOffset):
            self.system = work.index
        tool = s.get("ToolSelect")
        if isinstance(tool, ToolSelect):
            self.selected = tool.number if isinstance(tool.number, int) else None
            if self.turret:  # T0101: the offset with it
                self.register = tool.number % 100 if isinstance(tool.number, int) else "computed"
        if "ToolChange" in s:
            self.spindle_tool = self.selected
        length = s.get("ToolLengthOffset")
        if isinstance(length, ToolLengthOffset) and self.ctx.lathe:  # LinuxCNC's lathe G43 H2: X and Z (simulator)
            if length.mode == "cancel":
                self.register = 0
            elif length.mode != "positive":
                self.register = f"a tool offset set by {length.mode} length compensation"
            else:
                register = length.register if length.register is not None else self.spindle_tool
                self.register = register if isinstance(register, int) else "computed"
        setting = s.get("DataSetting")
        if isinstance(setting, DataSetting):
            if setting.table.startswith("work_offset"):
                self.unknown = "a work offset set in the program"
            else:  # a tool table's entry (written where it is one; another table holds no offset read here)
                self.table.write(setting, self.modes.scale)
        for key in FRAME_UNKNOWN:
            if key in s:
                self.unknown = "a coordinate setting or a frame change in the program"
        motion = s.get("Motion")
        if "MachineCoordinates" in s and isinstance(motion, Motion) and motion.axes and "BlockDelete" not in s:
            try:
                self._resolve(block, motion)
            except UnsupportedError as err:
                if self.ctx.on_unsupported == "warn":
                    return None  # the writer refuses the move and comments it out, with its warning
                self.ctx.diagnostics.error(err)
                return []
        return None

    def _resolve(self, block: Block, motion: Motion) -> None:
        """The block's move in machine coordinates as the same move in work coordinates (module docstring)."""
        where = self.ctx.at(block)
        lead = (f"the {self.target} dialect has no motion in machine coordinates, and this move cannot be put in "
                "work coordinates")
        if not self.modes.absolute:
            raise UnsupportedError(f"{lead} under incremental distance", where)
        if self.unknown:
            raise UnsupportedError(f"{lead} after {self.unknown} (its values are the run's)", where)
        beyond: dict[str, tuple[float, float]] = {}
        for axis, value in motion.axes.items():
            if not isinstance(value, (int, float)):
                raise UnsupportedError(f"{lead}: its {axis} is computed", where)
            offset, why = offset_beyond_frame(axis, self.system, {}, self.declared)
            if offset is None:
                raise UnsupportedError(f"{lead}: {why}", where)
            beyond[axis] = float(value), offset
        shift = self._tool_shift()
        if isinstance(shift, str):
            raise UnsupportedError(f"{lead}: {shift}", where)
        scale = self.modes.scale
        axes: dict[str, float | Expr] = {}
        for axis, (value, offset) in beyond.items():
            mm = offset + shift.get(axis, 0.0)  # radius on a diameter lathe's X
            if axis == "X" and self.ctx.diameter:
                mm *= 2.0
            axes[axis] = _tidy(value - mm / scale)
        block.sections["Motion"] = Motion(motion.mode, axes, motion.center, motion.radius)
        del block.sections["MachineCoordinates"]
        block.changed()

    def _tool_shift(self) -> dict[str, float] | str:
        """The lathe tool offset in force (mm, X a radius where X is a diameter), or why it is not known."""
        register = self.register
        if not self.ctx.lathe or register == 0:
            return {}
        if register == "computed":
            return "the tool offset register in force is computed"
        if isinstance(register, str):
            return f"{register} is not followed here"
        values = self.table.lathe(register, self.ctx.diameter)
        if values is None:
            return (f"the set-up gives tool offset {register} no X and Z (<Tools><Tool number=\"{register}\" x=... "
                    "z=...>)")
        return {"X": values[0], "Z": values[1]}


def _tidy(value: float) -> float:
    """A difference of decimal numbers without its binary noise (12 places: far below any control's resolution)."""
    return round(value, 12) + 0.0
