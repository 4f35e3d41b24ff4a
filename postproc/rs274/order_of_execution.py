"""The RS274/NGC order of execution for a block that moves and also stops the spindle or the coolant.

LinuxCNC (and grbl, which follows the NIST order) turn the spindle and the coolant on or off *before*
the block's motion (the NIST RS274/NGC v3 order of execution: spindle 7, coolant 8, motion 20): ``G1 X10 M5`` stops
the spindle and then cuts. A Fanuc-family block does what ends it after the motion, as the simulator
does (``postproc.ir.event_order``). Two lowering steps keep each stop where the source made it:

* ``stops_after_motion`` (RS274/NGC targets): a stop the source made after the motion (a Fanuc
  ``G01 X10. M05``) moves into a block of its own right after the moving block;
* ``stops_before_motion`` (Fanuc-family targets): a stop the source made before the motion (the reader
  flagged it ``before_motion``) moves into a block of its own right before it.

Starting the spindle or the coolant stays in the block: both orders run it before the motion.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
import copy
from typing import Final

from ..context import Context
from ..dialect import Dialect
from ..ir.event_order import moves
from ..ir import Block, Section
from ..lowering.lower import BlockStep, LoweringStep

_STOPS: Final[tuple[str, ...]] = ("SpindleControl", "Coolant")
"""What a block stops (or starts): most blocks hold neither, tested first with two dict look-ups (measured:
a ``frozenset.isdisjoint`` of the sections cost several times more per block)."""
_AFTER_STOPS: Final[tuple[str, ...]] = ("SpindleOrientation", "ProgramControl")
"""What acts after a block's stops (``postproc.ir.event_order``): an oriented stop, then a program stop or
end. It follows the stops into their block, so ``Y2.5 M05 M19`` stops the spindle before orienting it."""
_TOOL: Final[tuple[str, ...]] = ("ToolSelect", "ToolChange")
"""What RS274/NGC does before the spindle and the coolant (select tool 5, change tool 6): it goes along
into the block before, so a tool change still precedes a coolant off."""


@mypyc_attr(allow_interpreted_subclasses=True)
class StopsAfterMotion(LoweringStep):
    """Lowering step for RS274/NGC targets (see the module docstring)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _StopsAfter()


stops_after_motion = StopsAfterMotion()


@mypyc_attr(allow_interpreted_subclasses=True)
class _StopsAfter(BlockStep):
    """One run: only a block that stops or starts the spindle or the coolant is its business."""

    def __init__(self) -> None:
        super().__init__()
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if "SpindleControl" not in sections and "Coolant" not in sections:
            return None
        after = split_stops_after_motion(block)
        return None if after is None else [block, after]


def split_stops_after_motion(block: Block) -> Block | None:
    """The block ``stops_after_motion`` makes of a moving block's stops (taken out of ``block``), or None
    when the block has none to move. A step that fuses several per-block rewrites calls it."""
    sections = block.sections
    motion = sections.get("Motion")
    if motion is None or not getattr(motion, "axes", None):
        return None
    moved = {key: sections[key] for key in _STOPS if key in sections and _stops(sections[key])}
    if not moved:
        return None
    for key in _AFTER_STOPS:  # what the block does after its stops goes along, in the simulator's order
        if key in sections:
            moved[key] = sections[key]
    for key in moved:
        del sections[key]
    block.changed()
    after = Block(block.line, None, block.eol or "\n")
    after.sections = moved
    block.eol = "\n"
    return after


@mypyc_attr(allow_interpreted_subclasses=True)
class StopsBeforeMotion(LoweringStep):
    """Lowering step for targets that stop after the motion (see the module docstring). A source that
    stops after the motion too flags nothing: its blocks pass with no step each."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _StopsBefore() if ctx.stops_before_motion else None


stops_before_motion = StopsBeforeMotion()


@mypyc_attr(allow_interpreted_subclasses=True)
class _StopsBefore(BlockStep):
    """One run: only a block that stops or starts the spindle or the coolant is its business."""

    def __init__(self) -> None:
        super().__init__()
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if "SpindleControl" not in sections and "Coolant" not in sections:
            return None  # most blocks: nothing to move before the motion
        flagged = [key for key in _STOPS if key in sections and _flagged(sections[key])]
        if not flagged or not moves(sections):
            return None
        # what RS274/NGC runs before those stops goes with them: the tool change, then the spindle (S, M3/M4/M5)
        taken = set(flagged).union(key for key in (*_TOOL, "SpindleSpeed", "SpindleControl") if key in sections)
        before = Block(block.line, None, block.eol or "\n")
        before.sections = {key: _unflagged(sections.pop(key)) for key in list(sections) if key in taken}
        block.changed()
        return [before, block]


def _stops(section: object) -> bool:
    """A stop the source made after the motion."""
    stop = getattr(section, "direction", None) == "stop" or getattr(section, "mode", None) == "off"
    return stop and not _flagged(section)


def _flagged(section: object) -> bool:
    return getattr(section, "before_motion", False) is True


def _unflagged(section: Section) -> Section:
    """The section as it reads in a block without motion, where the flag says nothing."""
    if not _flagged(section):
        return section
    plain = copy.copy(section)
    plain.before_motion = False  # type: ignore[attr-defined]
    return plain
