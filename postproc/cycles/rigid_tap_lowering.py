"""The lowering step of rigid (spindle-synchronised) tapping: each ``RigidTap`` (``postproc.lowering.synchronised_tap``,
where the rules are described) kept as the target's synchronised move, written as its rigid tap cycle, or
refused. It lives with the cycles because it writes a tap cycle (``CannedCycle``), and the cycles package
reads ``RigidTap``: the section below, the step here."""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Iterator

from ..context import Context
from ..dialect import Dialect
from ..errors import Location, PostprocError, ProgramError, UnsupportedError
from ..ir.expr import Expr
from ..ir import (Block, CompoundMotion, CycleCancel, DistanceMode, Feed, MachineFunction, Motion,
                  ReturnLevel, Section, SpindleControl, SpindleSpeed)
from ..ir.state import PLANE_AXES
from ..lowering.lower import BlockStep, LoweringStep
from ..lowering.machine_functions import RIGID_TAP, comment_out
from ..lowering.synchronised_tap import RigidTap, rigid_taps
from .section import CannedCycle


@mypyc_attr(allow_interpreted_subclasses=True)
class ResolveRigidTaps(LoweringStep):
    """Lowering step (the module docstring): after ``expand_canned_cycles``, so an expanded rigid tap cycle
    shows its taps. A refused block is reported and not written, whatever ``--on-unsupported`` says. Back to
    its own dialect with no cycle expanded by force, every tap stays as written: the stream passes through."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if target.NAME == ctx.dialect and not ctx.setup.cycles.expanded():
            return None
        return _Taps(ctx, target)


resolve_rigid_taps = ResolveRigidTaps()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Taps(BlockStep):
    """One run: only a block with a machine function, a tap or an expansion is its business. A block
    rewritten into several is made whole before it goes on (a refusal found half-way drops it all)."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.target = target
        self.synchronises = target.SYNCHRONISED_TAP
        self.family = target.family()
        self.cycle_code = target.RIGID_TAP_CODE
        self.own_code = False  # the source writes the target family's rigid-tapping code itself

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if "MachineFunction" not in sections and "RigidTap" not in sections and "CompoundMotion" not in sections:
            return None  # the common block
        ctx, target, family = self.ctx, self.target, self.family
        synchronises, cycle_code = self.synchronises, self.cycle_code
        code = sections.get("MachineFunction")
        if isinstance(code, MachineFunction) and code.action == RIGID_TAP and code.family == family:
            self.own_code = True
        if isinstance(code, MachineFunction) and code.action == RIGID_TAP and code.family != family \
                and (synchronises or target.TAP_STROKES or target.RIGID_TAP_CYCLE):  # (the block first: the
            # target's flags are class attributes, each a look-up by name, ~270 instructions an expanded hole)
            _leave_out(block, code)
        taps = rigid_taps(block)
        if not taps:
            return None
        own = sections.get("RigidTap")
        if target.RIGID_TAP_CYCLE and isinstance(own, RigidTap) and own.stroke is None and taps == [own] \
                and (ctx.state.distance == "absolute" and ctx.state.plane == "XY" or not target.TAP_STROKES):
            # the cycle where its levels read as written (absolute, the XY plane); elsewhere the strokes
            try:
                as_cycle_call(block, ctx, target, own)
            except PostprocError as err:
                ctx.diagnostics.error(err)
                return []
            return None
        if target.TAP_STROKES and isinstance(own, RigidTap) and own.stroke is None:
            try:
                return list(as_strokes(block, ctx, target, own))
            except PostprocError as err:
                ctx.diagnostics.error(err)
            return []
        compound = sections.get("CompoundMotion")
        if target.TAP_STROKES and isinstance(compound, CompoundMotion) and "CannedCycle" not in sections:
            try:
                _strokes_in_expansion(block, ctx, target, compound)
            except PostprocError as err:
                ctx.diagnostics.error(err)
                return []
            return None
        if cycle_code and not synchronises and "RigidTap" in sections:
            try:
                return list(as_tap_cycle(block, ctx, target, sections["RigidTap"]))  # type: ignore[arg-type]
            except PostprocError as err:
                ctx.diagnostics.error(err)
            return []
        if cycle_code and not synchronises and not self.own_code and isinstance(compound, CompoundMotion) \
                and "CannedCycle" not in sections:
            try:
                return list(taps_as_cycles(block, ctx, target, compound))
            except PostprocError as err:
                ctx.diagnostics.error(err)
                return []
        why = _refusal(taps, target)
        if why is not None:
            ctx.diagnostics.error(UnsupportedError(why, ctx.at(block)))
            return []
        return None


def _leave_out(block: Block, code: MachineFunction) -> None:
    """The rigid-tapping code goes; a comment says where its meaning went."""
    comment_out(block, f"{code.describe()}: the taps after it are written spindle-synchronised")


def _refusal(taps: list[RigidTap], target: type[Dialect]) -> str | None:
    """Why ``target`` cannot run these taps exactly, or None."""
    strokes = [tap.stroke is not None for tap in taps]
    if any(strokes) and not target.TAP_STROKES:
        return (f"one stroke of a rigid tap (in, or out with the spindle reversed): {target.NAME} programs a rigid "
                "tap as one move in and out, and a stroke is not paired with its other here: refused, even with "
                "--on-unsupported warn")
    if all(strokes):
        return None  # strokes towards a controller that programs them (ISG <-> SINUMERIK G331/G332): written as read
    if not target.SYNCHRONISED_TAP:
        lack = f" ({target.RIGID_TAP_LACK})" if target.RIGID_TAP_LACK else ""
        return (f"a rigid (spindle-synchronised) tap: this translation writes no synchronised tap for {target.NAME}"
                f"{lack}, and a tap fed without the spindle in step breaks: refused, even with --on-unsupported warn")
    if any(tap.dwell for tap in taps):
        return (f"a rigid tap with a dwell at the bottom (P): {target.NAME}'s synchronised tap reverses at once "
                "and has no dwell there: refused, even with --on-unsupported warn")
    return None


def as_tap_cycle(block: Block, ctx: Context, target: type[Dialect], tap: RigidTap) -> Iterator[Block]:
    """A synchronised tap as the target's rigid tap cycle (the module docstring): three blocks."""
    state = ctx.state
    at = ctx.at(block)
    normal, start, bottom = _along_normal(ctx, tap, at, "no tap cycle is written for it",
                                          f"{target.NAME}'s tap cycle needs its start as the R level",
                                          f"{target.NAME}'s tap cycle taps")
    del block.sections["RigidTap"]
    block.changed()
    yield from _tap_cycle(block, ctx, target, tap, (normal, start, bottom), state.spindle, at)


def as_cycle_call(block: Block, ctx: Context, target: type[Dialect], tap: RigidTap) -> None:
    """A synchronised tap as a rigid tap cycle called once at the spot (``Dialect.RIGID_TAP_CYCLE``: SINUMERIK's
    ``CYCLE84``, whose pitch is a parameter): R at the start, the bottom at the end point, back to R, the
    spindle's direction in force (a counter-clockwise tap cycle for a counter-clockwise spindle). The cycle is the
    target's own, written natively: it moves by the target's rules (``Dialect.CYCLE_SEMANTICS``)."""
    state = ctx.state
    at = ctx.at(block)
    normal = PLANE_AXES[state.plane][2]
    if tap.speedup not in (None, 1.0) or isinstance(tap.pitch, Expr) \
            or any(isinstance(v, Expr) for v in tap.axes.values()):
        raise UnsupportedError("a rigid tap with a computed word or a faster way out: no tap cycle is written for it",
                               at)
    start = state.position.get(normal)
    if start is None:
        raise ProgramError(f"a rigid tap where the tool's {normal} position is unknown: the tap cycle needs its start "
                           "as the R level (program a move to a known point first)", at)
    incremental = state.distance == "incremental"
    for axis, value in tap.axes.items():
        if axis != normal and (value != 0.0 if incremental else value != state.position.get(axis)):
            raise UnsupportedError(f"a rigid tap that moves {axis} (an oblique tap): the tap cycle taps along "
                                   f"{normal} only", at)
    end = tap.axes.get(normal)
    if end is None:
        raise UnsupportedError(f"a rigid tap that does not move {normal}: the tap cycle taps along {normal} only", at)
    if state.spindle not in ("cw", "ccw"):
        raise ProgramError("a rigid tap with the spindle stopped cannot be run", at)
    assert not isinstance(end, Expr) and not isinstance(tap.pitch, Expr)  # (refused above)
    bottom = float(end) + (start if incremental else 0.0)
    del block.sections["RigidTap"]
    block.changed()
    block.sections["CannedCycle"] = CannedCycle(
        "tap" if state.spindle == "cw" else "tap_left", call=True, semantics=target.CYCLE_SEMANTICS,
        return_level="r",
        plane=state.plane, initial=start, r=start, bottom=bottom, dwell=tap.dwell, spindle=state.spindle,
        pitch=float(tap.pitch), words={normal: bottom})


def _tap_cycle(block: Block, ctx: Context, target: type[Dialect], tap: RigidTap, levels: tuple[str, float, float],
               direction: str | None, at: Location) -> Iterator[Block]:
    """The code block, ``block`` made the tap cycle at the spot from ``levels`` (the drilling axis, the start as
    R, the bottom) with the spindle turning ``direction``, and the cancel block (``as_tap_cycle``)."""
    state = ctx.state
    normal, start, bottom = levels
    incremental = state.distance == "incremental"
    rpm, mode = state.spindle_rpm, state.feed_mode
    if direction not in ("cw", "ccw") or not rpm:
        raise ProgramError("a rigid tap with the spindle stopped or at no speed cannot be run", at)
    if mode not in ("per_min", "per_rev"):
        raise UnsupportedError(f"a rigid tap in {mode.replace('_', ' ')} feed: no tap cycle feed says its pitch", at)
    pitch = tap.pitch
    assert not isinstance(pitch, Expr)
    code = MachineFunction(target.family(), target.RIGID_TAP_CODE, target.RIGID_TAP_CODE, RIGID_TAP,
                           "rigid tapping")
    head = Block(block.line, None, block.eol or "\n")
    head.sections = {"MachineFunction": code, "SpindleSpeed": SpindleSpeed(float(rpm))}
    yield head
    sections = block.sections
    if incremental:
        sections["DistanceMode"] = DistanceMode("absolute")
    sections["ReturnLevel"] = ReturnLevel("r")
    sections["CannedCycle"] = CannedCycle(
        "tap" if direction == "cw" else "tap_left", call=True, semantics=target.CYCLE_SEMANTICS,
        return_level="r",
        plane=state.plane, r=start, bottom=bottom, spindle=direction, pitch=pitch,
        words={normal: bottom, ctx.cycle_words.level if ctx.cycle_words is not None else "R": start},
        feed=pitch * float(rpm) if mode == "per_min" else pitch)
    sections["Feed"] = Feed(pitch * float(rpm) if mode == "per_min" else pitch)
    yield block
    tail = Block(block.line, None, block.eol or "\n")
    tail.sections = {"CycleCancel": CycleCancel()}
    if state.return_level != "r":
        tail.sections["ReturnLevel"] = ReturnLevel(state.return_level)
    if isinstance(state.feed, (int, float)):
        tail.sections["Feed"] = Feed(float(state.feed))
    if incremental:
        tail.sections["DistanceMode"] = DistanceMode("incremental")
    yield tail


def taps_as_cycles(block: Block, ctx: Context, target: type[Dialect], compound: CompoundMotion) -> Iterator[Block]:
    """An expanded rigid tap cycle of a family whose taps are rigid without a code (SINUMERIK ``CYCLE84``)
    towards a target that taps rigidly after its code: the moves before each synchronised tap, then the
    code, the tap cycle at the spot and its cancel (``as_tap_cycle``'s three blocks), then the moves after
    it; the block's other sections stay with its first part. A tap along anything but the drilling axis
    alone, or from a level the moves before it do not give, is refused."""
    if not any(isinstance(item, RigidTap) for item in compound.items):
        yield block
        return
    state = ctx.state
    at = ctx.at(block)
    normal = PLANE_AXES[state.plane][2]
    level: float | None = None
    if not any(isinstance(item, Motion) and normal in item.axes for item in compound.items):
        known = state.position.get(normal)  # no move along it in the block: the tap starts where the tool stands
        level = known if isinstance(known, float) else None
    direction = state.spindle
    part: list[Section] = []
    first = True
    for item in compound.items:
        if not isinstance(item, RigidTap):
            if isinstance(item, SpindleControl):
                direction = item.direction  # (a left-hand tap cycle turns the spindle counter-clockwise first)
            reached = item.axes.get(normal) if isinstance(item, Motion) else None
            if isinstance(reached, float):
                level = reached
            part.append(item)
            continue
        end = item.axes.get(normal)
        if item.dwell or item.stroke is not None or isinstance(item.pitch, Expr) or set(item.axes) != {normal} \
                or not isinstance(end, float) or level is None:
            raise UnsupportedError(f"a rigid tap with a dwell, or not along {normal} alone from a level the cycle's "
                                   f"moves give: no {target.NAME} tap cycle is written for it", at)
        if first:
            made = _first_part(block, compound.term, part)
            if made.sections:
                yield made
        else:
            yield from _later_part(block, part)
        first, part = False, []
        tap_block = Block(block.line, None, block.eol or "\n")
        tap_block.sections = {}
        yield from _tap_cycle(tap_block, ctx, target, item, (normal, level, end), direction, at)
    yield from _later_part(block, part)


def _first_part(block: Block, term: str, items: list[Section]) -> Block:
    """The block's first part: its own sections and the moves ``items`` before the first tap."""
    if items:
        block.sections["CompoundMotion"] = CompoundMotion(term, items)
    else:
        del block.sections["CompoundMotion"]
    block.changed()
    return block


def _along_normal(ctx: Context, tap: RigidTap, at: Location, unwritten: str, needs_start: str, taps: str,
                  same_speed: str | None = None) -> tuple[str, float, float]:
    """The axis normal to the plane, where the tap starts and its bottom, both absolute, for a target that taps
    along that axis only (its tap cycle, or its strokes); each phrase names what the target would write, in
    the error that refuses a tap it cannot: ``unwritten`` (computed words or a dwell), ``needs_start`` (the
    start unknown), ``taps`` (an oblique tap, or none along the normal) and, where the way out cannot be
    faster than the way in, ``same_speed``."""
    state = ctx.state
    normal = PLANE_AXES[state.plane][2]
    if tap.dwell or isinstance(tap.pitch, Expr) or any(isinstance(v, Expr) for v in tap.axes.values()):
        raise UnsupportedError(f"a rigid tap with a computed word or a dwell: {unwritten}", at)
    if same_speed is not None and tap.speedup is not None and tap.speedup > 1.0:
        raise UnsupportedError(f"a rigid tap whose way out is faster (by {tap.speedup:g} times): {same_speed}", at)
    incremental = state.distance == "incremental"
    start = state.position.get(normal)
    if start is None:
        raise ProgramError(f"a rigid tap where the tool's {normal} position is unknown: {needs_start} (program a "
                           "move to a known point first)", at)
    for axis, value in tap.axes.items():
        if axis != normal and (value != 0.0 if incremental else value != state.position.get(axis)):
            raise UnsupportedError(f"a rigid tap that moves {axis} (an oblique tap): {taps} along {normal} only", at)
    if normal not in tap.axes:
        raise UnsupportedError(f"a rigid tap that does not move {normal}: {taps} along {normal} only", at)
    end = tap.axes[normal]
    assert not isinstance(end, Expr)  # (refused above)
    return normal, start, float(end) + (start if incremental else 0.0)


def _later_part(block: Block, items: list[Section]) -> Iterator[Block]:
    """What an expansion does after a tap, one block an item (the first part's comment names the source)."""
    for item in items:
        part = Block(block.line, None, block.eol or "\n")
        part.sections = {item.KEY: item}
        yield part


def as_strokes(block: Block, ctx: Context, target: type[Dialect], tap: RigidTap) -> Iterator[Block]:
    """A synchronised tap as the target's two strokes (``Dialect.TAP_STROKES``, ISG ``G331``/``G332``):
    in to the end point with the spindle speed in force, out to the start; the sign of the pitch is the
    spindle's direction, the thread's hand ([V] TF5200 "Tapping (G331/G332)": K negative is a left-hand
    thread, G332 reverses the spindle itself, and M03/M04/M05 may not be programmed with G331/G332). A
    third block deselects the strokes with G01 and says again the spindle direction and the feed in force:
    whether the spindle turns back after G332, and which feed rate the next move has, are not confirmed
    [?], so neither is left to the controller."""
    state = ctx.state
    at = ctx.at(block)
    normal, start, bottom = _along_normal(ctx, tap, at, f"{target.NAME}'s strokes are not written for it",
                                          f"{target.NAME}'s retraction stroke needs it", f"{target.NAME}'s strokes tap",
                                          f"{target.NAME}'s retraction stroke runs at the speed of the way in")
    incremental = state.distance == "incremental"
    stroke_in, stroke_out, *after = _strokes(ctx, tap, normal, start, bottom, state.spindle, at)
    del block.sections["RigidTap"]
    block.changed()
    sections = block.sections
    if incremental:
        sections["DistanceMode"] = DistanceMode("absolute")
    sections["RigidTap"] = stroke_in
    sections["SpindleSpeed"] = SpindleSpeed(float(state.spindle_rpm or 0.0))
    yield block
    out = Block(block.line, None, block.eol or "\n")
    out.sections = {"RigidTap": stroke_out}
    yield out
    tail = Block(block.line, None, block.eol or "\n")
    tail.sections = {item.KEY: item for item in after}
    if incremental:
        tail.sections["DistanceMode"] = DistanceMode("incremental")
    yield tail


def _strokes(ctx: Context, tap: RigidTap, normal: str, start: float, bottom: float, direction: str | None,
             at: object) -> list[Section]:
    """The in and out strokes of a tap from ``start`` to ``bottom`` along ``normal`` with the spindle turning
    in ``direction``, then what the third block says (``as_strokes``): the linear mode, the spindle
    direction, the feed in force."""
    state = ctx.state
    rpm = state.spindle_rpm
    if direction not in ("cw", "ccw") or not rpm:
        raise ProgramError("a rigid tap with the spindle stopped or at no speed cannot be run", at)  # type: ignore[arg-type]
    assert not isinstance(tap.pitch, Expr)
    pitch = float(tap.pitch) if direction == "cw" else -float(tap.pitch)
    after: list[Section] = [RigidTap({normal: bottom}, pitch, stroke="in"), RigidTap({normal: start}, pitch, stroke="out"),
                            Motion("linear", {}), SpindleControl(direction)]
    if isinstance(state.feed, (int, float)):
        after.append(Feed(float(state.feed)))
    return after


def _strokes_in_expansion(block: Block, ctx: Context, target: type[Dialect], compound: CompoundMotion) -> None:
    """An expanded rigid tap cycle (Fanuc ``M29`` then ``G84``): each synchronised tap among its items becomes
    the strokes and what follows them (``_strokes``), from the level the item before it reached."""
    if not any(isinstance(item, RigidTap) for item in compound.items):
        return
    state = ctx.state
    at = ctx.at(block)
    normal = PLANE_AXES[state.plane][2]
    position: dict[str, float | Expr | None] = dict(state.position)
    direction = state.spindle
    items: list[Section] = []
    for item in compound.items:
        if isinstance(item, SpindleControl):
            direction = item.direction  # (a left-hand tap cycle turns the spindle counter-clockwise first)
        if isinstance(item, RigidTap):
            if item.stroke is not None:
                items.append(item)
                continue
            if item.dwell or isinstance(item.pitch, Expr) or any(isinstance(v, Expr) for v in item.axes.values()):
                raise UnsupportedError(f"a rigid tap with a computed word or a dwell: {target.NAME}'s strokes are "
                                       "not written for it", at)
            start = position.get(normal)
            end = item.axes.get(normal)
            if not isinstance(start, float) or not isinstance(end, float) or set(item.axes) != {normal}:
                raise UnsupportedError(f"a rigid tap that does not tap along {normal} alone from a known level: "
                                       f"{target.NAME}'s strokes are not written for it", at)
            items.extend(_strokes(ctx, item, normal, start, end, direction, at))
            continue
        if isinstance(item, Motion):
            position.update(item.axes)
        items.append(item)
    block.sections["CompoundMotion"] = CompoundMotion(compound.term, items)
    block.changed()
