"""The units a program starts in, written for a target of another dialect (a lowering step).

A program that reads a length before it programs its units (``G20``/``G21``, Fagor/ISG ``G70``/``G71``) runs in
its controller's power-on units: a parameter of the machine (Fanuc parameter 0000#2 INI [K], LinuxCNC's
``[RS274NGC] RS274NGC_STARTUP_CODE`` or ``[TRAJ] LINEAR_UNITS`` [K], grbl's ``$13`` reports only), which a
program copied to another controller does not carry. The translation and ``verify`` read such a program in
millimetres (``ModalState.units``'s start, whatever the set-up's ``<Machine units>``, which is the unit of the
set-up's own lengths): so the target gets those units written before anything that reads a length, or an inch
machine would run every millimetre as an inch, and verify could not see it (it reads the translation as it
read the source).

A subprogram defined before the main program (LinuxCNC ``o<name> sub``, ISG ``%L``) is passed over: it runs
where it is called. The units go in the first block that has more than a program start, tape mark or comment, beside what it
programs (``G21 G90 G54``), or in a block of their own before it where that block may not run (a block-delete
``/`` block) or is not a plain block of modal words and motion (a subprogram definition, a loop). A program that
programs its units there or before needs nothing; a copy to the same dialect passes untouched.
"""

from __future__ import annotations

from ..context import Context
from ..interp.control import SubEnd, SubStart
from ..dialect import Dialect
from ..ir import Block, Units
from .lower import BlockStep, LoweringStep
from ..ir.state import ModalState
from ..syntaxes.power_on_units import HEADER, PLAIN


class WriteUnitsAtStart(LoweringStep):
    """Lowering step: see the module docstring."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME or ctx.setup.controller.start_units is not None:
            return None  # (the reading put the set-up's power-on units where the program first reads a length)
        return _Units(ModalState().units)


write_units_at_start = WriteUnitsAtStart()


class _Units(BlockStep):
    """One run: every block until the first that reads a length (or says its units); none after it
    (``moves`` False: a plain move is then not its business, and ``done`` passes any other block)."""

    def __init__(self, units: str) -> None:
        super().__init__()
        self.units = units
        self.done = False
        self.depth = 0
        """Subprogram definitions open around the block (they come before the program that calls them)."""

    def take(self, block: Block) -> list[Block] | None:
        if self.done:
            return None
        control = block.sections.get("Control")
        if isinstance(control, SubStart):
            self.depth += 1  # a definition runs where it is called, not here: its lengths are read later
            return None
        if isinstance(control, SubEnd):
            self.depth -= 1
            return None
        if self.depth:
            return None
        keys = block.sections.keys()
        if not keys or ("Units" not in keys and HEADER.issuperset(keys)):
            return None
        self.done = True
        self.moves = False
        self.passes = True  # (no block is its business any more)
        if "Units" in keys:
            return None  # the program says its units before it reads a length
        if PLAIN.issuperset(keys):
            block.add(Units(self.units))
            block.changed()
            return None
        first = Block(block.line, None, "\n")
        first.add(Units(self.units))
        return [first, block]
