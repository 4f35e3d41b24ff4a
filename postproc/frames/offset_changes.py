"""What the frame evaluation (``postproc.frames.lowering``) follows of offset changes and data settings: the
program position a tool offset change moves (on a controller that keeps the machine point), the tool table
entries a program writes, and a G10's work offsets and work system rotation.

Functions of the evaluator (``ev``), apart from the frame commands and the carrying of moves: a module of its
own so that neither grows past one job (issue 30).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Final

from ..compensation.tool_length import ToolLength
from ..compensation.tool_table import ENTRY, TABLES, ToolTable
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..expr import Expr
from ..ir import Block, DataSetting, Section, ToolLengthOffset
from ..ir.verbatim import STORED_WORK_OFFSET
from .affine import XYZ
from .words import COMPUTED, LINEAR, SYMBOLIC, note

if TYPE_CHECKING:
    from .evaluation import Evaluation

MEASURED_ENTRIES: Final = frozenset(("tool_entry_at_point", "tool_entry_at_point_9"))
"""Tool table entries a program measures where the tool stands (LinuxCNC's, ``postproc.simulate.moves.touch_off``)."""
TOOL_TABLES: Final = frozenset((ENTRY, *TABLES))
"""Tool table writes a later tool offset change reads (``tool_entry``)."""


def current_point_reads(ev: Evaluation, s: dict[str, Section]) -> None:
    """What the program position and a read of it (``postproc.frames.parameters``) must know of the
    block: a tool offset change (``tool_change``); cutter compensation on forbids the read (rs274: "Cannot
    read current position with cutter radius compensation on" [V: ``interp_read.cc``
    ``read_integer_parameter``])."""
    length = s.get("ToolLengthOffset")
    if isinstance(length, ToolLengthOffset) and ev.ctx.length_at_axis:
        tool_change(ev, length)  # before the block's motion [V: rs274 order of execution]
    cc = s.get("CutterCompensation")
    if cc is not None:
        ev.reached.cutter = getattr(cc, "mode", "off") != "off"
    if "DynamicCutterCompensation" in s:
        ev.reached.cutter = True


def tool_change(ev: Evaluation, length: ToolLengthOffset) -> None:
    """A tool offset change on a controller that keeps the machine point until the axis is programmed
    (``Dialect.LENGTH_AT_PROGRAMMED_AXIS``): the program position moves by the change, ``current_z + old -
    new`` [V: LinuxCNC ``interp_convert.cc`` ``convert_tool_length_offset``, on every axis of the entry;
    rs274 ``G43 H1`` then ``G92 Z0`` sets the offset from the moved point], as the simulation's
    programmed point does (``postproc.simulate.moves``). Where the new offset is not known here (a computed
    register, one the set-up lacks, an entry measured where the tool stands), X, Y and Z are unknown."""
    run, p = ev.reached, ev.p
    if run.tools is None:
        run.tools = ToolLength(ToolTable(ev.ctx.setup))
    register = length.register
    old_z, old_side = run.tools.offset, run.sideways
    try:
        if isinstance(register, Expr) or isinstance(length.length, Expr) or (
                not run.table_known and length.mode in ("positive", "negative")):
            raise ProgramError("a computed tool offset, or an entry not known here")
        run.tools.change(length.mode, register, length.length, ev.scale)
        side = run.tools.table.sideways(register) if length.mode == "positive" and isinstance(register, int) \
            else {}
    except PostprocError:
        run.tools_known = False
        for axis in XYZ:
            p[axis] = None
        return
    if not run.tools_known:
        run.tools_known = True  # known again from here; the point before stays unknown
        for axis in XYZ:
            p[axis] = None
    changes = {"Z": run.tools.offset - old_z}
    for axis in set(side) | set(old_side):
        changes[axis] = changes.get(axis, 0.0) + side.get(axis, 0.0) - old_side.get(axis, 0.0)
    run.sideways = side
    for axis, change in changes.items():
        here = p.get(axis)
        if change and here is not None:
            p[axis] = here - change


def data_setting(ev: Evaluation, block: Block, s: dict[str, Section]) -> bool:
    """G10 L2: a work system's rotation (R) goes into the frame and out of the setting; an offset of
    the active system moves the program position (the tool stays)."""
    setting = s["DataSetting"]
    assert isinstance(setting, DataSetting)
    if ev.ctx.length_at_axis and (setting.table in TOOL_TABLES or setting.table in MEASURED_ENTRIES):
        tool_entry(ev, setting)
    if setting.table in MEASURED_ENTRIES and ev.frame is not None and not ev.frame.plain():
        # the entry is the tool's point in the work system without the tool offset, less the values
        # ([V] LinuxCNC convert_setup_tool): that point under the program's shift or rotation is not
        # worked out here, so no entry is guessed
        raise UnsupportedError("a tool entry measured where the tool stands, under a coordinate shift or rotation "
                               "of the program's own, is not modelled")
    if not setting.table.startswith("work_offset"):
        return False
    values = setting.values
    table = setting.table
    if table == STORED_WORK_OFFSET and setting.index == ev.modal.work_offset:
        for axis in values:  # taken at the next selection: where the tool then stands is not worked out here
            ev.p[axis] = None
        ev.g5x.get(setting.index, {}).clear()
        return False
    if table == STORED_WORK_OFFSET:
        table = "work_offset"  # a system not active: one meaning
    active = table == "work_offset" and setting.index == ev.modal.work_offset
    known = ev.g5x.setdefault(setting.index, {}) if table == "work_offset" else {}
    for axis, value in values.items():
        if axis == "R":
            continue
        if isinstance(value, Expr) or setting.incremental:
            known.pop(axis, None)
            if active:
                ev.p[axis] = None
            continue
        new = value * (ev.scale if axis in LINEAR else 1.0)
        old = known.get(axis)
        here = ev.p.get(axis)
        if active:
            ev.p[axis] = None if here is None or old is None else here + old - new
        known[axis] = new
    if "R" not in values:
        return False
    turn = values["R"]
    if isinstance(turn, Expr):
        raise ProgramError(COMPUTED)
    if ev.reached.symbolic:
        raise ProgramError(SYMBOLIC)
    if setting.table != "work_offset":
        raise ProgramError("a rotation (R) of an extended work system cannot be evaluated")
    frame = ev.frame_for("rs274")
    if ev.frame is not None and frame.rules != "rs274":
        raise ProgramError("a work system rotation (R) beside another controller's frame")
    frame.set_turn(setting.index, float(turn))
    if active:
        ev.p["X"], ev.p["Y"] = None, None  # [V] convert_setup moves the current point into the turned system
    rest = {k: v for k, v in values.items() if k != "R"}
    words = setting.text.split()
    if rest:
        s["DataSetting"] = DataSetting(setting.family, setting.table, setting.index, rest, setting.incremental,
                                       " ".join(w for w in words if not w.upper().startswith("R")))
        note(s, " ".join(w for w in words if w.upper().startswith("R")) + " evaluated")
    else:
        del s["DataSetting"]
        note(s, f"{setting.text} evaluated")
    return True


def tool_entry(ev: Evaluation, setting: DataSetting) -> None:
    """A program's tool table entry, which a later offset change reads (``tool_change``). One measured
    where the tool stands (``G10 L10``) is the current point plus the offset in force, less the word [V:
    LinuxCNC ``convert_setup_tool``; ``postproc.lowering.measured_entries``]; where that is not known here
    (work system 9's ``L11``, an unknown point, a computed word), every offset read after it is unknown."""
    run = ev.reached
    if run.tools is None:
        run.tools = ToolLength(ToolTable(ev.ctx.setup))
    if setting.table in MEASURED_ENTRIES:
        setting = _measured(ev, setting)
    if any(isinstance(v, Expr) for v in setting.values.values()) or setting.table in MEASURED_ENTRIES:
        run.table_known = False
        return
    try:
        run.tools.table.write(setting, ev.scale)
    except PostprocError:
        run.table_known = False


def _measured(ev: Evaluation, setting: DataSetting) -> DataSetting:
    """The whole entry a measured one sets (unchanged where it is not worked out here)."""
    run = ev.reached
    if setting.table != "tool_entry_at_point" or not run.tools_known or (
            ev.frame is not None and not ev.frame.plain()):
        return setting
    offsets = {"Z": run.tools.offset if run.tools is not None else 0.0, **run.sideways}
    values: dict[str, float | Expr] = {}
    for letter, value in setting.values.items():
        here = ev.p.get(letter)
        if letter not in XYZ:
            values[letter] = value
        elif isinstance(value, Expr) or here is None:
            return setting
        else:
            values[letter] = (here + offsets.get(letter, 0.0)) / ev.scale - float(value)
    return DataSetting(setting.family, ENTRY, setting.index, values, False, setting.text)
