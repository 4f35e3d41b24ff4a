"""Where a program stands while its cutter compensation is resolved (``cutter_compensation``): the state of one
resolution, and the programmed point it follows through the blocks run without compensation.

The common block (a plain absolute move while no compensation is on) is only kept (``ProgrammedPoint._note``):
its X, Y and Z are read when something asks where the program stands (``_settle``, before anything reads the
point), from the last kept move that names each, so a program that never turns compensation on reads none of its
moves (a copy's check: ~700 instructions a block compiled). A move by
increments from an unknown start point makes its axis count from zero in a frame of its own (``floating``: see
``cutter_compensation``'s docstring). Where the other blocks leave the point (a hole cycle kept native or
expanded, a reference return, a move in machine coordinates, a control statement) is ``point_after``'s answer,
shared with the tool length timing; where it is not known, a compensated start-up from there is a located error. The moves of the compensated stretch and what the compensation releases
are ``cutter_moves``'s; the blocks and the steps are ``cutter_resolver``'s and ``cutter_compensation``'s.
"""

from __future__ import annotations

from typing import Callable, Final, cast

from mypy_extensions import mypyc_attr

from ..context import Context
from ..errors import ProgramError, UnsupportedError
from ..ir.expr import Expr
from ..ir import Block, CompoundMotion, Motion, Section
from ..compensation.cutter_radius import Item
from ..compensation.geometry_for import cutter_for
from ..compensation.rules import CutterRules
from ..compensation.tool_table import ToolTable
from ..interp.control import LABEL
from .move_words import X as _X, Y as _Y, Z as _Z, NotedPoint, move_words
from .point_after import RETURNS, compound_end, cycle_end, loses_after, unknown_axes
from .rule_trial import RuleTrial
from .units_and_distance import UnitsAndDistance

MOVES: Final = frozenset(("rapid", "linear", "cw", "ccw"))
KEPT: Final = 16
"""Plain moves ``ProgrammedPoint._note`` keeps before it reads them (``_fold``): memory stays flat whatever the
program's length, and a fold of a CAM program's moves reads the last one (it names X, Y and Z) and drops the rest.
The moves it drops are freed there rather than with their blocks: a few at a time (64 cost the allocator ~80
instructions a block more, callgrind)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Unresolvable(UnsupportedError):
    """What the resolver cannot write as moves (a computed position, an axis it does not track...): a refusal of
    the resolution, not of the program, so a copy's check (``Resolver.check``) stops there without a word."""


@mypyc_attr(allow_interpreted_subclasses=True)
class UnknownHere(ProgramError):
    """What the resolver does not know where it stands (a start point, a computed arc's centre...), though the
    simulation, which runs the program from its start, may: a copy's check stops there without a word."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ProgrammedPoint:
    """The compensation state of one translation, and where its program stands (``pos``, mm)."""

    def __init__(self, ctx: Context, rules: CutterRules, release: Callable[[Item], None], diameters: bool,
                 checking: bool) -> None:
        self.ctx = ctx
        self.checking = checking
        """Only the compensated path's errors are wanted, the blocks pass unchanged (``check``)."""
        self.diameters = diameters
        """X words are diameters in the blocks (read halved, written doubled: see the module docstring)."""
        self.rules = rules
        self.inverse_time = False
        """G93 in force (a compensated move is then written per minute: see the module docstring)."""
        self.per_minute = False
        """The output was switched to G94 for a resolved stretch under G93 (G93 is due back)."""
        self.length_register: int | Expr | None = None
        """The tool length register in force (None: no length offset)."""
        self.cutter = cutter_for(rules, release)
        self.table = ToolTable(ctx.setup)
        self.modes = UnitsAndDistance()
        """The units (``scale``: mm per program unit) and the distance mode in force."""
        self.plane = "ZX" if ctx.lathe else "XY"
        self.work_offset = 1
        self.shifted = False
        """A coordinate setting (G92) was read: a machine position is then not the point plus the work offset."""
        self.programmed_offsets: dict[int, dict[str, float]] = {}
        """The work systems and axes whose offset the program set (G10 L2): the set-up's is not in force there."""
        self.selected: int | None = None
        self.spindle_tool: int | None = None
        self.last_register: int | None = None
        """The cutter compensation register programmed last (``register_absent="modal"``)."""
        self.pos: dict[str, float | None] = {"X": None, "Y": None, "Z": None}
        """The programmed point, mm (None: not known since the origin moved or a reference return); the axes the
        plain moves since programmed (``kept``, then ``noted``) are brought into it before anything reads it
        (``_settle``)."""
        self.kept: list[Motion] = []
        """The plain moves since the last ``_settle`` or ``_fold``, in order, not read yet (at most ``KEPT``). A
        kept ``Motion`` is read later than it went past: no step changes a move's words in place (a step that
        changes them makes a new ``Motion``, as ``move_words`` also relies on)."""
        self.noted = 0
        """Bits (``_X``, ``_Y``, ``_Z``) of the axes the plain moves folded since the last ``_settle``
        programmed (``_fold``: their numbers, no dictionary written, no number boxed)."""
        self.unknown = 0
        """Bits of the noted axes whose last number was computed (an expression): not known."""
        self.noted_x = 0.0
        self.noted_y = 0.0
        self.noted_z = 0.0
        self.passing = NotedPoint(move_words(ctx))
        """The straight moves of X, Y and Z numbers the lowering loop noted past the resolution (its ``point``, while it
        would only keep them: ``cutter_resolver.Resolution.follow``), program units, later than every ``kept`` move:
        ``_note`` and ``_settle`` bring them in after the kept moves (``_passed``)."""
        self.at: tuple[float, float] = (0.0, 0.0)
        """The controlled point in the plane the last released move ends at, mm."""
        self.at_normal = 0.0
        """The programmed point along the plane's normal where the last released move ends, mm."""
        self.floating: set[str] = set()
        """Axes whose ``pos`` counts from an unknown start point (see the module docstring)."""
        self.by_increments = False
        """The compensated stretch is written by increments (it started with a floating axis)."""
        self.held: dict[int, tuple[Block, bool]] = {}
        """A queued move (by ``id``) -> its block, and whether it was written in G91."""
        self.out: list[Block] = []
        self.failed = False
        self.trial: RuleTrial | None = None
        """The stretch being tried (its blocks held back until it ends)."""

    def _idle(self) -> bool:
        cutter = self.cutter
        return cutter.side is None and not cutter.queue and not cutter.arc_banned

    def _origin_moved(self) -> None:
        if not self._idle():
            raise Unresolvable("a change of the work origin with cutter compensation on cannot be resolved")
        self.pos = {axis: None for axis in self.pos}

    def _note(self, motion: Motion) -> None:
        """A plain absolute move while no compensation is on: kept, read only when something asks where the
        program stands (``_settle``), or when ``KEPT`` moves wait (``_fold``)."""
        if self.passing.noted:
            self._passed()  # (the moves the loop noted went before this one)
        kept = self.kept
        kept.append(motion)
        if len(kept) >= KEPT:
            self._fold()

    def _fold(self) -> None:
        """The kept moves' X, Y and Z, in mm, into the noted numbers, as noting each in turn would leave them:
        each axis's number is the one of the last kept move that names it (a computed word: not known), so the
        moves are read from the last back, until each of X, Y and Z is found. The scale and the distance mode are the kept moves' own: anything that
        changes them settles first."""
        kept = self.kept
        scale = self.modes.scale
        left = _X | _Y | _Z
        at = len(kept)
        while left and at > 0:
            at -= 1
            axes = kept[at].axes
            if left & _X:
                x = axes.get("X")
                if x is not None:
                    left &= ~_X
                    self.noted |= _X
                    if type(x) is float:
                        self.noted_x = x * scale
                        self.unknown &= ~_X
                    else:
                        self.unknown |= _X
            if left & _Y:
                y = axes.get("Y")
                if y is not None:
                    left &= ~_Y
                    self.noted |= _Y
                    if type(y) is float:
                        self.noted_y = y * scale
                        self.unknown &= ~_Y
                    else:
                        self.unknown |= _Y
            if left & _Z:
                z = axes.get("Z")
                if z is not None:
                    left &= ~_Z
                    self.noted |= _Z
                    if type(z) is float:
                        self.noted_z = z * scale
                        self.unknown &= ~_Z
                    else:
                        self.unknown |= _Z
        kept.clear()

    def _passed(self) -> None:
        """The moves the loop noted (``passing``) into the noted numbers, in mm, after the kept moves (folded first):
        as ``_fold`` would leave them had each been kept (a number: known; the scale is theirs, as the kept ones')."""
        if self.kept:
            self._fold()
        passing = self.passing
        bits = passing.noted
        passing.noted = 0
        scale = self.modes.scale
        self.noted |= bits
        self.unknown &= ~bits
        if bits & _X:
            self.noted_x = passing.x * scale
        if bits & _Y:
            self.noted_y = passing.y * scale
        if bits & _Z:
            self.noted_z = passing.z * scale

    def _settle(self) -> None:
        """Bring the axes the plain moves programmed into ``pos`` (an absolute number also ends an axis's frame of
        its own, ``floating``)."""
        if self.kept:
            self._fold()
        if self.passing.noted:
            self._passed()
        noted = self.noted
        if not noted:
            return
        self.noted = 0
        unknown = self.unknown
        pos = self.pos
        if noted & _X:
            pos["X"] = None if unknown & _X else self.noted_x
            self.floating.discard("X")
        if noted & _Y:
            pos["Y"] = None if unknown & _Y else self.noted_y
            self.floating.discard("Y")
        if noted & _Z:
            pos["Z"] = None if unknown & _Z else self.noted_z
            self.floating.discard("Z")

    def _in_plane(self, point: dict[str, float | None]) -> tuple[float | None, float | None]:
        a1, a2, _ = self.cutter.axes
        return point.get(a1), point.get(a2)

    def _entry_start(self) -> None:
        """Where the entry move starts: the programmed point, when known; in incremental mode an unknown
        point is the zero of a frame of its own (``floating``)."""
        if not self._idle():
            return
        if not self.modes.absolute:
            for axis, value in self.pos.items():
                if value is None:
                    self.pos[axis] = 0.0
                    self.floating.add(axis)
        self.by_increments = bool(self.floating)
        u, v = self._in_plane(self.pos)
        if u is not None and v is not None:
            self.at = (u, v)
        self.at_normal = self.pos.get(self.cutter.axes[2]) or 0.0

    def _target(self, motion: Motion) -> dict[str, float | None]:
        target = dict(self.pos)
        for axis, value in motion.axes.items():
            if isinstance(value, Expr):
                raise Unresolvable("a computed position under cutter compensation cannot be resolved")
            if axis not in target:
                raise Unresolvable(f"motion of axis {axis} with cutter compensation on cannot be resolved")
            scale = self.modes.scale * 0.5 if axis == "X" and self.diameters else self.modes.scale
            if self.modes.absolute:
                if axis in self.floating:
                    if not self._idle():
                        raise UnknownHere(f"an absolute {axis} in a compensated stretch of a program that moved by "
                                           "increments from an unknown start point")
                    self.floating.discard(axis)
                target[axis] = value * scale
            else:
                known = target[axis]
                target[axis] = None if known is None else known + value * scale
        return target

    def _track(self, block: Block) -> None:
        """The programmed point after a block run with no compensation on (the blocks other than a plain move:
        ``point_after``)."""
        sections = block.sections
        motion = sections.get("Motion")
        compound = sections.get("CompoundMotion")
        cycle = sections.get("CannedCycle")
        if LABEL in sections:
            self._lose()  # a jump's target: reached from elsewhere too (its own move is followed below)
        if cycle is not None and "MachineCoordinates" not in sections:
            self._track_cycle(cycle)  # a hole cycle (or a repeat of it): kept native, or its expansion not made yet
        elif isinstance(compound, CompoundMotion) and "MachineCoordinates" not in sections:
            self._track_compound(compound)
        elif compound is not None:
            self._lose()
        elif isinstance(motion, Motion) and motion.axes:
            if motion.mode in RETURNS or "MachineCoordinates" in sections:
                for axis in unknown_axes(motion):  # a machine position: not known in work coordinates
                    if axis in self.pos:
                        self.pos[axis] = None
                        self.floating.discard(axis)
            else:
                try:
                    self.pos = {axis: value for axis, value in self._target(motion).items()}
                except UnsupportedError:
                    self.pos = {axis: None for axis in self.pos}
        if loses_after(sections):
            self._lose()
        u, v = self._in_plane(self.pos)
        if u is not None and v is not None:
            self.at = (u, v)

    def _lose(self) -> None:
        """The point is not known after this block (``point_after``)."""
        self.pos = {axis: None for axis in self.pos}

    def _track_cycle(self, cycle: Section) -> None:
        """Where a hole cycle the target keeps native leaves the tool (``point_after.cycle_end``): its last hole,
        at the level the cycle returns to."""
        end = cycle_end(cycle)
        if end is None:
            self._lose()
            return
        self._land(cast("dict[str, float | None]", end))  # (only read)

    def _track_compound(self, compound: CompoundMotion) -> None:
        """Where an expanded cycle (a lathe roughing cycle, before a G42 for its finishing cycle) leaves the
        tool: its moves are absolute (``point_after.compound_end``); a computed word leaves its axis unknown,
        a move other than G0-G3 the whole point. Every axis it moves is absolute: a floating axis lands."""
        moved = compound_end(compound)
        if moved is None:
            self._lose()
            return
        self._land(moved)

    def _land(self, end: dict[str, float | None]) -> None:
        """Axes brought to absolute numbers in program units (None: not known) by a block run with no
        compensation on (an expanded or native cycle); an axis not followed here is left alone. (A dictionary,
        not a ``Mapping``: compiled, its items are walked natively, where a ``Mapping``'s were a method call and
        an iterator's generic steps: ~900 instructions an expanded hole.)"""
        pos = self.pos
        scale = self.modes.scale
        x_scale = scale * 0.5 if self.diameters else scale
        floating = self.floating
        for axis, value in end.items():
            if axis in pos:
                pos[axis] = None if value is None else value * (x_scale if axis == "X" else scale)
                if floating:
                    floating.discard(axis)
