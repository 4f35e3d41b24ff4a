"""Lowering steps for lean controllers (grbl and its kind): block-stream rewrites into what a controller
with no tool changer, no tool length cancel beside motion and no full-circle arc form runs. A dialect
takes them by listing them in its ``LOWERING`` (grbl does); compiled with the hot path, because every
block of such a translation passes through each (a straight move on two dictionary look-ups apiece).

* ``pause_for_tool_change``: grbl rejects M6 (no tool changer), so a tool change becomes a program
  pause ``T<n> M0`` with a comment naming the tool; a running spindle is stopped first, as a tool
  changer would (with a warning). grbl's reader reads ``T<n> M0`` back as a tool change. grbl runs
  M0 last in its block, so the rest of the block (spindle start, motion, M30) follows in a block of its
  own. With no tool selected there is no tool to name: the tool change is left for the writer to refuse.
* ``cancel_length_offset_first``: grbl refuses G49 (an axis command of its own) in a block with
  motion, so the cancel goes in a block of its own before the motion.
* ``close_full_circles``: grbl needs an end point in the plane of every arc (no full-circle form), so
  a full circle written as ``G3 I-7.`` gets a zero increment, in G91 for that one block. A helical full
  circle in absolute mode cannot be written so: it reaches the writer unchanged and is refused there.

Each step passes a program from the target's own dialect untouched (it is copied or normalised from its
own words).

``lower_for_lean_controller`` runs the three and the RS274/NGC ``stops_after_motion`` in one pass, in
that order, for a dialect that lists it instead of the four: every block of a translation passes each
step, nearly all untouched, and one test of a block's section names tells that for all four at once
(four generator layers cost grbl ~4 % of its time per block; measured with benchmarks/callgrind.sh).
"""

from __future__ import annotations

from typing import Iterator, Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..ir.expr import Expr
from ..ir import (
    Block, Comments, CompoundMotion, DistanceMode, Motion, Plane, ProgramControl, Section, SpindleControl,
    ToolLengthOffset, ToolSelect,
)
from ..ir.keys import watches_none
from ..ir.state import PLANE_AXES
from .order_of_execution import split_stops_after_motion, stops_after_motion
from ..lowering.expansion_items import expansion_items
from ..lowering.lower import BlockStep, LoweringStep
from ..lowering.move_words import NotedPoint, PassedPoint, move_words


def pause_for_tool_change(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME or target.TOOL_CHANGER:
        return blocks
    return _pause_for_tool_change(blocks, ctx)


def _pause_for_tool_change(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    pauses = _ToolChangePauses(ctx)
    for block in blocks:
        if _UNWATCHED(block.sections):  # a CAM block (a move, a block number, a feed rate): one set test
            yield block
            continue
        yield from pauses.split(block)


def cancel_length_offset_first(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME:
        return blocks
    return _cancel_length_offset_first(blocks)


def _cancel_length_offset_first(blocks: Iterator[Block]) -> Iterator[Block]:
    for block in blocks:
        first = _length_offset_cancel(block)
        if first is not None:
            yield first
        yield block


@mypyc_attr(allow_interpreted_subclasses=True)
class CloseFullCircles(LoweringStep):
    """``close_full_circles`` alone (a dialect that lists it without the other three: grblHAL)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME:
            return None
        return _CloseFullCircles(ctx)


close_full_circles = CloseFullCircles()


@mypyc_attr(allow_interpreted_subclasses=True)
class _CloseFullCircles(BlockStep):
    """One run: a move is its business (an arc may be a full circle to close), a straight one not (``passed``)."""

    def __init__(self, ctx: Context) -> None:
        super().__init__()
        self.circles = _FullCircles()
        self.point = passed(ctx)

    def take(self, block: Block) -> list[Block] | None:
        back = self.circles.close(block)  # before the block goes on: the next step sees it closed
        return None if back is None else [block, back]

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block that is only a move (``only_move``: no plane or distance mode to follow): only
        an arc may be a full circle to close."""
        arc = block.sections["Motion"]
        if not isinstance(arc, Motion) or (arc.mode != "cw" and arc.mode != "ccw") or not self.circles.closes(arc):
            return None  # a straight move, or an arc with its end point in its plane (most arcs)
        return self.take(block)


@mypyc_attr(allow_interpreted_subclasses=True)
class LowerForLeanController(LoweringStep):
    """``pause_for_tool_change``, ``cancel_length_offset_first``, ``close_full_circles`` and
    ``stops_after_motion`` (in that order) in one pass."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME:
            return stops_after_motion.start(ctx, target)
        return _Lean(ctx, not target.TOOL_CHANGER)


lower_for_lean_controller = LowerForLeanController()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Lean(BlockStep):
    """One run of the four: a move is its business (an arc may be a full circle to close), a straight one not
    (``passed``)."""

    def __init__(self, ctx: Context, pause: bool) -> None:
        super().__init__()
        self.pauses = _ToolChangePauses(ctx) if pause else None
        self.circles = _FullCircles()
        self.point = passed(ctx)

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        compound = sections.get("CompoundMotion")
        if compound is not None:
            if _expansion_only(sections):  # an expanded hole: only the spindle it leaves is noted
                pauses = self.pauses
                if pauses is not None:
                    pauses.follow(compound)
                return None
        elif watches_none(sections, _LEAN_WATCHED):
            arc = sections.get("Motion")
            if not isinstance(arc, Motion) or (arc.mode != "cw" and arc.mode != "ccw") or not self.circles.closes(arc):
                return None  # a straight move or an arc with its end point, a block number, a feed rate: no step
                # changes it (the plane and distance mode are those ``circles`` follows: the block sets neither)
        return self._rewrite(block)

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block that is only a move (``only_move``: none of ``_LEAN_WATCHED`` is there, not
        asked again): only an arc may be a full circle to close. An arc with its end point in its plane, most
        arcs, is told by ``_FullCircles.closes`` before ``_rewrite`` (which gave it back alone after a list a
        step: ~3,300 instructions an arc, ~190 a block of the benchmark's CAM program, callgrind)."""
        arc = block.sections["Motion"]
        if not isinstance(arc, Motion) or (arc.mode != "cw" and arc.mode != "ccw") or not self.circles.closes(arc):
            return None  # a straight move, or an arc with its end point in its plane: no step changes it
        return self._rewrite(block)

    def _rewrite(self, block: Block) -> list[Block]:
        """What the four steps make of a block that may be their business."""
        pauses = self.pauses
        paused = pauses.split(block) if pauses is not None else [block]
        made: list[Block] = []
        circles = self.circles
        for one in paused:
            first = _length_offset_cancel(one)
            if first is not None:
                made.extend(_stops_split(first, circles))
            made.extend(_stops_split(one, circles))
        return made


def passed(ctx: Context) -> NotedPoint:
    """The ``BlockStep.point`` of a step that a straight move alone in its block leaves as it is, in every state
    (``_Lean``, ``_CloseFullCircles``: only an arc may be a full circle to close): the lowering loop notes such a
    move of X, Y and Z numbers there, read once for all the steps that follow the point, instead of calling the
    step's ``take_move`` (which looked at it to give None: ~280 instructions a block compiled, every grbl and
    grblHAL translation, callgrind). Nothing reads what is noted there: nothing is (``PassedPoint``)."""
    return PassedPoint(move_words(ctx))


_EXPANSION_ONLY: Final = frozenset(("CompoundMotion", "Sequence", "Comments"))


def _expansion_only(sections: dict[str, Section]) -> bool:
    """A block that holds an expansion (``CompoundMotion``, asked first) is an expansion alone (an expanded cycle's
    hole), maybe numbered and commented: no step rewrites it (no tool change, length offset, arc or stop code of its
    own)."""
    if len(sections) == 1:  # (the expansion alone, most holes: no loop over the keys)
        return True
    for key in sections:
        if key not in _EXPANSION_ONLY:
            return False
    return True


def _stops_split(block: Block, circles: _FullCircles) -> list[Block]:
    """``close_full_circles`` then ``stops_after_motion`` on one block: what they make of it, in order."""
    back = circles.close(block)
    out = [block]
    after = split_stops_after_motion(block) if _has_stops(block.sections) else None
    if after is not None:
        out.append(after)
    if back is not None:
        out.extend(_stopped(back))
    return out


def _has_stops(sections: dict[str, Section]) -> bool:
    return "SpindleControl" in sections or "Coolant" in sections


def _stopped(block: Block) -> list[Block]:
    after = split_stops_after_motion(block) if _has_stops(block.sections) else None
    return [block] if after is None else [block, after]


_WATCHED: Final = frozenset(("ToolSelect", "ToolChange", "SpindleControl", "SpindleOrientation", "CompoundMotion"))
"""What ``pause_for_tool_change`` looks at: a block with none of these passes as it is."""
_UNWATCHED: Final = _WATCHED.isdisjoint
_LEAN_WATCHED: Final = _WATCHED | {"ToolLengthOffset", "Plane", "DistanceMode", "Coolant"}
"""What any of the four fused steps looks at besides an arc's ``Motion``."""
_PAUSE_KEYS: Final = ("Sequence", "BlockDelete", "ToolSelect", "ToolChange", "Comments")
"""What the pause block takes from the tool-change block (the rest runs after the pause)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class _ToolChangePauses:
    """``pause_for_tool_change``'s state: the tool selected and whether the spindle runs."""

    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx
        self.tool: int | Expr | None = None
        self.spindle = "stop"
        self.orient_stops = ctx.setup.cycles.orientation == "stop"
        self.items = expansion_items(ctx)

    def split(self, block: Block) -> list[Block]:
        """The block, preceded by the pause standing for its tool change (if it has one)."""
        sections = block.sections
        if _UNWATCHED(sections):
            return [block]
        out = [block]
        select = sections.get("ToolSelect")
        if isinstance(select, ToolSelect):
            self.tool = select.number
        if self.tool is not None and "ToolChange" in sections:
            pause = _pause(block, self.ctx, self.tool, self.spindle)
            self.spindle = "stop"
            if pause is not block:
                out.insert(0, pause)
        control = sections.get("SpindleControl")
        if isinstance(control, SpindleControl):
            self.spindle = control.direction
        if self.orient_stops and "SpindleOrientation" in sections:
            self.spindle = "stop"  # the writer stops the spindle before the operator orients it
        compound = sections.get("CompoundMotion")
        if compound is not None:
            self.follow(compound)
        return out

    def follow(self, compound: Section) -> None:
        """The spindle as an expansion leaves it (``ExpansionItems.spindle``: read once for the arc pass too)."""
        if isinstance(compound, CompoundMotion):
            items = self.items
            items.read(compound)
            spindle = items.spindle
            if spindle is not None:
                self.spindle = spindle


def _pause(block: Block, ctx: Context, tool: int | Expr, spindle: str) -> Block:
    """The pause ``T<n> [M5] M0 (TOOL CHANGE ...)`` standing for the block's tool change. grbl runs a
    block's spindle codes, motion and other stop codes before its M0, where the tool change comes first
    (the simulator's and a tool changer's order): whatever else the block does is left in ``block``, to
    run after the pause, and the pause is returned as a block of its own. A block that does nothing else
    becomes the pause (and is returned)."""
    sections = block.sections
    rest = {k: v for k, v in sections.items() if k not in _PAUSE_KEYS}
    control = sections.get("SpindleControl")
    stop_here = control is not None and control.direction == "stop"  # type: ignore[attr-defined]
    running = spindle != "stop"
    if stop_here and running:
        del rest["SpindleControl"]  # the block's M5 goes with the pause: it stops the running spindle
    pause: dict[str, Section] = {k: sections[k] for k in ("Sequence", "BlockDelete") if k in sections}
    pause["ToolSelect"] = ToolSelect(tool)
    if running and not stop_here:
        ctx.diagnostics.warn("the spindle is running at a tool change: a spindle stop is written before the pause", ctx.at(block))
    if running:
        pause["SpindleControl"] = SpindleControl("stop")
    # (a stopped spindle's M5 stays with the rest of the block, where the source runs it: after the tool
    # change and after the block's coolant on, ``postproc.ir.event_order``)
    pause["ProgramControl"] = ProgramControl("stop")
    note = f"TOOL CHANGE: LOAD T{tool}, THEN CYCLE START"
    comments = sections.get("Comments")
    pause["Comments"] = Comments([note] + (list(comments.texts) if comments is not None else []))  # type: ignore[attr-defined]
    if not rest:
        block.sections = pause
        block.changed()
        return block
    first = Block(block.line, None, block.eol or "\n")
    first.sections = pause
    if "BlockDelete" in sections:
        rest = {"BlockDelete": sections["BlockDelete"], **rest}
    block.sections = rest
    block.changed()
    return first


def _length_offset_cancel(block: Block) -> Block | None:
    """The block ``G49`` that goes before ``block`` (taken out of it), or None when it has no cancel beside
    motion."""
    sections = block.sections
    offset = sections.get("ToolLengthOffset")
    if not isinstance(offset, ToolLengthOffset) or offset.mode != "cancel" or (
            "Motion" not in sections and "CompoundMotion" not in sections):
        return None
    first = Block(block.line, None, "\n")
    first.sections = {"ToolLengthOffset": offset}
    del sections["ToolLengthOffset"]
    block.changed()
    return first


@mypyc_attr(allow_interpreted_subclasses=True)
class _FullCircles:
    """``close_full_circles``' state: the plane and the distance mode."""

    def __init__(self) -> None:
        self.plane = "XY"
        self.distance = "absolute"

    def close(self, block: Block) -> Block | None:
        """Give a full circle in ``block`` its zero end point; returns the block that restores G90 after
        it (when the circle is written in G91), else None."""
        sections = block.sections
        chosen = sections.get("Plane")
        if isinstance(chosen, Plane):
            self.plane = chosen.plane
        mode = sections.get("DistanceMode")
        if isinstance(mode, DistanceMode):
            self.distance = mode.mode
        arc = sections.get("Motion")
        if not isinstance(arc, Motion) or arc.mode not in ("cw", "ccw") or not self.closes(arc):
            return None
        a0 = PLANE_AXES[self.plane][0]
        absolute = self.distance == "absolute"
        sections["Motion"] = Motion(arc.mode, {a0: 0.0, **arc.axes}, arc.center, arc.radius)
        block.changed()
        if not absolute:
            return None
        sections["DistanceMode"] = DistanceMode("incremental")
        back = Block(block.line, None, block.eol or "\n")
        back.sections = {"DistanceMode": DistanceMode("absolute")}
        return back

    def closes(self, arc: Motion) -> bool:
        """Whether ``close`` gives ``arc`` (in the plane and distance mode followed so far) an end point: it has
        none in its plane and is no helix in absolute mode (which the writer refuses)."""
        a0, a1, _ = PLANE_AXES[self.plane]
        axes = arc.axes
        return not (a0 in axes or a1 in axes or (self.distance == "absolute" and len(axes) > 0))
