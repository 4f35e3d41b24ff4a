"""Which of a block's actions run before its motion and which after, as a controller runs them.

One rule for the writer and the simulator (``postproc.toolpath``): a block that holds both motion and
machine actions does what the motion needs first (tool change, spindle start, coolant on, a dwell,
every modal setting) and what ends it last (spindle stop, orientation, coolant off, program stop or
end). An expanded canned cycle written as several lines keeps that order, so the hole is never fed with
the spindle stopped or the old tool.
"""

from __future__ import annotations

from .ir import Section

AFTER_MOTION = frozenset(("SpindleOrientation", "ProgramControl"))
"""Sections that always act after the block's motion."""


def after_motion(key: str, section: Section) -> bool:
    """True when the section acts after the block's motion: a spindle stop, coolant off, an oriented
    stop, a program stop or end. Everything else (modal settings, tool change, spindle start, coolant
    on, dwell) acts before it."""
    if key in AFTER_MOTION:
        return True
    if key == "SpindleControl":
        return section.direction == "stop"  # type: ignore[attr-defined, no-any-return]
    if key == "Coolant":
        return section.mode == "off"  # type: ignore[attr-defined, no-any-return]
    return False
