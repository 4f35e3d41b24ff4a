"""The RS274/NGC order of execution for a block that moves and also stops the spindle or the coolant.

LinuxCNC (and grbl, which follows the NIST order) turn the spindle and the coolant on or off *before*
the block's motion (items 8 and 9 of the order of execution, motion is item 20): ``G1 X10 M5`` stops
the spindle and then cuts. A Fanuc-family block does what ends it after the motion, as the simulator
does (``postproc.event_order``). Written unchanged for such a target, the cut would run with the spindle
or the coolant already off: this lowering step moves a moving block's spindle stop and coolant off into
a block of their own right after it. Starting the spindle or the coolant stays in the block: both
orders run it before the motion.
"""

from __future__ import annotations

from typing import Iterator

from ..context import Context
from ..dialect import Dialect
from ..ir import Block

_STOPS = ("SpindleControl", "Coolant")


def stops_after_motion(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step for RS274/NGC targets (see the module docstring)."""
    for block in blocks:
        sections = block.sections
        motion = sections.get("Motion")
        if motion is None or not getattr(motion, "axes", None):
            yield block
            continue
        moved = {key: sections[key] for key in _STOPS if key in sections and _stops(sections[key])}
        if not moved:
            yield block
            continue
        for key in moved:
            del sections[key]
        block.changed()
        after = Block(block.line, None, block.eol or "\n")
        after.sections = moved
        block.eol = "\n"
        yield block
        yield after


def _stops(section: object) -> bool:
    return getattr(section, "direction", None) == "stop" or getattr(section, "mode", None) == "off"
