"""The resolver of cutter compensation (``cutter_compensation``'s steps run it): the blocks of a translation
through the compensation, the settings it follows, a G41/G42's register and radius, the stretches tried under
the target's own rules (``rule_trial``), and a copy's check (``Resolver.check``). One state machine with
``cutter_point`` (where the program stands) and ``cutter_moves`` (the moves in, the compensated blocks out).
"""

from __future__ import annotations

from typing import Callable, Final, Iterator

from mypy_extensions import mypyc_attr

from ..context import Context
from ..interp.control import ASSIGN, CONTROL, LABEL
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..ir.expr import Expr
from ..ir import (Block, CompoundMotion, CutterCompensation, DataSetting, Feed, FeedMode, Motion, Plane, ProgramControl,
                  Section, ToolChange, ToolLengthOffset, ToolSelect, WorkOffset)
from ..ir.keys import only_move
from ..compensation.cutter_radius import CutterRadius, Suspended
from ..compensation.cycle_entry import finishing_entry
from ..compensation.dynamic import DynamicCutterCompensation
from ..compensation.nose import TIPS, mirrored
from ..compensation.rules import CutterRules
from ..ir.state import PLANE_AXES
from .cutter_moves import CompensatedMoves
from .cutter_point import MOVES, Unresolvable, UnknownHere
from .point_after import FOLLOWED
from .rule_trial import STAND_IN_RADIUS, STRETCH_LIMIT, RuleTrial
from .lower import BlockStep, run_blocks, still_moving
from .move_words import moving

_MODAL: Final = frozenset(("Units", "DistanceMode", "Plane", "DataSetting", "WorkOffset", "ToolSelect",
                           "ToolChange", "ToolLengthOffset", "FeedMode"))
"""Settings the resolver keeps while no compensation is on (a block with none of them, and no G41/G42, is
only a move to track, or passes untouched)."""
_NOT_PLAIN: Final = _MODAL | {"CutterCompensation", "DynamicCutterCompensation", "CoordinateSet"}
"""A block with one of these goes the general way even while no compensation is on (``Resolver.block``)."""
_NOT_TRACKED: Final = FOLLOWED
"""A block with one of these is not a plain move to note (``ProgrammedPoint._track`` says where it leaves the tool,
``point_after``: a cycle kept native, a machine move, a control statement...)."""
_NOT_NOTED: Final = _NOT_PLAIN | _NOT_TRACKED
"""A block with none of these is at most a move to note (one set look-up a key for the common block)."""
_UNCHECKED: Final = (Unresolvable, UnknownHere)
_STOPS_CHECK: Final = frozenset((CONTROL, ASSIGN, LABEL))
"""A block with one of these leaves the program's text order (a call, a jump, a computation): what follows is not
what runs next, so a copy's check stops there."""
_CHECK_GENERAL: Final = _NOT_NOTED | _STOPS_CHECK


def _full_circle(motion: Motion) -> bool:
    """An arc with its centre and no end point (``G3 I-20``): a full turn back to where it starts."""
    return motion.mode in ("cw", "ccw") and bool(motion.center)


def _stop_and_cancel(cutter: CutterRadius) -> None:
    cutter.stop()
    cutter.cancel()


def keep_native(resolver: "Resolver", cc: CutterCompensation) -> bool:
    """Every G41/G42 by register stays for the target to write (a target whose rules cut the source's path)."""
    return True


@mypyc_attr(allow_interpreted_subclasses=True)
class Resolver(CompensatedMoves):
    """The compensation state of one translation, and the blocks it has released."""

    def __init__(self, ctx: Context, rules: CutterRules, keeps: Keeps | None = None, diameters: bool = False,
                 trial: CutterRules | None = None, checking: bool = False) -> None:
        super().__init__(ctx, rules, diameters, checking)
        self.keeps = keeps
        """Whether a G41/G42 by register stays for the target to write (with its G40); None: none does."""
        self.trial_rules = trial
        """The target's own rules, when modelled and not the source's: each stretch is tried under both."""

    def run(self, blocks: Iterator[Block]) -> Iterator[Block]:
        """The blocks with their compensation resolved (``resolution``, alone over the stream)."""
        return run_blocks(blocks, [self.resolution()])

    def resolution(self) -> BlockStep:
        """This resolver as a lowering step's run (``Resolution``)."""
        return Resolution(self)

    def check(self, blocks: Iterator[Block]) -> Iterator[Block]:
        """The blocks unchanged, checked (``checker``, alone over the stream)."""
        return run_blocks(blocks, [self.checker()])

    def checker(self) -> BlockStep:
        """A copy within one dialect keeps its compensation native: the blocks pass unchanged, but the path is
        computed from a copy of each block as for a resolution (the same geometry the simulation runs), so
        what the simulation refuses (a move turning back on itself, an inside arc smaller than the radius, a
        tool change under compensation...) is refused here too, at its line. Where the resolver cannot follow
        the program (``Unresolvable``, ``UnknownHere``, a radius the set-up lacks, a call or a jump), the check
        stops without a word: the copy is the program, and verify says what it cannot simulate."""
        return Checking(self)

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
        own = "CutterCompensation" in sections
        """The block turns compensation on or off itself (a Haas G70's, whose profile holds its G42/G40)."""
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
            self.cutter.start(dynamic.mode, dynamic.radius(self.modes.scale), self.plane,  # negative: the other side
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
            self._compound(block, compound, own)  # a finishing cycle's profile, compensated move by move
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

    def _compound(self, block: Block, compound: CompoundMotion, own: bool) -> None:
        """A lathe finishing cycle the source compensates as its profile (``CutterRules.profile_cycles``):
        the block without its moves waits as an event, then each move goes through the compensation as a
        block of its own (at the feed the cycle gives it), written as the compensated move. Under the mode
        set before the cycle (not ``own``) the offset is temporarily cancelled on the way to the start point
        and on the return to it, as the simulation runs it (``compensation.cycle_entry``)."""
        del block.sections["CompoundMotion"]
        block.changed()
        if block.sections:
            self.cutter.event({"block": block})
            self._mirror(lambda cutter: cutter.event({}))
        items = compound.items
        held: Suspended | None = None
        back: Section | None = None
        if not own:
            held, back = finishing_entry(self.cutter, items)

            def enter(cutter: CutterRadius) -> None:
                finishing_entry(cutter, items)  # the target's rules: the same entry, or the trial's refusal
            self._mirror(enter)
        feed: Feed | None = None
        for item in items:
            if item is back:
                self.cutter.cancel()
                self._mirror(lambda cutter: cutter.cancel())
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
        if held is not None:
            self.cutter.resume(held)

    def _modal(self, sections: dict[str, Section]) -> None:
        if "CoordinateSet" in sections:
            self.shifted = True
        if self.modes.follow(sections):
            self.cutter.sweep_slack = 0.001 if self.modes.inch else 0.0254
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
                self.table.write(setting, self.modes.scale)
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


Keeps = Callable[[Resolver, CutterCompensation], bool]
"""Whether the target writes a G41/G42 itself (given the resolver, for the tool data it tracks). (After the class:
a class given by its name in an alias is a ``ForwardRef``, compiled with the interpreter's compiler at import.)"""


@mypyc_attr(allow_interpreted_subclasses=True)
class Resolution(BlockStep):
    """A ``Resolver`` taking the blocks one at a time: every move is its business (an idle resolver notes
    it for a later entry move); a block it holds comes out with the blocks its compensation releases."""

    def __init__(self, resolver: Resolver) -> None:
        super().__init__()
        self.resolver = resolver
        self.idle = True
        self.radii = not resolver.diameters
        """X is a radius in the blocks: the common block's move is tracked here (else by ``_track``)."""
        self.last: Block | None = None
        """The program's last block the resolution took: where an error found at its end (``finish``) is located
        (a straight move the loop noted past it, ``follow``, leaves nothing queued that could fail there)."""
        self.follow()

    def follow(self) -> None:
        """``point`` (``BlockStep.point``) as the run stands: while an idle resolver only keeps a plain move
        (absolute, X a radius, no feed to write back in inverse time), a straight move of X, Y and Z numbers is noted
        by the loop (``ProgrammedPoint.passing``) instead of taken (~900 instructions a block compiled through
        ``take_move``: every grbl and grblHAL translation, callgrind)."""
        r = self.resolver
        self.point = r.passing if self.idle and self.radii and r.modes.absolute and not r.per_minute else None

    def take(self, block: Block) -> list[Block] | None:
        return self._take(block, False)

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block the loop found only a move (``only_move``, not asked again: ~270 instructions a
        block compiled). An idle resolver only notes or tracks the move, unless it writes the feed back in
        inverse time (``still_moving`` then, and on every other way)."""
        if self.idle and not self.resolver.per_minute:
            return self._take(block, True)
        return still_moving(block, self._take(block, True))

    def _take(self, block: Block, moved: bool) -> list[Block] | None:
        """``take``; ``moved``: the block is only a move (``only_move``), known to the caller."""
        r = self.resolver
        self.last = block
        sections = block.sections
        plain = self.idle
        odd = False
        if plain and not moved and not only_move(sections):  # one look at the keys: none asks for the general way
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
            if isinstance(motion, Motion) and r.modes.absolute and moving(motion.mode) and self.radii \
                    and not (odd and "MachineCoordinates" in sections):
                r._note(motion)
            elif motion is not None or odd:
                r._settle()
                r._track(block)
            if r.per_minute:
                r._back_to_inverse_time(block)
                self.follow()
            return None
        r._settle()
        if not r.failed and r.trial_rules is not None:
            r._try(block)
        if not r.failed:
            try:
                r.block(block)
            except PostprocError as err:
                located = err.located(r.ctx.at(block)) if err.location is None else err
                r.failed = True  # the queue no longer matches the program: nothing more is resolved
                if r.trial is not None and isinstance(err, UnsupportedError):
                    r._untried(located)
                else:
                    r.ctx.diagnostics.error(located)
                    r.out.append(block)
        else:
            r.out.append(block)
        idle = self.idle = r.failed or r._idle()
        made: list[Block] = []
        trial = r.trial
        if trial is not None:
            trial.resolved.extend(r.out)
            r.out.clear()
            if idle or len(trial.stretch) > STRETCH_LIMIT:
                made.extend(r._tried(idle))
        if r.out:
            made.extend(r.out)
            r.out.clear()
        self.follow()
        return made

    def finish(self) -> list[Block]:
        r = self.resolver
        if not r.failed:
            try:
                r.cutter.finish()
            except PostprocError as err:
                last = self.last
                if err.location is None and last is not None:
                    err = err.located(r.ctx.at(last))
                if r.trial is not None and isinstance(err, UnsupportedError):
                    r._untried(err)
                else:
                    r.ctx.diagnostics.error(err)
        made: list[Block] = []
        trial = r.trial
        if trial is not None:
            trial.resolved.extend(r.out)
            r.out.clear()
            made.extend(r._tried(True))
        made.extend(r.out)
        return made


@mypyc_attr(allow_interpreted_subclasses=True)
class Checking(BlockStep):
    """A ``Resolver`` checking a copy within one dialect (``Resolver.checker``), the blocks one at a time;
    once it stops, nothing more is its business."""

    def __init__(self, resolver: Resolver) -> None:
        super().__init__()
        self.resolver = resolver
        self.idle = True
        self.stopped = False

    def take(self, block: Block) -> list[Block] | None:
        if self.stopped:
            return None
        r = self.resolver
        sections = block.sections
        if self.idle:
            general = False
            for key in sections:
                if key in _CHECK_GENERAL:
                    general = True
                    break
            if not general:
                motion = sections.get("Motion")
                if isinstance(motion, Motion) and r.modes.absolute and moving(motion.mode):
                    r._note(motion)
                elif motion is not None:
                    r._settle()
                    r._track(block)
                return None
        if not _STOPS_CHECK.isdisjoint(sections):
            self.stopped = True
            self.moves = False
            return None
        r._settle()
        shadow = Block(block.line, block.text, block.eol, block.words)
        shadow.sections = dict(sections)  # the resolver rewrites its own dictionary, never a section
        try:
            r.block(shadow)
        except PostprocError as err:
            if not isinstance(err, _UNCHECKED):
                r.ctx.diagnostics.error(err.located(r.ctx.at(block)) if err.location is None else err)
            self.stopped = True
            self.moves = False
            return None
        r.out.clear()
        self.idle = r._idle()
        return None

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block the loop found only a plain move (``plain_move``): neither of its keys (``Motion``,
        ``Sequence``) is one of ``_CHECK_GENERAL``, so an idle check only keeps an absolute move (``_note``: read
        only if a G41/G42 comes), without ``take``'s loop over the keys (~300 instructions a block compiled: every
        block of a copy); the rest goes through ``take``."""
        if self.idle and not self.stopped:
            motion = block.sections["Motion"]
            r = self.resolver
            if isinstance(motion, Motion) and r.modes.absolute and moving(motion.mode):
                r._note(motion)
                return None
        return still_moving(block, self.take(block))

    def finish(self) -> list[Block]:
        if not self.stopped:
            r = self.resolver
            try:
                r.cutter.finish()
            except PostprocError as err:
                if not isinstance(err, _UNCHECKED):
                    r.ctx.diagnostics.error(err)
        return []
