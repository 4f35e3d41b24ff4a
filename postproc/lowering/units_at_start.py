"""The units a program starts in, written for a target of another dialect (a lowering step).

A program that reads a length before it programs its units (``G20``/``G21``, Fagor/ISG ``G70``/``G71``) runs in
its controller's power-on units: a parameter of the machine (Fanuc parameter 0000#2 INI [K], LinuxCNC's
``[RS274NGC] RS274NGC_STARTUP_CODE`` or ``[TRAJ] LINEAR_UNITS`` [K], grbl's ``$13`` reports only), which a
program copied to another controller does not carry. The translation and ``verify`` read such a program in
millimetres (``ModalState.units``'s start, whatever the set-up's ``<Machine units>``, which is the unit of the
set-up's own lengths): so the target gets those units written before anything that reads a length, or an inch
machine would run every millimetre as an inch, and verify could not see it (it reads the translation as it
read the source).

The units go in the first block that has more than a program start, tape mark or comment, beside what it
programs (``G21 G90 G54``), or in a block of their own before it where that block may not run (a block-delete
``/`` block) or is not a plain block of modal words and motion (a subprogram definition, a loop). A program that
programs its units there or before needs nothing; a copy to the same dialect passes untouched.
"""

from __future__ import annotations

from typing import Final, Iterator

from ..context import Context
from ..dialect import Dialect
from ..ir import Block, Units
from ..state import ModalState

HEADER: Final = frozenset(("ProgramStart", "TapeMark", "Comments", "Sequence"))
"""Sections of a block that read no length: the units may come after them."""
PLAIN: Final = frozenset(("Comments", "Coolant", "CutterCompensation", "CycleCancel", "DistanceMode", "Dwell", "Feed",
                          "FeedMode", "MachineCoordinates", "MachineFunction", "Motion", "PathControl", "Plane",
                          "ProgramControl", "ReturnLevel", "Sequence", "SpindleControl", "SpindleOrientation",
                          "SpindleSpeed", "ToolChange", "ToolLengthOffset", "ToolSelect", "WorkOffset", "DataSetting",
                          "CycleCall", "CompoundMotion"))
"""Sections of a plain block (modal words, motion, a data setting): the units can join them (``G21 G90 G54``)."""


def write_units_at_start(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step: see the module docstring."""
    if ctx.dialect == target.NAME:
        return blocks
    return _carry(blocks, ModalState().units)


def _carry(blocks: Iterator[Block], units: str) -> Iterator[Block]:
    for block in blocks:
        keys = block.sections.keys()
        if "Units" in keys:
            yield block  # the program says its units before it reads a length
            yield from blocks
            return
        if not keys or HEADER.issuperset(keys):
            yield block
            continue
        if PLAIN.issuperset(keys):
            block.add(Units(units))
            block.changed()
        else:
            first = Block(block.line, None, "\n")
            first.add(Units(units))
            yield first
        yield block
        yield from blocks
        return
