"""``translate --arcs``: every arc of the lowered program rewritten as chords (``lines:TOL``), in centre
form (``ijk``) or in radius form (``r``), for any target, after every other lowering step (so the arcs
of expanded cycles and patterns, and the compensated path a target without compensation receives, are
rewritten too).

Decisions (docs/cli.md says the same):
- ``lines:TOL``: TOL is in mm whatever the program's units (as ``verify --tolerance``). Each arc becomes
  the fewest equal-angle chords within TOL of it (helices: the other axes move in proportion); the last
  chord ends at the arc's own end point, as programmed. Refused at the arc's line: an arc under cutter
  compensation the target keeps native (it would compensate each chord, not the arc), under inverse-time
  feed (each chord would take the arc's time), or under scaling or polar coordinates the target keeps.
- ``ijk``: an R arc gets the centre offsets of the centre its controller computes.
- ``r``: a centre arc gets R (negative over 180 degrees). Where R places the centre badly (a full
  circle, which R cannot give, or an arc within reach of 180 degrees, where a rounding of R moves the
  centre far) the arc is split into equal pieces of at most 120 degrees, each written with R. Where
  even that moves the centre more than ``R_FORM_TOLERANCE_MM`` (an I/J/K arc whose end lies off its
  circle) it keeps its centre form, with a warning at its line.
- In the profile of a lathe cycle the target keeps (its block numbers delimit the profile), an arc is
  not split: ``lines`` refuses it, ``r`` keeps it in centre form with a warning.
- Under ``--on-unsupported warn`` a refused arc is written as it was, with a warning at its line.
- The start point must be known (programmed absolutely since the origin last moved) unless every word
  of the arc is incremental; else a located error. A program that computes is executed (flattened):
  an arc in a loop starts somewhere else each time.

Here: what an arc becomes (the passes, their position tracking and the forms' rules); an arc's words as
numbers and back (absolute or incremental, diameters, increment addresses) are ``arc_words.ArcWords``, the
plane arithmetic (chords, R pieces, centre errors) ``arc_geometry``. One module of about 620 lines: the forms and
the settle pass share one position tracking (``_Rewriter``) and the fast follow of a move held to it (``_Arcs``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final, Iterator

from mypy_extensions import mypyc_attr

from ..geometry.arc_end import SPIRAL
from ..context import Context
from ..dialect import Dialect
from ..errors import PostprocError, ProgramError, UnsupportedError, UsageError
from ..ir.event_order import after_motion
from ..ir.expr import Expr
from ..ir import Block, CompoundMotion, Motion, Section
from ..ir.keys import only_move
from ..numbers import EXACT
from ..ir.state import MM_PER_INCH, PLANE_AXES, ModalState, changes_nothing
from .lower import BlockStep, LoweringStep, run_blocks
from .arc_geometry import Arc, chord_points, r_centre_error, r_pieces, signed_radius, split
from .arc_words import ArcWords
from .expansion_items import expansion_items
from .move_words import NotedPoint, move_words
from .point_after import compound_end, cycle_end

FORMS: Final = ("lines", "ijk", "r")
SETTLE: Final = "settle"
"""Not a user's form: ``settle_arc_ends``'s pass (an arc whose end the two controllers judge or run apart)."""
MIN_TOLERANCE_MM = 1e-4
"""Finest chord tolerance accepted: below it the written numbers' rounding (``EXACT``) is no longer small."""
R_FORM_TOLERANCE_MM = 0.0005
"""Most an R form may move an arc's centre (half of ``verify``'s default tolerance)."""
CLEAR_HALF_CHORD_MM: Final = 1e-3
"""Shortest half chord ``_short_of_half_turn`` judges (a shorter one, a full circle's too: the general test)."""
WRITE_SLACK_MM = 2 * EXACT
"""What the writer's rounding may move a point (``postproc.numbers.EXACT``, at both ends of a chord)."""
ARCS: Final = frozenset(("cw", "ccw"))
MOVES: Final = frozenset(("rapid", "linear", "cw", "ccw"))


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(frozen=True)
class ArcOption:
    """What ``--arcs`` asks: ``form`` one of ``FORMS``; ``tolerance`` the chord tolerance in mm (lines)."""

    form: str
    tolerance: float = 0.0


def parse_arc_option(text: str) -> ArcOption:
    """``lines:TOL``, ``ijk`` or ``r`` (a ``UsageError`` otherwise)."""
    form, colon, value = text.strip().partition(":")
    form = form.lower()
    if form == "lines":
        try:
            tolerance = float(value)
        except ValueError:
            raise UsageError(f"--arcs lines takes a chord tolerance in mm (lines:0.01), got {text!r}") from None
        if not math.isfinite(tolerance) or tolerance < MIN_TOLERANCE_MM:
            raise UsageError(f"--arcs lines: the chord tolerance must be a finite number of at least "
                             f"{MIN_TOLERANCE_MM:g} mm, got {value!r}")
        return ArcOption("lines", tolerance)
    if form in ("ijk", "r") and not colon:
        return ArcOption(form)
    raise UsageError(f"--arcs takes lines:TOL, ijk or r, got {text!r}")


@mypyc_attr(allow_interpreted_subclasses=True)
class SettleArcEnds(LoweringStep):
    """The lowered program with each I/J/K arc written about the centre the source's controller turns it
    about where that controller moves the programmed one (``postproc.geometry.arc_end.START_RADIUS``): the target's
    controller then runs a circle through both ends, the source's path exactly. A pass over the program only
    for such a source; a spiral source whose arc the target's controller would refuse is refused where it is
    read (``postproc.syntaxes.modal_state``, ``TARGET_ARC_END``).

    For a target that refuses an R arc whose chord exceeds 2R by any rounding (``Dialect.R_ARC_FLOAT_SLACK``,
    grbl), an R arc within rounding reach of 180 degrees is written by I/J/K too, about the centre the
    source's controller computes: exact, where a larger R would move the centre by the square root of its
    change (a semicircle of R 25 mm given 0.001 mm more R turns 0.22 mm off), and the target accepts I/J/K
    within a tolerance of its own."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if not ctx.arc_end.settles_for(target.R_ARC_FLOAT_SLACK):
            return None
        return _Arcs(ctx, ArcOption(SETTLE), target)


settle_arc_ends = SettleArcEnds()


@mypyc_attr(allow_interpreted_subclasses=True)
class RewriteArcs(LoweringStep):
    """The program lowered for a target with its arcs rewritten as ``option`` asks (see the module
    docstring): the last lowering step of ``translate --arcs``."""

    def __init__(self, option: ArcOption) -> None:
        self.option = option

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _Arcs(ctx, self.option, target)


def rewrite_arcs(blocks: Iterator[Block], ctx: Context, option: ArcOption, target: type[Dialect]) -> Iterator[Block]:
    """The program lowered for ``target`` with its arcs rewritten as ``option`` asks (see the module docstring)."""
    return run_blocks(blocks, [_Arcs(ctx, option, target)])


@mypyc_attr(allow_interpreted_subclasses=True)
class _Arcs(BlockStep):
    """One run of the rewriting: every move is its business (it follows the position). A block whose arc
    cannot be rewritten is an error (a warning with ``--on-unsupported warn``), written as it was."""

    def __init__(self, ctx: Context, option: ArcOption, target: type[Dialect]) -> None:
        super().__init__()
        self.ctx = ctx
        self.rewriter = _Rewriter(ctx, option, target)
        self.kept_centres = option.form == SETTLE and ctx.arc_end.runs == SPIRAL
        """An I/J/K arc only moves the position, as a straight move does: the settle pass of a source whose controller
        keeps the programmed centre leaves such an arc as it is (``_Rewriter._settle``)."""
        self.settles = option.form == SETTLE
        """The settle pass (``settle_arc_ends``): an R arc clearly short of half a turn stays as it is."""
        self.follow()

    def follow(self) -> None:
        """``point`` (``BlockStep.point``) as the run stands: while the position is ``plain``, a straight move of X,
        Y and Z numbers is only noted (``take_move``)."""
        rewriter = self.rewriter
        self.point = rewriter.notes if rewriter.plain else None

    def take(self, block: Block) -> list[Block] | None:
        rewriter = self.rewriter
        if rewriter.plain:
            sections = block.sections
            kind = _inert(sections)
            if kind == MOVE:  # (a move with its feed, a comment: ~2% of a CAM program)
                if (motion := sections.get("Motion")) is None or isinstance(motion, Motion) and self.follow_move(motion):
                    return None
            elif kind == EXPANSION:  # (an expanded hole)
                compound = sections["CompoundMotion"]
                if isinstance(compound, CompoundMotion) and rewriter.moved_to_end(compound):
                    return None
        return self.rewrite(block)

    def rewrite(self, block: Block) -> list[Block] | None:
        """``take``'s general way (``_Rewriter.block``), for any block."""
        rewriter = self.rewriter
        rewriter.settle()
        try:
            out = rewriter.block(block)
        except PostprocError as err:
            ctx = self.ctx
            located = err if err.location is not None else err.located(ctx.at(block))
            if isinstance(err, UnsupportedError) and ctx.on_unsupported == "warn":
                ctx.diagnostics.warn(f"{err.message} (the arc is written as it was)", located.location)
            else:
                ctx.diagnostics.error(located)
            rewriter.unknown()
            rewriter.settle_plain()
            self.follow()
            return None
        rewriter.settle_plain()
        self.follow()
        return None if len(out) == 1 and out[0] is block else out

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block that is only a move (``follow_move``: ~2.5k instructions a block less compiled)."""
        if self.rewriter.plain:
            motion = block.sections["Motion"]
            if isinstance(motion, Motion) and self.follow_move(motion):
                return None
        return self.rewrite(block)

    def follow_move(self, motion: Motion) -> bool:
        """While the position is ``plain``, a move that only moves it to its words (as ``_track``) is followed so (True;
        False: the general way, ``rewrite``): a straight move, an I/J/K arc the pass leaves (``kept_centres``: grbl's
        from a Fanuc or LinuxCNC program), an R arc the settle pass keeps unbuilt (``_Rewriter.keeps_radius``: ~5k
        instructions less). X, Y and Z numbers are only noted (``_Rewriter.note``, ``move_words``); other words go
        into the position at once: while nothing read is symbolic (``ModalState.symbolic``) every word is a number,
        one ``dict.update`` (~800 instructions compiled)."""
        rewriter = self.rewriter
        mode = motion.mode
        if mode == "cw" or mode == "ccw":
            if motion.radius is None:
                if not self.kept_centres:
                    return False
            elif not self.settles:
                return False
            else:
                rewriter.settle()
                if not rewriter.keeps_radius(motion, False, False):
                    return False
        elif mode != "linear" and mode != "rapid":
            return False
        if rewriter.note(motion):
            return True
        rewriter.settle()
        position = rewriter.position
        if not self.ctx.state.symbolic:
            position.update(motion.axes)  # type: ignore[arg-type]  # numbers: nothing is symbolic yet
            return True
        for axis, value in motion.axes.items():  # (a float first: cheap compiled, an Expr test is not)
            position[axis] = value if isinstance(value, float) or not isinstance(value, Expr) else None
        return True


INERT: Final = frozenset(("Sequence", "Motion", "Comments", "Feed", "SpindleSpeed", "SpindleControl", "Coolant"))
"""Sections the pass has nothing to do with but the move: none changes what it reads of its ``ModalState`` (the
position, plane, units, distance and feed modes, polar coordinates)."""
GENERAL: Final = 0
"""``_inert``: a key that is neither ``INERT`` nor an expansion's."""
MOVE: Final = 1
"""``_inert``: every key ``INERT`` (a move, or none, beside sections the pass has nothing to do with)."""
EXPANSION: Final = 2
"""``_inert``: an expansion (``CompoundMotion``) and no move beside ``INERT`` sections (an expanded hole)."""


def _computed(value: object) -> bool:
    """An ``Expr`` (a float first: cheap compiled, an ``Expr`` test of the interpreted class is not)."""
    return type(value) is not float and isinstance(value, Expr)


def _inert(sections: dict[str, Section]) -> int:
    """``MOVE``: every key of the block is ``INERT``; ``EXPANSION``: every key but a ``CompoundMotion`` is, and none is
    a ``Motion``; else ``GENERAL`` (a loop over its few keys: ``issuperset`` is a bound method call; an expansion alone,
    an expanded hole, by its size and a look-up: the loop cost it ~300 instructions compiled)."""
    if len(sections) == 1 and "CompoundMotion" in sections:
        return EXPANSION
    kind = MOVE
    for key in sections:
        if key not in INERT:
            if key != "CompoundMotion":
                return GENERAL
            kind = EXPANSION
    if kind == EXPANSION and "Motion" in sections:
        return GENERAL
    return kind


@mypyc_attr(allow_interpreted_subclasses=True)
class _Rewriter:
    """Where the program stands (program units, as programmed: a diameter stays a diameter) and the
    settings an arc depends on."""

    def __init__(self, ctx: Context, option: ArcOption, target: type[Dialect]) -> None:
        self.ctx = ctx
        self.option = option
        self.target = target
        self.diameter = ctx.diameter and "lathe" in target.MACHINE_TYPES and target.DIAMETER_PROGRAMMING
        """X words are diameters in the lowered program (a target that programs radii got them halved:
        ``postproc.cycles.lathe_lowering``)."""
        self.in_profile = False
        """The block is in the profile of a lathe cycle the target keeps: run by the cycle, not in turn."""
        self.state = ModalState()
        if ctx.lathe:
            self.state.plane = "ZX"
        self.compensating = False
        self.scaling = False
        self.restate = False
        """An arc became lines: the next move is written from its sections (a modal G2 it relied on is gone)."""
        self.position = self.state.position  # (the same dictionary: nothing replaces it)
        self.read = move_words(ctx)
        """A plain move's numbers, read once for the steps that follow the point (``note``)."""
        self.notes = NotedPoint(self.read)
        self.expansions = expansion_items(ctx)
        """What an expansion holds (an arc among its moves?), read once for the steps that ask it (``_compound``)."""
        """The X, Y and Z of the plain moves since the position was last brought up to date (``settle``, before
        anything reads it)."""
        self.plain = False
        """A straight move alone in its block only moves the position to its words (``settle_plain``)."""
        self.settle_plain()

    def note(self, motion: Motion) -> bool:
        """A straight move's X, Y and Z numbers noted for ``settle`` (False: it has other words, for the position
        at once)."""
        words = self.read
        bits = words.read(motion)
        if bits < 0:
            return False
        self.notes.note(words, bits)
        return True

    def settle(self) -> None:
        """The noted numbers into the position (``note``)."""
        self.notes.into(self.position)

    def settle_plain(self) -> None:
        """``plain``: not in a kept cycle's profile, no move to restate, absolute words, no increment addresses."""
        self.plain = not self.in_profile and not self.restate and self.state.distance != "incremental" \
            and not self.ctx.increments

    def unknown(self, axes: object = None) -> None:
        """The position is not known (on ``axes``, default all) until programmed absolutely again."""
        position = self.state.position
        for axis in list(position) if axes is None else axes:  # type: ignore[attr-defined]
            position[axis] = None

    # -- one block ----------------------------------------------------------------------------------
    def block(self, block: Block) -> list[Block]:
        """The block, or the blocks its arc became."""
        sections = block.sections
        rare = self.in_profile or not only_move(sections)
        """A key but a block number and a move (or a profile to leave): the other sections are looked for. The
        common block (``only_move``: neither key is modal, ``state.MODAL_KEYS``) skips their nine look-ups and
        ``changes_nothing``'s loop (this pass runs over every block of every translation to grbl)."""
        if rare:
            in_profile = "InProfile" in sections
            if in_profile != self.in_profile:
                self.unknown()  # a profile starts where its cycle stood, and after it the cycle's end is not tracked
                self.in_profile = in_profile
            if not changes_nothing(sections) or "CutterCompensation" in sections \
                    or "DynamicCutterCompensation" in sections:  # (not frozenset.isdisjoint: ~800 instructions compiled)
                self._settings(sections)
            coords = sections.get("CoordinateSet")
            if coords is not None:
                for axis, value in coords.axes.items():  # type: ignore[attr-defined]
                    self.state.position[axis] = None if isinstance(value, Expr) else value
        motion = sections.get("Motion")
        compound = sections.get("CompoundMotion") if rare else None
        out: list[Block] = [block]
        if isinstance(motion, Motion) and motion.mode is not None:
            if self.restate and motion.mode in MOVES:
                block.changed()
                block.canonical = False
                self.restate = False
            machine = rare and "MachineCoordinates" in sections
            if motion.mode in ARCS:
                pieces = self._arc(block, motion, self.state.distance == "incremental", machine)
                if pieces is not None:
                    out = self._split_block(block, pieces)
            else:
                self._track(motion, self.state.distance == "incremental", machine)
        elif isinstance(motion, Motion) or rare and "CannedCycle" in sections:
            self.unknown()  # a native canned cycle (or its repeat) ends where its rules say
        if isinstance(compound, CompoundMotion):
            self._compound(block, compound)
        if rare and ("CannedCycle" in sections or "LatheCycle" in sections and compound is None):
            self.unknown()  # a native cycle ends where its controller's rules say
            cycle = sections.get("CannedCycle")
            if cycle is not None:  # a hole cycle: over its last hole at its return level
                self.state.position.update(cycle_end(cycle) or {})
        return out

    def _settings(self, sections: dict[str, Section]) -> None:
        self.state.apply(sections)
        cc = sections.get("CutterCompensation")
        if cc is not None:
            self.compensating = getattr(cc, "mode", "off") != "off"
        if "DynamicCutterCompensation" in sections:
            self.compensating = True
        frame = sections.get("FrameChange")
        if frame is not None:
            kind = getattr(frame, "kind", "")
            if kind == "scale":
                self.scaling = True
            elif kind == "scale_off":
                self.scaling = False

    def moved_to_end(self, compound: CompoundMotion) -> bool:
        """Without an arc among an expansion's moves (``ExpansionItems.arcs``: a hole's) they only move the position to
        where they end (``point_after.compound_end``, found once for every step that follows the point): the position
        there (True), the moves not walked (~1.6k instructions a move compiled). False: ``_compound`` walks them."""
        if self.ctx.increments:
            return False
        read = self.expansions
        read.read(compound)
        if read.arcs:
            return False
        end = compound_end(compound)  # (None: a move other than G0-G3 among them, the walk's)
        if end is None:
            return False
        if not self.notes.note_end(end):  # (X, Y and Z numbers, a hole's: noted as a plain move's are)
            self.settle()
            self.position.update(end)
        return True

    def _compound(self, block: Block, compound: CompoundMotion) -> None:
        """An expansion's moves (absolute, program units): its arcs rewritten in place (without one: ``moved_to_end``)."""
        if self.moved_to_end(compound):
            return
        items: list[Section] = []
        changed = False
        for item in compound.items:
            if isinstance(item, Motion) and item.mode in ARCS:
                pieces = self._arc(block, item, False, False)
                if pieces is not None:
                    items.extend(pieces)
                    changed = True
                    continue
            elif isinstance(item, Motion) and item.mode is not None:
                self._track(item, False, False)
            items.append(item)
        if changed:
            compound.items = items
            block.changed()

    # -- positions ------------------------------------------------------------------------------------
    def _track(self, motion: Motion, incremental: bool, machine: bool) -> None:
        position = self.state.position
        if motion.mode in ("home", "home2") or machine:
            self.unknown(self._real(a) for a in motion.axes)
            return
        increments = self.ctx.increments
        if not increments and not incremental:  # most moves: each word is where the axis goes
            for axis, value in motion.axes.items():
                # a number first: a float test is cheap compiled, one of the interpreted Expr is not
                position[axis] = value if isinstance(value, float) or not isinstance(value, Expr) else None
            return
        for axis, value in motion.axes.items():
            real = increments.get(axis) if increments else None
            if isinstance(value, Expr):
                position[real or axis] = None
            elif real is not None or incremental:
                known = position.get(real or axis)
                position[real or axis] = None if known is None else known + value
            else:
                position[axis] = value

    def _real(self, axis: str) -> str:
        increments = self.ctx.increments
        return increments.get(axis, axis) if increments else axis

    # -- one arc ------------------------------------------------------------------------------------
    def _arc(self, block: Block, motion: Motion, incremental: bool, machine: bool) -> list[Motion] | None:
        """The motions that replace the arc, or None when it stays as it is (position tracked)."""
        form = self.option.form
        if form == SETTLE:
            return self._settle(motion, incremental, machine)
        if form == "ijk" and motion.radius is None or form == "r" and motion.radius is not None:
            self._track(motion, incremental, machine)
            return None
        if machine:
            raise ProgramError("an arc in machine coordinates cannot be run")
        if form == "lines":
            self._check_lines()
        if self.state.extra.get("polar"):
            raise UnsupportedError("--arcs: an arc in polar coordinates (kept for the target) cannot be rewritten")
        plane = self.state.plane
        a1, a2, _ = PLANE_AXES[plane]
        geometry = self.words(motion, incremental, (a1, a2))
        arc = geometry.arc()
        if form == "lines":
            mm = self._mm()
            tolerance = (self.option.tolerance - WRITE_SLACK_MM) / mm
            try:
                points = list(chord_points(arc, tolerance, geometry.quantum))
            except ValueError as err:
                raise UnsupportedError(f"--arcs lines: {err}") from None
            motions = [geometry.piece("linear", p, others, None, None) for p, others in points]
            if self.in_profile and len(motions) > 1:
                raise UnsupportedError("--arcs lines: an arc in the profile of a lathe cycle the target keeps cannot "
                                       "become lines (the cycle's block numbers delimit its profile)")
            self.restate = True
        elif form == "ijk":
            motions = [geometry.piece(motion.mode or "cw", arc.end, {a: e for a, (_, e) in arc.along.items()},
                                       (arc.centre[0] - arc.start[0], arc.centre[1] - arc.start[1]), None)]
        else:
            replaced = self._r_form(block, arc, geometry, motion.mode or "cw")
            if replaced is None:
                geometry.finish()
                return None
            motions = replaced
        geometry.finish()
        return motions

    def _settle(self, motion: Motion, incremental: bool, machine: bool) -> list[Motion] | None:
        """An I/J/K arc as the target's controller must be given it to run the source controller's path
        (``settle_arc_ends``): with the centre the source turns about where that is not the programmed one
        (exact: the written arc is then a circle through both ends); else left as it is."""
        if motion.radius is not None:
            return self._settle_radius(motion, incremental, machine)
        if self.ctx.arc_end.runs == SPIRAL or machine or not motion.center or self.state.extra.get("polar") or any(
                isinstance(v, Expr) for v in (*motion.center.values(), *motion.axes.values())):
            self._track(motion, incremental, machine)
            return None
        a1, a2, _ = PLANE_AXES[self.state.plane]
        try:
            geometry = self.words(motion, incremental, (a1, a2))
        except ProgramError:  # the start is not known here: the arc is judged when the program runs
            self._track(motion, incremental, machine)
            return None
        arc = geometry.arc()
        offsets = {a: float(v) for a, v in motion.center.items()}  # type: ignore[arg-type]  # numbers, checked above
        programmed = (arc.start[0] + offsets.get(a1, 0.0), arc.start[1] + offsets.get(a2, 0.0))  # I: a radius
        if math.hypot(arc.centre[0] - programmed[0], arc.centre[1] - programmed[1]) > geometry.quantum:
            motions = [geometry.piece(motion.mode or "cw", arc.end, {a: e for a, (_, e) in arc.along.items()},
                                      (arc.centre[0] - arc.start[0], arc.centre[1] - arc.start[1]), None)]
            geometry.finish()
            return motions
        geometry.finish()
        return None

    def _settle_radius(self, motion: Motion, incremental: bool, machine: bool) -> list[Motion] | None:
        """An R arc for a target that refuses any chord over 2R (``Dialect.R_ARC_FLOAT_SLACK``): by I/J/K
        where R rounded by the writer and by the target's floating point moves the centre more than
        ``R_FORM_TOLERANCE_MM`` (an arc within reach of 180 degrees); else left as it is."""
        if self.keeps_radius(motion, incremental, machine):
            self._track(motion, incremental, machine)
            return None
        a1, a2, _ = PLANE_AXES[self.state.plane]
        try:
            geometry = self.words(motion, incremental, (a1, a2))
            arc = geometry.arc()
        except ProgramError:  # the start is not known here, or the arc cannot be run: judged where it runs
            self._track(motion, incremental, machine)
            return None
        mm = self._mm()
        slack = WRITE_SLACK_MM / mm + abs(float(motion.radius)) * self.target.R_ARC_FLOAT_SLACK  # type: ignore[arg-type]  # a number
        if r_centre_error(arc, slack) * mm <= R_FORM_TOLERANCE_MM:
            geometry.finish()
            return None
        motions = [geometry.piece(motion.mode or "cw", arc.end, {a: e for a, (_, e) in arc.along.items()},
                                  (arc.centre[0] - arc.start[0], arc.centre[1] - arc.start[1]), None)]
        geometry.finish()
        return motions

    def keeps_radius(self, motion: Motion, incremental: bool, machine: bool) -> bool:
        """The settle pass leaves the R arc unbuilt: no care for R (``Dialect.R_ARC_FLOAT_SLACK``), not judged here
        (machine coordinates, polar, a computed word), or clearly short of half a turn (position settled)."""
        share = self.target.R_ARC_FLOAT_SLACK
        if not share or machine or self.state.extra.get("polar") or _computed(motion.radius):
            return True
        for value in motion.axes.values():
            if _computed(value):
                return True
        return self._short_of_half_turn(motion, incremental, share)

    def _short_of_half_turn(self, motion: Motion, incremental: bool, slack_share: float) -> bool:
        """The R arc is clearly short of half a turn: R off by the slack moves its centre under half of
        ``R_FORM_TOLERANCE_MM`` (the centre lies sqrt(R^2 - h^2) off the chord's middle, h half the chord: concave in
        R, so R less the slack moves it most, ``r_centre_error``'s worst trial). False: the general test, which
        builds the arc and its centre three times (~60k instructions compiled), decides."""
        if incremental or self.diameter or self.ctx.increments:
            return False
        a1, a2, _ = PLANE_AXES[self.state.plane]
        position = self.position
        s1, s2 = position.get(a1), position.get(a2)
        radius = motion.radius
        if s1 is None or s2 is None or not (type(radius) is float or isinstance(radius, (int, float))):
            return False  # (a float first: cheap compiled, a test of a tuple of types is not)
        e1, e2 = motion.axes.get(a1, s1), motion.axes.get(a2, s2)
        if not (type(e1) is float or isinstance(e1, (int, float))) or not (
                type(e2) is float or isinstance(e2, (int, float))):
            return False
        mm = self._mm()
        half = math.hypot(e1 - s1, e2 - s2) * mm / 2.0
        r = abs(float(radius)) * mm
        low = r - (WRITE_SLACK_MM + r * slack_share)
        if half < CLEAR_HALF_CHORD_MM or low <= half:
            return False
        return math.sqrt((r - half) * (r + half)) - math.sqrt((low - half) * (low + half)) \
            <= R_FORM_TOLERANCE_MM / 2.0

    def _r_form(self, block: Block, arc: Arc, geometry: ArcWords, mode: str) -> list[Motion] | None:
        mm = self._mm()
        slack = WRITE_SLACK_MM / mm
        pieces = [arc] if r_centre_error(arc, slack) * mm <= R_FORM_TOLERANCE_MM else split(
            arc, r_pieces(arc), geometry.quantum)
        worst = max(r_centre_error(piece, slack) for piece in pieces) * mm
        if len(pieces) > 1 and self.in_profile:
            self.ctx.diagnostics.warn("--arcs r: the arc keeps its centre form: R needs it split, and it is in the "
                                      "profile of a lathe cycle the target keeps", self.ctx.at(block))
            return None
        if worst > R_FORM_TOLERANCE_MM:
            self.ctx.diagnostics.warn(f"--arcs r: the arc keeps its centre form: written with R its centre would "
                                      f"move {worst:.4f} mm (its end point lies off its circle)", self.ctx.at(block))
            return None
        motions = []
        for piece in pieces:
            motions.append(geometry.piece(mode, piece.end, {a: e for a, (_, e) in piece.along.items()}, None,
                                           signed_radius(piece)))
        return motions

    def _check_lines(self) -> None:
        if self.compensating:
            raise UnsupportedError("--arcs lines: an arc under cutter compensation the target keeps cannot become "
                                   "lines (the target would compensate each chord, not the arc)")
        if self.state.feed_mode == "inverse_time":
            raise UnsupportedError("--arcs lines: an arc under inverse-time feed cannot become lines (each chord "
                                   "would take the arc's time)")
        if self.scaling:
            raise UnsupportedError("--arcs lines: an arc under scaling the target keeps cannot become lines (the "
                                   "scaling would scale the chord tolerance)")

    def words(self, motion: Motion, incremental: bool, plane: tuple[str, str]) -> ArcWords:
        """The arc of ``motion`` as numbers, from where the program stands (``ArcWords``)."""
        return ArcWords(self.state, self.ctx, self.diameter, motion, incremental, plane)

    def _mm(self) -> float:
        """mm per program unit."""
        return MM_PER_INCH if self.state.units == "inch" else 1.0

    def _split_block(self, block: Block, motions: list[Motion]) -> list[Block]:
        """The block with its arc as ``motions``: what acts before the motion stays with the first, what
        acts after it (and an expansion, which runs after the block's motion) goes with the last."""
        block.changed()
        block.canonical = False
        block.sections["Motion"] = motions[0]
        if len(motions) == 1:
            return [block]
        out = [block]
        for motion in motions[1:]:
            piece = Block(block.line, None, block.eol)
            piece.sections["Motion"] = motion
            out.append(piece)
        last = out[-1].sections
        for key, section in list(block.sections.items()):
            if key == "CompoundMotion" or after_motion(key, section):
                last[key] = block.sections.pop(key)
        return out
