"""Structured control flow as Custom Macro B jumps to block numbers: a lowering for Fanuc-family targets.

Macro B has ``IF [c] GOTO n``, ``GOTO n`` and ``WHILE [c] DOm`` .. ``ENDm`` [V: DIALECTS.md 1.1 "Control
flow"]: no ``ELSE``, no loop tested at its end, no named label. The standard spelling of the others is
conditional jumps to block numbers, each number on one block, which is what this step writes:

* ``If c`` .. ``ElseIf d`` .. ``Else`` .. ``EndIf``: ``IF [not c] GOTO a`` .. ``GOTO e`` / ``Na`` /
  ``IF [not d] GOTO b`` .. ``GOTO e`` / ``Nb`` .. ``Ne`` (the branch's test jumps past it when it is false;
  the end of a branch taken jumps to the end);
* ``Do`` .. ``Until c`` (or ``DoWhile c``): ``Na`` .. ``IF [not c] GOTO a`` (``IF [c] GOTO a``);
* a named ``Label`` and every ``GotoLabel`` to it: ``Na`` on a block of its own before the labelled block,
  ``GOTO a``; a label on two blocks is refused (the neutral jump would take the first one searched).

The numbers start above the program's highest block number (``HIGHEST_SEQUENCE``, which the interpreter
step records when it keeps the program), so none meets one of the program's own and Fanuc's search (forward
from the jump, then from the start) finds each on its one block, as the neutral jump does. A number beyond
``MAX_SEQUENCE`` is refused. Fanuc wants an operator in every condition [K: Fanuc 0i-MF operator's manual,
"Conditional expressions" use EQ NE GT GE LT LE]: a bare value ``v`` in a condition this step writes becomes
``v NE 0``, and ``and``/``or``/``xor`` of comparisons (1 or 0) Fanuc's ``AND``/``OR``/``XOR``, exact on 0 and 1.
Jumping out of a ``WHILE`` loop is allowed, into one is not [K: same manual, "Repetition": "branch from
inside the loop to the outside"]: every jump written here stays in its construct or leaves it.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Iterator

from ..interp.conditions import negated, truth
from ..context import Context
from ..interp.control import (
    CONTROL, Do, DoWhile, Else, ElseIf, EndIf, Goto, GotoLabel, If, Until, While,
)
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir.expr import Binary, Expr, Num
from ..ir import Block, Section
from ..ir.modal import Sequence
from ..syntaxes.program import HIGHEST_SEQUENCE

MAX_SEQUENCE = 99999
"""The highest block number Fanuc writes: ``N`` + 5 digits [K: DIALECTS.md 1.1, 8 digits on a 30i only]."""
LABEL = "Label"
_BITWISE = {"and": "bitand", "or": "bitor", "xor": "bitxor"}
_SPELT = (If, ElseIf, Else, EndIf, Do, Until, DoWhile, GotoLabel)


def number_jumps(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Each ``If``/``ElseIf``/``Else``/``EndIf``, ``Do``/``Until``/``DoWhile``, ``Label`` and ``GotoLabel``
    as Macro B jumps to block numbers of their own (module docstring); every other block as it is. Back to
    the reading dialect itself the stream passes through (its own statements are Macro B already)."""
    if ctx.dialect == target.NAME:
        return blocks
    return _numbered_jumps(blocks, ctx)


def _numbered_jumps(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    jumps: _Jumps | None = None
    control_key, label_key = CONTROL, LABEL
    for block in blocks:
        sections = block.sections
        if control_key not in sections and label_key not in sections:
            yield block  # the common block: no statement, no label
            continue
        control = sections.get(control_key)
        if label_key not in sections and not isinstance(control, _SPELT):
            if isinstance(control, (While, Goto)):
                _own_condition(block, control)
            yield block
            continue
        if jumps is None:
            jumps = _Jumps(ctx)
        yield from jumps.block(block)


def _fanuc(cond: Expr) -> Expr:
    """``cond`` with an operator (``truth``) and logical ``and``/``or`` of 1-or-0 values as Fanuc's."""
    cond = truth(cond)
    if isinstance(cond, Binary) and cond.op in _BITWISE:
        return Binary(_BITWISE[cond.op], _fanuc(cond.left), _fanuc(cond.right))
    return cond


def _own_condition(block: Block, control: While | Goto) -> None:
    """Another dialect's ``WHILE``/``IF .. GOTO`` condition with the operator Fanuc needs."""
    cond = control.cond
    if cond is None:
        return
    spelt = _fanuc(cond)
    if spelt is not cond:
        block.sections = dict(block.sections)
        block.sections[CONTROL] = (While(control.label, spelt) if isinstance(control, While)
                                   else Goto(control.target, spelt))


@dataclass
class _If:
    """An open IF block's jumps. (Each record here has a docstring: ``dataclasses`` imports ``inspect`` to write
    one for a class without.)"""

    branch: int | None
    """The number the current branch's test jumps to when false (None: no test pending, after ``Else``)."""
    end: int | None = None
    """The number at ``EndIf`` a taken branch jumps to (allocated by the first ``ElseIf``/``Else``)."""


@dataclass
class _Jumps:
    """One run's jump numbers: the next free one, the open IF blocks and loops, the labels and where they stand."""

    ctx: Context
    next: int | None = None
    ifs: dict[str, _If] = field(default_factory=dict)
    loops: dict[str, int] = field(default_factory=dict)
    labels: dict[str, int] = field(default_factory=dict)
    placed: set[str] = field(default_factory=set)

    def number(self, block: Block) -> int:
        if self.next is None:
            highest = self.ctx.run_data.get(HIGHEST_SEQUENCE)
            if highest is None:
                raise UnsupportedError("jumps numbered by the translation (the program's block numbers are not "
                                       "known here)", self.ctx.at(block))
            self.next = max(int(highest), 0) + 1  # from N1: N0 is no sequence number to jump to [K]
        number = self.next
        if number > MAX_SEQUENCE:
            raise UnsupportedError(f"a jump target numbered above the program's highest block number: N{number} "
                                   f"(Fanuc's block numbers end at N{MAX_SEQUENCE})", self.ctx.at(block))
        self.next = number + 1
        return number

    def block(self, block: Block) -> Iterator[Block]:
        sections = dict(block.sections)
        label = sections.pop(LABEL, None)
        if label is not None:
            name: str = getattr(label, "name")
            if name in self.placed:
                raise UnsupportedError(f"the label {name!r} on more than one block (Fanuc's GOTO needs one)",
                                       self.ctx.at(block))
            self.placed.add(name)
            number = self.labels.get(name)
            if number is None:
                number = self.labels[name] = self.number(block)
            yield _numbered(block, number)
        control = sections.get(CONTROL)
        before: list[int] = []
        after: list[Block] = []
        if isinstance(control, If):
            self.ifs[control.label] = _If(self.number(block))
            sections[CONTROL] = Goto(Num(float(self.ifs[control.label].branch or 0)), _fanuc(negated(control.cond)))
        elif isinstance(control, (ElseIf, Else)):
            state = self._if(control.label, block)
            if state.end is None:
                state.end = self.number(block)
            sections[CONTROL] = Goto(Num(float(state.end)))
            if state.branch is not None:
                after.append(_numbered(block, state.branch))
            state.branch = None
            if isinstance(control, ElseIf):
                state.branch = self.number(block)
                after.append(_control(block, Goto(Num(float(state.branch)), _fanuc(negated(control.cond)))))
        elif isinstance(control, EndIf):
            state = self._if(control.label, block)
            del self.ifs[control.label]
            before = [n for n in (state.branch, state.end) if n is not None]
            del sections[CONTROL]
        elif isinstance(control, Do):
            self.loops[control.label] = self.number(block)
            before = [self.loops[control.label]]
            del sections[CONTROL]
        elif isinstance(control, (Until, DoWhile)):
            start = self.loops.pop(control.label, None)
            if start is None:
                raise UnsupportedError(f"the end of loop {control.label!r}, which no written loop opened",
                                       self.ctx.at(block))
            cond = negated(control.cond) if isinstance(control, Until) else control.cond
            sections[CONTROL] = Goto(Num(float(start)), _fanuc(cond))
        elif isinstance(control, GotoLabel):
            number = self.labels.get(control.label)
            if number is None:
                number = self.labels[control.label] = self.number(block)
            sections[CONTROL] = Goto(Num(float(number)), None if control.cond is None else _fanuc(control.cond))
        for number in before:
            yield _numbered(block, number)
        if sections:
            rest = copy.copy(block)
            rest.sections = sections
            yield rest
        yield from after

    def _if(self, label: str, block: Block) -> _If:
        state = self.ifs.get(label)
        if state is None:
            raise UnsupportedError(f"a branch of the condition {label!r}, which no written IF opened",
                                   self.ctx.at(block))
        return state


def _numbered(block: Block, number: int) -> Block:
    """A block holding only the block number ``N<number>``, at ``block``'s line."""
    mark = Block(block.line, None, "\n")
    mark.sections = {"Sequence": Sequence(number)}
    return mark


def _control(block: Block, control: Section) -> Block:
    """A block holding only ``control``, at ``block``'s line."""
    made = Block(block.line, None, "\n")
    made.sections = {CONTROL: control}
    return made
