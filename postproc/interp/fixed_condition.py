"""Whether a loop's test can ever change: a static look at the loop's blocks, done once when the loop is
entered (``RunState._fixed``).

A loop whose test holds now and reads only variables nothing in the loop sets, with no way out but its
test, never ends: the run would spend the set-up's work bound (seconds) before its error. The proof is
kept to what the blocks say for certain, and gives up (the loop runs, under its bounds) at anything that
could change a variable or leave the loop another way:

* a variable the test reads through a computed number (``#[#2]``), or one the family does not call plain
  (the machine's, whose value may change without an assignment: LinuxCNC's offsets after ``G10``);
* an assignment (or a counted loop's counter) with a computed target, or to a variable that is not plain
  (an alarm variable: the write stops the run);
* a call (it may set variables), a subprogram definition (its end may set a returned value), a jump, a
  return, a break out of this loop, a block that ends the program, or a word that ends it by a computed
  number.
"""

from __future__ import annotations

from typing import Callable, Iterator

from .control import (ASSIGN, CONTROL, Assign, Break, Call, Continue, Do, DoWhile, Else, ElseIf, EndFor, EndIf,
                       EndRepeat, EndSwitch, EndWhile, For, If, IfThen, ModalCallCancel, Repeat, Switch, Case,
                       Default, Until, While)
from ..ir.expr import Binary, Expr, Func, Num, Unary, Var, VarKey
from ..ir import Block
from .store import Program

STRUCTURE = (If, ElseIf, Else, EndIf, While, EndWhile, Do, DoWhile, Until, Repeat, EndRepeat, For, EndFor,
             Switch, Case, Default, EndSwitch, Continue, ModalCallCancel)
"""Control statements that stay inside the loop and set nothing (a counted loop's counter aside)."""


def read_keys(expr: Expr) -> set[VarKey] | None:
    """The variables ``expr`` reads, or None when one of them has a computed number."""
    keys: set[VarKey] = set()
    for node in _nodes(expr):
        if isinstance(node, Var):
            key = _literal_key(node)
            if key is None:
                return None
            keys.add(key)
    return keys


def _nodes(expr: Expr) -> Iterator[Expr]:
    stack = [expr]
    while stack:
        node = stack.pop()
        yield node
        if isinstance(node, Unary):
            stack.append(node.operand)
        elif isinstance(node, Binary):
            stack += (node.left, node.right)
        elif isinstance(node, Func):
            stack += node.args


def condition_is_fixed(program: Program, first: int, last: int, head: int, cond: Expr,
                       plain: Callable[[VarKey], bool], ends: Callable[[Block], bool]) -> bool:
    """True when ``cond`` (the test of the loop headed at ``head``, whose blocks are ``first`` .. ``last``
    inclusive, the test's own block included) can never change while the loop runs and nothing in it leaves
    the loop: then the loop never ends once its test holds. ``plain(key)``: only an assignment changes the
    variable and an assignment does nothing else; ``ends(block)``: the block ends the program, or may (a
    word of an end code's letter whose number is computed)."""
    tested = read_keys(cond)
    if tested is None or not all(plain(k) for k in tested):
        return False
    blocks = program.blocks
    pairs = program.pairs
    for pos in range(first, last + 1):
        block = blocks[pos]
        sections = block.sections
        control = sections.get(CONTROL)
        if control is not None:
            if isinstance(control, Break):
                if pairs.get(pos, head) == head:
                    return False  # leaves this loop
            elif isinstance(control, IfThen):
                if not _sets_only_others(control.assign, tested, plain):
                    return False
            elif isinstance(control, For):
                if not _sets_only_others(Assign([(control.counter, control.start)]), tested, plain):
                    return False
            elif isinstance(control, Call) or not isinstance(control, STRUCTURE):
                return False  # a call, jump, return, modal call, subprogram definition or end
        assign = sections.get(ASSIGN)
        if assign is not None and not _sets_only_others(assign, tested, plain):  # type: ignore[arg-type]
            return False
        if ends(block):
            return False
    return True


def _sets_only_others(assign: Assign, tested: set[VarKey], plain: Callable[[VarKey], bool]) -> bool:
    """Every target of ``assign`` is a plain variable the test does not read."""
    for var, _ in assign.items:
        key = _literal_key(var)
        if key is None or key in tested or not plain(key):
            return False
    return True


def _literal_key(var: Var) -> VarKey | None:
    """The variable's identity where the program spells it (None: its number is computed)."""
    if var.name is not None:
        return var.name
    if isinstance(var.index, Num) and var.index.value.is_integer():
        return int(var.index.value)
    return None
