"""Evaluation: hand-computed values for every operator and function, both vacancy regimes, errors."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.interp.evaluation import MappingEnv, TOLERANCE_EQUAL, certain_failure, describe, evaluate_number, var_key
from postproc.interp.evaluation import evaluate
from postproc.ir.expr import (
    BINARY_OPS, FUNCTIONS, Binary, EvalError, Expr, Func, Num, Unary, Vacancy, Var,
)
from postproc.rs274.expressions import FANUC_SPELLING, LINUXCNC_SPELLING
from tests.test_rs274_expressions import trees

FANUC = MappingEnv({1: 3.0, 2: -2.0, 3: 0.0, 4: 25.0}, Vacancy.NULL)
LCNC = MappingEnv({1: 3.0, 2: -2.0, "depth": 4.0}, Vacancy.ZERO)


def n(v: float) -> Num:
    return Num(v)


def v(i: int) -> Var:
    return Var(Num(float(i)))


def b(op: str, x: float | Expr, y: float | Expr) -> Binary:
    return Binary(op, x if isinstance(x, Expr) else Num(x), y if isinstance(y, Expr) else Num(y))


def f(name: str, *args: float | Expr) -> Func:
    return Func(name, [a if isinstance(a, Expr) else Num(a) for a in args])


# (tree, expected value): hand-computed.
VALUES = [
    (b("add", 1.5, 2.25), 3.75), (b("sub", 1, 3), -2.0), (b("mul", -2, 3.5), -7.0), (b("div", 7, 2), 3.5),
    (b("pow", 2, 10), 1024.0), (b("pow", -2, 3), -8.0), (b("pow", 4, 0.5), 2.0),
    (b("mod_pos", 7, 3), 1.0), (b("mod_pos", -7, 3), 2.0), (b("mod_pos", 7, -3), 1.0),
    (b("mod_pos", -7, -3), 2.0), (b("mod_pos", 7.5, 2), 1.5),
    (b("rem_int", 10, 3), 1.0), (b("rem_int", -10, 3), -1.0), (b("rem_int", 10.4, 2.6), 1.0),
    (b("fmod", -7, 3), -1.0), (b("fmod", 7.5, -2), 1.5),  # C fmod: the dividend's sign, reals kept
    (b("eq", 1, 1), 1.0), (b("eq", 1, 1.00001), 0.0), (b("ne", 1, 1.00001), 1.0),
    (b("eq_tol", 1, 1.00005), 1.0), (b("eq_tol", 1, 1.0002), 0.0),
    (b("ne_tol", 1, 1.00005), 0.0), (b("ne_tol", 1, 1.0002), 1.0),
    (b("gt", 2, 1), 1.0), (b("gt", 1, 1), 0.0), (b("ge", 1, 1), 1.0), (b("ge", 0.99999, 1), 0.0),
    (b("lt", 1, 2), 1.0), (b("lt", 2, 2), 0.0), (b("le", 2, 2), 1.0), (b("le", 1, 0.99999), 0.0),
    (b("and", 2, 3), 1.0), (b("and", 2, 0), 0.0), (b("or", 0.5, 0), 1.0), (b("or", 0, 0), 0.0),
    (b("xor", 2, 0), 1.0), (b("xor", 2, 3), 0.0),
    (b("bitand", 12, 10), 8.0), (b("bitor", 12, 10), 14.0), (b("bitxor", 12, 10), 6.0),
    (Unary("neg", n(2)), -2.0), (Unary("pos", n(-2)), -2.0), (Unary("not", n(0)), 1.0), (Unary("not", n(3)), 0.0),
    (f("sin", 30), 0.5), (f("cos", 60), 0.5), (f("tan", 45), 1.0),
    (f("asin", -0.5), -30.0), (f("asin_360", -0.5), 330.0), (f("asin_360", 0.5), 30.0),
    (f("acos", -0.5), 120.0), (f("atan", -1), -45.0), (f("atan_360", -1), 315.0),
    (f("atan2", -1, -1), -135.0), (f("atan2_360", -1, -1), 225.0), (f("atan2", 1, 0), 90.0),
    (f("atan2_360", 0, 1), 0.0), (f("atan2_360", 0, -1), 180.0),
    (f("sqrt", 16), 4.0), (f("abs", -3.5), 3.5), (f("exp", 0), 1.0), (f("ln", math.e), 1.0),
    (f("round", 2.5), 3.0), (f("round", -2.5), -3.0), (f("round", 2.49), 2.0), (f("round", -1.2), -1.0),
    (f("trunc", 1.7), 1.0), (f("trunc", -1.7), -1.0), (f("away", 1.2), 2.0), (f("away", -1.2), -2.0),
    (f("away", 3.0), 3.0), (f("floor", -1.5), -2.0), (f("floor", 1.5), 1.0), (f("ceil", -1.5), -1.0),
    (f("ceil", 1.2), 2.0), (f("bcd", 25), 37.0), (f("bcd", 1234), 4660.0), (f("bin", 37), 25.0),
    (f("bin", 4660), 1234.0), (f("round_address", 1.00333), 1.003), (f("round_address", -1.0005), -1.001),
    # ISG's functions (new neutral names): FRACT keeps the sign, SQR squares, DEXP/LOG are base 10
    (f("fract", 2.75), 0.75), (f("fract", -2.75), -0.75), (f("sqr", -3), 9.0), (f("exp10", 2), 100.0),
    (f("log10", 1000), 3.0),
    # a value stored into an integer type: a whole number within the range passes unchanged
    (f("whole_in", 255, 0, 255), 255.0), (f("whole_in", -128, -128, 127), -128.0),
]


@pytest.mark.parametrize("tree, expected", VALUES, ids=lambda x: describe(x) if isinstance(x, Expr) else str(x))
def test_hand_computed_value(tree: Expr, expected: float) -> None:
    assert evaluate(tree, FANUC) == pytest.approx(expected, abs=1e-12)


def test_every_operator_and_function_has_a_hand_computed_value() -> None:
    ops = {t.op for t, _ in VALUES if isinstance(t, Binary)}
    funcs = {t.name for t, _ in VALUES if isinstance(t, Func)}
    assert ops == set(BINARY_OPS)
    assert funcs | {"exists"} == set(FUNCTIONS)


def test_tolerance_is_linuxcnc_2_9_0s() -> None:
    assert TOLERANCE_EQUAL == 1e-4


# Fanuc vacancy: #0 and unset variables are vacant.
@pytest.mark.parametrize("tree, expected", [
    (v(5), None), (v(0), None), (b("mul", v(5), 5), 0.0), (b("add", v(5), v(5)), 0.0),
    (Unary("neg", v(5)), 0.0), (f("sqrt", v(5)), 0.0), (f("cos", v(5)), 1.0),
    (b("eq", v(5), v(0)), 1.0), (b("eq", v(5), 0), 0.0), (b("ne", v(5), 0), 1.0), (b("ne", v(5), v(0)), 0.0),
    (b("eq", v(3), 0), 1.0), (b("eq", v(3), v(0)), 0.0),
    (b("gt", v(5), -1), 1.0), (b("ge", v(5), 0), 1.0), (b("lt", v(5), 1), 1.0), (b("le", v(5), 0), 1.0),
    (Var(b("sub", v(1), 2)), 3.0), (Var(n(1.4)), 3.0), (Var(n(1.5)), -2.0),
])
def test_fanuc_vacancy(tree: Expr, expected: float | None) -> None:
    assert evaluate(tree, FANUC) == expected


@pytest.mark.parametrize("tree, expected", [
    (v(7), 0.0), (b("eq_tol", v(7), 0), 1.0), (Var(name="depth"), 4.0), (f("exists", Var(name="depth")), 1.0),
    (f("exists", Var(name="nope")), 0.0), (f("exists", v(9)), 1.0), (Var(n(1.00005)), 3.0),
])
def test_linuxcnc_unset_numbered_reads_zero(tree: Expr, expected: float) -> None:
    assert evaluate(tree, LCNC) == expected


@pytest.mark.parametrize("env, tree, message", [
    (FANUC, b("div", v(1), v(3)), "division by zero in #1/#3"),
    (FANUC, b("div", v(1), v(5)), "division by zero in #1/#5"),
    (LCNC, b("mod_pos", 7, 0), "division by zero in 7 MOD 0"),
    (FANUC, b("rem_int", 7, 0.4), "division by zero in 7 MOD 0.4"),
    (FANUC, b("pow", -8, b("div", 1, 3)), "negative number raised to a non-integer power in -8**[1/3]"),
    (FANUC, f("sqrt", v(2)), "square root of a negative number in SQRT[#2] (-2)"),
    (FANUC, f("asin", 1.5), "the argument of ASIN[1.5] is outside -1..1 (1.5)"),
    (FANUC, f("acos", -2), "the argument of ACOS[-2] is outside -1..1 (-2)"),
    (FANUC, f("ln", 0), "logarithm of a number that is not positive in LN[0] (0)"),
    (FANUC, f("exp", 1000), "the result of EXP[1000] is too large"),
    (FANUC, b("bitand", 1.5, 1), "1.5 AND 1 needs non-negative integers, not 1.5"),
    (FANUC, f("bin", 10), "BIN[10]: 10 is not a BCD number"),
    (FANUC, Var(v(5)), "the variable number in #[#5] is vacant"),
    (LCNC, Var(name="nope"), "named parameter #<nope> is not defined"),
    (LCNC, Var(n(1.5)), "the variable number in #1.5 is not an integer (1.5)"),
    (FANUC, b("mul", 1e200, 1e200), "the result of 1e+200*1e+200 is not a finite number"),
    (FANUC, f("whole_in", 2.5, 0, 255), "2.5 does not fit the variable's type (whole numbers 0 to 255): how the "
                                       "controller converts it is not known"),
    (FANUC, f("whole_in", -1, 0, 4294967295), "-1 does not fit the variable's type (whole numbers 0 to "
                                              "4294967295): how the controller converts it is not known"),
])
def test_errors_name_the_construct(env: MappingEnv, tree: Expr, message: str) -> None:
    with pytest.raises(EvalError) as info:
        evaluate(tree, env)
    assert info.value.message == message
    assert info.value.location is None


def test_evaluate_number_refuses_vacant() -> None:
    with pytest.raises(EvalError) as info:
        evaluate_number(v(5), FANUC, "a feed")
    assert info.value.message == "#5 is vacant where a feed is required"
    assert evaluate_number(b("add", v(5), 1), FANUC) == 1.0


def test_var_key() -> None:
    assert var_key(v(12), FANUC) == 12
    assert var_key(Var(b("add", v(1), 1)), FANUC) == 4
    assert var_key(Var(name="_g"), LCNC) == "_g"


def test_round_address_follows_the_increment() -> None:
    inch = MappingEnv({}, Vacancy.NULL, increment=0.0001)
    assert evaluate(f("round_address", 1.00333), inch) == pytest.approx(1.0033)


# -- certain_failure: what fails whatever the program does (issue #31, item 4) ---------------------------


@pytest.mark.parametrize("expr, message", [
    (b("div", 1.0, 0.0), "division by zero in 1/0"),
    (Func("sqrt", [n(-4.0)]), "square root of a negative number in SQRT[-4] (-4)"),
    (Func("ln", [b("sub", 2.0, 2.0)]), "logarithm of a number that is not positive in LN[2-2] (0)"),
    (b("add", v(1), Func("acos", [n(2.0)])), "the argument of ACOS[2] is outside -1..1 (2)"),
    (b("div", v(1), b("mul", 0.0, 5.0)), "division by zero in #1/[0*5]"),
    (b("rem_int", v(1), 0.0), "division by zero in #1 MOD 0"),
    (Var(b("div", 1.0, 0.0)), "division by zero in 1/0"),
])
def test_a_part_of_constants_that_fails_is_found(expr: Expr, message: str) -> None:
    err = certain_failure(expr)
    assert err is not None and err.message == message


@pytest.mark.parametrize("expr", [
    b("div", 1.0, v(1)), Func("sqrt", [v(1)]), Func("ln", [b("add", v(1), 0.0)]), b("div", 1.0, 4.0),
    Func("exists", [Var(name="x")]), Func("round_address", [n(1.0)]),
])
def test_what_depends_on_the_run_is_not_refused(expr: Expr) -> None:
    assert certain_failure(expr) is None


def _env(values: list[float], vacancy: Vacancy) -> MappingEnv:
    return MappingEnv({i: x for i, x in enumerate(values) if x == x}, vacancy)  # NaN: left vacant


_VALUES = st.lists(st.one_of(st.floats(-50, 50), st.just(0.0), st.just(float("nan"))), min_size=34, max_size=34)


@settings(max_examples=300, deadline=None)
@given(trees(FANUC_SPELLING), _VALUES)
def test_what_is_certain_to_fail_fails_with_any_variables(expr: Expr, values: list[float]) -> None:
    """Sound: an expression refused as certain to fail raises whatever the variables hold (vacant ones
    included); complete on constants: an expression with no variable is refused exactly when it fails."""
    err = certain_failure(expr)
    for vacancy in (Vacancy.NULL, Vacancy.ZERO):
        try:
            evaluate(expr, _env(values, vacancy))
            failed = False
        except EvalError:
            failed = True
        if err is not None:
            assert failed, (describe(expr), err.message)
        elif not _reads_variables(expr):
            assert not failed, describe(expr)


@settings(max_examples=150, deadline=None)
@given(trees(LINUXCNC_SPELLING))
def test_constants_fail_exactly_when_refused_in_linuxcnc_spelling(expr: Expr) -> None:
    if _reads_variables(expr):
        return
    try:
        evaluate(expr, MappingEnv({}, Vacancy.ZERO))
        failed = False
    except EvalError:
        failed = True
    assert failed == (certain_failure(expr) is not None), describe(expr)


def _reads_variables(expr: Expr) -> bool:
    if isinstance(expr, Var):
        return True
    if isinstance(expr, Unary):
        return _reads_variables(expr.operand)
    if isinstance(expr, Binary):
        return _reads_variables(expr.left) or _reads_variables(expr.right)
    if isinstance(expr, Func):
        return any(_reads_variables(a) for a in expr.args)
    return False
