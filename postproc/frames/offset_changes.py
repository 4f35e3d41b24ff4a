"""What the frame evaluation (``postproc.frames.lowering``) follows of offset changes and data settings: the
program position a tool offset change moves (on a controller that keeps the machine point), the tool table
entries a program writes, and a G10's work offsets and work system rotation.

Functions of the evaluator (``ev``), apart from the frame commands and the carrying of moves: a module of its
own so that neither grows past one job (issue 30).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Final

from ..compensation.tool_length import ToolLength
from ..compensation.tool_table import ENTRY, TABLES, ToolTable
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..ir.expr import Expr
from ..ir import Block, DataSetting, Section, ToolLengthOffset
from ..ir.verbatim import STORED_WORK_OFFSET
from ..setup.work_offsets import declared_offsets
from .affine import XYZ
from .words import COMPUTED, LINEAR, SYMBOLIC, note

if TYPE_CHECKING:
    from .evaluation import Evaluation

MEASURED_ENTRIES: Final = frozenset(("tool_entry_at_point", "tool_entry_at_point_9"))
"""Tool table entries a program measures where the tool stands (LinuxCNC's, ``postproc.simulate.position.Position.touch_off``)."""
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
    turn = _turn(ev)
    if turn and ("X" in changes or "Y" in changes):
        # the offsets are the machine's (unturned); the program point moves by them turned back [V: LinuxCNC
        # convert_tool_length_offset, ``rotate(&dx, &dy, -settings->rotation_xy)``; rs274 run: g10_l1_l10.ngc]
        changes["X"], changes["Y"] = _rotate(changes.get("X", 0.0), changes.get("Y", 0.0), -turn)
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
    if setting.table in MEASURED_ENTRIES and ev.frame is not None and not ev.frame.plain():
        # the frame leaves the block: the entry it measures is worked out here, under the frame, and goes on
        # as the whole entry it sets (``G10 L1``), which means the same without the frame
        s["DataSetting"] = setting = measured_in_frame(ev, setting)
    if ev.ctx.length_at_axis and (setting.table in TOOL_TABLES or setting.table in MEASURED_ENTRIES):
        tool_entry(ev, setting)
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
        if old is None and table == "work_offset":
            old = _declared(ev, setting.index, axis)
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
    frame = ev.frame_for("shared_offset")
    if ev.frame is not None and frame.rules != "shared_offset":
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
    LinuxCNC ``convert_setup_tool``; ``postproc.frames.measured_entries``]; where that is not known here
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


def _declared(ev: Evaluation, system: int, axis: str) -> float | None:
    """A work system's offset before the program sets it, as the simulation takes it
    (``postproc.simulate.position.Position._beyond``): the set-up's; every one zero where the set-up gives none; None
    where it gives others but not this one."""
    setup = ev.ctx.setup
    declared = declared_offsets(setup, tuple(setup.machine.axes), False)
    if not declared:
        return 0.0
    return declared.get(system, {}).get(axis)


def _turn(ev: Evaluation) -> float:
    """The active work system's XY rotation (shared_offset rules: ``G10 L2 R``, degrees); 0 under other rules."""
    frame = ev.frame
    if frame is None or frame.rules != "shared_offset":
        return 0.0
    return frame.turns.get(frame.work, 0.0)


def _rotate(x: float, y: float, degrees: float) -> tuple[float, float]:
    """(x, y) turned by ``degrees`` counter-clockwise (LinuxCNC ``Interp::rotate``)."""
    t = math.radians(degrees)
    c, s = math.cos(t), math.sin(t)
    return x * c - y * s, x * s + y * c


def measured_in_frame(ev: Evaluation, setting: DataSetting) -> DataSetting:
    """A tool entry measured where the tool stands (``G10 L10``) under the program's G92/G52 offset and its
    work system's rotation: the whole entry it sets (values in program units), as LinuxCNC works it out [V:
    ``interp_convert.cc`` ``convert_setup_tool`` with ``interp_find.cc`` ``find_current_in_system_without_tlo``;
    rs274 2.9.0~pre1 run on LinuxCNC's own ``g10_l1_l10.ngc`` here]. With ``t`` the point without the tool
    offset in the system's unturned axes, ``t = p + R^-1 o`` (``p`` the program's current point, ``o`` the
    entry in force; the G92 offset cancels), the entry is ``R (t - word)`` with X and Y both given; with X
    alone ``R (t_x - X, 0)`` plus the old entry's part along the turned Y axis (with Y alone the converse);
    Z ``t_z - Z``. Refused by name where a value it needs is not known here: work system 9's entry (``L11``),
    another controller's frame, an unknown point or offset."""
    if setting.table != "tool_entry_at_point":
        raise UnsupportedError("a tool entry measured in work system 9 under a coordinate shift or "
                               "rotation of the program's own: that system's origin is the machine's, not known here")
    frame = ev.frame
    assert frame is not None
    if frame.rules != "shared_offset":
        raise UnsupportedError("a tool entry measured where the tool stands under another controller's frame")
    run = ev.reached
    if not run.tools_known or not run.table_known:
        raise UnsupportedError(f"{setting.describe()}: the tool offset in force or the entry is not known here (a "
                               "computed register or entry, or one the set-up does not give)")
    scale = ev.scale
    turn = _turn(ev)
    length = run.tools.offset if run.tools is not None else 0.0
    ox, oy = _rotate(run.sideways.get("X", 0.0), run.sideways.get("Y", 0.0), -turn)
    words: dict[str, float] = {}
    for letter, value in setting.values.items():
        if isinstance(value, Expr):
            raise UnsupportedError(f"a computed {letter} in {setting.describe()}: the entry is worked out here, "
                                   "which needs the number")
        words[letter] = float(value)
    needed = ("X", "Y") if "X" in words or "Y" in words else ()
    for axis in (*needed, *(("Z",) if "Z" in words else ())):
        if ev.p.get(axis) is None:
            raise UnsupportedError(f"{setting.describe()} where the tool's {axis} is not known here (after a reference "
                                   "return, a move in machine coordinates, a cycle or a change of work offset): "
                                   "program a move to a known point first")
    values: dict[str, float | Expr] = {k: v for k, v in setting.values.items() if k not in XYZ}
    if needed:
        px, py = ev.p["X"], ev.p["Y"]
        assert px is not None and py is not None
        tx, ty = px + ox, py + oy
        if "X" in words and "Y" in words:
            ex, ey = _rotate(tx - words["X"] * scale, ty - words["Y"] * scale, turn)
        else:
            table = run.tools.table if run.tools is not None else None
            old = table.across.get(setting.index, {}) if table is not None else {}
            kx, ky = _rotate(old.get("X", 0.0), old.get("Y", 0.0), -turn)  # the old entry in the turned axes
            if "X" in words:
                kept = _rotate(0.0, ky, turn)
                ex, ey = _rotate(tx - words["X"] * scale, 0.0, turn)
            else:
                kept = _rotate(kx, 0.0, turn)
                ex, ey = _rotate(0.0, ty - words["Y"] * scale, turn)
            ex, ey = ex + kept[0], ey + kept[1]
        values["X"], values["Y"] = ex / scale, ey / scale
    if "Z" in words:
        pz = ev.p["Z"]
        assert pz is not None
        values["Z"] = (pz + length) / scale - words["Z"]
    return DataSetting(setting.family, ENTRY, setting.index, values, False, setting.text)
