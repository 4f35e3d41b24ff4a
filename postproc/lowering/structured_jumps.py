"""Jumps as the nested constructs they have the shape of: a lowering for targets that have no GOTO here.

LinuxCNC's o-words nest (``if``/``else``/``endif``, ``while``, ``do``/``while``) and jump nowhere [V: LinuxCNC
docs "O Codes"; ``interp_o_word.cc`` has no goto]. ISG has ``$GOTO``, but not to a target inside the loop
the jump is in ("Jump inside a loop is not allowed ... A loop always can be left completely" [V: Beckhoff
TF5200 diagnosis ID 21480]) and a block number is a target only as the label ``N<n>:`` [V: TF5200
programming manual "The $GOTO statement"], which another dialect's numbered block is not: it gets the same
nested spelling. What has the shape of a construct is written as it:

* a forward jump (``GotoLabel`` to a named ``Label``, ``Goto`` to a block number) whose target is the first
  block after it carrying that label or number (which the neutral jump, searching forward first, takes),
  at the same depth of constructs as the jump: the blocks between skipped when the condition holds,
  ``o1 if [not c]`` .. ``o1 endif`` before the target (``o1 if [0]`` for a jump without condition). Several
  jumps to one target close there, innermost first. A target inside a construct opened after the jump,
  a construct closed or branched (``else``) before the target, or no target after the jump (a jump back)
  has no such shape: an ``UnsupportedError``, so the program is flattened with the usual warning; the
  blocks between a jump and its target are held until the target decides (at most the program's symbolic
  part, which is in memory anyway);
* a forward jump from the body of a ``while`` loop (also a counted one) straight to the block after the
  loop's end (SINUMERIK ``LOOP`` .. ``IF c GOTOF OUT`` .. ``ENDLOOP`` ``OUT:``): ``o2 if [c]`` ``o1 break``
  ``o2 endif`` (LinuxCNC's ``break`` and ISG's ``$BREAK`` leave the innermost loop [V: the same manuals]);
* ``Until c`` (SINUMERIK ``REPEAT`` .. ``UNTIL``): ``o1 while [not c]`` after ``o1 do``;
* ISG only (``nest_jumps_keeping_equality``): a jump back to a named label, both outside every loop, stays
  the jump it is (``$GOTO [NAME]``: the label went by, and a label is on one block);
* LinuxCNC only (``nest_forward_jumps``): an exact equality in a condition. LinuxCNC's ``EQ``/``NE`` count
  values closer than 1e-4 as equal (``postproc.interp.evaluation``), its ``LE``/``GE``/``LT``/``GT`` are exact [V:
  rs274, same module], so ``a == b`` is written ``[a LE b] AND [a GE b]`` and ``a <> b``
  ``[a LT b] OR [a GT b]``: the same value for every number.

Back to the reading dialect itself the stream passes through (its own jumps are its own).
"""

from __future__ import annotations

import copy
from typing import Final, Iterator

from mypy_extensions import mypyc_attr

from ..interp.conditions import negated
from ..context import Context
from ..interp.control import (
    CONTROL, Break, Case, Default, Do, DoWhile, Else, ElseIf, EndFor, EndIf, EndRepeat, EndSwitch, EndWhile, For, Goto,
    GotoLabel, If, Repeat, SubEnd, SubStart, Switch, Until, While,
)
from ..dialect import Dialect
from ..errors import Location, UnsupportedError
from ..ir.expr import Binary, Expr, Func, Num, Unary
from ..ir import Block, Section
from .lower import BlockStep, LoweringStep

LABEL: Final = "Label"
_OPENING: Final = (If, While, Do, For, Repeat, Switch, SubStart)
_CLOSING: Final = (EndIf, EndWhile, DoWhile, Until, EndFor, EndRepeat, EndSwitch, SubEnd)
_BRANCHING: Final = (ElseIf, Else, Case, Default)
_EXACT: Final = {"eq": ("and", "le", "ge"), "ne": ("or", "lt", "gt")}
"""An exact comparison as two exact ones LinuxCNC has, and the logical operator joining them."""


@mypyc_attr(allow_interpreted_subclasses=True)
class NestForwardJumps(LoweringStep):
    """Forward jumps as ``if`` .. ``endif`` (or ``break``), ``Until`` as ``do`` .. ``while``, exact equalities
    as two comparisons (module docstring: LinuxCNC); every other block as it is. With ``keep_equality``:
    ``nest_jumps_keeping_equality``, the conditions as they are (ISG)."""

    def __init__(self, keep_equality: bool) -> None:
        self.keep_equality = keep_equality

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME:
            return None
        if self.keep_equality:
            return _Nested(_Nest(ctx, f"{target.NAME}'s GOTO may not stay in a loop or reach a numbered block",
                                 exact=False, back_to_labels=True))
        return _Nested(_Nest(ctx, f"{target.NAME} has no GOTO", exact=True))


nest_forward_jumps = NestForwardJumps(False)
nest_jumps_keeping_equality = NestForwardJumps(True)


@mypyc_attr(allow_interpreted_subclasses=True)
class _Nested(BlockStep):
    """One run: a block with a statement or a label is its business, and every block while a jump's stretch
    is held or a loop is being left."""

    def __init__(self, nest: _Nest) -> None:
        super().__init__()
        self.moves = False
        self.nest = nest

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        nest = self.nest
        if CONTROL not in sections and LABEL not in sections and not nest.busy:
            return None  # the common block: no statement, no label, no jump's stretch to hold it
        made = list(nest.block(block))
        nest.busy = self.moves = bool(nest.jumps) or nest.leaving is not None
        return made

    def finish(self) -> list[Block]:
        return list(self.nest.end())


@mypyc_attr(allow_interpreted_subclasses=True)
class _Open:
    """An open construct (``key`` "") or the stretch a forward jump skips (``key``: its target)."""

    def __init__(self, key: str, label: str, at: Location, loop: str | None = None, cond: Expr | None = None,
                 looping: bool = False) -> None:
        self.key = key
        self.looping = looping
        """A construct that repeats its body (a ``while``, ``for``, ``do`` or ``repeat`` loop)."""
        self.label = label
        """A construct's own label; a jump's fresh one (``jump:n``)."""
        self.at = at
        self.loop = loop
        """A construct: its kind when it is a loop a ``break`` leaves (``while``)."""
        self.cond = cond
        """A jump's condition (None: always)."""
        self.held: list[Block] = []
        """A jump's stretch: the blocks after it, held until its target decides its shape."""


@mypyc_attr(allow_interpreted_subclasses=True)
class _Nest:
    """The constructs open and the jumps waiting for their targets where the stream stands."""

    def __init__(self, ctx: Context, why: str, exact: bool, back_to_labels: bool = False) -> None:
        self.ctx = ctx
        self.back_to_labels = back_to_labels
        """A jump back to a named label outside every loop, from outside every loop, stays a jump (ISG)."""
        self.labels: dict[str, int] = {}
        """Named labels that went by -> the loops open there."""
        self.why = why
        """Why a jump must have a construct's shape, for the messages."""
        self.exact_equality = exact
        self.busy = False
        """A jump's stretch is held or a loop's end waits for the block after it: every block comes here."""
        self.open: list[_Open] = []
        self.count = 0
        self.jumps = 0
        """Jumps whose target has not come yet."""
        self.leaving: tuple[_Open, _Open, Block] | None = None
        """A jump's stretch that ran to its loop's end, the loop, and that end: a ``break`` if the next block
        is the target."""

    def block(self, block: Block) -> Iterator[Block]:
        if self.leaving is not None:
            yield from self.left(block)
        sections = block.sections
        if self.jumps and (LABEL in sections or "Sequence" in sections):
            names = _names(block)
            while self.open and self.open[-1].key in names:
                yield from self.emit(self.skipped(self.open.pop()))
            crossed = next((o.at for o in self.open if o.key in names), None)
            if crossed is not None:
                raise UnsupportedError(f"a jump into a construct opened after it ({self.why}, and the jump has "
                                       "no if shape)", crossed)
        if self.back_to_labels and LABEL in sections:
            self.labels[str(getattr(sections[LABEL], "name"))] = self.loops()
        control = sections.get(CONTROL)
        if control is None:
            yield from self.emit([block])
            return
        at = self.ctx.at(block)
        top = self.open[-1] if self.open else None
        if isinstance(control, _CLOSING + _BRANCHING) and top is not None and top.key:
            below = self.open[-2] if len(self.open) > 1 else None
            if isinstance(control, (EndWhile, EndFor)) and below is not None and below.loop is not None \
                    and below.label == control.label:
                self.open.pop()
                self.open.pop()
                self.leaving = (top, below, self.exact(block, control))
                return
            raise UnsupportedError(f"a jump out of a construct or over its branches ({self.why}, and the jump "
                                   "has no if or break shape)", top.at)
        if isinstance(control, GotoLabel) and self.labels.get(control.label) == 0 and self.loops() == 0:
            yield from self.emit([block])  # back to a label outside every loop, from outside every loop
            return
        if isinstance(control, (Goto, GotoLabel)):
            key = control.label if isinstance(control, GotoLabel) else _number_key(control.target)
            if key is None:
                raise UnsupportedError(f"a jump to a computed block number ({self.why})", at)
            rest = _without_control(block)
            if rest is not None:
                yield from self.emit([rest])
            self.count += 1
            self.jumps += 1
            self.open.append(_Open(key, f"jump:{self.count}", at, cond=control.cond))
            return
        if isinstance(control, _OPENING):
            loop = "while" if isinstance(control, (While, For)) else None
            self.open.append(_Open("", getattr(control, "label", ""), at, loop,
                                   looping=isinstance(control, (While, For, Do, Repeat))))
        elif isinstance(control, _CLOSING) and self.open:
            self.open.pop()
        if isinstance(control, Until):
            control = DoWhile(control.label, negated(control.cond))
            block = _with_control(block, control)
        yield from self.emit([self.exact(block, control)])

    def loops(self) -> int:
        """The loops open where the stream stands."""
        return sum(1 for o in self.open if o.looping)

    def left(self, block: Block) -> Iterator[Block]:
        """The block after a loop's end that a jump's stretch ran to: the jump leaves the loop if it is the
        jump's target (``if [c]`` ``break`` ``endif``), otherwise it has no shape here."""
        assert self.leaving is not None
        jump, loop, end = self.leaving
        self.leaving = None
        if jump.key not in _names(block):
            raise UnsupportedError(f"a jump out of a construct to other than the block after its end ({self.why}, "
                                   "and the jump has no if or break shape)", jump.at)
        self.jumps -= 1
        where = jump.held[0] if jump.held else end
        leave = [_made(where, If(jump.label, Num(1.0) if jump.cond is None else jump.cond)),
                 _made(where, Break(loop.label)), _made(where, EndIf(jump.label))]
        yield from self.emit(leave + jump.held + [end])

    def skipped(self, jump: _Open) -> list[Block]:
        """A jump's stretch, its target reached at its depth: ``if [not c]`` .. ``endif``."""
        self.jumps -= 1
        where = jump.held[0] if jump.held else None
        cond = Num(0.0) if jump.cond is None else negated(jump.cond)
        head = Block(where.line if where is not None else jump.at.line, None, "\n")
        head.sections = {CONTROL: self.exact_cond(If(jump.label, cond))}
        tail = Block(head.line, None, "\n")
        tail.sections = {CONTROL: EndIf(jump.label)}
        return [head, *jump.held, tail]

    def emit(self, made: list[Block]) -> Iterator[Block]:
        """``made`` into the innermost jump's stretch, or out when no jump waits."""
        holder = next((o for o in reversed(self.open) if o.key), None)
        if holder is None:
            yield from made
        else:
            holder.held.extend(made)

    def exact(self, block: Block, control: Section) -> Block:
        spelt = self.exact_cond(control)
        return block if spelt is control else _with_control(block, spelt)

    def exact_cond(self, control: Section) -> Section:
        cond = getattr(control, "cond", None)
        if isinstance(cond, Expr) and self.exact_equality:
            exact = _exact(cond)
            if exact is not cond:
                control = copy.copy(control)
                setattr(control, "cond", exact)
        return control

    def end(self) -> Iterator[Block]:
        if self.leaving is not None:
            raise UnsupportedError(f"a jump out of a loop to the program's end ({self.why})", self.leaving[0].at)
        waiting = next((o for o in self.open if o.key), None)
        if waiting is not None:
            raise UnsupportedError(f"a jump back, or to a target not after it ({self.why}; only a forward jump "
                                   "has an if shape)", waiting.at)
        return iter(())


def _made(where: Block, control: Section) -> Block:
    made = Block(where.line, None, "\n")
    made.sections = {CONTROL: control}
    return made


def _with_control(block: Block, control: Section) -> Block:
    changed = copy.copy(block)
    changed.sections = dict(block.sections)
    changed.sections[CONTROL] = control
    return changed


def _without_control(block: Block) -> Block | None:
    """A jump's block without the jump: what else it holds (a block number, a comment), or None."""
    rest = {k: v for k, v in block.sections.items() if k != CONTROL}
    if not rest:
        return None
    changed = copy.copy(block)
    changed.sections = rest
    return changed


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
