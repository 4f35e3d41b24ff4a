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
  its own, which may be a target's new one).

Past the set-up's ``numberMax`` (the largest number its controller takes: a Fanuc's or LinuxCNC's N address
has five digits, a sixth is an alarm) the numbering wraps back to START (``following``), as
``<Output blockNumbers>``'s numbering of the written lines does. A wrap gives a number to a second block,
which is harmless where nothing names it (a block number is then a label) but makes a reference ambiguous
where its target's new number comes round again: that is refused, once, located at the first block past
``numberMax`` (the one the wrap renumbers: ``wrapped``). A START above ``numberMax`` leaves nothing to wrap
into and is not wrapped (the writer refuses its first block where the dialect states no limit of its own,
and grbl's 10,000,000 stands: ``Writer.MAX_BLOCK_NUMBER``). (Was: no maximum, N100000 written for a Fanuc,
exit 0.)

A program number (Fanuc ``M98 P``, ``G65 P``) names a program, not a block: it is not rewritten.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

from ..errors import Location, ProgramError
from ..interp.control import CONTROL, Goto, Return
from ..ir import Block, Section
from ..ir.expr import Expr, Num
from .block_references import PROFILE_RANGE, names_block_numbers

if TYPE_CHECKING:
    from ..setup.groups import OutputSettings


def takes_number(block: Block) -> bool:
    """A renumbering run numbers this block (the writer's ``normalized`` does: a line of the dialect with words
    that opens no program)."""
    return block.text is not None and bool(block.words) and "ProgramStart" not in block.sections


def following(number: int, step: int, start: int, ceiling: int) -> int:
    """The number after ``number``: past ``ceiling`` (``numberMax``) back to ``start``, where ``start`` is under it."""
    after = number + step
    return start if after > ceiling >= start else after


def refusal(number: int, limit: int, dialect: str, ceiling: int) -> str | None:
    """Why the controller takes no block ``number`` (None: it does). ``limit``: the dialect's own largest
    (``Writer.MAX_BLOCK_NUMBER``, grbl's; 0: none stated), else the set-up's ``numberMax`` (``ceiling``) is."""
    if limit and number > limit:
        return (f"--renumber numbers this block N{number}, above {limit}, the largest the {dialect} controller takes "
                f"(it refuses the line): start or step lower")
    if not limit and number > ceiling:  # (a START above it: nothing to wrap into)
        return (f"--renumber numbers this block N{number}, above numberMax {ceiling}, the largest block number the "
                f"set-up's controller takes (<Output numberMax>): start at {ceiling} or lower")
    return None


class Renumbering:
    """The first pass of one renumbering run: the number each block will carry, and the references'."""

    def __init__(self, blocks: list[Block], start: int, output: "OutputSettings",
                 takes_number: Callable[[Block], bool]) -> None:
        """``output``: the set-up's, its ``renumberStep`` and its ``numberMax``, past which the numbering wraps to
        ``start`` (``following``); ``takes_number``: the writer numbers this block (its ``normalized``'s rule)."""
        step = output.renumber_step
        ceiling = output.number_max
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
        self.ceiling = ceiling
        self.start = start
        self.step = step
        self.next = start
        """The number the writer's next numbered block gets (``take``, second pass)."""
        self.wrapped: tuple[Block, int] | None = None
        """The first block past ``numberMax`` and the number it would have got: the wrap renumbers it START."""
        self.wrap_refused = False
        """A reference the wrap made ambiguous was refused (once a run: the run has failed)."""
        self.at: Callable[[Block, str | None], Location] = lambda block, letter: Location("", block.line, 1)
        """Where a block's word is (``rewritten``'s ``at``, kept for a refusal located at another block)."""
        self.numbered_times: dict[int, int] = {}
        """Number -> how many blocks the numbering gives it (more than one only past a wrap)."""
        passed: int | None = None
        """The number past ``numberMax`` the last block would have been followed by."""
        number = start
        for block in blocks:
            sequence = block.sections.get("Sequence")
            old = getattr(sequence, "number", None) if sequence is not None else None
            if isinstance(old, int):
                self.by_old.setdefault(old, []).append(block)
            if takes_number(block):
                if passed is not None and self.wrapped is None:
                    self.wrapped = (block, passed)
                self.new[id(block)] = mark = number
                self.numbered_times[mark] = self.numbered_times.get(mark, 0) + 1
                after = following(number, step, start, ceiling)
                passed = number + step if after != number + step else None
                number = after
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
        self.at = at
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
        if self.written_numbers.get(new, 0) > 1 and self.numbered_times.get(new, 0) > 1 and self.wrapped is not None:
            past, would = self.wrapped
            if self.wrap_refused:
                return new  # (refused once, at the wrap: the run has failed)
            self.wrap_refused = True
            raise ProgramError(f"--renumber would number this block N{would}, past numberMax {self.ceiling} (the largest "
                               f"block number the set-up's controller takes), and wrapped back to N{self.new[id(past)]} "
                               f"the numbering gives N{new} to several blocks: {what} on line {block.line}, N{old}, "
                               f"would name more than one block. Renumber with a smaller START or STEP (or raise "
                               f"numberMax, if the controller takes more digits)", self.at(past, None))
        if self.written_numbers.get(new, 0) > 1:
            raise ProgramError(f"--renumber cannot rewrite {what} N{old}: its new number N{new} would be on several "
                               f"blocks (a block that is not renumbered keeps that number)", where)
        self.references.append((block, target, new))
        return new

    def take(self, block: Block, limit: int, dialect: str, at: Callable[[Block], Location]) -> int:
        """The number the writer writes on ``block``, the next (second pass); a located error where the controller
        takes no such number (``refusal``: ``limit`` is the dialect's own, 0 none)."""
        number = self.next
        problem = refusal(number, limit, dialect, self.ceiling)
        if problem is not None:
            raise ProgramError(problem, at(block))
        self.actual[id(block)] = number
        self.next = following(number, self.step, self.start, self.ceiling)
        return number

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
