"""Jumps and tests at a loop's end as o-word blocks: a lowering for RS274/NGC targets, which have no GOTO.

LinuxCNC's o-words nest (``if``/``else``/``endif``, ``while``, ``do``/``while``) and jump nowhere [V: LinuxCNC
docs "O Codes"; ``interp_o_word.cc`` has no goto]. What has the shape of one is written as it:

* a forward jump (``GotoLabel`` to a named ``Label``, ``Goto`` to a block number) whose target is the first
  block after it carrying that label or number (which the neutral jump, searching forward first, takes),
  at the same depth of constructs as the jump: the blocks between skipped when the condition holds,
  ``o1 if [not c]`` .. ``o1 endif`` before the target (``o1 if [0]`` for a jump without condition). Several
  jumps to one target close there, innermost first. A target inside a construct opened after the jump,
  a construct closed or branched (``else``) before the target, or no target after the jump (a jump back)
  has no such shape: an ``UnsupportedError``, so the program is flattened with the usual warning;
* ``Until c`` (SINUMERIK ``REPEAT`` .. ``UNTIL``, ISG ``$REPEAT``): ``o1 while [not c]`` after ``o1 do``;
* an exact equality in a condition: LinuxCNC's ``EQ``/``NE`` count values closer than 1e-4 as equal
  (``postproc.evaluation``), its ``LE``/``GE``/``LT``/``GT`` are exact [V: rs274, same module], so
  ``a == b`` is written ``[a LE b] AND [a GE b]`` and ``a <> b`` ``[a LT b] OR [a GT b]``: the same
  value for every number.
"""

from __future__ import annotations

import copy
from typing import Iterator

from ..conditions import negated
from ..context import Context
from ..control import (
    CONTROL, Case, Default, Do, DoWhile, Else, ElseIf, EndFor, EndIf, EndRepeat, EndSwitch, EndWhile, For, Goto,
    GotoLabel, If, Repeat, SubEnd, SubStart, Switch, Until, While,
)
from ..dialect import Dialect
from ..errors import Location, UnsupportedError
from ..expr import Binary, Expr, Func, Num, Unary
from ..ir import Block, Section

LABEL = "Label"
_OPENING = (If, While, Do, For, Repeat, Switch, SubStart)
_CLOSING = (EndIf, EndWhile, DoWhile, Until, EndFor, EndRepeat, EndSwitch, SubEnd)
_BRANCHING = (ElseIf, Else, Case, Default)
_EXACT = {"eq": ("and", "le", "ge"), "ne": ("or", "lt", "gt")}
"""An exact comparison as two exact ones LinuxCNC has, and the logical operator joining them."""


def nest_forward_jumps(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Forward jumps as ``if`` .. ``endif``, ``Until`` as ``do`` .. ``while``, exact equalities as two
    comparisons (module docstring); every other block as it is."""
    open_: list[tuple[str, str, Location]] = []
    """Open constructs and skipped stretches, innermost last: ("", "", where) for a construct,
    (target, label, where) for the stretch a forward jump skips."""
    count = 0
    pending = 0
    for block in blocks:
        sections = block.sections
        control = sections.get(CONTROL)
        if pending and (LABEL in sections or "Sequence" in sections):
            names = _names(block)
            while open_ and open_[-1][0] in names:
                _, label, _ = open_.pop()
                pending -= 1
                mark = Block(block.line, None, "\n")
                mark.sections = {CONTROL: EndIf(label)}
                yield mark
            crossed = next((where for key, _, where in open_ if key in names), None)
            if crossed is not None:
                raise UnsupportedError("a jump into a construct opened after it (LinuxCNC has no GOTO, and the "
                                       "jump has no if shape)", crossed)
        if control is None:
            yield block
            continue
        at = ctx.at(block)
        if isinstance(control, _CLOSING + _BRANCHING) and open_ and open_[-1][0]:
            raise UnsupportedError("a jump out of a construct or over its branches (LinuxCNC has no GOTO, and "
                                   "the jump has no if shape)", open_[-1][2])
        if isinstance(control, (Goto, GotoLabel)):
            key = control.label if isinstance(control, GotoLabel) else _number_key(control.target)
            if key is None:
                raise UnsupportedError("a jump to a computed block number (LinuxCNC has no GOTO)", at)
            count += 1
            label = f"jump:{count}"
            open_.append((key, label, at))
            pending += 1
            control = If(label, Num(0.0) if control.cond is None else negated(control.cond))
        else:
            if isinstance(control, _OPENING):
                open_.append(("", "", at))
            elif isinstance(control, _CLOSING) and open_:
                open_.pop()
            if isinstance(control, Until):
                control = DoWhile(control.label, negated(control.cond))
        cond = getattr(control, "cond", None)
        if isinstance(cond, Expr):
            exact = _exact(cond)
            if exact is not cond:
                control = copy.copy(control)
                setattr(control, "cond", exact)
        if control is not sections[CONTROL]:
            block = copy.copy(block)
            block.sections = dict(sections)
            block.sections[CONTROL] = control
        yield block
    if pending:
        where = next(w for key, _, w in open_ if key)
        raise UnsupportedError("a jump back, or to a target not after it (LinuxCNC has no GOTO; only a forward "
                               "jump has an if shape)", where)


def _names(block: Block) -> set[str]:
    """What a jump may name to reach ``block``: its label, its block number as ``N<n>``."""
    names = set()
    label: Section | None = block.sections.get(LABEL)
    if label is not None:
        names.add(str(getattr(label, "name")))
    sequence = block.sections.get("Sequence")
    if sequence is not None:
        names.add(f"N{getattr(sequence, 'number')}")
    return names


def _number_key(target: Expr) -> str | None:
    if isinstance(target, Num) and target.value.is_integer() and target.value >= 0:
        return f"N{int(target.value)}"
    return None


def _exact(cond: Expr) -> Expr:
    """``cond`` with each exact ``eq``/``ne`` as two exact comparisons (module docstring)."""
    if isinstance(cond, Binary):
        left, right = _exact(cond.left), _exact(cond.right)
        spelt = _EXACT.get(cond.op)
        if spelt is not None:
            join, first, second = spelt
            return Binary(join, Binary(first, left, right), Binary(second, left, right))
        if left is not cond.left or right is not cond.right:
            return Binary(cond.op, left, right)
        return cond
    if isinstance(cond, Unary):
        operand = _exact(cond.operand)
        return cond if operand is cond.operand else Unary(cond.op, operand)
    if isinstance(cond, Func):
        args = [_exact(a) for a in cond.args]
        return cond if all(a is b for a, b in zip(args, cond.args)) else Func(cond.name, args)
    return cond
