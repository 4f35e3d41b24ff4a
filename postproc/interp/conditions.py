"""Conditions rewritten without changing when they hold: the negation a jump needs to skip a branch.

A control statement's condition is true when its value is non-zero (``postproc.interp.control``). A target that
spells an ``IF .. ELSE`` or a loop tested at its end as conditional jumps (Fanuc Macro B) or an
``UNTIL c`` as a ``do .. while`` (LinuxCNC) jumps on the opposite condition. ``negated`` builds it from the
same operators, so each target spells it with what it already has: a comparison flips (``lt`` <-> ``ge``,
exact as the operators are: no operand is NaN, ``postproc.interp.evaluation`` refuses one), ``and``/``or`` follow
De Morgan, and any other value ``v`` becomes ``v == 0``.
"""

from __future__ import annotations

from ..ir.expr import Binary, Expr, Num, Unary

_FLIPPED = {"eq": "ne", "ne": "eq", "gt": "le", "le": "gt", "ge": "lt", "lt": "ge",
            "eq_tol": "ne_tol", "ne_tol": "eq_tol"}
"""Each comparison and the one true exactly when it is false."""
_DE_MORGAN = {"and": "or", "or": "and"}
"""Logical ``and``/``or`` (non-zero is true) and the operator of their negation over negated operands."""


def is_truth_value(cond: Expr) -> bool:
    """Whether ``cond`` is 1 or 0 by construction (a comparison, a logical operator, ``not``)."""
    if isinstance(cond, Binary):
        return cond.op in _FLIPPED or cond.op in ("and", "or", "xor")
    return isinstance(cond, Unary) and cond.op == "not"


def truth(cond: Expr) -> Expr:
    """``cond`` as a comparison or a logical combination of them: a value ``v`` becomes ``v != 0`` (a
    controller such as Fanuc wants an operator in every condition)."""
    if is_truth_value(cond):
        if isinstance(cond, Unary):
            return negated(cond.operand)
        return cond
    return Binary("ne", cond, Num(0.0))


def negated(cond: Expr) -> Expr:
    """A condition true exactly when ``cond`` is false."""
    if isinstance(cond, Binary):
        flipped = _FLIPPED.get(cond.op)
        if flipped is not None:
            return Binary(flipped, cond.left, cond.right)
        other = _DE_MORGAN.get(cond.op)
        if other is not None:
            return Binary(other, negated(cond.left), negated(cond.right))
    if isinstance(cond, Unary) and cond.op == "not":
        return truth(cond.operand)
    return Binary("eq", cond, Num(0.0))
