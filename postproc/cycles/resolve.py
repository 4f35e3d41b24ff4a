"""CannedCycleResolveSyntax: hole cycle words + modal state -> a resolved ``CannedCycle`` and its motion.

Runs after the dialect's block syntax (which gives a cycle block a ``CycleCall`` and leaves the cycle
words in ``block.values``, and a block repeating an active cycle a ``Motion(None)``) and before
``ModalStateSyntax``. It applies DIALECTS.md §2.1's common rules: the initial level, G98/G99, G90/G91
meanings of R and Z, modal cycle data, repetition, cancel, K/L repeats, the three planes, dwell P,
peck Q and shift Q, and refuses what the controller refuses with a located error. Then it has the
cycle's family syntax expand it and moves the tracked position to where the tool ends.

The ``semantics`` attribute names the controller family's rules, registered by a family base
(``postproc.cycles.semantics``; every pipeline says which, the core has no default family). Which letter carries which cycle word (the
hole bottom, the R level, Q, P, the repeat count) and how a cycle is named in messages comes from the
reading dialect (``ctx.cycle_words``, a ``CycleWords``), so another dialect's letters reuse this logic.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any, Final

from mypy_extensions import mypyc_attr

from postproc.cycle_words import CycleWords
from postproc.errors import ConfigError, Location, PostprocError, ProgramError, UnsupportedError
from postproc.ir.expr import Expr
from postproc.ir import Block, CompoundMotion, Motion, NativeCode, Section
from postproc.setup.machine_setup import CycleSettings
from postproc.ir.source_map import ExecutedBlock
from postproc.ir.state import MM_PER_INCH, PLANE_AXES, CycleState, ModalState
from postproc.context import Context
from postproc.syntaxes.syntax import Syntax
from postproc.xmlio import DEFAULT, lxml_etree

from .back_boring import BackBoringExpansion
from .boring import BoringExpansion
from .drilling import DrillingExpansion
from .expansion import CycleExpansion, TooManyMoves
from .fine_boring import FineBoringExpansion
from .manual_boring import ManualBoringExpansion
from .peck_drilling import PeckDrillingExpansion
from .rigid_tap import RIGID_KEY, end_rigid_mode, note_rigid_mode, rigid_pitch
from .section import WORD_ORDER, CannedCycle
from .semantics import DWELLING, PECK, SHIFT, TAP, Semantics, semantics_named, semantics_names
from .tapping import TappingExpansion

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

EXPANSIONS: Final[tuple[type[CycleExpansion], ...]] = (
    DrillingExpansion, PeckDrillingExpansion, TappingExpansion, BoringExpansion, FineBoringExpansion, BackBoringExpansion,
    ManualBoringExpansion,
)
"""The built-in family expansions, one per cycle family."""

GROUP_01: Final = frozenset(("rapid", "linear", "cw", "ccw"))
"""Motion modes that cancel a canned cycle."""
AXIS_LETTERS: Final = frozenset("XYZABCUVW")
STATE_KEY: Final = "CannedCycleResolveSyntax"
"""``ctx.state.extra`` key: the plane the active cycle was commanded in."""
DWELL_KEY: Final = "CannedCycleResolveSyntax.P"
_NATIVE_KEY: Final = "CannedCycleResolveSyntax.native"
"""Set while the active cycle is one with computed words, kept verbatim."""
"""``ctx.state.extra`` key: the last cycle P, which RS274 tapping falls back on even after G80."""
ACTIVE_KEY: Final = "CannedCycleResolveSyntax.active"
"""``ctx.state.extra`` key: (the last resolved ``CannedCycle``, its expansion) while the cycle is active,
for a hole pattern that repeats it (``active_cycle``)."""
WORD_RANK: Final = {letter: rank for rank, letter in enumerate(WORD_ORDER)}
"""Cycle word letter -> its place in ``WORD_ORDER`` (a block's words are kept in that order)."""
_SHIFT_AXIS: Final = {"+X": (1.0, 0), "-X": (-1.0, 0), "+Y": (1.0, 1), "-Y": (-1.0, 1)}
"""Set-up shift direction -> sign and plane axis (first/second), Fanuc's parameter table for G17-G19."""


@mypyc_attr(allow_interpreted_subclasses=True)
class CannedCycleResolveSyntax(Syntax):
    """Resolves hole cycles per ``semantics``; child elements replace the built-in family expansions."""

    XNAME = "CannedCycleResolveSyntax"
    __slots__ = ("semantics", "expansions", "_rules", "_by_kind", "_words_of")

    def __init__(self, semantics: str, expansions: list[CycleExpansion] | None = None) -> None:
        rules = semantics_named(semantics)
        if rules is None:
            raise ValueError(f"unknown cycle semantics {semantics!r} (use {' or '.join(semantics_names())})")
        self.semantics = semantics
        self.expansions = list(expansions or [])
        """Expansions given in XML, overriding the built-in one of their kinds."""
        self._rules: Semantics = rules
        self._by_kind: dict[str, CycleExpansion] = {}
        self._words_of: tuple[CycleWords | None, str, frozenset[str], frozenset[str], tuple[str, ...]] = (
            None, "", frozenset(), frozenset(), ())
        """(cycle words, repeat address) -> their letters (``_letters``): the last run's, worked out again only
        when a run reads other cycle words."""
        for expansion in [cls() for cls in EXPANSIONS] + self.expansions:
            for kind in expansion.KINDS:
                self._by_kind[kind] = expansion

    @classmethod
    def from_xml(cls, el: etree._Element) -> "CannedCycleResolveSyntax":
        unknown = set(el.attrib) - {"semantics"}
        if unknown:
            raise ValueError(f"unknown attribute(s) {', '.join(sorted(unknown))}")
        semantics = el.get("semantics")
        if semantics is None:
            raise ValueError(f"needs attribute 'semantics' ({' or '.join(semantics_names())}: how the controller moves "
                             "through a cycle)")
        expansions = []
        for child in DEFAULT.children(el):
            if not isinstance(child, CycleExpansion):
                raise ValueError(f"<{type(child).XNAME}> is not a cycle expansion")
            expansions.append(child)
        return cls(semantics, expansions)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        el.set("semantics", self.semantics)
        for expansion in self.expansions:
            el.append(expansion.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.semantics, tuple(self.expansions))

    def __repr__(self) -> str:
        return f"CannedCycleResolveSyntax({self.semantics!r})"

    # -- per block ---------------------------------------------------------------------------------
    def build(self, block: Block, ctx: Context) -> None:
        state = ctx.state
        sections = block.sections
        if state.cycle is None and "CycleCall" not in sections:
            extra = state.extra  # (most runs hold no extra state: no look-up then)
            if "MachineFunction" in sections or len(extra) != 0 and RIGID_KEY in extra:
                try:  # a rigid tapping code, or what ends its mode (rare)
                    note_rigid_mode(sections, state)
                except ProgramError as err:
                    raise err.located(ctx.at(block)) from None
            return  # the common block: no cycle anywhere (kept first and cheap, it runs on every block)
        if "MachineFunction" in sections:
            note_rigid_mode(sections, state)
        call = sections.get("CycleCall")
        if call is not None:
            if block.values and _computed(block):
                self._native(block, ctx, call.kind)  # type: ignore[attr-defined]
                return
            state.extra.pop(_NATIVE_KEY, None)
            self._resolve_or_drop(block, ctx, call.kind, True)  # type: ignore[attr-defined]
            return
        if state.cycle is None:
            return
        motion = sections.get("Motion")
        if isinstance(motion, Motion):  # (typed: its mode read natively, not by name: ~300 instructions a hole)
            mode = motion.mode
        else:
            mode = None if motion is None else getattr(motion, "mode")
        if "CycleCancel" in sections or (motion is not None and mode in GROUP_01):
            _cancel(state)
            state.extra.pop(_NATIVE_KEY, None)
            return
        if motion is not None and mode is not None:
            return  # a reference return (group 00) leaves the cycle in force
        if motion is None and _any_key(sections, _NOT_CYCLE_DATA):
            return  # G04 (its P is the dwell's), a G10, a verbatim code such as M98 P..: not cycle data
        lane = ctx.hole_lane  # the run's next-hole lane, where it applies (``postproc.fast.holes``): it takes
        if lane is not None and _NATIVE_KEY not in state.extra and lane.repeat(block, ctx):  # only words of
            return  # the plane's axes, and declines a computed one (the checks below hold for what it takes)
        if _any_key(block.values, self._letters(ctx)[0]):
            if _NATIVE_KEY in state.extra or _computed(block):  # a hole known only when the program runs
                self._native(block, ctx, state.cycle.kind)
                return
            self._resolve_or_drop(block, ctx, state.cycle.kind, False)
            if lane is not None:
                lane.resolved(block, ctx)

    def _native(self, block: Block, ctx: Context, kind: str) -> None:
        """A cycle with computed words (a program kept symbolically): its holes are known only when the
        program runs, so the block travels verbatim, and so do the blocks repeating it, until the cycle
        is cancelled. Executing the program evaluates the words first and never comes here."""
        for key in ("CycleCall", "Motion", "Feed", "ReturnLevel"):
            block.sections.pop(key, None)
        block.add(NativeCode(ctx.dialect, "a canned cycle with computed words", block.text or ""))
        position = ctx.state.position
        for axis in position:
            position[axis] = None  # the hole is known only when the program runs, and so is the tool
        ctx.state.cycle = CycleState(kind)
        ctx.state.extra[_NATIVE_KEY] = kind
        ctx.state.extra.pop(ACTIVE_KEY, None)

    def _resolve_or_drop(self, block: Block, ctx: Context, kind: str, call: bool) -> None:
        """Resolve; on an error the block's cycle sections go too, so later steps do not report the
        same block again (the error itself is reported by the pipeline)."""
        try:
            self._resolve(block, ctx, kind, call)
        except PostprocError:
            drop_cycle_sections(block)
            raise

    def _letters(self, ctx: Context) -> tuple[frozenset[str], frozenset[str], tuple[str, ...]]:
        """The addresses that carry cycle data (axes, the level, peck/shift, dwell and the repeat count),
        those of them a cycle record keeps (in ``WORD_ORDER``), and the repeat-count letters in order of
        preference: the same for every block of a run."""
        cw = cycle_words(ctx)
        address = ctx.setup.input.repeat_address
        known = self._words_of
        if known[0] is not cw or known[1] != address:
            repeat = cw.repeat_letters(address)
            letters = frozenset("XYZABCUVW" + cw.level + cw.peck + cw.shift + cw.dwell + "".join(cw.bottom.values())
                                + "".join(repeat))
            known = self._words_of = (cw, address, letters, letters.intersection(WORD_ORDER), repeat)
        return known[2], known[3], known[4]

    def _resolve(self, block: Block, ctx: Context, kind: str, call: bool) -> None:
        rules = self._rules
        sections = block.sections
        state = ctx.state
        cw = cycle_words(ctx)
        code = cw.name(kind)
        fail = Failer(ctx, block, code, call)
        if kind in rules.unsupported:
            raise UnsupportedError(f"{code} has no {kind.replace('_', ' ')} meaning under {rules.name} "
                                   "cycle semantics", fail.at_code())
        units = sections.get("Units")
        if units is not None:
            state.set_units(units.system)  # type: ignore[attr-defined]
        plane = _modal(sections, "Plane", "plane", state.plane)
        _, kept, repeat_letters = self._letters(ctx)
        # numbers only: a cycle with computed words went to _native
        values = block.values
        words: dict[str, float | int] = {
            k: values[k] for k in sorted(kept.intersection(values), key=WORD_RANK.__getitem__)}  # type: ignore[misc]
        fail.words = words
        first, second, normal = PLANE_AXES[plane]
        for letter in words:
            if letter in AXIS_LETTERS and letter not in (first, second, normal):
                raise fail(f"{code} cannot move axis {letter}: only {first}, {second} and {normal} "
                           "take part in a hole cycle", letter)
        active = state.cycle
        if active is not None and state.extra.get(STATE_KEY, plane) != plane:
            raise fail(f"the plane cannot change while {code} is active (cancel the cycle first)")
        same = active is not None and (rules.carry_over or active.kind == kind)
        modal = dict(active.words) if same and active is not None else {}
        depth = cw.bottom_letter(plane, normal)
        modal_letters = (cw.level, cw.peck, cw.shift, cw.dwell, depth)  # in force until the cycle is cancelled
        modal.update({k: v for k, v in words.items() if k in modal_letters})
        if cw.dwell in words:
            state.extra[DWELL_KEY] = words[cw.dwell]
        elif rules.sticky_tap_dwell and kind in TAP and DWELL_KEY in state.extra:
            modal[cw.dwell] = state.extra[DWELL_KEY]
        holes = self._holes(ctx, words, call, plane, repeat_letters, fail)
        read = kind  # the dialect's cycle, kept in force; ``kind`` from here is what this block does
        undwelled = cw.undwelled.get(kind)
        if undwelled is not None and not modal.get(cw.dwell):
            kind = undwelled
        feed = _modal(sections, "Feed", "value", state.feed)
        return_level = _modal(sections, "ReturnLevel", "level", state.return_level)
        spindle = _modal(sections, "SpindleControl", "direction", state.spindle)
        self._check(kind, code, modal, cw, depth, feed, return_level, spindle, call, fail)
        pitch = rigid_pitch(sections, state, kind, code, feed, _modal(sections, "SpindleSpeed", "rpm", state.spindle_rpm),
                            _modal(sections, "FeedMode", "mode", state.feed_mode),
                            cw.peck if cw.peck in modal else None, fail)

        incremental = _modal(sections, "DistanceMode", "mode", state.distance) == "incremental"
        initial, r, bottom, top = self._levels(ctx, kind, code, modal, normal, cw.level, depth, incremental, fail)
        here = {k: v for k, v in state.position.items() if k in "XYZ" and v is not None}
        position, step = _positions(code, words, here, plane, incremental, holes, fail)
        if holes and rules.rise_to_r and r > initial and (first not in here or second not in here):
            missing = first if first not in here else second
            raise fail(f"{code} rises to R where the tool stands, but its {missing} position is unknown")
        q = modal.get(cw.peck if kind in PECK else cw.shift)
        cycle = CannedCycle(
            kind, call=call, semantics=rules.name, return_level=return_level, plane=plane,
            initial=initial, r=r, bottom=bottom, top=top, q=q if kind in PECK else None,
            clearance=_clearance(ctx, kind, state.units), dwell=_seconds(modal.get(cw.dwell), rules, cw),
            orient=ctx.setup.cycles.orient_angle if kind in SHIFT else None, feed=feed, repeat=holes,
            spindle=spindle, motion=state.motion, start=here, position=position, step=step,
            shift=_shift(ctx, kind, q, first, second), words=words, pitch=pitch,
        )
        expansion, limit = self._by_kind[kind], ctx.setup.limits.moves_per_block
        repeat = next((k for k in repeat_letters if k in words), None)

        self.install(block, ctx, cycle, LazyExpansion(expansion, cycle, limit, fail, code, cw.peck, repeat, ctx))
        if active is not None:
            active.kind, active.words = read, modal  # the initial level stays while a cycle is active
        else:
            state.cycle = CycleState(read, modal, initial)
        state.extra[STATE_KEY] = plane

    def expansion(self, kind: str) -> CycleExpansion:
        """The expansion that makes ``kind``'s motion (the XML's, else the built-in one)."""
        return self._by_kind[kind]

    def install(self, block: Block, ctx: Context, cycle: CannedCycle, lazy: "LazyExpansion",
                 end: dict[str, float] | None = None) -> None:
        """Give the block its cycle record and its motion (made when read), and move the tracked tool to
        where the block leaves it (``end``, found by the expansion when not given)."""
        state = ctx.state
        expansion = lazy.expansion
        if end is None:
            try:
                end = expansion.end(cycle, lazy.limit)
            except TooManyMoves as err:
                raise lazy.too_many(err) from None
        sections = block.sections
        block.add(cycle)
        block.add(CompoundMotion.lazy(cycle.kind, lazy))  # expanded only for a target without the cycle
        state.extra[ACTIVE_KEY] = (cycle, expansion)
        if "CycleCall" in sections:
            del sections["CycleCall"]
        motion = sections.get("Motion")
        if motion is not None and motion.mode is None:  # type: ignore[attr-defined]
            del sections["Motion"]
        position = state.position
        for axis, value in end.items():
            position[axis] = value

    def _holes(self, ctx: Context, words: dict[str, Any], call: bool, plane: str, repeat_letters: tuple[str, ...],
               fail: "Failer") -> int:
        """How many holes the block makes: K/L (once without), none without hole position data."""
        rules = self._rules
        repeat, letter = 1, None
        for candidate in repeat_letters:
            if candidate in words:
                repeat, letter = int(words[candidate]), candidate
                break
        if letter is not None and repeat < 0:
            raise fail(f"repeat count {letter} cannot be negative", letter)
        most = cycle_words(ctx).max_repeat
        if letter is not None and most is not None and repeat > most:
            raise fail(f"repeat count {letter}{repeat} is more than the controller accepts ({letter}0-{letter}{most})",
                       letter)
        if letter is not None and repeat == 0 and rules.zero_repeat_error:
            raise fail(f"repeat count {letter} cannot be 0", letter)
        first, second, normal = PLANE_AXES[plane]
        position_words = (first, second, normal) if rules.any_axis_repeats else (first, second)
        return repeat if call or any(k in words for k in position_words) else 0

    def _check(self, kind: str, code: str, modal: dict[str, Any], cw: CycleWords, depth: str,
               feed: float | None, return_level: str, spindle: str, call: bool, fail: "Failer") -> None:
        """The words the cycle needs, and the combinations the controller refuses."""
        rules = self._rules
        if depth not in modal:
            raise fail(f"{code} needs a hole bottom {depth}")
        if cw.level not in modal:
            raise fail(f"{code} needs an R level {cw.level}")
        dwell = cw.dwell
        p = modal.get(dwell)
        if rules.dwell_required and kind in DWELLING and p is None:
            raise fail(f"{code} needs a dwell time {dwell}")
        if p is not None and p < 0:
            raise fail(f"{code} dwell time {dwell} cannot be negative", dwell)
        if kind in PECK:
            peck = cw.peck
            q = modal.get(peck)
            if q is None:
                raise fail(f"{code} needs a peck depth {peck}")
            if q <= 0:
                raise fail(f"{code} peck depth {peck} must be positive", peck)
        if kind in SHIFT:
            shift = cw.shift
            q = modal.get(shift)
            if q is None and kind == "back_bore":
                raise fail(f"{code} needs a shift {shift}")
            if q is not None and q < 0:
                raise fail(f"{code} shift {shift} cannot be negative: the set-up gives its direction", shift)
        if feed is None or feed <= 0:
            raise fail(f"{code} needs a feed rate F")
        if kind == "back_bore" and return_level == "r":
            if call:
                raise fail(f"{code} cannot be used with {cw.return_to_r}")
            where = fail.at(_code_column(Block(fail.line, fail.text), cw.return_to_r))
            raise ProgramError(f"{code} cannot be used with {cw.return_to_r}", where)
        if rules.spindle_checked and kind in TAP and spindle != ("cw" if kind == "tap" else "ccw"):
            direction = "cw" if kind == "tap" else "ccw"
            turning = "clockwise" if direction == "cw" else "counterclockwise"
            if direction in cw.spindle:
                turning += f" ({cw.spindle[direction]})"
            raise fail(f"{code} needs the spindle turning {turning}")
        if rules.spindle_checked and kind in ("bore_stop", "bore_manual") and spindle not in ("cw", "ccw"):
            raise fail(f"{code} needs the spindle turning")

    def _levels(self, ctx: Context, kind: str, code: str, modal: dict[str, Any], normal: str, level: str,
                depth: str, incremental: bool, fail: "Failer") -> tuple[float, float, float, float | None]:
        """(initial level, R level, bottom, top of a counterbore) on the drilling axis. The initial
        level is the one the active cycle started at; G91 R is measured from it."""
        start = ctx.state.position.get(normal)
        active = ctx.state.cycle
        initial = active.initial if active is not None else start
        if initial is None:
            raise fail(f"the initial level of {code} is unknown: {normal} was never positioned absolutely")
        if start is None and (active is None or self._rules.position_at_clear):
            # Fanuc positions each hole at the tool's current level, whatever it is, then goes to R: a cycle
            # in force needs no number for it (a G28 Z in cycle mode, group 00, leaves the cycle in force and
            # the tool at its reference point). RS274 chooses its positioning level by where the tool stands.
            raise fail(f"the {normal} position before {code} is unknown: program {normal} absolutely first")
        r, bottom = float(modal[level]), float(modal[depth])
        if incremental:
            r += initial
            bottom += r
        if kind != "back_bore":
            if bottom > r:
                raise fail(f"{code} hole bottom {depth} is above the R level", depth)
            return initial, r, bottom, None
        if ctx.setup.cycles.back_boring_levels == "seed":
            if bottom >= r:
                raise fail(f"{code} {depth} must lie below {level} (back-boring levels 'seed': {depth} is the "
                           f"bottom, {level} the top)", depth)
            return initial, r, bottom, r
        if r >= bottom:
            raise fail(f"{code} {level} must lie below {depth} (back-boring levels 'manual': {level} is the "
                       f"bottom, {depth} the top)", level)
        return initial, r, r, bottom


@mypyc_attr(allow_interpreted_subclasses=True)
class LazyExpansion:
    """A cycle block's moves, made when a step asks for them (``CompoundMotion.lazy``). A class and not a
    closure: it holds what the expansion needs and nothing of the block that holds it (a compiled closure
    keeps every local of its function, the block too: a reference cycle per cycle block, which only the
    collector, paused while a program streams, would free)."""

    __slots__ = ("expansion", "cycle", "limit", "fail", "code", "peck", "repeat", "ctx")

    def __init__(self, expansion: CycleExpansion, cycle: CannedCycle, limit: int, fail: Failer, code: str,
                 peck: str, repeat: str | None, ctx: Context) -> None:
        self.expansion, self.cycle, self.limit, self.fail = expansion, cycle, limit, fail
        self.code, self.peck, self.repeat, self.ctx = code, peck, repeat, ctx

    def __call__(self) -> list[Section]:
        try:
            items = self.expansion.items(self.cycle, self.limit)
        except TooManyMoves as err:
            raise self.too_many(err) from None
        self.ctx.moves_made += len(items)
        return items

    def too_many(self, err: TooManyMoves) -> PostprocError:
        """The bound on moves per block, located at the word that makes the moves (pecks or repeats)."""
        return self.fail(f"{self.code}: {err.message}", self.peck if err.role == "peck" else self.repeat)


def drop_cycle_sections(block: Block) -> None:
    """A block whose cycle is refused loses its cycle sections, so later steps do not report it again (the
    error itself is reported by the pipeline)."""
    block.sections.pop("CycleCall", None)
    motion = block.sections.get("Motion")
    if motion is not None and motion.mode is None:  # type: ignore[attr-defined]
        del block.sections["Motion"]


def _any_key(mapping: dict[str, Any], keys: frozenset[str]) -> bool:
    """Whether ``mapping`` has a key of ``keys``: compiled, a loop over its few keys costs a fraction of
    ``keys.isdisjoint(mapping)``, a bound-method call that builds an iterator (once per hole)."""
    for key in mapping:
        if key in keys:
            return True
    return False


@mypyc_attr(allow_interpreted_subclasses=True)
class Failer:
    """Makes a located ProgramError: at the named word when the block has it, else at the cycle's G word.
    Where that is gets worked out only when an error is made (a ``Location`` per hole cost the cycles
    benchmark ~16k instructions a hole)."""

    __slots__ = ("ctx", "line", "origin", "text", "code", "call", "words")

    def __init__(self, ctx: Context, block: Block, code: str, call: bool) -> None:
        self.ctx, self.code, self.call = ctx, code, call
        self.line = block.line
        self.origin = block.origin if type(block) is not Block and isinstance(block, ExecutedBlock) else None
        """Where the block is (its file and call stack): not the block itself, which holds the expansion
        that holds this (a reference cycle per cycle block, freed only by the paused collector). (A block read
        from the text is a ``Block`` itself, told natively: an ``ExecutedBlock`` test alone is a look-up of the
        interpreted class and a generic test, ~400 instructions a hole compiled.)"""
        self.text = block.text
        """The text as read: an expansion made later (``CompoundMotion.lazy``) still points at its word
        after a lowering step rewrote the block."""
        self.words: dict[str, Any] = {}
        """The cycle's words (set once read): an error about one of them points at it."""

    def at(self, col: int) -> Location:
        """What ``Context.at`` says of the block."""
        origin = self.origin
        if origin is None:
            return Location(self.ctx.file, self.line, col)
        return Location(origin.file, self.line, col, origin.note())

    def at_code(self) -> Location:
        """Where the cycle's code is (its G word when the block calls the cycle, else the block)."""
        return self.at(_code_column(Block(self.line, self.text), self.code) if self.call else 1)

    def __call__(self, message: str, letter: str | None = None) -> ProgramError:
        if letter is not None and letter in self.words:
            return ProgramError(message, self.at(self.ctx.column_of(Block(self.line, self.text), letter)))
        return ProgramError(message, self.at_code())


def _positions(code: str, words: dict[str, Any], here: dict[str, float], plane: str, incremental: bool,
               holes: int, fail: Failer) -> tuple[dict[str, float], dict[str, float]]:
    """The first hole in the plane and the step to the next (G91: increments from where the tool is)."""
    position: dict[str, float] = {}
    step: dict[str, float] = {}
    for axis in PLANE_AXES[plane][:2]:
        now = here.get(axis)
        if incremental:
            step[axis] = float(words.get(axis, 0.0))
            if now is not None:
                position[axis] = now + step[axis]
        elif axis in words:
            position[axis] = float(words[axis])
        elif now is not None:
            position[axis] = now
        if holes and axis not in position:
            raise fail(f"the hole position of {code} is unknown: {axis} was never positioned absolutely")
    return position, step


def cycle_words(ctx: Context) -> CycleWords:
    """The reading dialect's cycle words; a dialect with canned cycles must declare them."""
    cw = ctx.cycle_words
    if cw is None:
        raise ConfigError(f"the {ctx.dialect} dialect reads canned cycles but declares no cycle words "
                          "(Dialect.CYCLE_WORDS)")
    return cw


def _modal(sections: dict[str, Any], key: str, attr: str, default: Any) -> Any:
    """This block's own modal word if it has one (it applies before the cycle), else the state's."""
    section = sections.get(key)
    return default if section is None else getattr(section, attr)


def _computed(block: Block) -> bool:
    return any(isinstance(value, Expr) for value in block.values.values())


def _cancel(state: ModalState) -> None:
    end_rigid_mode(state)
    state.cycle = None
    state.extra.pop(STATE_KEY, None)
    state.extra.pop(ACTIVE_KEY, None)


def active_cycle(state: ModalState) -> tuple[CannedCycle, CycleExpansion] | None:
    """The active cycle as last resolved (its levels, dwell, feed, return level...) and the expansion
    that makes its motion, or None when no cycle with numeric words is active."""
    if state.cycle is None:
        return None
    active: tuple[CannedCycle, CycleExpansion] | None = state.extra.get(ACTIVE_KEY)
    return active


def _clearance(ctx: Context, kind: str, units: str) -> float | None:
    """G73 retract or G83 clearance d (mm: the reading dialect's fixed one, else the set-up's), in program
    units."""
    if kind not in PECK:
        return None
    d = peck_clearance_mm(kind, ctx.peck_clearance_mm, ctx.setup.cycles)
    return d if units == "mm" else d / MM_PER_INCH


def peck_clearance_mm(kind: str, fixed: float | None, cycles: CycleSettings) -> float:
    """The G73 retract (``peck_chip``) or G83 clearance (``peck_deep``) in mm of a controller whose fixed
    clearance is ``fixed`` (``Dialect.PECK_CLEARANCE_MM``), else the machine parameters ``cycles``."""
    if fixed is not None:
        return fixed
    return cycles.peck_retract if kind == "peck_chip" else cycles.peck_clearance


_NOT_CYCLE_DATA: Final = frozenset(("Dwell", "NativeCode", "MachineFunction", "DataSetting", "HolePattern"))
"""Sections whose block's words belong to them, not to the active cycle."""


def _seconds(p: float | int | None, rules: Semantics, cw: CycleWords) -> float | None:
    if p is None:
        return None
    if cw.dwell_unit is not None:
        return float(p) * cw.dwell_unit
    return p / 1000.0 if rules.dwell_ms else float(p)


def _shift(ctx: Context, kind: str, q: float | None, first: str, second: str) -> dict[str, float] | None:
    if kind not in SHIFT:
        return None
    sign, index = _SHIFT_AXIS[ctx.setup.cycles.shift_direction]
    return {(first, second)[index]: sign * abs(float(q or 0.0))}


# A pattern text, not a compiled pattern: compiled where first used (``re``'s cache), so a start that
# reports no error compiles none (each ``re.compile`` at import costs every start ~0.3-1M instructions).
_COMMENT: Final = r"\([^)]*\)?"


def _code_column(block: Block, code: str) -> int:
    """Column of the cycle's code in the source text (comments blanked, leading zeros allowed)."""
    text = re.sub(_COMMENT, lambda m: " " * len(m.group(0)), (block.text or "").upper())
    letter, number = code[:1].upper(), code[1:].lstrip("0")
    m = re.search(re.escape(letter) + r"\s*0*" + re.escape(number) + r"(?![\d.])", text)
    return m.start() + 1 if m else 1
