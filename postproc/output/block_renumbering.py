"""``--renumber`` in a program's own dialect: an exact old -> new mapping of its block numbers.

The writer numbers the blocks it normalises (``WordWriter.normalized``), one after the other. A word that
names a block by its number (``GOTO n``, ``IF [..] GOTO n``, ``M99 P n``, a lathe cycle's profile range
``P ns Q nf``) must name the same block after, so the renumbering runs in two passes: ``Renumbering``
first goes over the whole program (the writer lists it: a renumbering run holds the program in memory) and
gives each block the number the writer will write on it, then the writer writes every literal reference
with its target's new number (``rewritten``). After the run, ``check`` holds the writer to that first pass:
a target written with another number than the one its references got (a dialect that keeps such a line
as written) refuses the reference, located.

What cannot be rewritten exactly is refused, located at the reference:

* a computed target (``GOTO #1``, ``GOTO [#1+10]``, ``M99 P#2``): its value is only known when it runs;
* a number no block of the program carries (Fanuc would alarm), or one that only a block the writer does
  not number carries (it keeps its number, another block may get the same one);
* a number on several blocks of the file (a subprogram's and the main program's included). Fanuc searches
  a jump's number forward from the jump, then from the program start [K: ``interp.control.Goto``, the
  Custom Macro B search as the interpreter runs it; not re-read in a manual here], so which block a
  repeated number names depends on where the jump stands, and on whether the controller holds the file's
  subprograms as programs of their own (this tool's simulator searches the whole file); a return's names
  a block of a caller not known here. The renumbering gives the blocks different numbers and the reference
  can only name one: refused rather than guessed;
* a new number that the program writes on more than one block (a block the writer does not number keeps
  its own, which may be a target's new one). ``--renumber`` has no maximum and does not wrap at
  ``numberMax`` (only ``<Output blockNumbers>``'s numbering of the written lines does, and it refuses every
  program that names block numbers): no wrapped number can land on a target.

A program number (Fanuc ``M98 P``, ``G65 P``) names a program, not a block: it is not rewritten.
"""

from __future__ import annotations

from typing import Callable

from ..errors import Location, ProgramError
from ..interp.control import CONTROL, Goto, Return
from ..ir import Block, Section
from ..ir.expr import Expr, Num
from .block_references import PROFILE_RANGE, names_block_numbers

def takes_number(block: Block) -> bool:
    """A renumbering run numbers this block (the writer's ``normalized`` does: a line of the dialect with words
    that opens no program)."""
    return block.text is not None and bool(block.words) and "ProgramStart" not in block.sections


class Renumbering:
    """The first pass of one renumbering run: the number each block will carry, and the references'."""

    def __init__(self, blocks: list[Block], start: int, step: int, takes_number: Callable[[Block], bool]) -> None:
        """``takes_number``: the writer numbers this block (the rule its ``normalized`` follows)."""
        self.blocks = blocks
        """The program, kept so every block's ``id`` names it until the run ends."""
        self.new: dict[int, int] = {}
        """``id`` of a block -> the number the writer will write on it."""
        self.by_old: dict[int, list[Block]] = {}
        """Old number -> the blocks of the file that carried it, in order."""
        self.written_numbers: dict[int, int] = {}
        """Number -> how many blocks of the file will carry it after the renumbering (the writer's numbers, and
        the old numbers of the blocks it does not number, which may keep them)."""
        self.actual: dict[int, int] = {}
        """``id`` of a block -> the number the writer did write on it (second pass)."""
        self.references: list[tuple[Block, Block, int]] = []
        """(referencing block, target block, the number written for it): checked after the run."""
        self.rewritten_ids: set[int] = set()
        """The referencing blocks the writer wrote through ``rewritten`` (or that it refused)."""
        number = start
        for block in blocks:
            sequence = block.sections.get("Sequence")
            old = getattr(sequence, "number", None) if sequence is not None else None
            if isinstance(old, int):
                self.by_old.setdefault(old, []).append(block)
            if takes_number(block):
                self.new[id(block)] = mark = number
                number += step
            elif isinstance(old, int):
                mark = old
            else:
                continue
            self.written_numbers[mark] = self.written_numbers.get(mark, 0) + 1

    def rewritten(self, block: Block, at: Callable[[Block, str | None], Location],
                  profile_letters: Callable[[Section], dict[str, str]]) -> Block:
        """``block`` with every block number it names replaced by its target's new number (a copy; the
        block itself is left as read). ``at``: where the block's word with that letter is (None: the
        block's start); ``profile_letters``: a lathe cycle's letter of each profile parameter (``ns``,
        ``nf``), the writer's family's spelling. Raises the located ``ProgramError`` of the first
        reference that cannot be rewritten exactly."""
        self.rewritten_ids.add(id(block))  # (written through here: refused here, or rewritten)
        sections = dict(block.sections)
        replaced: dict[str, int] = {}
        control = sections.get(CONTROL)
        if isinstance(control, Goto):
            new = self._target(block, control.target, at(block, None), "the jump's target")
            sections[CONTROL] = Goto(Num(float(new)), control.cond, control.fallthrough)
        elif isinstance(control, Return) and control.target is not None:
            new = self._target(block, control.target, at(block, None), "the return's block number")
            sections[CONTROL] = Return(control.name, control.value, Num(float(new)))
        elif control is not None and getattr(control, "target", None) is not None:
            raise ProgramError(f"--renumber cannot rewrite the block number a {type(control).__name__} names",
                               at(block, None))
        cycle = sections.get("LatheCycle")
        params = getattr(cycle, "params", None)
        if cycle is not None and isinstance(params, dict) and any(name in params for name in PROFILE_RANGE):
            letters = profile_letters(cycle)
            for name in PROFILE_RANGE:
                if name not in params:
                    continue
                letter = letters.get(name)
                if letter is None:
                    raise ProgramError(f"--renumber cannot tell which word of the cycle names its profile's "
                                       f"{'first' if name == 'ns' else 'last'} block", at(block, None))
                value = block.values.get(letter, params[name])
                where = at(block, letter)
                replaced[letter] = self._target(block, value, where,
                                                f"the profile's {'first' if name == 'ns' else 'last'} block")
        copy = Block(block.line, block.text, block.eol,
                     [(letter, str(replaced[letter.upper()]) if letter.upper() in replaced else num)
                      for letter, num in block.words])
        copy.values = dict(block.values)
        for letter, new in replaced.items():
            copy.values[letter] = new
        copy.sections = sections
        return copy

    def _target(self, block: Block, value: object, where: Location, what: str) -> int:
        """The new number of the block that ``value`` (a reference of ``block``) names."""
        if isinstance(value, Num):
            value = value.value
        if isinstance(value, Expr) or not isinstance(value, (int, float)):
            raise ProgramError(f"--renumber cannot rewrite a computed block number ({what} is only known when the "
                               f"program runs): write it as a number, or renumber without it", where)
        if value != int(value):
            raise ProgramError(f"--renumber: {what} N{value} is no block number", where)
        old = int(value)
        found = self.by_old.get(old, [])
        if not found:
            raise ProgramError(f"--renumber cannot rewrite {what} N{old}: no block of the "
                               f"file carries that number", where)
        if len(found) > 1:
            lines = ", ".join(str(target.line) for target in found[:4])
            raise ProgramError(f"--renumber cannot rewrite {what} N{old}: the number is on several blocks (lines "
                               f"{lines}) and the renumbering would give each its own", where)
        target = found[0]
        new = self.new.get(id(target))
        if new is None:
            raise ProgramError(f"--renumber cannot rewrite {what} N{old}: its block (line {target.line}) is not "
                               f"renumbered and keeps its number", where)
        if self.written_numbers.get(new, 0) > 1:
            raise ProgramError(f"--renumber cannot rewrite {what} N{old}: its new number N{new} would be on several "
                               f"blocks (a block that is not renumbered keeps that number)", where)
        self.references.append((block, target, new))
        return new

    def numbered(self, block: Block, number: int) -> None:
        """The writer wrote ``number`` on ``block`` (second pass)."""
        self.actual[id(block)] = number

    def check(self, at: Callable[[Block], Location]) -> list[ProgramError]:
        """After the run: a reference whose target was written with another number than the one it got, and a
        block that names block numbers and was not written through ``rewritten`` (its line kept as written)."""
        errors: list[ProgramError] = []
        for block in self.blocks:
            if names_block_numbers(block) and id(block) not in self.rewritten_ids:
                errors.append(ProgramError("--renumber cannot rewrite the block numbers this line names: the "
                                           "writer keeps it as written", at(block)))
        for block, target, new in self.references:
            if self.actual.get(id(target)) != new:
                errors.append(ProgramError(f"--renumber cannot rewrite a reference to line {target.line}: that block "
                                           f"is not written with N{new}", at(block)))
        return errors
