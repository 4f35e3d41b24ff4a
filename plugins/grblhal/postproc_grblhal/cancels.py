"""Lowering step: a canned-cycle cancel in a block of its own where the block has axis words of its own.

grblHAL's G80 leaves no motion mode in force, and axis words are then refused even in ``G43.1 Z`` (error 31
[V: grblHAL core ``gcode.c``, "[G80 Errors]"]); its writer therefore writes a cancel as a bare ``G0`` (which ends
the cycle and moves nothing). A bare motion code conflicts with another axis command in its block (``G28 Z0``,
``G92``, ``G10``, ``G43.1 Z``: error 37, ``Status_GcodeAxisCommandConflict``), so a cancel sharing a block with
anything but modal settings stands in a block of its own before it (``GrblhalWriter.cycle_cancel_words``).
"""

from __future__ import annotations

from typing import Final

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir import Block, Motion
from postproc.lowering.lower import BlockStep, LoweringStep

GROUP_01: Final = frozenset(("rapid", "linear", "cw", "ccw"))
"""Motion modes that end a cycle themselves (no cancel is written beside them)."""
BESIDE_A_BARE_MOTION_CODE: Final = frozenset((
    "CycleCancel", "Sequence", "Comments", "BlockDelete", "SpindleControl", "SpindleSpeed", "Coolant",
    "ProgramControl", "Feed", "FeedMode", "ReturnLevel", "DistanceMode", "Units", "Plane", "ToolSelect",
    "WorkOffset", "PathControl", "Dwell",
))
"""What may share a block with a bare motion code: nothing with axis words of its own."""


class CancelCyclesAlone(LoweringStep):
    """Lowering step (module docstring); a grblHAL program is written as it reads."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return None if ctx.dialect == target.NAME else _Alone()


cancel_cycles_alone = CancelCyclesAlone()


class _Alone(BlockStep):
    def __init__(self) -> None:
        super().__init__()
        self.moves = False  # a block that is only a move holds no cancel

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if "CycleCancel" not in sections or BESIDE_A_BARE_MOTION_CODE.issuperset(sections):
            return None
        motion = sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in GROUP_01:
            return None
        first = Block(block.line, None, "\n")
        first.sections = {key: sections.pop(key) for key in ("Sequence", "BlockDelete") if key in sections}
        if "BlockDelete" in sections:  # both halves are skipped with the block
            first.sections["BlockDelete"] = sections["BlockDelete"]
        first.sections["CycleCancel"] = sections.pop("CycleCancel")
        block.changed()
        return [first, block]
