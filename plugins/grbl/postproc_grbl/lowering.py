"""grbl's own lowering steps (``Grbl.LOWERING``): pure block-stream rewrites into what grbl 1.1 runs.

* ``pause_for_tool_change``: grbl rejects M6 (no tool changer), so a tool change becomes a program
  pause ``T<n> M0`` with a comment naming the tool; a running spindle is stopped first, as a tool
  changer would (with a warning). The grbl reader reads ``T<n> M0`` back as a tool change. In a block
  that also moves, the pause goes in a block of its own before it (M0 acts after a block's motion).
* ``cancel_length_offset_first``: grbl refuses G49 (an axis command of its own) in a block with
  motion, so the cancel goes in a block of its own before the motion.
* ``close_full_circles``: grbl needs an end point in the plane of every arc (no full-circle form), so
  a full circle written as ``G3 I-7.`` gets a zero increment, in G91 for that one block. A helical full
  circle in absolute mode cannot be written so: it reaches the writer unchanged and is refused there.

Each step passes a program back to grbl untouched (it is copied or normalised from its own words).
"""

from __future__ import annotations

from typing import Iterator

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir import (
    Block, Comments, CompoundMotion, DistanceMode, Motion, ProgramControl, Section, SpindleControl, ToolSelect,
)
from postproc.state import PLANE_AXES


def pause_for_tool_change(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME or target.TOOL_CHANGER:
        return blocks
    return _pause_for_tool_change(blocks, ctx)


def _pause_for_tool_change(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    tool: int | None = None
    spindle = "stop"
    orient_stops = ctx.setup.cycles.orientation == "stop"
    for block in blocks:
        sections = block.sections
        if not sections:
            yield block
            continue
        select = sections.get("ToolSelect")
        if select is not None:
            tool = select.number  # type: ignore[attr-defined]
        if "ToolChange" in sections and ("Motion" in sections or "CompoundMotion" in sections):
            first = _pause_first(block)
            _pause(first, ctx, tool, spindle)
            yield first
            spindle = "stop"
        elif "ToolChange" in sections and "ProgramControl" not in sections:
            _pause(block, ctx, tool, spindle)
            spindle = "stop"
        control = sections.get("SpindleControl")
        if control is not None:
            spindle = control.direction  # type: ignore[attr-defined]
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


def _pause_first(block: Block) -> Block:
    """The tool change of a block that also moves, in a block of its own before it: grbl runs M0 after
    the block's motion, and the motion needs the new tool (``postproc.event_order``)."""
    sections = block.sections
    first = Block(block.line, None, "\n")
    first.sections = {"ToolChange": sections.pop("ToolChange")}
    select = sections.pop("ToolSelect", None)
    if select is not None:
        first.sections["ToolSelect"] = select
    block.changed()
    return first


def _pause(block: Block, ctx: Context, tool: int | None, spindle: str) -> None:
    sections = block.sections
    rest = {k: v for k, v in sections.items() if k != "ToolChange"}
    added: dict[str, Section] = {}
    if "ToolSelect" not in sections and tool is not None:
        added["ToolSelect"] = ToolSelect(tool)
    if spindle != "stop" and "SpindleControl" not in sections:
        ctx.diagnostics.warn("the spindle is running at a tool change: M5 written before the pause",
                             ctx.at(block))
        added["SpindleControl"] = SpindleControl("stop")
    added["ProgramControl"] = ProgramControl("stop")
    name = f"T{tool}" if tool is not None else "THE NEXT TOOL"
    note = f"TOOL CHANGE: LOAD {name}, THEN CYCLE START"
    comments = rest.pop("Comments", None)
    added["Comments"] = Comments([note] + (list(comments.texts) if comments is not None else []))  # type: ignore[attr-defined]
    block.sections = {**rest, **added}
    block.changed()


def cancel_length_offset_first(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    if ctx.dialect == target.NAME:
        return blocks
    return _cancel_length_offset_first(blocks)


def _cancel_length_offset_first(blocks: Iterator[Block]) -> Iterator[Block]:
    for block in blocks:
        sections = block.sections
        offset = sections.get("ToolLengthOffset")
        if offset is None or offset.mode != "cancel" or (  # type: ignore[attr-defined]
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
        s = sections.get("Plane")
        if s is not None:
            plane = s.plane  # type: ignore[attr-defined]
        s = sections.get("DistanceMode")
        if s is not None:
            distance = s.mode  # type: ignore[attr-defined]
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
