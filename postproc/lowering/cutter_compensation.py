"""Cutter radius compensation resolved for a target without it (grbl): the compensated path, written
as plain moves.

The path is the simulation's (``cutter_radius.CutterRadius`` under the source dialect's rules,
``Dialect.CUTTER_RULES``), so it is the source controller's path move for move: each move of the
compensated stretch is rewritten to its compensated end (an arc to its compensated centre, in I/J
from the compensated start), an outside corner adds its arc (a rapid's: a straight traverse) in a
block of its own, and a block without motion keeps its place behind the move the compensation holds
back. The compensated stretch is written in absolute positions: a block the program wrote in G91 gets
a G90 and a G91 after it. A program that moves only by increments from where the tool stands (its
start point unknown: an incremental thread milling program) is compensated in a frame of its own, its
start point at zero, and its stretch written by increments (compensation moves with the path, so the
increments are the same wherever it starts); an absolute word on such an axis within the stretch is a
located error. A source whose rules are not modelled leaves its G41/G42 to the writer,
which refuses them.

What the simulation refuses under compensation (a canned cycle, a move in machine coordinates, a
reference return, a plane the rules do not compensate in, a start point not known, a tool change) is a located
error here too. The exit move in machine coordinates (``G40`` then ``G53 G0 Z0``) takes the plane's axes back
to the programmed point: they are written as its machine position from the set-up's ``<WorkOffsets>``
(``_exit_in_machine``). A copy within one dialect keeps its compensation, but its path is computed all the same
(``_Resolver.check``), so the copy refuses what the simulation refuses. In the ZX plane (G18) the plane's points are (Z, X), as the simulation has them.

On a lathe (the ZX plane) the path is the imaginary tool tip's, as the simulation writes it: the nose
centre one nose radius beside the programmed path, moved by the radius in the tip's direction
(``<Tool tip>``, ``postproc.compensation.nose``). The lathe lowering has written X as a radius for a
target that is no lathe control (``postproc.cycles.lathe_lowering``), so the geometry is true. A lathe
target programmed in diameters (a Fanuc T stretch towards LinuxCNC in G7, whose rules differ) keeps X a
diameter in its blocks: the resolver halves it where it reads it and doubles it where it writes it; an
arc's I stays a radius [V: rs274 2.9, G7 G18 ``G2 X20 Z-5 I5 K0`` from X10 Z0 turns about X radius 10;
V: grblHAL core ``gcode.c`` (f80fc34), diameter mode halves the X word only, an arc's IJK untouched;
K: Fanuc T, I is a radius in either mode].

Inverse time (G93) under compensation: the controller runs each compensated move at F times the
length of the *programmed* move per minute, an outside corner's arc at the rate of the move after it
[V: rs274 2.9, LinuxCNC's tests/interp/inverse-time-with-comp]. Written as moves, G93 would time the
compensated length instead, so the resolved stretch is written per minute (G94 with those rates) and
G93 comes back with the first block after it.

Towards a target whose own modelled rules differ (Fanuc's and LinuxCNC's), each stretch from G41/G42 to
the move after G40 is held back and run under both rules (``rule_trial``): it keeps its G41/G42 where both
cut the same path, else it is written as the source's moves. (Over 600 lines: the resolver is one state
machine whose queue, positions and modes the trial shares; split, each half would reach into the other.)

Compensation by a diameter in the program (LinuxCNC's G41.1/G42.1, ``DynamicCutterCompensation``) is
resolved the same way for every target but its source's own (``resolve_dynamic_cutter_compensation``):
no other dialect spells it, and a target with G41/G42 would need a register holding that radius, which
the set-up does not promise. The G41/G42 such a target writes itself pass untouched. A computed diameter
(``G41.1 D#100`` in a subprogram) keeps its block verbatim, which the target refuses: the program is
then flattened, each run's diameter a number.
"""

from __future__ import annotations

import math
from typing import Callable, Final, Iterator

from mypy_extensions import mypyc_attr

from ..block_rules import ArcError, arc_centre
from ..context import Context
from ..control import ASSIGN, CONTROL, LABEL
from ..dialect import RULES_UNKNOWN_KEY, Dialect
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..expr import Expr
from ..ir import (Block, CompoundMotion, CutterCompensation, DataSetting, DistanceMode, Feed, FeedMode, Motion, Plane,
                  ProgramControl, Section, ToolChange, ToolLengthOffset, ToolSelect, Units, WorkOffset)
from ..compensation.cutter_radius import CutterRadius, Item, Segment
from ..compensation.dynamic import DynamicCutterCompensation
from ..compensation.nose import TIPS, mirrored
from ..compensation.geometry_for import cutter_for
from ..compensation.rules import CutterRules
from ..compensation.tool_table import ToolTable
from ..setup.work_offsets import declared_offsets, offset_beyond_frame
from ..state import PLANE_AXES
from .inverse_time import move_length
from .rule_trial import STAND_IN_RADIUS, STRETCH_LIMIT, RuleTrial

Keeps = Callable[["_Resolver", CutterCompensation], bool]
"""Whether the target writes a G41/G42 itself (given the resolver, for the tool data it tracks)."""
MM_PER_INCH = 25.4
ARC_OFF_MM = 0.005
ARC_OFF_RATIO = 0.001
"""How far an arc's end may lie off the circle through its start before a controller refuses it: [V] grbl
``gcode.c`` (error 33 beyond 0.005 mm and 0.1 % of the radius). LinuxCNC joins an arc to a move within
its corner tolerance (0.05 rad) without moving the start onto the compensated circle, so its compensated
arc may start off the circle; such an arc is refused here rather than written one grbl rejects."""
MOVES: Final = frozenset(("rapid", "linear", "cw", "ccw"))
_SEGMENT_KIND: Final = {"rapid": "rapid", "linear": "feed", "cw": "cw", "ccw": "ccw"}
_MOTION_MODE: Final = {"rapid": "rapid", "feed": "linear", "cw": "cw", "ccw": "ccw"}
_MODAL: Final = frozenset(("Units", "DistanceMode", "Plane", "DataSetting", "WorkOffset", "ToolSelect",
                           "ToolChange", "ToolLengthOffset", "FeedMode"))
"""Settings the resolver keeps while no compensation is on (a block with none of them, and no G41/G42, is
only a move to track, or passes untouched)."""
_NOT_PLAIN: Final = _MODAL | {"CutterCompensation", "DynamicCutterCompensation", "CoordinateSet"}
"""A block with one of these goes the general way even while no compensation is on (``_Resolver.block``)."""
_NOT_TRACKED: Final = frozenset(("MachineCoordinates", "CompoundMotion"))
"""A block with one of these is not a plain move to track (``_Resolver._track`` says where it leaves the tool)."""
_NOT_NOTED: Final = _NOT_PLAIN | _NOT_TRACKED
"""A block with none of these is at most a move to note (one set look-up a key for the common block)."""
RESOLVED: Final = "cutter_compensation_resolved"
"""``Context.run_data`` key: the target for which ``resolve_dynamic_cutter_compensation`` resolves every G41/G42
as well (it keeps none and tries none), so the target's own ``resolve_cutter_compensation`` (grbl's, after
steps that leave compensation alone) finds nothing left and passes the blocks untouched: a second resolver
was ~1.5k instructions a block (``fanuc grbl 0``, compiled). After an error the first resolves nothing more, and
neither does the second now: a later G41/G42 is the target writer's refusal."""
_X: Final = 1
_Y: Final = 2
_Z: Final = 4
"""The bits of ``_Resolver.noted``: the axes a plain move noted since ``pos`` was last brought up to date."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Unresolvable(UnsupportedError):
    """What the resolver cannot write as moves (a computed position, an axis it does not track...): a refusal of
    the resolution, not of the program, so a copy's check (``_Resolver.check``) stops there without a word."""


@mypyc_attr(allow_interpreted_subclasses=True)
class UnknownHere(ProgramError):
    """What the resolver does not know where it stands (a start point, a computed arc's centre...), though the
    simulation, which runs the program from its start, may: a copy's check stops there without a word."""


_UNCHECKED: Final = (Unresolvable, UnknownHere)
_STOPS_CHECK: Final = frozenset((CONTROL, ASSIGN, LABEL))
"""A block with one of these leaves the program's text order (a call, a jump, a computation): what follows is not
what runs next, so a copy's check stops there."""
_CHECK_GENERAL: Final = _NOT_NOTED | _STOPS_CHECK


def resolve_cutter_compensation(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step: G41/G42 become the compensated path for a target without cutter compensation,
    where the source dialect's rules are modelled (see the module docstring)."""
    if ctx.dialect == target.NAME or target.CUTTER_COMPENSATION:
        return blocks
    rules: CutterRules | None = ctx.cutter_rules  # none for a program written from the neutral IR
    if rules is None:
        why = ctx.run_data.get(RULES_UNKNOWN_KEY)
        return blocks if why is None else _refuse_unmodelled(blocks, ctx, target, str(why))
    if ctx.run_data.get(RESOLVED) is target:
        return blocks  # (the generic step already resolved every G41/G42 for this target)
    return _Resolver(ctx, rules, diameters=_takes_diameters(ctx, target)).run(blocks)


def _refuse_unmodelled(blocks: Iterator[Block], ctx: Context, target: type[Dialect], why: str) -> Iterator[Block]:
    """A G41/G42 from a source whose rules are not modelled, towards a target without compensation: a located
    error naming what is unknown (not that the target cannot express it: it is written as moves where the rules
    are known); the section goes, so the writer does not refuse it a second time."""
    for block in blocks:
        cc = block.sections.get("CutterCompensation")
        if isinstance(cc, CutterCompensation) and cc.mode != "off":
            ctx.diagnostics.error(UnsupportedError(
                f"cutter radius compensation ({cc.mode}) cannot be resolved into moves for {target.NAME}, which has "
                f"none: {why}", ctx.at(block)))
            del block.sections["CutterCompensation"]
            block.changed()
        yield block


def _takes_diameters(ctx: Context, target: type[Dialect]) -> bool:
    """The blocks still hold X as a diameter (a lathe target programmed in diameters)."""
    return ctx.diameter and "lathe" in target.MACHINE_TYPES and target.DIAMETER_PROGRAMMING


def resolve_dynamic_cutter_compensation(blocks: Iterator[Block], ctx: Context,
                                        target: type[Dialect]) -> Iterator[Block]:
    """Lowering step: G41.1/G42.1 (compensation by a diameter) become the compensated path for every
    target but the source's own dialect (see the module docstring); a G41/G42 by register is left to the
    target where it has cutter compensation, unless its modelled rules differ from the source's."""
    rules: CutterRules | None = ctx.cutter_rules
    if rules is None:
        return blocks
    if ctx.dialect == target.NAME:
        return blocks if ctx.lathe else _Resolver(ctx, rules, checking=True).check(blocks)
    differ = _rules_differ(rules, target, ctx)
    keeps = _native if target.CUTTER_COMPENSATION and not differ else None
    trial = target.cutter_rules(ctx.setup) if target.CUTTER_COMPENSATION and differ else None
    if keeps is None and trial is None:
        ctx.run_data[RESOLVED] = target
    return _Resolver(ctx, rules, keeps, _takes_diameters(ctx, target), trial).run(blocks)


def _rules_differ(rules: CutterRules, target: type[Dialect], ctx: Context) -> bool:
    """The target compensates by rules of its own that are modelled and not the source's (NIST version 3's
    entry move and inside corners against LinuxCNC's, Fanuc's straight outer corners against LinuxCNC's
    arcs): its G41/G42 may cut another path, so each stretch is tried under both (``rule_trial``) and
    written as the source's compensated moves where the paths differ. Rules that differ only in their name
    (a Haas lathe's and Fanuc T's) are the same."""
    theirs: CutterRules | None = target.cutter_rules(ctx.setup)
    return theirs is not None and not theirs.cuts_like(rules)


def resolve_cutter_compensation_unless(blocks: Iterator[Block], ctx: Context,
                                       keeps: Keeps) -> Iterator[Block]:
    """G41/G42 become the compensated path where ``keeps`` says the target cannot write them as they are
    (and the source's rules are modelled: else the target's own step decides); G41.1/G42.1 always."""
    rules: CutterRules | None = ctx.cutter_rules
    if rules is None:
        return blocks
    return _Resolver(ctx, rules, keeps).run(blocks)


def _noise_free(value: float | Expr) -> float | Expr:
    """A computed coordinate rounded to 1e-9 program units: the conversions leave float noise (0.1 in as
    2.54 mm and back is 0.10000000000000002), which a writer that keeps every digit a value needs (Mach3's)
    would write; 1e-9 is far below any controller's resolution."""
    return round(value, 9) if isinstance(value, float) else value


def _full_circle(motion: Motion) -> bool:
    """An arc with its centre and no end point (``G3 I-20``): a full turn back to where it starts."""
    return motion.mode in ("cw", "ccw") and bool(motion.center)


def _stop_and_cancel(cutter: CutterRadius) -> None:
    cutter.stop()
    cutter.cancel()


def _native(resolver: "_Resolver", cc: CutterCompensation) -> bool:
    return True


@mypyc_attr(allow_interpreted_subclasses=True)
class _Resolver:
    """The compensation state of one translation, and the blocks it has released."""

    def __init__(self, ctx: Context, rules: CutterRules, keeps: Keeps | None = None, diameters: bool = False,
                 trial: CutterRules | None = None, checking: bool = False) -> None:
        self.ctx = ctx
        self.checking = checking
        """Only the compensated path's errors are wanted, the blocks pass unchanged (``check``)."""
        self.diameters = diameters
        """X words are diameters in the blocks (read halved, written doubled: see the module docstring)."""
        self.rules = rules
        self.keeps = keeps
        """Whether a G41/G42 by register stays for the target to write (with its G40); None: none does."""
        self.inverse_time = False
        """G93 in force (a compensated move is then written per minute: see the module docstring)."""
        self.per_minute = False
        """The output was switched to G94 for a resolved stretch under G93 (G93 is due back)."""
        self.length_register: int | Expr | None = None
        """The tool length register in force (None: no length offset)."""
        self.cutter = cutter_for(rules, self._release)
        self.table = ToolTable(ctx.setup)
        self.scale = 1.0
        """mm per program unit."""
        self.absolute = True
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
        """The programmed point, mm (None: not known since the origin moved or a reference return); the axes a
        plain move noted since (``noted``) are brought into it before anything reads it (``_settle``)."""
        self.noted = 0
        """Bits (``_X``, ``_Y``, ``_Z``) of the axes the plain moves since the last ``_settle`` programmed: a
        plain move, the common block, only notes its numbers (no dictionary written, no number boxed)."""
        self.unknown = 0
        """Bits of the noted axes whose last number was computed (an expression): not known."""
        self.noted_x = 0.0
        self.noted_y = 0.0
        self.noted_z = 0.0
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
        self.trial_rules = trial
        """The target's own rules, when modelled and not the source's: each stretch is tried under both."""
        self.trial: RuleTrial | None = None
        """The stretch being tried (its blocks held back until it ends)."""

    def run(self, blocks: Iterator[Block]) -> Iterator[Block]:
        idle = True
        radii = not self.diameters
        """X is a radius in the blocks: the common block's move is tracked here (else by ``_track``)."""
        for block in blocks:
            sections = block.sections
            plain = idle
            odd = False
            if plain:  # one look at the keys: none asks for the general way (a G41/G42, a setting)
                for key in sections:
                    if key in _NOT_NOTED:
                        odd = True
                        break
                if odd:
                    for key in sections:
                        if key in _NOT_PLAIN:
                            plain = False
                            break
            if plain:
                motion = sections.get("Motion")  # the common block: a move, noted for a later entry move
                if isinstance(motion, Motion) and self.absolute and motion.mode in MOVES and radii \
                        and not (odd and "MachineCoordinates" in sections):
                    self._note(motion)
                elif motion is not None or odd:
                    self._settle()
                    self._track(block)
                if self.per_minute:
                    self._back_to_inverse_time(block)
                yield block
                continue
            self._settle()
            if not self.failed and self.trial_rules is not None:
                self._try(block)
            if not self.failed:
                try:
                    self.block(block)
                except PostprocError as err:
                    located = err.located(self.ctx.at(block)) if err.location is None else err
                    self.failed = True  # the queue no longer matches the program: nothing more is resolved
                    if self.trial is not None and isinstance(err, UnsupportedError):
                        self._untried(located)
                    else:
                        self.ctx.diagnostics.error(located)
                        self.out.append(block)
            else:
                self.out.append(block)
            idle = self.failed or self._idle()
            if self.trial is not None:
                self.trial.resolved.extend(self.out)
                self.out.clear()
                if idle or len(self.trial.stretch) > STRETCH_LIMIT:
                    yield from self._tried(idle)
            if self.out:
                yield from self.out
                self.out.clear()
        if not self.failed:
            try:
                self.cutter.finish()
            except PostprocError as err:
                if self.trial is not None and isinstance(err, UnsupportedError):
                    self._untried(err)
                else:
                    self.ctx.diagnostics.error(err)
        if self.trial is not None:
            self.trial.resolved.extend(self.out)
            self.out.clear()
            yield from self._tried(True)
        yield from self.out

    def check(self, blocks: Iterator[Block]) -> Iterator[Block]:
        """A copy within one dialect keeps its compensation native: the blocks pass unchanged, but the path is
        computed from a copy of each block as for a resolution (the same geometry the simulation runs), so
        what the simulation refuses (a move turning back on itself, an inside arc smaller than the radius, a
        tool change under compensation...) is refused here too, at its line. Where the resolver cannot follow
        the program (``Unresolvable``, ``UnknownHere``, a radius the set-up lacks, a call or a jump), the check
        stops without a word: the copy is the program, and verify says what it cannot simulate."""
        stream = iter(blocks)
        idle = True
        for block in stream:
            sections = block.sections
            if idle:
                general = False
                for key in sections:
                    if key in _CHECK_GENERAL:
                        general = True
                        break
                if not general:
                    motion = sections.get("Motion")
                    if isinstance(motion, Motion) and self.absolute and motion.mode in MOVES:
                        self._note(motion)
                    elif motion is not None:
                        self._settle()
                        self._track(block)
                    yield block
                    continue
            if not _STOPS_CHECK.isdisjoint(sections):
                yield block
                yield from stream
                return
            self._settle()
            shadow = Block(block.line, block.text, block.eol, block.words)
            shadow.sections = dict(sections)  # the resolver rewrites its own dictionary, never a section
            try:
                self.block(shadow)
            except PostprocError as err:
                if not isinstance(err, _UNCHECKED):
                    self.ctx.diagnostics.error(err.located(self.ctx.at(block)) if err.location is None else err)
                yield block
                yield from stream
                return
            self.out.clear()
            idle = self._idle()
            yield block
        try:
            self.cutter.finish()
        except PostprocError as err:
            if not isinstance(err, _UNCHECKED):
                self.ctx.diagnostics.error(err)

    # -- a stretch tried under the target's rules (``rule_trial``) -------------------------------------
    def _try(self, block: Block) -> None:
        """Hold a block of a stretch compensated by register (a stretch by a diameter is always resolved)."""
        if self.trial is None:
            cc = block.sections.get("CutterCompensation")
            if not (self._idle() and isinstance(cc, CutterCompensation) and cc.mode != "off"
                    and "DynamicCutterCompensation" not in block.sections):
                return
            assert self.trial_rules is not None
            self.trial = RuleTrial(self.trial_rules)
        self.trial.hold(block)

    def _tried(self, decided: bool) -> list[Block]:
        trial, self.trial = self.trial, None
        assert trial is not None
        return trial.outcome(decided and not self.failed, self.ctx.diagnostics, refused=self.failed)

    def _untried(self, err: PostprocError) -> None:
        """The source's rules cannot be simulated in a tried stretch: its G41/G42 stay as written (the
        target has its own), the path unchecked, unless the target's rules refuse the stretch as far as it
        was tried (a LinuxCNC entry arc for a Fanuc): then nothing can be written, a located error. Nothing
        more is resolved."""
        assert self.trial is not None
        trial, self.trial = self.trial, None
        self.out = trial.as_read()
        if trial.refusal is not None:
            self.ctx.diagnostics.error(UnsupportedError(
                f"{err.message}; nor can the stretch be kept as written: the target's rules refuse it or cannot be simulated on it "
                f"({trial.refusal.message})", err.location))
            return
        self.ctx.diagnostics.warn(f"{err.message}: cutter compensation is kept as written, its path under the "
                                  "target's own rules unchecked", err.location)

    def _radius(self, register: int, block: Block) -> float:
        """The register's radius; in a tried stretch an unknown one is a stand-in, and an error only where
        the rules' paths differ (the path is then written as moves, which needs the radius)."""
        try:
            return self.table.radius(register)
        except PostprocError as err:
            if self.checking:
                raise UnknownHere(err.message) from None  # the set-up's tool data: verify names it
            if self.trial is None:
                raise
            self.trial.missing = err.located(self.ctx.at(block)) if err.location is None else err
            return STAND_IN_RADIUS

    def _mirror(self, call: Callable[[CutterRadius], None]) -> None:
        if self.trial is not None:
            self.trial.mirror(call)

    # -- one block -----------------------------------------------------------------------------------
    def block(self, block: Block) -> None:
        sections = block.sections
        if "ToolChange" in sections:
            self.cutter.tool_change()  # the simulation's check, before the block's own G40/G41/G42
        self._modal(sections)
        cc = sections.get("CutterCompensation")
        if isinstance(cc, CutterCompensation) and self.keeps is not None and self._idle() \
                and (cc.mode == "off" or self.keeps(self, cc)):
            cc = None  # the target writes its own G41/G42/G40
        dynamic = sections.get("DynamicCutterCompensation")
        if isinstance(dynamic, DynamicCutterCompensation):
            del sections["DynamicCutterCompensation"]
            sections.pop("NativeCode", None)  # its G41.1/G42.1 D.., which the section says (inert)
            block.changed()
            if self._idle():
                self.cutter.axes = PLANE_AXES[self.plane]
                self._entry_start()
            tip = TIPS[mirrored(dynamic.orientation or 0)] if self._nose() else (0, 0)
            self.cutter.start(dynamic.mode, dynamic.radius(self.scale), self.plane,  # negative: the other side
                              (float(tip[0]), float(tip[1])))
        elif isinstance(cc, CutterCompensation) and cc.mode == "off" and self._idle():
            pass  # a G40 with nothing to cancel: written as it is (grbl has G40)
        elif isinstance(cc, CutterCompensation):
            del sections["CutterCompensation"]
            block.changed()
            if cc.mode == "off":
                self.cutter.cancel()
                self._mirror(lambda cutter: cutter.cancel())
            else:
                register = self._register(cc.register)
                radius = self._radius(register, block)
                tip = TIPS[self.table.tip(register)] if self._nose() else (0, 0)
                if self._idle():
                    self.cutter.axes = PLANE_AXES[self.plane]
                    self._entry_start()
                self.cutter.start(cc.mode, radius, self.plane, (float(tip[0]), float(tip[1])))
                if self.trial is not None:
                    plane, mode = self.plane, cc.mode
                    self.trial.cutter.sweep_slack = self.cutter.sweep_slack
                    self._mirror(lambda cutter: cutter.start(mode, radius, plane, (float(tip[0]), float(tip[1]))))
        if (isinstance(dynamic, DynamicCutterCompensation) or isinstance(cc, CutterCompensation)) and not sections:
            return  # the block only turned compensation on or off: nothing is left to write
        if self._idle():
            self._track(block)
            self._back_to_inverse_time(block)
            self.out.append(block)
            return
        compound = sections.get("CompoundMotion")
        if "CannedCycle" in sections or (compound is not None and not (
                isinstance(compound, CompoundMotion) and compound.term in self.rules.profile_cycles)):
            raise ProgramError("a canned cycle with cutter compensation on cannot be run (cancel it first)")
        motion = sections.get("Motion")
        if isinstance(compound, CompoundMotion):
            self._compound(block, compound)  # a finishing cycle's profile, compensated move by move
        elif isinstance(motion, Motion) and (motion.axes or _full_circle(motion)):
            self._move(block, motion)
        elif isinstance(motion, Motion) and motion.mode is not None and motion.mode not in MOVES:
            raise Unresolvable(f"motion '{motion.mode}' with cutter compensation on cannot be resolved")
        else:
            self.cutter.event({"block": block})
            self._mirror(lambda cutter: cutter.event({}))
        control = sections.get("ProgramControl")
        if isinstance(control, ProgramControl):
            if control.kind in ("stop", "optional_stop"):
                self.cutter.stop()  # a stop writes the queued move at its compensated end [V]
                self._mirror(lambda cutter: cutter.stop())
            elif control.kind in ("end", "end_rewind"):
                self.cutter.stop()
                self.cutter.cancel()
                self._mirror(_stop_and_cancel)

    def _compound(self, block: Block, compound: CompoundMotion) -> None:
        """A lathe finishing cycle the source compensates as its profile (``CutterRules.profile_cycles``):
        the block without its moves waits as an event, then each move goes through the compensation as a
        block of its own (at the feed the cycle gives it), written as the compensated move."""
        del block.sections["CompoundMotion"]
        block.changed()
        if block.sections:
            self.cutter.event({"block": block})
            self._mirror(lambda cutter: cutter.event({}))
        feed: Feed | None = None
        for item in compound.items:
            if isinstance(item, Feed):
                feed = item
            elif isinstance(item, Motion) and item.mode in MOVES:
                move = Block(block.line, None, "\n")
                move.sections = {"Motion": item}
                if feed is not None and item.mode != "rapid":
                    move.sections["Feed"], feed = feed, None
                self._move(move, item)
            else:
                raise Unresolvable(f"a {type(item).__name__} inside a lathe cycle under tool nose radius "
                                       "compensation cannot be resolved")

    def _modal(self, sections: dict[str, Section]) -> None:
        if "CoordinateSet" in sections:
            self.shifted = True
        units = sections.get("Units")
        if isinstance(units, Units):
            scale = MM_PER_INCH if units.system == "inch" else 1.0
            self.scale = scale
            self.cutter.sweep_slack = 0.001 if units.system == "inch" else 0.0254
        distance = sections.get("DistanceMode")
        if isinstance(distance, DistanceMode):
            self.absolute = distance.mode == "absolute"
        plane = sections.get("Plane")
        if isinstance(plane, Plane):
            if plane.plane != self.plane and self.cutter.side is not None:
                raise ProgramError(f"the plane cannot change to {plane.plane} while cutter compensation is on "
                                   "(cancel it first)")
            self.plane = plane.plane
        setting = sections.get("DataSetting")
        if isinstance(setting, DataSetting):
            if setting.table.startswith("work_offset"):
                self._origin_moved()
                self.programmed_offsets.setdefault(setting.index, {}).update(
                    {axis: 0.0 for axis in setting.values})  # (which axes: the values are the frame's now)
            else:
                self.table.write(setting, self.scale)
        offset = sections.get("WorkOffset")
        if isinstance(offset, WorkOffset) and offset.index != self.work_offset:
            self.work_offset = offset.index
            self._origin_moved()
        feed_mode = sections.get("FeedMode")
        if isinstance(feed_mode, FeedMode):
            self.inverse_time = feed_mode.mode == "inverse_time" and not self.checking  # (a check writes nothing)
        length = sections.get("ToolLengthOffset")
        if isinstance(length, ToolLengthOffset):
            self.length_register = length.register if length.mode == "positive" else None
        select = sections.get("ToolSelect")
        if isinstance(select, ToolSelect) and isinstance(select.number, int):
            self.selected = select.number
        if isinstance(sections.get("ToolChange"), ToolChange):
            self.spindle_tool = self.selected

    def _origin_moved(self) -> None:
        if not self._idle():
            raise Unresolvable("a change of the work origin with cutter compensation on cannot be resolved")
        self.pos = {axis: None for axis in self.pos}

    def _nose(self) -> bool:
        """Compensation on a lathe, in its ZX plane: the path is the imaginary tool tip's."""
        return self.plane == "ZX" and self.ctx.lathe

    def _register(self, register: int | Expr | None) -> int:
        if isinstance(register, Expr):
            raise Unresolvable("cutter compensation with a computed register cannot be resolved")
        if register is None and self.rules.register_absent == "offset":  # the lathe lowering names it
            raise ProgramError("tool nose radius compensation takes the radius of the offset the T code selected, "
                               "and none is (program T with its offset number, T0101)")
        if register is None and self.rules.register_absent == "modal":
            if self.last_register is None:
                raise ProgramError("cutter compensation without its register takes the register programmed last, "
                                   "and none was: program D")
            return self.last_register
        if register is None:
            if self.rules.register_absent != "tool" or self.spindle_tool is None:
                raise ProgramError("cutter compensation without its register takes the tool in the spindle, which "
                                   "is not known here (no tool change before it): program its register")
            register = self.spindle_tool
        self.last_register = register
        return register

    # -- positions -----------------------------------------------------------------------------------
    def _note(self, motion: Motion) -> None:
        """A plain absolute move while no compensation is on: its X, Y and Z, in mm, noted for ``_settle``."""
        axes = motion.axes
        scale = self.scale
        x = axes.get("X")
        if x is not None:
            self.noted |= _X
            if type(x) is float:
                self.noted_x = x * scale
                self.unknown &= ~_X
            else:
                self.unknown |= _X
        y = axes.get("Y")
        if y is not None:
            self.noted |= _Y
            if type(y) is float:
                self.noted_y = y * scale
                self.unknown &= ~_Y
            else:
                self.unknown |= _Y
        z = axes.get("Z")
        if z is not None:
            self.noted |= _Z
            if type(z) is float:
                self.noted_z = z * scale
                self.unknown &= ~_Z
            else:
                self.unknown |= _Z

    def _settle(self) -> None:
        """Bring the axes the plain moves noted into ``pos`` (an absolute number also ends an axis's frame of
        its own, ``floating``)."""
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
        if not self.absolute:
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
            scale = self.scale * 0.5 if axis == "X" and self.diameters else self.scale
            if self.absolute:
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
        """The programmed point after a block run with no compensation on."""
        sections = block.sections
        motion = sections.get("Motion")
        compound = sections.get("CompoundMotion")
        if isinstance(compound, CompoundMotion) and "MachineCoordinates" not in sections:
            self._track_compound(compound)
        elif "CompoundMotion" in sections or "MachineCoordinates" in sections:
            self.pos = {axis: None for axis in self.pos}
        elif isinstance(motion, Motion) and motion.axes:
            if motion.mode in ("home", "home2"):
                self.pos = {axis: None for axis in self.pos}
                return
            try:
                self.pos = {axis: value for axis, value in self._target(motion).items()}
            except UnsupportedError:
                self.pos = {axis: None for axis in self.pos}
        u, v = self._in_plane(self.pos)
        if u is not None and v is not None:
            self.at = (u, v)

    def _track_compound(self, compound: CompoundMotion) -> None:
        """Where an expanded cycle (a lathe roughing cycle, before a G42 for its finishing cycle) leaves the
        tool: its moves are absolute (``CompoundMotion``); anything else makes the point unknown. Every
        expanded hole of a translation that resolves compensation passes here, so the moves are followed
        in one dictionary, with ``_target``'s checks of each word (a dictionary a move through ``_target``
        cost the cycles bench 36k instructions a hole). A refused absolute word of a floating axis
        leaves the point where the expansion started: the translation has failed, nothing reads it."""
        pos = dict(self.pos)
        scale = self.scale
        x_scale = scale * 0.5 if self.diameters else scale
        floating = self.floating
        for item in compound.items:
            if not isinstance(item, Motion):
                continue
            if item.mode not in MOVES:
                pos = {axis: None for axis in pos}
                continue
            for axis, value in item.axes.items():
                if isinstance(value, Expr) or axis not in pos:  # _target's refusals: the point is not known
                    self.pos = {axis: None for axis in self.pos}
                    return
                if floating and axis in floating:
                    if not self._idle():
                        raise ProgramError(f"an absolute {axis} in a compensated stretch of a program that moved "
                                           "by increments from an unknown start point")
                    floating.discard(axis)
                pos[axis] = value * (x_scale if axis == "X" else scale)
        self.pos = pos

    def _move(self, block: Block, motion: Motion) -> None:
        if "MachineCoordinates" in block.sections or motion.mode in ("home", "home2"):
            if self.cutter.side is not None or self.cutter.queue:
                raise ProgramError("a move in machine coordinates or a reference return with cutter compensation "
                                   "on cannot be run")
            # the first move after G40 (the exit move) in machine coordinates: [V] rs274 (LinuxCNC's
            # mmount.ngc, G40 then G53 G0 Z0) runs it straight from the compensated end to the programmed
            # point, X and Y included; written as it is, it keeps the compensated X and Y, so each plane axis
            # the block does not name is written as the programmed point's machine position (``_exit_in_machine``)
            self._exit_in_machine(block, motion)
            self.cutter.arc_banned = False
            self._track(block)
            self.out.append(block)
            return
        kind = _SEGMENT_KIND.get(motion.mode or "")
        if kind is None:
            raise Unresolvable(f"motion '{motion.mode}' with cutter compensation on cannot be resolved")
        a1, a2, normal = self.cutter.axes
        start_1, start_2 = self._in_plane(self.pos)
        target = self._target(motion)
        end_1, end_2 = self._in_plane(target)
        if start_1 is None or start_2 is None or end_1 is None or end_2 is None:
            raise UnknownHere(f"the start point of a compensated move is not known (program {a1} and {a2} "
                               "absolutely after the origin moved)")
        end = {axis: value for axis, value in target.items() if value is not None}
        seg = Segment(kind, {"line": block.line}, end, self.pos.get(normal) or 0.0)
        seg.fields["source"] = id(seg)
        start = (start_1, start_2)
        self.held[id(seg)] = (block, not self.absolute)
        if kind in ("cw", "ccw"):
            offsets = {a: v * self.scale for a, v in (motion.center or {}).items() if isinstance(v, (int, float))}
            if isinstance(motion.radius, Expr) or any(isinstance(v, Expr) for v in (motion.center or {}).values()):
                raise Unresolvable("a computed arc under cutter compensation cannot be resolved")
            radius = None if motion.radius is None else motion.radius * self.scale
            try:
                c = arc_centre(start, (end_1, end_2), (a1, a2), radius, offsets, kind == "cw",
                               self.ctx.arc_end, self.scale != 1.0, self.scale)
            except ArcError as err:
                raise UnknownHere(err.message) from None
            if c is None:
                raise UnknownHere("a zero-length arc under cutter compensation cannot be resolved")
            seg.centre = seg.ccentre = c
            seg.turn = 1 if kind == "ccw" else -1
            self._per_minute(block, kind, target, c)
            if self.trial is not None:
                self.trial.move(seg, start)
            self.cutter.arc(seg, start)
        else:
            self._per_minute(block, kind, target, None)
            if self.trial is not None:
                self.trial.move(seg, start)
            self.cutter.line(seg, start)
        self.pos = target

    def _exit_in_machine(self, block: Block, motion: Motion) -> None:
        """The exit move in machine coordinates (``G53 G0 Z0`` after G40): a plane axis the block does not name
        must still go from the compensated end to the programmed point, so it is written as that point's
        machine position: the programmed point plus the set-up's offset of the active work system (and the
        external one), the function the simulation puts machine positions in its frame by
        (``setup.work_offsets``). Where that is not known (the program set the offset, the set-up gives
        none, a reference return's intermediate point, a tool offset across the plane), a located error names
        what is missing."""
        names = motion.axes
        u, v = self._in_plane(self.pos)
        a1, a2, _ = self.cutter.axes
        missing = [(axis, programmed) for axis, programmed, at in ((a1, u, self.at[0]), (a2, v, self.at[1]))
                   if axis not in names and (programmed is None or abs(programmed - at) > 1e-9)]
        if not missing:
            return
        needs = (f"a move in machine coordinates or a reference return as the first move after compensation is "
                 f"cancelled cannot be resolved: it also takes {' and '.join(a for a, _ in missing)} from the "
                 "compensated point back to the programmed one")
        if motion.mode not in ("rapid", "linear") or self.diameters:
            raise Unresolvable(f"{needs} (program a move in work coordinates after the cancel first)")
        if any(programmed is None for _, programmed in missing):
            raise Unresolvable(f"{needs}, which is not known here (program a move in work coordinates after the "
                               "cancel first)")
        register = self.length_register
        if register is not None and (not isinstance(register, int) or self.table.sideways(register)):
            raise Unresolvable(f"{needs}, in machine coordinates under a tool offset across the plane (program a "
                               "move in work coordinates after the cancel first)")
        if self.shifted:
            raise Unresolvable(f"{needs}, in machine coordinates after a coordinate setting the frame holds "
                               "(program a move in work coordinates after the cancel first)")
        declared = declared_offsets(self.ctx.setup, ("X", "Y", "Z"), False)
        axes = dict(names)
        for axis, programmed in missing:
            offset, why = offset_beyond_frame(axis, self.work_offset, self.programmed_offsets, declared)
            if offset is None or axis in self.programmed_offsets.get(self.work_offset, {}) \
                    or axis in self.programmed_offsets.get(0, {}):
                raise Unresolvable(f"{needs}, which needs the work offset: {why or 'the program sets it'} (or "
                                   "program a move in work coordinates after the cancel first)")
            assert programmed is not None
            axes[axis] = _noise_free((programmed + offset) / self.scale)
        order = sorted(axes, key=lambda a: "XYZABCUVW".find(a) % 10)
        block.sections["Motion"] = Motion(motion.mode, {a: axes[a] for a in order}, None, None)
        block.changed()

    def _per_minute(self, block: Block, kind: str, target: dict[str, float | None],
                    centre: tuple[float, float] | None) -> None:
        """Under G93, the block's feed per minute: F times its programmed length (see the module docstring)."""
        if not self.inverse_time or kind == "rapid":
            return
        feed = block.sections.get("Feed")
        if not isinstance(feed, Feed) or isinstance(feed.value, Expr):
            raise UnknownHere("an inverse-time move without its F under cutter compensation")
        start = {a: v for a in "XYZ" if (v := self.pos.get(a)) is not None}
        end = {a: v for a in "XYZ" if (v := target.get(a)) is not None}
        if len(start) < 3 or len(end) < 3:
            raise UnknownHere("the start point of a compensated inverse-time move is not known (program X, Y and "
                               "Z absolutely first)")
        length = move_length(start, end, self.plane, "linear" if kind == "feed" else kind, centre)
        block.sections["Feed"] = Feed(feed.value * length / self.scale)
        if not self.per_minute or "FeedMode" in block.sections:  # the first of the stretch, or its own G93
            block.sections["FeedMode"] = FeedMode("per_min")
        block.changed()
        self.per_minute = True

    def _back_to_inverse_time(self, block: Block) -> None:
        """The first block after a stretch written per minute brings G93 back (unless it sets a mode)."""
        if self.per_minute and self.inverse_time and self._idle():
            self.per_minute = False
            if "FeedMode" not in block.sections:
                block.sections["FeedMode"] = FeedMode("inverse_time")
                block.changed()

    def _idle(self) -> bool:
        cutter = self.cutter
        return cutter.side is None and not cutter.queue and not cutter.arc_banned

    # -- what the compensation releases --------------------------------------------------------------
    def _release(self, item: Item) -> None:
        if self.trial is not None:
            self.trial.record(item)
        if not isinstance(item, Segment):
            self.out.append(item["block"])
            return
        own = self.held.pop(id(item), None)
        if own is not None:
            block, incremental = own
            self._rewrite(block, item, incremental)
            return
        source = self.held.get(item.fields.get("source", 0))  # an outside corner, before the move that makes it
        corner = Block(item.fields["line"], None, "\n")
        if source is not None:
            feed = source[0].sections.get("Feed")
            if isinstance(feed, Feed):
                corner.sections["Feed"] = feed  # the corner runs at the feed of the move after it
                mode = source[0].sections.get("FeedMode")
                if isinstance(mode, FeedMode) and mode.mode == "per_min":
                    corner.sections["FeedMode"] = mode  # that feed per minute (G93 resolved)
        self._rewrite(corner, item, source is not None and source[1])

    def _rewrite(self, block: Block, seg: Segment, incremental: bool) -> None:
        """The block's move as the compensated one, in absolute program units."""
        sections = block.sections
        scale = self.scale
        a1, a2, normal = self.cutter.axes
        xy = seg.xy if seg.xy is not None else (seg.end[a1], seg.end[a2])
        old = sections.get("Motion")
        by_increments = self.by_increments
        origin = self.at if by_increments else (0.0, 0.0)
        axes: dict[str, float | Expr] = {a1: (xy[0] - origin[0]) / scale, a2: (xy[1] - origin[1]) / scale}
        if isinstance(old, Motion) and normal in old.axes and normal in seg.end:
            axes[normal] = (seg.end[normal] - (self.at_normal if by_increments else 0.0)) / scale
        center: dict[str, float | Expr] | None = None
        if seg.turn != 0 and seg.ccentre is not None:
            cc = seg.ccentre
            off = abs(math.hypot(self.at[0] - cc[0], self.at[1] - cc[1]) - math.hypot(xy[0] - cc[0], xy[1] - cc[1]))
            if off > ARC_OFF_MM and off > ARC_OFF_RATIO * math.hypot(xy[0] - cc[0], xy[1] - cc[1]):
                raise Unresolvable(f"the compensated arc starts {off:.4f} mm off its circle (the source controller "
                                       "joins it to a nearly tangent move without a corner and runs it so; written as "
                                       "an arc, the target refuses it)", self.ctx.at(block))
            center = {a1: (cc[0] - self.at[0]) / scale, a2: (cc[1] - self.at[1]) / scale}
        x = axes.get("X")
        if self.diameters and isinstance(x, float):
            axes["X"] = x * 2.0  # a diameter (an arc's I stays a radius)
        axes = {a: _noise_free(axes[a]) for a in "XYZ" if a in axes}  # written X, Y, Z
        if center is not None:
            center = {a: _noise_free(center[a]) for a in "XYZ" if a in center}
        sections["Motion"] = Motion(_MOTION_MODE[seg.kind], axes, center, None)
        self.at = xy
        self.at_normal = seg.end.get(normal, self.at_normal)
        switched = incremental != by_increments  # the block's own mode is not the one it is written in
        if switched:
            sections["DistanceMode"] = DistanceMode("incremental" if by_increments else "absolute")
        block.changed()
        self.out.append(block)
        if switched:
            back = Block(block.line, None, "\n")
            back.sections = {"DistanceMode": DistanceMode("incremental" if incremental else "absolute")}
            self.out.append(back)
