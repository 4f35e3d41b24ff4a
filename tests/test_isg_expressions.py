"""ISG expressions: hand-checked readings, and the reader/writer round trip over generated trees."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.errors import UnsupportedError
from postproc.interp.evaluation import MappingEnv, evaluate
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Vacancy, Var
from postproc.rs274.expressions import ExprSyntaxError

from postproc.isg_family.expressions import BINARY, FUNCTIONS, P_BASE, parse_expr, spell_expr, spell_word_value, \
    parse_word_value

P = {P_BASE + n: float(n) for n in range(1, 10)}  # P1 = 1, ..., P9 = 9
ENV = MappingEnv(dict(P), Vacancy.NULL)  # as the default was: ISG reads no vacant value (isg/variables.py)


@pytest.mark.parametrize("text, value", [
    ("2 + 3 * 4", 14.0), ("2 ** 3 ** 2", 64.0), ("[-2] ** 2", 4.0), ("-[2 ** 2]", -4.0), ("[1 + 2] * 3", 9.0), ("7 MOD 3", 1.0),
    ("-7 MOD 3", -1.0), ("P2 * P3 - P4", 2.0), ("SQR[P3]", 9.0), ("SQRT[16]", 4.0), ("INT[-2.7]", -2.0),
    ("FRACT[2.75]", 0.75), ("ROUND[2.5]", 3.0), ("ROUND[-2.5]", -3.0), ("DEXP[2]", 100.0), ("LOG[1000]", 3.0),
    ("LN[1]", 0.0), ("EXP[0]", 1.0), ("ABS[-3]", 3.0), ("SIN[30]", 0.5), ("COS[60]", 0.5), ("TAN[45]", 1.0),
    ("ASIN[1]", 90.0), ("ACOS[0]", 90.0), ("ATAN[1]", 45.0), ("P1 == 1", 1.0), ("P1 != 1", 0.0),
    ("P1 < P2", 1.0), ("P2 > P3", 0.0), ("P2 <= 2", 1.0), ("P2 >= 3", 0.0), ("1 + 2 < 4", 1.0),
    ("'16#FF'", 255.0), ("'0x10'", 16.0), ("'H1f'", 31.0), ("'2#101'", 5.0),
])
def test_isg_expression_values(text: str, value: float) -> None:
    end, tree = parse_expr(text, 0)
    assert end == len(text)
    assert evaluate(tree, ENV) == pytest.approx(value, abs=1e-12)


@pytest.mark.parametrize("text, message", [
    ("P0", "P0: P parameters P1 to P499"), ("P500", "P500: P parameters P1 to P499"),
    ("P1[2]", "P parameter arrays are not modelled"), ("FOO[1]", "unknown function or variable 'FOO'"),
    ("SIN 30", "'[' expected after SIN"), ("-2 ** 2", "a sign before '**' is ambiguous"),
    ("3 * -P1 ** 2", "a sign before '**' is ambiguous"), ("[1 + 2", "']' expected"), ("'16#XY'", "malformed constant"),
])
def test_isg_expression_errors(text: str, message: str) -> None:
    with pytest.raises(ExprSyntaxError) as caught:
        parse_expr(text, 0)
    assert message in caught.value.message


def test_only_mapped_variables_have_an_isg_spelling() -> None:
    assert spell_expr(Var(Num(501.0))) == "P1" and spell_expr(Var(Num(999.0))) == "P499"
    for number in (1.0, 500.0, 1000.0, 5021.0):
        with pytest.raises(UnsupportedError):
            spell_expr(Var(Num(number)))
    with pytest.raises(UnsupportedError):
        spell_expr(Var(name="depth"))  # a LinuxCNC named parameter


def _trees() -> st.SearchStrategy[Expr]:
    leaves = st.one_of(
        st.integers(-1000, 1000).map(lambda n: Num(n / 8)),
        st.integers(1, 499).map(lambda n: Var(Num(float(P_BASE + n)))),
        st.sampled_from(["V.L.DEPTH", "V.P.X_1", "V.E.FEED"]).map(lambda n: Var(name=n)),
    )
    ops = sorted({op for op, _ in BINARY.values()})
    funcs = sorted(FUNCTIONS.values())
    return st.recursive(leaves, lambda inner: st.one_of(
        st.builds(Binary, st.sampled_from(ops), inner, inner),
        st.builds(lambda f, a: Func(f, [a]), st.sampled_from(funcs), inner),
        st.builds(lambda a: Unary("neg", a), inner),
    ), max_leaves=12)


def _canonical(e: Expr) -> Expr:
    """What reading a spelling gives back: a negated number is a negative number."""
    if isinstance(e, Unary):
        inner = _canonical(e.operand)
        if e.op == "neg" and isinstance(inner, Num):
            return Num(-inner.value)
        return Unary(e.op, inner)
    if isinstance(e, Binary):
        return Binary(e.op, _canonical(e.left), _canonical(e.right))
    if isinstance(e, Func):
        return Func(e.name, [_canonical(a) for a in e.args])
    return e


@settings(max_examples=300, deadline=None)
@given(_trees())
def test_isg_spelling_reads_back_as_the_same_tree(tree: Expr) -> None:
    text = spell_expr(tree)
    end, back = parse_expr(text, 0)
    assert end == len(text), text
    assert back == _canonical(tree), text
    word = spell_word_value(tree)
    end, value = parse_word_value(word, 0)
    assert end == len(word) and value == _canonical(tree), word
