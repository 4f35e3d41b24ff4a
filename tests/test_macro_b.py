"""Fanuc macro statements: text -> node -> text, byte for byte, and pinned located errors."""

from __future__ import annotations

import pytest

from postproc.interp.control import Assign, EndWhile, Goto, IfThen, While
from postproc.errors import UnsupportedError
from postproc.ir.expr import Binary, Func, Num, Var
from postproc.ir import Section
from postproc.rs274.expressions import ExprSyntaxError
from postproc.rs274.macro_b import parse_statement_fanuc, spell_statement_fanuc

V1, V2 = Var(Num(1.0)), Var(Num(2.0))

TABLE = [
    ("#1=#2+1.", Assign([(V1, Binary("add", V2, Num(1.0)))])),
    ("#[#2+1.]=SIN[30.]", Assign([(Var(Binary("add", V2, Num(1.0))), Func("sin", [Num(30.0)]))])),
    ("#100=#0", Assign([(Var(Num(100.0)), Var(Num(0.0)))])),
    ("IF [#1 GT 2.] GOTO 10", Goto(Num(10.0), Binary("gt", V1, Num(2.0)))),
    ("GOTO 10", Goto(Num(10.0))),
    ("GOTO #5", Goto(Var(Num(5.0)))),
    ("GOTO [#5+10.]", Goto(Binary("add", Var(Num(5.0)), Num(10.0)))),
    ("IF [#1 EQ #0] THEN #2=1.", IfThen(Binary("eq", V1, Var(Num(0.0))), Assign([(V2, Num(1.0))]))),
    ("WHILE [#1 LT 10.] DO1", While("1", Binary("lt", V1, Num(10.0)))),
    ("WHILE [[#1 GT 0.] AND [#2 LE 3.]] DO3", While("3", Binary("bitand", Binary("gt", V1, Num(0.0)),
                                                                     Binary("le", V2, Num(3.0))))),
    ("END1", EndWhile("1")),
]


@pytest.mark.parametrize("text, node", TABLE, ids=[t for t, _ in TABLE])
def test_validate_all_fanuc(text: str, node: Section) -> None:
    assert parse_statement_fanuc(text) == node
    assert spell_statement_fanuc(node) == text


@pytest.mark.parametrize("text, node", [
    ("if[#1gt2]goto10", Goto(Num(10.0), Binary("gt", V1, Num(2.0)))),
    ("#1 = #2 + 1", Assign([(V1, Binary("add", V2, Num(1.0)))])),
    ("WHILE[#1LT10]DO 1", While("1", Binary("lt", V1, Num(10.0)))),
    ("END 2", EndWhile("2")),
    ("GOTO10", Goto(Num(10.0))),
])
def test_other_spellings(text: str, node: Section) -> None:
    assert parse_statement_fanuc(text) == node


@pytest.mark.parametrize("text, message, pos", [
    ("END4", "END needs a loop number 1 to 3", 3),
    ("END", "END needs a loop number 1 to 3", 3),
    ("WHILE [#1 LT 2] DO", "DO needs a loop number 1 to 3", 18),
    ("WHILE [#1 LT 2]", "DO expected after WHILE [..]", 15),
    ("IF [#1 LT 2] #2=1", "GOTO or THEN expected after IF [..]", 13),
    ("IF #1 LT 2 GOTO 5", "'[' expected", 3),
    ("GOTO -5", "a sequence number, '#' or '[' expected after GOTO", 5),
    ("GOTO X", "a sequence number, '#' or '[' expected after GOTO", 5),
    ("#1 #2", "'=' expected", 3),
    ("#1=2 X5", "unknown operator 'X'", 5),
    ("GOTO 5 X", "unexpected 'X' after the statement", 7),
    ("#1=", "expression expected", 3),
    ("G01 X1", "a macro statement (#i=, IF, GOTO, WHILE, END) expected", 0),
    ("IF [#1 LT 2] THEN X1", "'#' expected", 18),
])
def test_errors(text: str, message: str, pos: int) -> None:
    with pytest.raises(ExprSyntaxError) as info:
        parse_statement_fanuc(text)
    assert (info.value.message, info.value.pos) == (message, pos)


@pytest.mark.parametrize("node, message", [
    (While("100", Num(1.0)), "fanuc loop numbers are 1 to 3, not '100'"),
    (Assign([(V1, Num(1.0)), (V2, Num(2.0))]), "fanuc assigns one variable per block, not 2"),
    (Assign([(Var(name="x"), Num(1.0))]), "fanuc has no named variables (#<x>)"),
    (Goto(Num(1.0), Binary("eq_tol", V1, V2)), "fanuc has no operator for 'eq_tol'"),
])
def test_unsupported(node: Section, message: str) -> None:
    with pytest.raises(UnsupportedError) as info:
        spell_statement_fanuc(node)
    assert info.value.message == message
