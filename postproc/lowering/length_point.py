"""Where the programmed point stands, for the tool length timing (``postproc.lowering.length_timing``): the Z (and a
lathe's X) after each block, in program units, None where it is not known; the offset between a machine-coordinate
Z and the programmed one; the length a change puts in force.

Split from ``length_timing`` along its seam: that module decides *when* a length change applies on the target
(held, moved, completed or refused); this one only follows *where* the program stands, which both the waiting
change and the completed one read. Where a block that is no plain move leaves the point is
``postproc.lowering.point_after``'s one answer (a native hole cycle, an expanded cycle, a call or a jump).
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..compensation.tool_table import ToolTable
from ..errors import PostprocError
from ..interp.control import LABEL
from ..ir import Block, CompoundMotion, DataSetting, Motion, Section, WorkOffset
from ..ir.expr import Expr
from ..setup.machine_setup import MachineSetup
from ..setup.work_offsets import declared_offsets, offset_beyond_frame
from .point_after import compound_end, cycle_end, loses_after

AXIS: Final = "Z"
MM_PER_INCH: Final = 25.4
PLAIN: Final = frozenset(("rapid", "linear", "cw", "ccw"))
"""The plain moves (G0-G3): a number of theirs is where the axis ends."""


def follow_point(block: Block, pos: dict[str, float | None], absolute: bool, in_force: tuple[str, object, object],
            table: ToolTable | None, inch: bool, beyond: float | None) -> None:
    """Move ``pos`` (program units) to the point after the block's motion, None where it is not known. A
    machine-coordinate Z is the programmed Z plus the work offset in force (``beyond``, ``MachineFrame``) plus the
    mill's length in force (``in_force`` read in ``table``; None on a lathe: not followed)."""
    sections = block.sections
    if LABEL in sections:
        for axis in pos:
            pos[axis] = None  # a jump's target: reached from elsewhere too (``point_after``)
    cycle = sections.get("CannedCycle")
    if cycle is not None and "CompoundMotion" not in sections:
        end = cycle_end(cycle)  # a hole cycle kept native ends over its last hole at its return level
        for axis in pos:
            pos[axis] = None if end is None else end.get(axis)
        return
    compound = sections.get("CompoundMotion")
    if isinstance(compound, CompoundMotion) and "MachineCoordinates" not in sections and not loses_after(sections):
        moved = compound_end(compound)  # an expanded cycle: its moves are absolute
        for axis in pos:
            if moved is None:
                pos[axis] = None
            elif axis in moved:
                pos[axis] = moved[axis]
        return
    if compound is not None or "RigidTap" in sections or "CycleCall" in sections or loses_after(sections):
        for axis in pos:
            pos[axis] = None  # a native lathe cycle's end, a call's, a modal cycle call's: not followed here
        return
    motion = sections.get("Motion")
    if not isinstance(motion, Motion):
        return
    axes = motion.axes
    for axis in pos:
        value = axes.get(axis)
        if value is None:
            continue
        if isinstance(value, Expr) or motion.mode not in PLAIN:
            pos[axis] = None
        elif "MachineCoordinates" in sections:
            length = None if table is None or axis != AXIS else length_in_force(in_force, table, inch)
            pos[axis] = None if length is None or beyond is None else float(value) - beyond - length
        elif absolute:
            pos[axis] = float(value)
        else:
            known = pos[axis]
            pos[axis] = None if known is None else known + float(value)


@mypyc_attr(allow_interpreted_subclasses=True)
class MachineFrame:
    """What lies between a machine-coordinate Z and the programmed one (besides the length): the set-up's offset of
    the active work system and the external one (``postproc.setup.work_offsets``, as the simulation subtracts it).
    Only a declared offset counts: where the set-up gives the active system none (or no ``<WorkOffsets>`` at all,
    which the simulation takes as zero on both sides of ``verify``, so it could not see a wrong guess), or after a
    G10 work offset, G92/G52 or a frame change (values only the run knows here), the programmed Z after a machine
    move is not known, and a length change that needs it is a located error (issue 26: writing the machine's Z0
    as the program's Z0 sent a Haas program's first rapid down to the part's zero)."""

    def __init__(self, setup: MachineSetup) -> None:
        self.declared = declared_offsets(setup, (AXIS,), False)
        self.system = 1  # G54 (or the dialect's first system) at power-on [K: DIALECTS.md, modal defaults]
        self.offset = offset_beyond_frame(AXIS, self.system, {}, self.declared)[0]
        """The offset of ``system`` in mm (None: the set-up gives none), found when the system changes: the
        tool length timing asks ``beyond`` of every block."""
        self.known = True
        self.machine_z = False
        """The programmed Z is unknown since a machine-coordinate move whose offset is not known."""

    def follow(self, sections: dict[str, Section]) -> None:
        work = sections.get("WorkOffset")
        if isinstance(work, WorkOffset) and work.index != self.system:
            self.system = work.index
            self.offset = offset_beyond_frame(AXIS, self.system, {}, self.declared)[0]
        setting = sections.get("DataSetting")
        if "CoordinateSet" in sections or "FrameChange" in sections or (
                isinstance(setting, DataSetting) and setting.table.startswith("work_offset")):
            self.known = False

    def placed(self, sections: dict[str, Section], known: bool) -> None:
        if known:
            self.machine_z = False
        elif "MachineCoordinates" in sections:
            self.machine_z = True

    def why(self) -> str:
        """What the located error adds where a machine move left the programmed Z unknown."""
        if not self.machine_z:
            return ""
        if not self.known:
            return " (a move in machine coordinates after a work offset, a coordinate shift or a frame set in the program)"
        return (f" (a move in machine coordinates: {offset_beyond_frame(AXIS, self.system, {}, self.declared)[1]}"
                f" to put it in work coordinates)")

    def beyond(self, inch: bool) -> float | None:
        """The offset in program units; None where it is not known."""
        if not self.known:
            return None
        value = self.offset
        return None if value is None else value / MM_PER_INCH if inch else value


def length_in_force(key: tuple[str, object, object], table: ToolTable, inch: bool) -> float | None:
    """The length a ``_key`` puts in force, program units; None where the set-up does not give it."""
    mode, register, length = key
    scale = MM_PER_INCH if inch else 1.0
    if mode == "cancel":
        return 0.0
    if mode == "dynamic":
        return float(length) if isinstance(length, (int, float)) else None
    if not isinstance(register, int) or mode not in ("positive", "negative"):
        return None
    try:
        value = table.length(register)
    except PostprocError:
        return None
    return (value if mode == "positive" else -value) / scale


