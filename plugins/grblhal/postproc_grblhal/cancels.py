"""Lowering step: a canned-cycle cancel in a block of its own where the block has axis words of its own.

grblHAL's G80 leaves no motion mode in force, and axis words are then refused even in ``G43.1 Z`` (error 31
[V: grblHAL core ``gcode.c``, "[G80 Errors]"]); its writer therefore writes a cancel as a bare ``G0`` (which ends
the cycle and moves nothing). A bare motion code conflicts with another axis command in its block (``G28 Z0``,
``G92``, ``G10``, ``G43.1 Z``: error 37, ``Status_GcodeAxisCommandConflict``), so a cancel sharing a block with
anything but modal settings stands in a block of its own before it (``GrblhalWriter.cycle_cancel_words``).
"""

from __future__ import annotations

from typing import Final, Iterator

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir import Block, Motion

GROUP_01: Final = frozenset(("rapid", "linear", "cw", "ccw"))
"""Motion modes that end a cycle themselves (no cancel is written beside them)."""
BESIDE_A_BARE_MOTION_CODE: Final = frozenset((
    "CycleCancel", "Sequence", "Comments", "BlockDelete", "SpindleControl", "SpindleSpeed", "Coolant",
    "ProgramControl", "Feed", "FeedMode", "ReturnLevel", "DistanceMode", "Units", "Plane", "ToolSelect",
    "WorkOffset", "PathControl", "Dwell",
))
"""What may share a block with a bare motion code: nothing with axis words of its own."""


def cancel_cycles_alone(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step (module docstring); a grblHAL program is written as it reads."""
    if ctx.dialect == target.NAME:
        return blocks
    return _alone(blocks)


def _alone(blocks: Iterator[Block]) -> Iterator[Block]:
    for block in blocks:
        sections = block.sections
        if "CycleCancel" not in sections or BESIDE_A_BARE_MOTION_CODE.issuperset(sections):
            yield block
            continue
        motion = sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in GROUP_01:
            yield block
            continue
        first = Block(block.line, None, "\n")
        first.sections = {key: sections.pop(key) for key in ("Sequence", "BlockDelete") if key in sections}
        if "BlockDelete" in sections:  # both halves are skipped with the block
            first.sections["BlockDelete"] = sections["BlockDelete"]
        first.sections["CycleCancel"] = sections.pop("CycleCancel")
        block.changed()
        yield first
        yield block
