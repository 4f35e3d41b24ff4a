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
"""

from __future__ import annotations

from typing import Iterator, Final

from ..context import Context
from ..dialect import Dialect
from ..expr import Expr
from ..ir import (
    Block, Comments, CompoundMotion, DistanceMode, Motion, Plane, ProgramControl, Section, SpindleControl,
    ToolLengthOffset, ToolSelect,
)
from ..state import PLANE_AXES


def pause_for_tool_change(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME or target.TOOL_CHANGER:
        return blocks
    return _pause_for_tool_change(blocks, ctx)


def _pause_for_tool_change(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    tool: int | Expr | None = None
    spindle = "stop"
    orient_stops = ctx.setup.cycles.orientation == "stop"
    for block in blocks:
        sections = block.sections
        if _UNWATCHED(sections):  # a CAM block (a move, a block number, a feed rate): one set test
            yield block
            continue
        select = sections.get("ToolSelect")
        if isinstance(select, ToolSelect):
            tool = select.number
        if tool is not None and "ToolChange" in sections:
            pause = _pause(block, ctx, tool, spindle)
            spindle = "stop"
            if pause is not block:
                yield pause
        control = sections.get("SpindleControl")
        if isinstance(control, SpindleControl):
            spindle = control.direction
        if orient_stops and "SpindleOrientation" in sections:
            spindle = "stop"  # the writer stops the spindle before the operator orients it
        compound = sections.get("CompoundMotion")
        if isinstance(compound, CompoundMotion):
            for item in compound.items:
                if isinstance(item, SpindleControl):
                    spindle = item.direction
                elif isinstance(item, ProgramControl) and item.kind == "stop":
                    spindle = "stop"  # the writer stops a running spindle before a pause
        yield block


_WATCHED: Final = frozenset(("ToolSelect", "ToolChange", "SpindleControl", "SpindleOrientation", "CompoundMotion"))
"""What ``pause_for_tool_change`` looks at: a block with none of these passes as it is."""
_UNWATCHED: Final = _WATCHED.isdisjoint
_PAUSE_KEYS: Final = ("Sequence", "BlockDelete", "ToolSelect", "ToolChange", "Comments")
"""What the pause block takes from the tool-change block (the rest runs after the pause)."""


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
    if stop_here:
        del rest["SpindleControl"]  # the block's M5 goes with the pause
    pause: dict[str, Section] = {k: sections[k] for k in ("Sequence", "BlockDelete") if k in sections}
    pause["ToolSelect"] = ToolSelect(tool)
    if spindle != "stop" and not stop_here:
        ctx.diagnostics.warn("the spindle is running at a tool change: a spindle stop is written before the pause", ctx.at(block))
    if spindle != "stop" or stop_here:
        pause["SpindleControl"] = SpindleControl("stop")
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


def cancel_length_offset_first(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME:
        return blocks
    return _cancel_length_offset_first(blocks)


def _cancel_length_offset_first(blocks: Iterator[Block]) -> Iterator[Block]:
    for block in blocks:
        sections = block.sections
        offset = sections.get("ToolLengthOffset")
        if not isinstance(offset, ToolLengthOffset) or offset.mode != "cancel" or (
                "Motion" not in sections and "CompoundMotion" not in sections):
            yield block
            continue
        first = Block(block.line, None, "\n")
        first.sections = {"ToolLengthOffset": offset}
        yield first
        del sections["ToolLengthOffset"]
        block.changed()
        yield block


def close_full_circles(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME:
        return blocks
    return _close_full_circles(blocks)


def _close_full_circles(blocks: Iterator[Block]) -> Iterator[Block]:
    plane = "XY"
    distance = "absolute"
    for block in blocks:
        sections = block.sections
        chosen = sections.get("Plane")
        if isinstance(chosen, Plane):
            plane = chosen.plane
        mode = sections.get("DistanceMode")
        if isinstance(mode, DistanceMode):
            distance = mode.mode
        arc = sections.get("Motion")
        if not isinstance(arc, Motion) or arc.mode not in ("cw", "ccw"):
            yield block
            continue
        a0, a1, _ = PLANE_AXES[plane]
        absolute = distance == "absolute"
        if a0 in arc.axes or a1 in arc.axes or (absolute and arc.axes):
            yield block  # an end point in the plane; or a helix the writer refuses
            continue
        sections["Motion"] = Motion(arc.mode, {a0: 0.0, **arc.axes}, arc.center, arc.radius)
        block.changed()
        if not absolute:
            yield block
            continue
        sections["DistanceMode"] = DistanceMode("incremental")
        eol = block.eol
        yield block
        back = Block(block.line, None, eol or "\n")
        back.sections = {"DistanceMode": DistanceMode("absolute")}
        yield back
