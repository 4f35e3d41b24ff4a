"""When a tool length change applies, carried across controllers that disagree (a generic lowering step).

Two rules (``Dialect.LENGTH_AT_PROGRAMMED_AXIS``):

* at the programmed axis ([V] LinuxCNC rs274, [V] grbl ``gcode.c``, [V] ISG by default): a change moves
  nothing; the machine keeps its Z until Z is next programmed absolutely, where the new length applies
  (an incremental Z moves the machine by its increment);
* at the next move (the simulation's model of Fanuc and the rest, ``postproc.compensation.tool_length``):
  the next move of any axis takes the controlled Z to the programmed Z plus the new length.

A change beside an absolute Z move means the same under both, and so does every other block of a
program that changes the length there (typical posts: ``G43 H1 Z15.``). Otherwise:

* towards "at the next move" from "at the programmed axis": the change is moved to the next block that
  programs Z absolutely (the moves between keep the machine Z under both rules; an incremental Z moves it
  by the same increment under the old length as under the new one). Where a later change replaces it
  first, only the last is written; one still waiting at the program end changed no move and is left out.
  A canned cycle, a tool table write or a cutter compensation change while it waits is a located error
  (the two would then differ).
* towards "at the programmed axis" from "at the next move": the change goes to the next motion block,
  which gets the Z the program stands at (absolute, program units) if it has none, so the target moves Z
  there as the source does. Where that Z is not known (no absolute Z since the start or a work offset
  change) and the target reads its current position (``Dialect.POSITION_READS``: LinuxCNC's ``Z#5422``,
  read when the block is read, before its own ``G43``), the move gets that read instead [V: rs274, tests/
  test_length_timing_position_read.py], for an axis nothing has placed since the start (``unplaced``: no
  move naming it, no work offset, frame, cycle or machine move), unless cutter compensation is on (rs274
  refuses the read then) or a change written alone since moved the target's program point (a change replaced
  before any move stays where it was written, ``diverged``). Otherwise, or where the next move is incremental, a reference
  return, a cycle or a machine-coordinate move, the change is a located error asking for Z beside it, and
  so is a tool table write between the two. A
  reference return is such a move through its intermediate point: given absolutely, both rules take the
  point with the new length (the change goes beside it); given incrementally (``G49`` then ``G91 G28 Z0``,
  a common program end), its point is written absolutely from the known Z (``G49 G90 G28 Z<z>``, then
  ``G91`` again), so the target moves there as the source does [V: rs274 runs G49 and G90 before G28 in
  one block, its order of execution]. From a Z not known, an incremental return naming Z keeps its increments,
  its Z one plus the new length minus the old (``G49`` from length 100, then ``G91 G28 Z0``: ``G91 G49 G28
  Z-100.``): the target's increment runs from where its machine stands, still with the old length, to the
  source's point with the new [V: rs274, tests/test_length_timing_rs274.py; grbl ``gcode.c`` adds an increment
  to the machine position]. An incremental return that does not name Z stays a located error: naming Z would
  send Z to the reference point too.

A target that applies a change only when the length axis moves (Fagor, ``Dialect.LENGTH_AT_AXIS_MOVE``) gets,
from a source that applies it at the next move of any axis, the change beside the next move with the Z the program
stands at, as a target of the first rule: a move of Z to where it is takes the new length on both.

On a lathe the same holds for X and Z together: a Fanuc T/GSK offset (``T0102``, become LinuxCNC's lathe
``G43 H02`` in ``postproc.cycles.lathe_lowering``) applies at the next move of any axis, LinuxCNC's where
each axis is programmed, so the move gets both. ISG and Fagor targets get their D words from
``postproc.isg_family.tool_data`` after this step.

Where the program stands (its Z after each block, the work offset under a machine-coordinate Z, the length
a change puts in force) is followed in ``postproc.lowering.length_point``; this module decides when a change applies.
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..errors import Location, UnsupportedError
from ..ir.expr import Binary, Expr, Num, Var
from ..ir import Block, CutterCompensation, DataSetting, DistanceMode, Motion, Section, ToolLengthOffset
from ..ir.keys import watches_none
from ..compensation.tool_table import ToolTable
from .lower import BlockStep, LoweringStep, still_moving
from .length_point import AXIS, MM_PER_INCH, PLAIN, MachineFrame, follow_point, length_in_force
from .move_words import Z as Z_BIT, NotedPoint, move_words, moving
from .point_after import FOLLOWED
from .units_and_distance import UnitsAndDistance

_WATCHED: Final = frozenset(("ToolLengthOffset", "Motion", "CompoundMotion", "CycleCall", "DistanceMode", "Units",
                             "WorkOffset", "CoordinateSet", "DataSetting", "CutterCompensation", "RigidTap")) | FOLLOWED
_STRAIGHT: Final = frozenset(("rapid", "linear"))
"""The modes whose block moves nothing without an axis word (an arc without one is a full circle)."""
_RETURNS: Final = frozenset(("home", "home2"))
"""Reference returns (G28, G30): a move through an intermediate point in work coordinates."""


def _watches_any(sections: dict[str, Section]) -> bool:
    """A key of the block is in ``_WATCHED``: a loop over its few keys (compiled, ``_WATCHED.isdisjoint(sections)``
    was a bound method call, ~700 instructions an expanded hole)."""
    for key in sections:
        if key in _WATCHED:
            return True
    return False


_STATE: Final = _WATCHED - {"Motion"} | {"MachineCoordinates", "FrameChange"}
"""What a block must lack for ``_complete``'s short way (a plain move or none, nothing else to follow)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class TimeLengthChanges(LoweringStep):
    """Lowering step: a tool length change placed where the target applies it as the source does (see
    the module docstring); nothing to do between controllers with the same rule. On a lathe only the
    way to a controller that applies it at the programmed axes is taken (Fanuc T/GSK -> LinuxCNC)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME or not target.TOOL_LENGTH_OFFSET and not _writes_lengths(target):
            return None
        if not ctx.length_at_axis and target.LENGTH_AT_AXIS_MOVE and not ctx.lathe:
            return _Complete(ctx, target)  # (Fagor) the next move gets Z: that applies it there, as on the source
        if ctx.length_at_axis == target.LENGTH_AT_PROGRAMMED_AXIS:
            return None
        if ctx.lathe:  # Fanuc T/GSK T0102 -> LinuxCNC's lathe G43 H02 (``postproc.cycles.lathe_lowering``)
            return None if ctx.length_at_axis else _Complete(ctx, target)
        return _Defer(ctx, target) if ctx.length_at_axis else _Complete(ctx, target)


time_length_changes = TimeLengthChanges()


def _writes_lengths(target: type[Dialect]) -> bool:
    """A target without a tool table that still gets lengths written (grbl: ``G43.1 Z<length>``)."""
    return target.LENGTH_AT_PROGRAMMED_AXIS


def _key(offset: ToolLengthOffset) -> tuple[str, object, object]:
    return offset.mode, offset.register, offset.length


def _absolute_z(block: Block, absolute: bool) -> bool:
    """The block programs Z absolutely in work coordinates (a plain move or a reference return's
    intermediate point)."""
    motion = block.sections.get("Motion")
    return (isinstance(motion, Motion) and motion.mode is not None and AXIS in motion.axes and absolute
            and "MachineCoordinates" not in block.sections)


@mypyc_attr(allow_interpreted_subclasses=True)
class _Defer(BlockStep):
    """Towards a target that applies a change at the next move: each change goes to the next absolute Z. A
    block that is only a move is its business only while a change waits (it may be that Z)."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.ctx = ctx
        self.target = target
        self.pending: ToolLengthOffset | None = None
        self.written: tuple[str, object, object] = ("cancel", None, None)  # what the target has in force
        self.in_force: tuple[str, object, object] = ("cancel", None, None)  # what the source has programmed
        self.modes = UnitsAndDistance()
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if self.pending is None and "ToolLengthOffset" not in sections:  # nothing to carry: only the distance mode
            if "DistanceMode" in sections:
                self.modes.follow(sections)
            return None
        modes = self.modes
        modes.follow(sections)
        absolute = modes.absolute
        offset = sections.get("ToolLengthOffset")
        if isinstance(offset, ToolLengthOffset):
            same = _key(offset) == self.in_force
            self.in_force = _key(offset)
            if same and self.pending is None:
                return None  # changes nothing (a G49 in a start-up line): left where it is
            if _absolute_z(block, absolute) or offset.mode == "dynamic" and not self.target.DYNAMIC_TOOL_LENGTH:
                # (a length the target cannot write stays at its block, whose writing refuses it there)
                self._wait(None)
                self.written = _key(offset)
                return None
            del sections["ToolLengthOffset"]
            block.changed()
            self._wait(offset)
            if not sections:
                return []  # nothing else in the block: the change is written where it applies
        pending = self.pending
        if pending is not None:
            clash = _clash(sections)
            if clash is not None:
                self.ctx.diagnostics.error(UnsupportedError(
                    f"{clash} while a tool length change waits for the next absolute Z (the source applies it "
                    "there, the target at its next move): program Z beside the length change",
                    self.ctx.at(block)))
                self._wait(None)
            elif _absolute_z(block, absolute):
                if _key(pending) != self.written:
                    sections["ToolLengthOffset"] = pending
                    self.written = _key(pending)
                    block.changed()
                self._wait(None)
        return None

    def _wait(self, pending: ToolLengthOffset | None) -> None:
        """``pending`` waits for the next absolute Z (None: nothing waits, and a plain move is not looked at)."""
        self.pending = pending
        self.moves = pending is not None


def _clash(sections: dict[str, Section]) -> str | None:
    """What a waiting change cannot be carried past (a cycle kept native too: its first move applies the change
    on one controller and its first Z level on the other)."""
    if "CompoundMotion" in sections or "CycleCall" in sections or "RigidTap" in sections or _native_cycle(sections):
        return "a canned cycle"
    if "DataSetting" in sections:
        return "a data setting"
    if "CutterCompensation" in sections:
        return "a cutter compensation change"
    return None


_UNPLACING: Final = frozenset(("WorkOffset", "CoordinateSet", "FrameChange", "CompoundMotion", "CycleCall",
                                "RigidTap", "MachineCoordinates", "DataSetting", "CannedCycle", "LatheCycle"))
"""What leaves the program's point on an axis other than where the start put it, on the target as on the
source, without a number here: after it a position read is not written (the simulation's start no longer
stands for it, ``postproc.frames.parameters``)."""

HELD: Final = 1000
"""Blocks without motion held behind a waiting change at most (then it is refused where it was written)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class _Complete(BlockStep):
    """Towards a target that applies a change at the programmed axis: the change goes to the next move,
    which gets the Z the program stands at: its number where it is known, else, on a target that reads its
    current position (``Dialect.POSITION_READS``) and without cutter compensation (rs274 refuses the read
    under it), that read (``_position_read``). The blocks between are held (at most ``HELD``, else a located
    error); a change that meets no move (the program ends first) stays where it was written. Every move is
    its business: it follows the programmed point."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.ctx = ctx
        self.target = target
        axes: tuple[str, ...] = ("X", AXIS) if ctx.lathe else (AXIS,)  # a lathe offset moves X and Z (LinuxCNC's lathe G43 H)
        self.axes = axes
        self.pos: dict[str, float | None] = {a: None for a in axes}  # the programmed point, program units; None: unknown
        self.modes = UnitsAndDistance()
        self.in_force: tuple[str, object, object] = ("cancel", None, None)
        self.applied: tuple[str, object, object] = self.in_force  # the length the machine stands with: the last change that met its move
        self.held: list[Block] = []  # the changing block and the blocks after it, while a change waits
        self.table = ToolTable(ctx.setup)
        self.pending: tuple[ToolLengthOffset, Location] | None = None  # the waiting change, and where it was written
        self.compensating = False  # cutter radius compensation is on (the target reads no position then)
        self.diverged: set[str] = set()  # axes whose program point on the target a change written alone has moved
        self.unplaced = set(axes)  # axes nothing has placed or re-expressed since the start: only they are read
        self.frame = MachineFrame(ctx.setup)  # what puts a machine-coordinate Z in the program's frame
        self.mill = axes == (AXIS,)
        self.words = move_words(ctx)  # a plain move's numbers, read once for the steps that follow the point
        self.notes = NotedPoint(self.words)  # a plain absolute move's Z waits here (``_settle``): no dictionary written
        self.follow()

    def follow(self) -> None:
        """``point`` (``BlockStep.point``) as the run stands: while no change waits, on a mill, in absolute mode,
        with no axis diverged or unplaced, a straight move of X, Y and Z numbers only notes its Z (``_take``)."""
        self.point = self.notes if (self.pending is None and self.mill and self.modes.absolute and len(self.diverged) == 0
                                    and len(self.unplaced) == 0) else None

    def take(self, block: Block) -> list[Block] | None:
        out = self._take(block, watches_none(block.sections, _STATE))
        self.follow()
        return out

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block the loop found only a move (``plain_move``): it holds none of ``_STATE``, and is
        not asked again (~270 instructions a block compiled). While no change waits the move only moves the
        point here; else a waiting change may be put on it (``still_moving``)."""
        if self.pending is None:
            out = self._take(block, True)
        else:  # (the move may get the Z the change needs: other words)
            motion = block.sections["Motion"]
            out = still_moving(block, self._take(block, True), motion, motion.axes if isinstance(motion, Motion) else None)
        self.follow()
        return out

    def _take(self, block: Block, quiet: bool) -> list[Block] | None:
        """``take``; ``quiet``: the block holds none of ``_STATE`` (``watches_none``)."""
        sections = block.sections
        pending = self.pending
        axes = self.axes
        pos = self.pos
        if pending is None and quiet:  # the common block: at most a plain move
            motion = sections.get("Motion")
            if isinstance(motion, Motion):  # (typed: its fields are read natively, not by name)
                plain = moving(motion.mode)  # (``PLAIN``)
                words = motion.axes
                absolute = self.modes.absolute
                if self.mill and plain and len(self.diverged) == 0 and len(self.unplaced) == 0:
                    read = self.words
                    bits = read.read(motion)  # (its numbers, read once for the steps that follow the point)
                    if bits >= 0:
                        if bits & Z_BIT:
                            if absolute:
                                self.notes.note(read, bits)  # (into ``pos`` before it is read: ``_settle``)
                            else:
                                self._settle()
                                known = pos[AXIS]
                                pos[AXIS] = None if known is None else known + read.z
                        return None
                self._settle()
                for axis in axes:
                    value = words.get(axis)
                    if value is None:
                        continue
                    if not plain:
                        pos[axis] = None
                    elif type(value) is float:
                        known = pos[axis]
                        pos[axis] = value if absolute else None if known is None else known + value
                    elif isinstance(value, Expr):
                        pos[axis] = None
                    else:
                        known = pos[axis]
                        pos[axis] = float(value) if absolute else None if known is None else known + value
                diverged = self.diverged
                if diverged and plain and absolute:
                    diverged.difference_update(words)
                unplaced = self.unplaced
                if unplaced:
                    unplaced.difference_update(words)
            return None
        self._settle()
        ctx = self.ctx
        held = self.held
        frame = self.frame
        before = frame.beyond(False) if "WorkOffset" in sections else None  # mm
        frame.follow(sections)
        if not _watches_any(sections):
            if pending is None:
                return None
            held.append(block)
            if len(held) >= HELD:
                _refuse(ctx, self.target, pending[1], f"no move follows it within {HELD} blocks")
                self.pending = None
                return _release(held, pending[0])
            return []
        modes = self.modes
        if modes.follow(sections):
            for a, v in pos.items():
                pos[a] = None if v is None else v / MM_PER_INCH if modes.inch else v * MM_PER_INCH
        inch = modes.inch
        absolute = modes.absolute
        cutter = sections.get("CutterCompensation")
        if isinstance(cutter, CutterCompensation):
            self.compensating = cutter.mode != "off"
        if "WorkOffset" in sections or "CoordinateSet" in sections:
            after = frame.beyond(False)
            for a in axes:
                known = pos[a]
                # a change of work system keeps the machine where it stands: the programmed Z reads in the new
                # system, the two systems' set-up offsets apart (as the simulation has it); else not known
                pos[a] = (known + (before - after) / (MM_PER_INCH if inch else 1.0)
                          if a == AXIS and not ctx.lathe and known is not None and before is not None
                          and after is not None and "CoordinateSet" not in sections else None)
        unplaced = self.unplaced
        if unplaced and not _UNPLACING.isdisjoint(sections):
            unplaced.clear()  # the point moved or was re-expressed by what only the run knows (held blocks too)
        table = self.table
        setting = sections.get("DataSetting")
        if isinstance(setting, DataSetting):
            table.write(setting, MM_PER_INCH if inch else 1.0)
        moves = _moves(sections)
        offset = sections.get("ToolLengthOffset")
        if isinstance(offset, ToolLengthOffset) and pending is not None and _key(offset) == _key(pending[0]):
            del sections["ToolLengthOffset"]  # it restates the waiting change (``T0101`` twice): that one still waits
            block.changed()
            offset = None
        in_force = self.in_force
        change = isinstance(offset, ToolLengthOffset) and _key(offset) != in_force
        out: list[Block] = []
        lathe = ctx.lathe
        if isinstance(offset, ToolLengthOffset):
            in_force = self.in_force = _key(offset)
            if pending is not None:  # a later change replaces the waiting one, which stays where it was written:
                out.extend(_release(held, pending[0]))  # it moves nothing there on the target, and the
                pending = self.pending = None  # settings a verify compares keep the source's order; the target's
                self.diverged.update(axes)  # program point now differs from the source's until each axis is programmed
            if change and not moves:
                self.pending = offset, ctx.at(block, ctx.column_of(block, "H"))
                held.append(block)
                return out
        elif pending is not None and not moves:
            clash = _clash(sections)
            if clash is not None:
                _refuse(ctx, self.target, pending[1], f"{clash} follows it")
                out.extend(_release(held, pending[0]))
                self.pending = None
                follow_point(block, pos, absolute, in_force, None if lathe else table, inch, frame.beyond(inch))
                out.append(block)
                return out
            held.append(block)
            return []
        restore = False  # a reference return was written absolutely: G91 again after it
        if moves and (pending is not None or change and not self.target.LENGTH_AT_AXIS_MOVE):
            # (towards Fagor a change beside a move is left where it is: it applies there if the move moves Z,
            # which ``postproc.isg_family.tool_data`` checks; only a change written alone is carried)
            at = ctx.at(block, ctx.column_of(block, "H")) if pending is None else pending[1]
            motion = sections.get("Motion")
            moved = pending is not None
            missing = [] if not isinstance(motion, Motion) else [a for a in axes if a not in motion.axes]
            target = self.target
            compensating = self.compensating
            diverged = self.diverged
            returns = not target.LENGTH_AT_AXIS_MOVE  # (a Fagor return is written in machine coordinates)
            if _sets_z(block, absolute, axes) or (_returns_through(block, absolute, axes) if returns
                                                   else _moves_named(block, axes)):
                pass
            elif returns and _incremental_return(block, absolute, axes, pos):
                assert isinstance(motion, Motion)
                words = dict(motion.axes)  # (a new dictionary: ``move_words`` keys its reads on the old one)
                for a, value in motion.axes.items():
                    known = pos[a]
                    assert known is not None and not isinstance(value, Expr)  # (tested above)
                    words[a] = known + float(value)
                motion.axes = words
                sections["DistanceMode"] = DistanceMode("absolute")
                block.changed()
                restore = True
            elif returns and not lathe and _incremental_z_return(block, absolute) and _shifted_return(
                    block, length_in_force(self.applied, table, inch), length_in_force(in_force, table, inch)):
                pass
            elif (isinstance(motion, Motion) and motion.mode in PLAIN and absolute
                    and all(pos[a] is not None or (not compensating and a in target.POSITION_READS and a in unplaced
                                                   and a not in diverged and _reads_here(sections)) for a in missing)
                    and "MachineCoordinates" not in sections and "CompoundMotion" not in sections):
                words = dict(motion.axes)  # (a new dictionary: ``move_words`` keys its reads on the old one)
                for a in missing:
                    known = pos[a]
                    words[a] = _position_read(target, a, ctx.diameter) if known is None else known
                motion.axes = words
                block.changed()
            elif not returns and isinstance(motion, Motion) and motion.mode in _RETURNS:
                _refuse(ctx, target, at, "the next move is a reference return, which the target makes in machine "
                        "coordinates")
                moved = False
            else:
                _refuse(ctx, target, at,
                        f"the programmed {' and '.join(axes)} is not known where it applies{frame.why()}")
                moved = False  # refused once: taken out, so no later step refuses it again
                if pending is None:
                    del sections["ToolLengthOffset"]
                    block.changed()
            if pending is not None:
                out.extend(_release(held, None))
            if moved and pending is not None:
                sections["ToolLengthOffset"] = pending[0]
                block.changed()
            self.pending = None
            self.applied = in_force
        follow_point(block, pos, absolute, in_force, None if lathe else table, inch, frame.beyond(inch))
        frame.placed(sections, pos.get(AXIS) is not None)
        if unplaced:
            motion = sections.get("Motion")
            if isinstance(motion, Motion):
                unplaced.difference_update(motion.axes)
        diverged = self.diverged
        if diverged:
            motion = sections.get("Motion")
            if (isinstance(motion, Motion) and motion.mode in PLAIN and absolute
                    and "MachineCoordinates" not in sections):
                diverged.difference_update(motion.axes)
        if restore:
            out.append(block)
            out.append(_incremental_again(block))
            return out
        if not out:
            return None
        out.append(block)
        return out

    def _settle(self) -> None:
        """The Z a plain absolute move noted (``notes``: its X and Y are not followed here) into ``pos``, before
        anything reads it."""
        notes = self.notes
        noted = notes.noted
        if noted:
            notes.noted = 0
            if noted & Z_BIT:
                self.pos[AXIS] = notes.z

    def finish(self) -> list[Block]:
        pending = self.pending
        if pending is None:
            return []
        self.pending = None
        return _release(self.held, pending[0])


def _reads_here(sections: dict[str, Section]) -> bool:
    """A read in this block is the point the source's move starts from: the block changes no work system, frame
    or units (the target reads before the block's own changes, its words are in the new ones)."""
    return _UNPLACING.isdisjoint(sections) and "Units" not in sections


def _position_read(target: type[Dialect], axis: str, diameter: bool) -> Expr:
    """The word value that keeps ``axis`` at its current point on ``target``: its position parameter, read
    when the block is read, so before the block's own offset change (``Dialect.POSITION_READS``); the new
    offset then applies to that point as the source's controller applies it at its next move. Doubled for a
    diameter X where the read is a radius (``Dialect.POSITION_READ_RADIUS``)."""
    read: Expr = Var(index=Num(float(target.POSITION_READS[axis])))
    if axis == "X" and diameter and target.POSITION_READ_RADIUS:
        read = Binary("mul", read, Num(2.0))
    return read


def _moves(sections: dict[str, Section]) -> bool:
    """The block moves an axis: a cycle, a rigid tap, or a motion naming an axis. A motion code alone
    (``G00 T101``, a lathe program's usual tool line) only sets the modal motion and moves nothing [K: a block
    moves only the axes it names; ``postproc.simulate.simulator`` makes no move of it either], so a change in
    it still waits for the next move."""
    if "CompoundMotion" in sections or "RigidTap" in sections or _native_cycle(sections):
        return True
    motion = sections.get("Motion")
    if not isinstance(motion, Motion):
        return False
    return bool(motion.axes) or motion.mode not in _STRAIGHT


def _native_cycle(sections: dict[str, Section]) -> bool:
    """A hole or lathe cycle the target keeps (its ``CompoundMotion`` dropped by the cycle steps): it moves."""
    return ("CannedCycle" in sections or "LatheCycle" in sections) and "CompoundMotion" not in sections


def _returns_through(block: Block, absolute: bool, axes: tuple[str, ...]) -> bool:
    """A reference return whose intermediate point names every one of ``axes`` absolutely: both rules apply
    the new length there."""
    motion = block.sections.get("Motion")
    return (isinstance(motion, Motion) and motion.mode in _RETURNS and absolute and all(a in motion.axes for a in axes)
            and "MachineCoordinates" not in block.sections)


def _incremental_return(block: Block, absolute: bool, axes: tuple[str, ...], pos: dict[str, float | None]) -> bool:
    """A reference return whose intermediate point is given in increments of ``axes`` only, from a known point:
    it can be written absolutely."""
    motion = block.sections.get("Motion")
    return (isinstance(motion, Motion) and motion.mode in _RETURNS and not absolute and bool(motion.axes)
            and all(a in axes and type(v) is float and pos[a] is not None for a, v in motion.axes.items())
            and all(a in motion.axes for a in axes) and "MachineCoordinates" not in block.sections)


def _incremental_z_return(block: Block, absolute: bool) -> bool:
    """A reference return whose intermediate point names Z by a plain increment (``G91 G28 Z0``)."""
    motion = block.sections.get("Motion")
    return (isinstance(motion, Motion) and motion.mode in _RETURNS and not absolute
            and type(motion.axes.get(AXIS)) is float and "MachineCoordinates" not in block.sections)


def _shifted_return(block: Block, old: float | None, new: float | None) -> bool:
    """An incremental return's Z increment for the target, where the programmed Z is not known: the source
    takes the intermediate point at the programmed Z plus the increment, with the new length (machine Z: z + dz
    + new); the target first re-expresses where it stands under the new length (program Z: z + old - new, the
    machine not moving) and adds its increment there, so dz + new - old reaches the same machine Z [V: rs274
    runs G43/G49 before G28 in one block; ``convert_tool_length_offset`` moves the program's current point,
    not the machine]. False where the set-up lacks a length."""
    if old is None or new is None:
        return False
    motion = block.sections["Motion"]
    assert isinstance(motion, Motion)
    motion.axes = {**motion.axes, AXIS: float(motion.axes[AXIS]) + new - old}  # type: ignore[arg-type]  # (a new
    # dictionary: ``postproc.lowering.move_words`` keys its reads on the old one)
    block.changed()
    return True


def _incremental_again(block: Block) -> Block:
    """The block after a reference return written absolutely: incremental distance again."""
    again = Block(block.line, None, block.eol or "\n")
    again.sections["DistanceMode"] = DistanceMode("incremental")
    return again


def _release(held: list[Block], keep: ToolLengthOffset | None) -> list[Block]:
    """The held blocks, the first (the changing one) without its change unless ``keep``; a block left
    with nothing is dropped."""
    first = held[0]
    if keep is None:
        del first.sections["ToolLengthOffset"]
        first.changed()
    out = [block for block in held if block is not first or block.sections]
    held.clear()
    return out


def _refuse(ctx: Context, target: type[Dialect], at: Location, why: str) -> None:
    where = "when Z next moves" if target.LENGTH_AT_AXIS_MOVE else "at the next absolute Z"
    ctx.diagnostics.error(UnsupportedError(
        f"this tool length change applies at the next move on the source's controller and only {where} on the "
        f"target's, and {why}: program Z beside the length change", at))


def _moves_named(block: Block, axes: tuple[str, ...]) -> bool:
    """The block's move names every one of ``axes``, absolutely or by an increment: a target that applies a
    change when the axis moves (``Dialect.LENGTH_AT_AXIS_MOVE``) applies it in that move, as the source does."""
    motion = block.sections.get("Motion")
    return isinstance(motion, Motion) and motion.mode in PLAIN and all(a in motion.axes for a in axes)


def _sets_z(block: Block, absolute: bool, axes: tuple[str, ...]) -> bool:
    """The block's move ends at every one of ``axes`` programmed absolutely, in work or in machine
    coordinates: where the two rules agree."""
    motion = block.sections.get("Motion")
    return (isinstance(motion, Motion) and motion.mode in PLAIN and all(a in motion.axes for a in axes)
            and (absolute or "MachineCoordinates" in block.sections))
