"""expand_lathe_cycles: keep a lathe cycle native where the target runs it, else write its moves; and
give a target that is no lathe control the lathe program in its own terms.

A lathe cycle is native when the target runs it (``Dialect.LATHE_CYCLES``) and the set-up does not force
its expansion (``<Cycles expand=...>``). G70-G73 share their profile blocks, so they are native only
together: a profile commented out for an expanded G71 must not be left to a native G70. An expanded
cycle loses its ``LatheCycle`` and is written as its ``CompoundMotion`` (a comment naming the source
line, then the moves); its first block becomes a comment, and each profile block a comment too (the
controller never ran it where it stands).

For a target that reads no lathe programs (grbl), the moves are made its own: the ZX plane is selected first, U/W increments become absolute X/Z (from the tracked position; a
located error where it is unknown), and on a diameter program X is halved (such a target takes a
radius: ``Dialect.DIAMETER_PROGRAMMING``), and the set-up's lathe tool offsets are written into its
coordinates (``postproc.cycles.lathe_offsets``). A lathe target without the source's incremental addresses
(LinuxCNC, whose U/W are axes) gets absolute X/Z too, and one that changes lathe tools with M6
(``Dialect.LATHE_TURRET`` False) gets the turret index as a tool change (a T naming the station already in
position, ``T0200`` after ``T0202``, indexes nothing: only its offset is written, ``_same_station``) and its
offset number as the register of its tool length offset code, and of a G41/G42 that names none: a turret lathe's tool nose
radius compensation takes the nose radius and tip of the offset in force [K: Fanuc T, GSK: the radius
and tip columns of the offset the T code selected], LinuxCNC's G41 without D the spindle tool's entry,
which is not the offset's (``T0102``). A target that is no lathe control gets that register named too: its
compensation is resolved into moves with the offset's radius and tip (``lowering.cutter_compensation``).

A switch of how X reads inside the program (``XProgramming``, LinuxCNC's G7/G8) goes for a target without
``Dialect.X_MODE_SWITCH``: the reader converted every X to the set-up's mode, which the target writes.

A cycle whose profile turns nose compensation on in its first block and off in its last (the Haas form,
``NOSE_PROFILE``) is expanded for every other controller: the roughing to the nose's path and the finishing
under compensation are the source controller's own (another controller's rules for that form are not known).
A lathe cycle under tool nose radius compensation is refused where its compensated moves are not known:
towards another controller (Fanuc T's G71/G72 type I under compensation, ``CutterRules.roughing_cycles``, are
read and simulated as Fanuc T runs them and kept in a Fanuc T copy, but no other controller is known to rough
so; LinuxCNC refuses G71/G72 with compensation on [V: ``interp_g7x.cc``]), and in the simulation of a
source whose compensation is simulated (LinuxCNC's) unless its rules run the cycle. A finishing cycle (G70)
is its profile, which compensation runs as any other moves: it stays.
"""

from __future__ import annotations

from typing import Any, Callable, Iterator

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir.expr import Expr
from postproc.errors import PostprocError, UnsupportedError
from postproc.ir import (
    Block, Comments, CompoundMotion, CutterCompensation, DistanceMode, FeedMode, MachineFunction, Motion, Plane,
    SpindleControl, ToolChange, ToolLengthOffset, ToolSelect, one_line,
)
from postproc.ir.lathe_sections import CoordinateSet, LatheCycle

from ..interp.control import CONTROL, LABEL
from ..ir.source_map import ExecutedBlock
from ..lowering.machine_functions import comment_out
from .lathe_offsets import LatheOffsets

THREAD_CHAMFER = ("thread-chamfer-on", "thread-chamfer-off")
"""The actions of a code that switches the threading cycles' pull-out chamfer on or off (Haas M23/M24, the
reader applies it: ``postproc.rs274.lathe_cycles``): towards another family it becomes a comment
(``_chamfer_switch_noted``)."""

NOSE_PROFILE = "nose_profile"
"""``LatheCycle.params`` key set by the reader (``postproc.rs274.lathe_cycles``) on a cycle whose profile turns
tool nose radius compensation on in its first block and off in its last (the Haas form): its moves are
the source controller's, so it is written expanded for every other controller, its profile blocks as comments."""

def lathe_tool(number: int) -> int:
    """The tool of a lathe T word: T0101 (tool and offset, four digits) is tool 1; T1 to T99 name the tool."""
    return number // 100 if number >= 100 else number


PROFILE_CYCLES = frozenset(("turn_finish", "turn_rough", "face_rough", "pattern_repeat"))


def expand_lathe_cycles(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering transform (see the module docstring); a mill program passes through untouched."""
    if not ctx.lathe:
        return blocks
    return _lower(blocks, ctx, target)


def _native(target: type[Dialect], ctx: Context) -> frozenset[str]:
    if "lathe" not in target.MACHINE_TYPES:
        return frozenset()
    forced = ctx.setup.cycles.expanded()
    if "all" in forced:
        return frozenset()
    native = frozenset(k for k in target.LATHE_CYCLES if k not in forced)
    if not PROFILE_CYCLES <= native:
        native -= PROFILE_CYCLES
    return native


def _lower(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    native = _native(target, ctx)
    foreign = "lathe" not in target.MACHINE_TYPES
    radius = ctx.diameter and (foreign or not target.DIAMETER_PROGRAMMING)
    absolute = target.WRITER is not None and dict(target.INCREMENTAL_AXES) != dict(ctx.increments)
    """A target written to has not the source's incremental addresses (LinuxCNC's U/W are axes): U/W become
    X/Z. (The simulator, which writes nothing, reads the source's own.)"""
    tracker = _Position(ctx, radius) if foreign or radius or absolute else None
    turret = ctx.lathe_turret and (foreign or not target.LATHE_TURRET)
    """A turret index becomes a tool change: not from a source that changes tools with M6 (LinuxCNC, grblHAL),
    whose ``T1 M6`` applies no offset (its ``G43 H`` does, and is its own) and whose ``T1`` alone selects the next
    tool without changing it, to a mill control too (was: ``T1`` written ``T1 M06`` for ISG, a change where the
    source only prepared one, exit 0)."""
    offsets = LatheOffsets(ctx, radius) if foreign and ctx.lathe_turret else None
    """A turret index applies its offset (LinuxCNC's ``T1 M6`` applies none: its ``G43 H`` does)."""
    plane_set = not foreign
    start_mode = ctx.state.feed_mode  # read before any block: the source's mode at the start
    target_mode = target.LATHE_FEED_AT_START if not foreign else "per_min"
    dry = bool(ctx.run_data.get("dry_run"))
    """A dry run (``postproc.api._keep_check``) lowers the program from its first construct on, not from its start,
    which the translation's own lowering gave the source's feed mode: said at the dry run's first block, an ``M98``
    there could no longer stand alone, and that was the reason the program was flattened ("M98 sharing its line
    with other words (FeedMode)") whatever its true one."""
    mode_set = start_mode == target_mode or dry
    flowing = False
    """A control statement or label has passed: where a cycle starts is the text's, not each run's."""
    repeated: UnsupportedError | None = None
    """In a dry run, the first expansion's refusal, should a control statement follow (a jump may repeat it)."""
    turning = False
    """The spindle turns before the block (a turret index must not become a tool change then)."""
    station: int | None = None
    """The turret station at the cutting position (the last index; None: not known, as at the start)."""
    nose = _NoseCompensation(ctx, target, turret and ctx.lathe_turret)
    own_nose: set[int] = set()
    """Lines of the roughing cycles whose profile turns nose compensation on and off (``NOSE_PROFILE``),
    expanded."""
    same_controller = target.NAME == ctx.dialect
    """Only the source's own controller runs such a cycle natively (the same set-up writes it)."""
    skip_departure = False
    """A native G70 over such a profile was written: the block the reader made for its departure goes."""
    family = target.family()
    drop_switches = not target.X_MODE_SWITCH
    for block in blocks:
        sections = block.sections
        if not flowing and (CONTROL in sections or LABEL in sections) and not isinstance(block, ExecutedBlock):
            flowing = True
            if repeated is not None:
                ctx.diagnostics.error(repeated)
        if drop_switches and "XProgramming" in sections:
            del sections["XProgramming"]  # the IR's X is the set-up's mode: written so
            block.changed()
            if not sections:
                continue
        function = sections.get("MachineFunction")
        if isinstance(function, MachineFunction) and function.action in THREAD_CHAMFER and function.family != family:
            _chamfer_switch_noted(block, function)
        nose.block(block)
        profile = sections.get("InProfile")
        if profile is not None:
            if native and getattr(profile, "cycle", None) not in own_nose:
                yield block
                continue
            source = (block.text or " ".join(a + n for a, n in block.words)).strip()
            block.sections = {"Comments": Comments([f"PROFILE LINE {block.line}: {source}"])}
            block.changed()
            yield block
            continue
        cycle = sections.get("LatheCycle")
        compound = sections.get("CompoundMotion")
        if skip_departure and cycle is None and isinstance(compound, CompoundMotion) and compound.term == "turn_finish":
            skip_departure = False  # the native G70 makes its departure itself
            continue
        if isinstance(cycle, LatheCycle):
            flagged = bool(cycle.params.get(NOSE_PROFILE)) or (
                cycle.kind == "thread_single" and int(cycle.params.get("chamfer", 0)) > 0)
            # a chamfered G92 (a Haas lathe's, M23) pulls out so on its own controller only: no word says it
            keep = cycle.kind in native and (not flagged or same_controller)
            if flagged and not keep:
                own_nose.add(block.line)
            if keep:
                sections.pop("CompoundMotion", None)
                if flagged and cycle.kind == "turn_finish":
                    sections.pop("CutterCompensation", None)  # the reader's: the profile's own blocks say it
                    skip_departure = True
            else:
                source = (block.text or " ".join(a + n for a, n in block.words)).strip()
                if cycle.form != "first" and (flowing or dry and repeated is None):
                    # as a hole cycle's (``postproc.cycles.lowering``): its moves are expanded from where the
                    # reading left the tool, which is where it runs only where the text is the order of execution
                    # (was: a G71 in an M98 subprogram kept symbolically for LinuxCNC, roughed from where the text
                    # after the call left the tool, exit 0; verify found it 105 mm off)
                    refusal = UnsupportedError(
                        f"the lathe cycle in '{one_line(source)}' would be written as the moves of one run, but the "
                        "program's control flow (a subprogram, a loop or a jump) runs it from other positions",
                        ctx.at(block))
                    if flowing:
                        ctx.diagnostics.error(refusal)
                        continue
                    repeated = refusal
                del sections["LatheCycle"]
                block.changed()
                if cycle.form == "first":
                    comments = sections.get("Comments")
                    texts = comments.texts if isinstance(comments, Comments) else []
                    sections["Comments"] = Comments([f"LINE {block.line}: {source} (cycle data)", *texts])
        if not mode_set and block.sections and "TapeMark" not in block.sections \
                and "ProgramStart" not in block.sections and "Comments" not in block.sections:
            mode_set = True
            if "FeedMode" not in block.sections:
                block.add(FeedMode(start_mode))  # the target starts in another feed mode: say the source's
                block.changed()
        try:  # a refusal below is reported where it stands and the block left out: the run goes on to the
            # program's other errors (raised, it ended the translation with no error list)
            if turret:
                select = sections.get("ToolSelect")
                same = _same_station(block, station)
                if not same and not _turret(block, ctx, turning):
                    continue
                if same or "ToolSelect" in block.sections:
                    if not foreign:
                        _select_offset(select, block, ctx)
                    elif offsets is not None:
                        _report(offsets.select, block, ctx, select)
                        if same and not block.sections and isinstance(select, ToolSelect):
                            _offset_note(block, select)
                if isinstance(select, ToolSelect) and "ToolChange" in block.sections:
                    station = lathe_tool(select.number) if isinstance(select.number, int) else None
                elif isinstance(select, ToolSelect) and not same:
                    station = None  # the T word was left out (``--on-unsupported warn``): the turret is not known
                nose.select(select)
                turning = _turns_after(block, turning)
            if tracker is not None:
                if not plane_set and ("Motion" in sections or "CompoundMotion" in sections):
                    block.add(Plane("ZX"))
                    plane_set = True
                back_to_absolute = tracker.block(block)
                if offsets is not None:
                    _report(offsets.block, block, ctx, tracker)
                if back_to_absolute:
                    yield block
                    back = Block(block.line, None, block.eol)
                    back.add(DistanceMode("absolute"))
                    if offsets is not None:
                        # the offsets follow the distance mode block by block: without this block they took the
                        # program for incremental from the reference return on (was: ``G28 U0. W0.`` then
                        # ``T0202`` / ``G0 X50. Z5.`` refused as "an incremental move takes a new lathe tool
                        # offset" towards grbl, though every move is absolute)
                        _report(offsets.block, back, ctx, tracker)
                    yield back  # the reference return went in incremental mode: back to absolute
                    continue
        except UnsupportedError as err:
            ctx.diagnostics.error(err)
            continue
        yield block


class _NoseCompensation:
    """Tool nose radius compensation through the lowering: the register a G41/G42 without one reads, and
    the lathe cycles it must not run over (see the module docstring)."""

    __slots__ = ("ctx", "on", "offset", "name_register", "refuse_cycles", "own")

    def __init__(self, ctx: Context, target: type[Dialect], name_register: bool) -> None:
        self.ctx = ctx
        self.on = False
        self.offset: int | None = None
        """The offset number of the last turret index (``T0102``: 2)."""
        self.name_register = name_register
        self.refuse_cycles = (target.NAME != ctx.dialect if target.WRITER is not None
                              else ctx.cutter_rules is not None)
        self.own = target.WRITER is None or target.NAME == ctx.dialect
        """The source's own controller runs the program (its simulation, or a copy): a roughing cycle its rules
        run under compensation (``CutterRules.roughing_cycles``) was read as it runs it."""

    def select(self, select: object) -> None:
        if isinstance(select, ToolSelect) and isinstance(select.number, int):
            self.offset = select.number % 100

    def block(self, block: Block) -> None:
        sections = block.sections
        cc = sections.get("CutterCompensation")
        if isinstance(cc, CutterCompensation):
            self.on = cc.mode != "off"
            if self.on and cc.register is None and self.name_register and self.offset:
                sections["CutterCompensation"] = CutterCompensation(cc.mode, self.offset)
                block.changed()
        cycle = sections.get("LatheCycle")
        if self.on and self.refuse_cycles and isinstance(cycle, LatheCycle) and cycle.kind != "turn_finish" \
                and cycle.form != "first":  # reported once, at the block that runs the cycle
            rules = self.ctx.cutter_rules
            if rules is not None and cycle.kind in rules.roughing_cycles:
                if self.own:
                    return
                self.ctx.diagnostics.error(UnsupportedError(
                    f"a lathe cycle ({cycle.kind.replace('_', ' ')}) under tool nose radius compensation: "
                    f"{self.ctx.dialect} roughs to the compensated shape with the offset temporarily cancelled for "
                    "the cycle, which no other controller's compensation is known to do (its moves would be written "
                    "with compensation off and on around them, not modelled here); cancel compensation before the "
                    "cycle and turn it on for the finishing cycle", self.ctx.at(block)))
                return
            self.ctx.diagnostics.error(UnsupportedError(
                f"a lathe cycle ({cycle.kind.replace('_', ' ')}) under tool nose radius compensation: how the "
                "controller compensates inside it is not modelled (Fanuc T's stock removal cycles of type I are; "
                "type II pockets, the pattern repeating cycle and other controllers' rules are not in our sources), "
                "so its moves are not known; cancel compensation before the cycle and turn it on for the finishing "
                "cycle",
                self.ctx.at(block)))


def _chamfer_switch_noted(block: Block, function: MachineFunction) -> None:
    """A code that switches the threading cycles' pull-out chamfer on or off (Haas M23/M24) has no equivalent
    in another family, and needs none: the cycles after it carry their chamfer in their own words
    (``LatheCycle`` ``chamfer``), so it becomes a comment where it stood."""
    comment_out(block, f"{function.text}: {function.name or function.action}, in the threading cycles' words")


def _same_station(block: Block, station: int | None) -> bool:
    """A turret lathe's T naming the station already at the cutting position (``T0200`` after ``T0202``) indexes
    nothing: it only selects the offset (00 cancels it) [K: Fanuc-style lathe operator's manual (C-KL205608,
    "Tool indexing and tool offset (T function)"): the first two digits index the turret, the last two select
    the offset, T..00 cancels it, its example cancels with ``T0100`` after ``T0101``]. A target that changes
    tools with M6 must not get a tool change for it: LinuxCNC's M6 always runs one, the spindle stopped first
    [V: LinuxCNC ``interp_convert.cc`` ``convert_tool_change``, no test of the tool in the spindle], grbl's is a
    pause. So the T word goes, its offset kept (``_select_offset``, ``LatheOffsets.select``)."""
    select = block.sections.get("ToolSelect")
    if not isinstance(select, ToolSelect) or not isinstance(select.number, int) or "ToolChange" in block.sections \
            or station is None or lathe_tool(select.number) != station:
        return False
    del block.sections["ToolSelect"]
    block.changed()
    return True


def _offset_note(block: Block, select: ToolSelect) -> None:
    """A ``T0200`` that only changed the offset, for a target that gets the offsets in its coordinates
    (``LatheOffsets``): nothing of the block is left to write, so a note says where it went (an empty line
    was written, the block gone without a trace). Not its T word: grbl takes ``T`` as a tool number (0-255,
    stored and nothing else [V: grbl 1.1 ``gcode.c``, ``MAX_TOOL_NUMBER 255``, ``gc_state.tool``]), and the
    offset number would read as another tool."""
    number = select.number
    if not isinstance(number, int):
        return
    block.sections["Comments"] = Comments([f"T{number:04d}: offset {number % 100:02d}, in the coordinates"])
    block.changed()


def _turret(block: Block, ctx: Context, turning: bool) -> bool:
    """A lathe's T indexes the turret: for a mill control it is a tool change, to the tool number alone
    (T0101 is tool 1 with offset 1; a tool's offsets are the target's own). A computed T (``T#1``) is
    refused: which tool it names is known when it runs (the program is flattened for it). So is an index
    while the spindle turns: the turret indexes with the spindle running [K: Fanuc T, the T code only
    indexes], a mill control's tool change stops it [V: rs274's M6 is STOP_SPINDLE_TURNING then
    CHANGE_TOOL], unless the set-up's machine changes tools with the spindle on (``ControllerSettings.
    tool_change_with_spindle_on``: LinuxCNC's TOOL_CHANGE_WITH_SPINDLE_ON). False: the block is refused
    (reported; with ``--on-unsupported warn`` the T is left out with a note instead)."""
    select = block.sections.get("ToolSelect")
    if isinstance(select, ToolSelect) and isinstance(select.number, Expr):
        raise UnsupportedError("a computed lathe T word (the tool and offset it selects are known when the "
                               "program runs)", ctx.at(block))
    if isinstance(select, ToolSelect) and isinstance(select.number, int) and "ToolChange" not in block.sections:
        if turning and not ctx.setup.controller.tool_change_with_spindle_on:
            err = UnsupportedError(f"a turret index (T{select.number:04d}) with the spindle turning: a mill "
                                   "control changes the tool with the spindle stopped, the lathe keeps it "
                                   "turning (stop the spindle before the index, or give a set-up whose machine "
                                   "changes tools with the spindle on: <Controller toolChangeWithSpindleOn=\"true\"/>)",
                                   ctx.at(block))
            if ctx.on_unsupported != "warn":
                ctx.diagnostics.error(err)
                return False
            ctx.diagnostics.warn(err.message + "; the T word is left out", err.location)
            del block.sections["ToolSelect"]
            comments = block.sections.get("Comments")
            texts = comments.texts if isinstance(comments, Comments) else []
            block.sections["Comments"] = Comments([*texts, f"UNSUPPORTED T{select.number:04d}"])
            block.changed()
            return True
        block.sections["ToolSelect"] = ToolSelect(lathe_tool(select.number))
        block.add(ToolChange())
        block.changed()
    return True


def _select_offset(select: object, block: Block, ctx: Context) -> None:
    """A lathe target that changes tools as a mill does (LinuxCNC) applies the X/Z offsets of a tool table
    entry with its tool length offset code [K: LinuxCNC lathe tool table, G43 H uses entry H's X and Z
    offsets], not with the tool change: the turret index's offset number (``T0102``: tool 1, offset 2)
    becomes that code's register (``G43 H2``), offset 0 its cancel. Without it the machine would cut
    with no offset at all."""
    if not isinstance(select, ToolSelect) or not isinstance(select.number, int):
        return
    if "ToolLengthOffset" in block.sections:
        raise UnsupportedError("a turret index and a tool length offset in one block (the index selects the "
                               "offset itself)", ctx.at(block))
    offset = select.number % 100
    block.add(ToolLengthOffset("positive", offset) if offset else ToolLengthOffset("cancel"))
    block.changed()


def _report(step: Callable[[Block, Any], None], block: Block, ctx: Context, arg: Any) -> None:
    """Run a step of the lathe offsets on ``block``; its error is reported (located at the block)."""
    try:
        step(block, arg)
    except PostprocError as err:
        ctx.diagnostics.error(err if err.location is not None else err.located(ctx.at(block)))


def _turns_after(block: Block, turning: bool) -> bool:
    """Whether the spindle turns after ``block`` (a tool change or a program end stops it)."""
    sections = block.sections
    control = sections.get("SpindleControl")
    if isinstance(control, SpindleControl):
        return control.direction in ("cw", "ccw")
    end = sections.get("ProgramControl")
    if "ToolChange" in sections or (end is not None and getattr(end, "kind", None) in ("end", "end_rewind")):
        return False
    return turning


class _Position:
    """Where the tool is (program units, X as programmed), to make U/W absolute and X a radius."""

    __slots__ = ("ctx", "increments", "radius", "x", "z", "incremental")

    def __init__(self, ctx: Context, radius: bool) -> None:
        self.ctx = ctx
        self.increments = ctx.increments
        """The reading dialect's incremental addresses (U -> X, W -> Z: ``Dialect.INCREMENTAL_AXES``)."""
        self.radius = radius
        self.x: float | None = None
        self.z: float | None = None
        self.incremental = False
        """G91 in force (Fanuc T systems B and C)."""

    def block(self, block: Block) -> bool:
        """Rewrite the block's moves; True when it was made incremental (a reference return through
        the present point, ``G28 U0 W0``) and the program must return to absolute after it."""
        sections = block.sections
        changed = False
        mode = sections.get("DistanceMode")
        if isinstance(mode, DistanceMode):
            self.incremental = mode.mode == "incremental"
        motion = sections.get("Motion")
        increments = self.increments
        if isinstance(motion, Motion) and motion.mode in ("home", "home2") and not self.incremental \
                and motion.axes and all(a in increments and motion.axes[a] == 0.0 for a in motion.axes):
            # through the present point, wherever it is: the same return in incremental mode
            motion.axes = {increments[a]: 0.0 for a in motion.axes}
            block.add(DistanceMode("incremental"))
            self.x = self.z = None
            block.changed()
            return True
        if isinstance(motion, Motion) and motion.mode is not None:
            changed = self.motion(block, motion)
        compound = sections.get("CompoundMotion")
        if isinstance(compound, CompoundMotion):
            for item in compound.items:
                if isinstance(item, Motion):
                    incremental, self.incremental = self.incremental, False  # compound moves are absolute
                    self.motion(block, item)
                    self.incremental = incremental
            changed = True
        coords = sections.get("CoordinateSet")
        if isinstance(coords, CoordinateSet):
            x, z = coords.axes.get("X", self.x), coords.axes.get("Z", self.z)
            self.x = None if isinstance(x, Expr) else x  # computed: where the tool is is known when it runs
            self.z = None if isinstance(z, Expr) else z
            diameter = coords.axes.get("X")
            if self.radius and diameter is not None:
                if isinstance(diameter, Expr):
                    raise UnsupportedError("a computed X on a target that programs radii (halve it in the program)",
                                           self.ctx.at(block))
                sections["CoordinateSet"] = CoordinateSet({**coords.axes, "X": diameter / 2.0})
                changed = True
        if changed:
            block.changed()
        return False

    def motion(self, block: Block, motion: Motion) -> bool:
        """Rewrite one motion in place; True when it changed."""
        axes = motion.axes
        increments = self.increments
        if "X" not in axes and increments.keys().isdisjoint(axes):
            self._track(motion, axes)
            return False
        new: dict[str, float | Expr] = {}
        for axis, value in axes.items():
            real = increments.get(axis)
            if real is not None:
                base = self.x if real == "X" else self.z if real == "Z" else None
                if base is None or not isinstance(value, float):
                    raise UnsupportedError(f"an incremental {axis} move from an unknown position (the target has no "
                                           f"{axis} address: program an absolute {real} first)",
                                           self.ctx.at(block))
                new[real] = base + value
            else:
                new[axis] = value
        self._track(motion, new)
        x = new.get("X")
        if self.radius and x is not None:
            if isinstance(x, Expr):
                raise UnsupportedError("a computed X on a target that programs radii (halve it in the program)",
                                       self.ctx.at(block))
            new["X"] = x / 2.0
        motion.axes = new
        return True

    def _track(self, motion: Motion, axes: dict[str, float | Expr]) -> None:
        if motion.mode in ("home", "home2"):
            moved = {self.increments.get(a, a) for a in axes}
            self.x = None if "X" in moved else self.x
            self.z = None if "Z" in moved else self.z
            return
        if self.incremental:
            if "X" in axes:
                self.x = None if self.x is None or not isinstance(axes["X"], float) else self.x + axes["X"]
            if "Z" in axes:
                self.z = None if self.z is None or not isinstance(axes["Z"], float) else self.z + axes["Z"]
            return
        if "X" in axes:
            self.x = axes["X"] if isinstance(axes["X"], float) else None
        if "Z" in axes:
            self.z = axes["Z"] if isinstance(axes["Z"], float) else None

