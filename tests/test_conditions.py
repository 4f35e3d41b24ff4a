"""``postproc.interp.conditions``: the negation a jump needs holds exactly when the condition does not, and a
condition given an operator holds exactly when it did (checked by evaluating both on random values,
ties included: the comparisons are exact)."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from postproc.interp.conditions import negated, truth
from postproc.interp.evaluation import MappingEnv, evaluate
from postproc.ir.expr import Binary, Expr, Num, Unary, Vacancy, Var

_VALUES = st.sampled_from([-2.0, -0.5, 0.0, 0.5, 1.0, 2.0, 3.0])
"""Few values, so that ties (where a flipped comparison would be wrong) come up often."""
_OPS = ["eq", "ne", "gt", "ge", "lt", "le", "eq_tol", "ne_tol"]


def _leaf() -> st.SearchStrategy[Expr]:
    return st.one_of(_VALUES.map(Num), st.sampled_from([1, 2]).map(lambda n: Var(index=Num(float(n)))))


def _cond(depth: int = 0) -> st.SearchStrategy[Expr]:
    comparison = st.builds(Binary, st.sampled_from(_OPS), _leaf(), _leaf())
    if depth > 1:
        return st.one_of(comparison, _leaf())
    inner = _cond(depth + 1)
    return st.one_of(comparison, _leaf(), st.builds(Binary, st.sampled_from(["and", "or", "xor"]), inner, inner),
                     st.builds(Unary, st.just("not"), inner), st.builds(Binary, st.just("add"), _leaf(), _leaf()))


def _holds(cond: Expr, a: float, b: float) -> bool:
    value = evaluate(cond, MappingEnv({1: a, 2: b}, Vacancy.NULL))
    return value is not None and value != 0.0


@given(_cond(), _VALUES, _VALUES)
def test_the_negation_holds_exactly_when_the_condition_does_not(cond: Expr, a: float, b: float) -> None:
    assert _holds(negated(cond), a, b) is not _holds(cond, a, b)


@given(_cond(), _VALUES, _VALUES)
def test_a_condition_with_an_operator_holds_exactly_when_it_did(cond: Expr, a: float, b: float) -> None:
    spelt = truth(cond)
    assert isinstance(spelt, Binary)
    assert _holds(spelt, a, b) is _holds(cond, a, b)


def test_a_comparison_flips_and_and_or_follow_de_morgan() -> None:
    x, one = Var(index=Num(1.0)), Num(1.0)
    assert negated(Binary("lt", x, one)) == Binary("ge", x, one)
    assert negated(Binary("and", Binary("gt", x, one), Binary("eq", x, one))) == \
        Binary("or", Binary("le", x, one), Binary("ne", x, one))
    assert negated(x) == Binary("eq", x, Num(0.0)) and truth(x) == Binary("ne", x, Num(0.0))
