"""Which of a block's actions run before its motion and which after, as a controller runs them.

One rule for the writer and the simulator (``postproc.simulate.toolpath``): a block that holds both motion and
machine actions does what the motion needs first (tool change, spindle start, coolant on, a dwell,
every modal setting) and what ends it last (spindle stop, orientation, coolant off, program stop or
end). An expanded canned cycle written as several lines keeps that order, so the hole is never fed with
the spindle stopped or the old tool.

A reader whose controller stops the spindle or the coolant *before* the motion (the RS274/NGC order of
execution: LinuxCNC, grbl) says so on the section (``before_motion``); such a stop acts before it.
"""

from __future__ import annotations

from typing import Mapping

from . import Section

AFTER_MOTION = frozenset(("SpindleOrientation", "ProgramControl"))
"""Sections that always act after the block's motion."""
MACHINE_AFTER = frozenset(("spindle-stop", "coolant-off", "stop", "optional-stop"))
"""Actions of a machine-specific code (``MachineFunction``) that act after the motion, as their standard
counterparts do."""
MOVING = frozenset(("CompoundMotion", "CycleCall", "CannedCycle"))
"""Sections that make a block move whatever its ``Motion`` holds (a canned cycle or its expansion)."""


def after_motion(key: str, section: Section) -> bool:
    """True when the section acts after the block's motion: a spindle stop, coolant off, an oriented
    stop, a program stop or end. Everything else (modal settings, tool change, spindle start, coolant
    on, dwell, a stop flagged ``before_motion``) acts before it."""
    if key in AFTER_MOTION:
        return True
    if key == "SpindleControl":
        return section.direction == "stop" and not section.before_motion  # type: ignore[attr-defined]
    if key == "Coolant":
        return section.mode == "off" and not section.before_motion  # type: ignore[attr-defined]
    if key == "MachineFunction":
        return section.action in MACHINE_AFTER  # type: ignore[attr-defined]
    return False


def moves(sections: Mapping[str, Section]) -> bool:
    """True when a block moves the machine: a motion with axis words, a canned cycle or its expansion."""
    motion = sections.get("Motion")
    if motion is not None and getattr(motion, "axes", None):
        return True
    return not MOVING.isdisjoint(sections.keys())
