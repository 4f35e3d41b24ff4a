"""LinuxCNC o-word lines and assignments: text -> node -> text byte for byte, the readings rs274 also
accepts, pinned located errors, the do/while context, hypothesis round trips, and rs274 as the oracle
for the grammar facts (what it accepts, what it refuses, that the canonical spellings run)."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from postproc.interp.control import (
    Assign, Break, Call, Continue, Do, DoWhile, Else, ElseIf, EndIf, EndRepeat, EndWhile, Goto, If, Repeat,
    Return, SubEnd, SubStart, While,
)
from postproc.errors import UnsupportedError
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.ir import ProgramStart, Section
from postproc.rs274.expressions import LINUXCNC_SPELLING, ExprSyntaxError
from postproc.rs274.oword import (
    OwordParser, parse_assignments, parse_oword_line, spell_assignments, spell_oword,
)
from tests.support import rs274
from tests.test_rs274_expressions import trees

V1, V2, V5 = Var(Num(1.0)), Var(Num(2.0)), Var(Num(5.0))
X = Var(name="x")
LT3 = Binary("lt", V1, Num(3.0))

# Canonical text -> node, and node -> the same text.
TABLE: list[tuple[str, Section]] = [
    ("o100 sub", SubStart("100")),
    ("o<probe> sub", SubStart("<probe>")),
    ("o100 endsub", SubEnd("100")),
    ("o100 endsub [#1*2.]", SubEnd("100", Binary("mul", V1, Num(2.0)))),
    ("o<probe> return", Return("<probe>")),
    ("o<probe> return [#<_value>+1.]", Return("<probe>", Binary("add", Var(name="_value"), Num(1.0)))),
    ("o100 call", Call("100", {}, None, "macro")),
    ("o100 call [1.] [#2] [#<x>+1.]", Call("100", {1: Num(1.0), 2: V2, 3: Binary("add", X, Num(1.0))},
                                          None, "macro")),
    ("o<my-sub.v2> call [-1.]", Call("<my-sub.v2>", {1: Num(-1.0)}, None, "macro")),
    ("o#5 call [SIN[30.]]", Call(V5, {1: Func("sin", [Num(30.0)])}, None, "macro")),
    ("o[#5+1.] call", Call(Binary("add", V5, Num(1.0)), {}, None, "macro")),
    ("o1 if [#1 LT 3.]", If("1", LT3)),
    ("o1 elseif [#1 EQ 2. OR #2 GT 0.]",
     ElseIf("1", Binary("or", Binary("eq_tol", V1, Num(2.0)), Binary("gt", V2, Num(0.0))))),
    ("o1 else", Else("1")),
    ("o1 endif", EndIf("1")),
    ("o2 while [#1 LT 3.]", While("2", LT3)),
    ("o2 endwhile", EndWhile("2")),
    ("o3 do", Do("3")),
    ("o4 repeat [#5]", Repeat("4", V5)),
    ("o4 endrepeat", EndRepeat("4")),
    ("o2 break", Break("2")),
    ("o2 continue", Continue("2")),
    ("o0 if [1.]", If("0", Num(1.0))),
]


@pytest.mark.parametrize("text, node", TABLE, ids=[t for t, _ in TABLE])
def test_validate_all_linuxcnc(text: str, node: Section) -> None:
    assert parse_oword_line(text) == node
    assert spell_oword(node) == text


def test_do_while_spelling() -> None:
    node = DoWhile("3", LT3)
    assert spell_oword(node) == "o3 while [#1 LT 3.]"
    assert parse_oword_line("o3 while [#1 LT 3.]", do_labels={"3"}) == node
    assert parse_oword_line("o3 while [#1 LT 3.]", do_labels={"4"}) == While("3", LT3)


# Other spellings rs274 reads the same way (it deletes blanks and lower-cases outside comments);
# each was run through rs274 (test_rs274_reads_the_other_spellings).
OTHER = [
    ("O100 SUB", SubStart("100")),
    ("o 1 0 0 sub", SubStart("100")),
    ("o0100 sub", SubStart("100")),
    ("o100. sub", SubStart("100")),
    ("o1.0 if [1]", If("1", Num(1.0))),
    ("o<My Sub> sub", SubStart("<mysub>")),
    ("O<PROBE> CALL[1][2]", Call("<probe>", {1: Num(1.0), 2: Num(2.0)}, None, "macro")),
    ("o100 while[#1 LT 3]", While("100", LT3)),
    ("o100 WHILE [#1lt3]", While("100", LT3)),
    ("o100 end if", EndIf("100")),
    ("o100 i f [1]", If("100", Num(1.0))),
    ("o100 if [1] (a comment)", If("100", Num(1.0))),
    ("o100 if [1] ; to the end (of the line", If("100", Num(1.0))),
    ("o100 else(x)(y);z", Else("100")),
    ("o100 call (first) [1] (between) [2] (after)", Call("100", {1: Num(1.0), 2: Num(2.0)}, None, "macro")),
    ("o100 call [4] ; [5]", Call("100", {1: Num(4.0)}, None, "macro")),
    ("  o100 endsub[5]", SubEnd("100", Num(5.0))),
]


@pytest.mark.parametrize("text, node", OTHER, ids=[t for t, _ in OTHER])
def test_other_spellings(text: str, node: Section) -> None:
    assert parse_oword_line(text) == node


@pytest.mark.parametrize("text", ["o100", "O100 (c)", "O 1 0 0", "o0100", "O100.0 ; c"])
def test_a_bare_number_starts_a_fanuc_style_subprogram(text: str) -> None:
    """rs274 reads ``O100`` alone on its line as the start of a subprogram that M98 P100 runs."""
    assert parse_oword_line(text) == ProgramStart(100)


def test_starts_at_pos() -> None:
    assert parse_oword_line("N10 o1 do", 4) == Do("1")


@pytest.mark.parametrize("text, message, pos", [
    ("G0 X1", "o-word expected", 0),
    ("o<x>", "a bare o-word starts a Fanuc-style subprogram and takes a number, not a name or an expression", 0),
    ("o#1 (c)", "a bare o-word starts a Fanuc-style subprogram and takes a number, not a name or an expression",
     0),
    ("o100 [1]", "o-word command (sub, call, if, while, do, repeat, ...) expected", 5),
    ("o100 foo", "unknown o-word command 'foo'", 5),
    ("o100 dox", "unexpected 'x' after the o-word statement (only a comment may follow)", 7),
    ("o100 subroutine", "unexpected 'r' after the o-word statement (only a comment may follow)", 8),
    ("o sub", "o-word number or <name> expected", 2),
    ("o-1 if [1]", "o-word number or <name> expected", 1),
    ("o1.5 if [1]", "o-word number 1.5 is not a whole number", 1),
    ("o<abc sub", "'>' expected: an o-word name is written o<name>", 9),
    ("o<> sub", "empty o-word name", 1),
    ("o<a#b> sub", "o-word names use letters, digits, '_', '-' and '.', not '#'", 3),
    ("o<a/b> call", "o-word names use letters, digits, '_', '-' and '.', not '/'", 3),
    ("o#5 sub", "a computed o-number (o#.., o[..]) is read only with call, not with sub", 1),
    ("o[2] if [1]", "a computed o-number (o#.., o[..]) is read only with call, not with if", 1),
    ("o100 while 1", "'[' expected after while", 11),
    ("o100 if sin[90]", "'[' expected after if", 8),
    ("o100 repeat", "'[' expected after repeat", 11),
    ("o100 if [1] + [0]", "unexpected '+' after the o-word statement (only a comment may follow)", 12),
    ("o100 if [1] G0 X1", "unexpected 'G' after the o-word statement (only a comment may follow)", 12),
    ("o100 else [1]", "unexpected '[' after the o-word statement (only a comment may follow)", 10),
    ("o100 call #5", "unexpected '#' after the o-word statement (only a comment may follow)", 10),
    ("o100 call [4] sin[1]", "unexpected 's' after the o-word statement (only a comment may follow)", 14),
    ("o100 return 5", "unexpected '5' after the o-word statement (only a comment may follow)", 12),
    ("o100 (x) if [1]", "o-word command (sub, call, if, while, do, repeat, ...) expected", 5),
    ("o100 if [1] (open", "unclosed comment", 12),
    ("o100 if [1] (a (b) c)", "nested comment: '(' inside a comment", 15),
    ("o100 if [#1 LT]", "unexpected ']' in expression", 14),
    ("o100 call" + " [1]" * 31, "too many call arguments: at most 30 (#1-#30)", 130),
])
def test_errors(text: str, message: str, pos: int) -> None:
    with pytest.raises(ExprSyntaxError) as info:
        parse_oword_line(text)
    assert (info.value.message, info.value.pos) == (message, pos)


def test_error_is_located_by_the_caller() -> None:
    with pytest.raises(ExprSyntaxError) as info:
        parse_oword_line("N10 o100 while 1", 4)
    assert str(info.value.at("prog.ngc", 7)) == "prog.ngc:7:16: error: '[' expected after while"


@pytest.mark.parametrize("node, message", [
    (Goto(Num(10.0)), "linuxcnc has no o-word for Goto"),
    (Call("100", {1: V1}, None, "sub"),
     "an o-word call gives the subprogram its own #1-#30; this call shares the caller's locals (a subprogram call)"),
    (Call("100", {}, Num(3.0), "macro"), "an o-word call has no repeat count"),
    (Call("100", {1: V1, 3: V1}, None, "macro"),
     "an o-word call sets #1 to #n in order (at most #30); this call sets #1, #3"),
    (Call("100", {i: V1 for i in range(1, 32)}, None, "macro"),
     "an o-word call sets #1 to #n in order (at most #30); this call sets "
     + ", ".join(f"#{i}" for i in range(1, 32))),
    (Return(None), "a LinuxCNC return names its subprogram: o<name> return (this Return has no name)"),
    (Return("100", None, Num(20.0)), "a LinuxCNC return cannot continue at a sequence number"),
    (While("x", V1), "'x' is not a LinuxCNC o-word label (a number, or <name> in lower case)"),
    (SubStart("<Probe>"), "'<Probe>' is not a LinuxCNC o-word label (a number, or <name> in lower case)"),
    (SubStart("0100"), "'0100' is not a LinuxCNC o-word label (a number, or <name> in lower case)"),
    (If("1", Binary("bitand", V1, V2)), "linuxcnc has no operator for 'bitand'"),
])
def test_unsupported(node: Section, message: str) -> None:
    with pytest.raises(UnsupportedError) as info:
        spell_oword(node)
    assert info.value.message == message


# ----------------------------------------------------------------------------- context: OwordParser

def _parse_program(lines: list[str]) -> list[Section]:
    p = OwordParser()
    return [p.parse(text, 0, n) for n, text in enumerate(lines, 1)]


def test_while_after_do_ends_it_and_starts_a_loop_otherwise() -> None:
    nodes = _parse_program(["o1 do", "o2 while [1]", "o2 endwhile", "o1 while [#1 LT 3]", "o3 while [0]"])
    assert nodes == [Do("1"), While("2", Num(1.0)), EndWhile("2"), DoWhile("1", LT3), While("3", Num(0.0))]


def test_nested_do_loops() -> None:
    nodes = _parse_program(["o1 do", "o2 do", "o2 while [1]", "o1 while [1]"])
    assert nodes == [Do("1"), Do("2"), DoWhile("2", Num(1.0)), DoWhile("1", Num(1.0))]


def test_labels_are_scoped_per_subprogram() -> None:
    nodes = _parse_program(["o1 do", "o<s> sub", "o1 while [1]", "o1 endwhile", "o<s> endsub", "o1 while [1]"])
    assert nodes == [Do("1"), SubStart("<s>"), While("1", Num(1.0)), EndWhile("1"), SubEnd("<s>"),
                     DoWhile("1", Num(1.0))]


@pytest.mark.parametrize("lines, message, pos", [
    (["o1 do", "o1 while [1]", "o1 while [1]"],
     "label o1 is already used by the do on line 1 in the main program (LinuxCNC would read it as the end of "
     "that do loop): each if or loop needs its own label", 1),
    (["o<s> sub", "o1 if [1]", "o1 endif", "o1 while [1]"],
     "label o1 is already used by the if on line 2 in o<s>: each if or loop needs its own label", 1),
    (["o1 while [1]", "o1 endwhile", "o1 do"],
     "label o1 is already used by the while on line 1 in the main program: each if or loop needs its own label", 1),
    (["o<a> sub", "o<b> sub"], "o<b> sub inside the definition of o<a> (line 1): subprogram definitions do not nest",
     1),
    (["o<a> sub", "o<b> endsub"], "o<b> endsub does not end a definition: o<a> sub (line 1) is being defined", 1),
    (["o<b> endsub"], "o<b> endsub does not end a definition: no sub is open", 1),
    (["o4 repeat [3]", "o4 break"], "break leaves a while or do loop only: o4 is the repeat on line 1", 1),
    (["o4 if [1]", "o4 continue"], "continue leaves a while or do loop only: o4 is the if on line 1", 1),
    (["o4 break"], "break leaves a while or do loop only: no loop o4 is open", 1),
])
def test_context_errors(lines: list[str], message: str, pos: int) -> None:
    with pytest.raises(ExprSyntaxError) as info:
        _parse_program(lines)
    assert (info.value.message, info.value.pos) == (message, pos)


# ----------------------------------------------------------------------------- assignments

ASSIGNMENTS: list[tuple[str, Assign]] = [
    ("#1=5.", Assign([(V1, Num(5.0))])),
    ("#1=-#2", Assign([(V1, Unary("neg", V2))])),
    ("#1=[#2+1.]", Assign([(V1, Binary("add", V2, Num(1.0)))])),
    ("#1=-[#2+1.]", Assign([(V1, Unary("neg", Binary("add", V2, Num(1.0))))])),
    ("#1=SIN[90.]", Assign([(V1, Func("sin", [Num(90.0)]))])),
    ("#<x>=EXISTS[#<y>]", Assign([(X, Func("exists", [Var(name="y")]))])),
    ("#<_g>=1.", Assign([(Var(name="_g"), Num(1.0))])),
    ("#[#1+1.]=#[#2]", Assign([(Var(Binary("add", V1, Num(1.0))), Var(V2))])),
    ("#1=5. #2=#1 #<x>=[#1*2.]", Assign([(V1, Num(5.0)), (V2, V1), (X, Binary("mul", V1, Num(2.0)))])),
    ("#5601=1.", Assign([(Var(Num(5601.0)), Num(1.0))])),
]


@pytest.mark.parametrize("text, node", ASSIGNMENTS, ids=[t for t, _ in ASSIGNMENTS])
def test_validate_all_assignments(text: str, node: Assign) -> None:
    assert parse_assignments(text) == (len(text), node)
    assert spell_assignments(node) == text


@pytest.mark.parametrize("text, end, node", [
    ("#1=5#2=6", 8, Assign([(V1, Num(5.0)), (V2, Num(6.0))])),
    ("#1 = 5 G0 X#1", 6, Assign([(V1, Num(5.0))])),
    ("#<X>=1 (c)", 6, Assign([(X, Num(1.0))])),
    ("##1=8", 5, Assign([(Var(V1), Num(8.0))])),
])
def test_assignments_end_where_the_words_start(text: str, end: int, node: Assign) -> None:
    assert parse_assignments(text) == (end, node)


def test_assignments_from_pos() -> None:
    assert parse_assignments("G0 X1 #1=2", 6) == (10, Assign([(V1, Num(2.0))]))


@pytest.mark.parametrize("text, message, pos", [
    ("#1=1+2", "LinuxCNC reads one value after '=': bracket an expression, #1=[#2+1]", 4),
    ("#1=#2 *3", "LinuxCNC reads one value after '=': bracket an expression, #1=[#2+1]", 6),
    ("#1 4", "'=' expected", 3),
    ("#1=", "expression expected", 3),
    ("#0=1", "parameter number out of range: #0 (LinuxCNC has #1-#5601)", 0),
    ("#1=1 #5602=1", "parameter number out of range: #5602 (LinuxCNC has #1-#5601)", 5),
    ("#5420=1", "#5420 is read-only in LinuxCNC", 0),
    ("#5021=1", "#5021 is read-only in LinuxCNC", 0),
    ("#<a b>=1", "named parameter expected: #<name> with letters, digits and _", 3),
    ("G0", "'#' expected", 0),
])
def test_assignment_errors(text: str, message: str, pos: int) -> None:
    with pytest.raises(ExprSyntaxError) as info:
        parse_assignments(text)
    assert (info.value.message, info.value.pos) == (message, pos)


@pytest.mark.parametrize("node, message", [
    (Assign([(Var(Num(0.0)), Num(1.0))]), "LinuxCNC cannot set #0 (settable: #1-#5601, not the read-only ones)"),
    (Assign([(Var(Num(5400.0)), Num(1.0))]), "LinuxCNC cannot set #5400 (settable: #1-#5601, not the read-only ones)"),
    (Assign([(V1, Binary("rem_int", V1, V2))]), "linuxcnc has no operator for 'rem_int'"),
])
def test_unsupported_assignments(node: Assign, message: str) -> None:
    with pytest.raises(UnsupportedError) as info:
        spell_assignments(node)
    assert info.value.message == message


# ----------------------------------------------------------------------------- hypothesis round trips

_exprs = trees(LINUXCNC_SPELLING)
_labels = st.one_of(st.integers(0, 99999).map(str),
                    st.text("abcdefghijklmnopqrstuvwxyz0123456789_-.", min_size=1, max_size=12).map(lambda s: f"<{s}>"))
_call_names = st.one_of(_labels, st.builds(Var, st.integers(1, 30).map(lambda i: Num(float(i)))),
                        st.builds(lambda e: Var(e), _exprs))


def _nodes() -> st.SearchStrategy[Section]:
    lab, ex = _labels, _exprs
    return st.one_of(
        st.builds(SubStart, lab), st.builds(SubEnd, lab, st.none() | ex), st.builds(Return, lab, st.none() | ex),
        st.builds(lambda n, a: Call(n, dict(enumerate(a, 1)), None, "macro"), _call_names,
                  st.lists(ex, max_size=4)),
        st.builds(If, lab, ex), st.builds(ElseIf, lab, ex), st.builds(Else, lab), st.builds(EndIf, lab),
        st.builds(While, lab, ex), st.builds(EndWhile, lab), st.builds(Do, lab), st.builds(Repeat, lab, ex),
        st.builds(EndRepeat, lab), st.builds(Break, lab), st.builds(Continue, lab),
    )


@settings(max_examples=400, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(_nodes())
def test_oword_round_trip(node: Section) -> None:
    try:
        text = spell_oword(node)
    except UnsupportedError:  # nesting beyond the bound, a Var spelt without a fixed index
        assume(False)
        return
    assert parse_oword_line(text) == node, text


@settings(max_examples=200, suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
@given(st.lists(st.tuples(st.one_of(st.integers(1, 5601).filter(lambda i: i not in range(5021, 5430))
                                    .map(lambda i: Var(Num(float(i)))),
                                    st.sampled_from(["x", "_g", "a1"]).map(lambda n: Var(name=n)),
                                    st.builds(Var, _exprs)), _exprs), min_size=1, max_size=4))
def test_assignment_round_trip(items: list[tuple[Var, Expr]]) -> None:
    node = Assign(items)
    try:
        text = spell_assignments(node)
    except UnsupportedError:
        assume(False)
        return
    assert parse_assignments(text + " G0 X1") == (len(text), node), text


# ----------------------------------------------------------------------------- rs274 as the oracle

needs_rs274 = pytest.mark.skipif(not rs274.available(), reason="rs274 is not installed")


def _messages(program: str) -> list[str]:
    return [line.split('MESSAGE("')[1].rstrip('")').strip() for line in rs274.run_rs274(program)
            if "MESSAGE(" in line]


@needs_rs274
def test_rs274_runs_the_canonical_spellings() -> None:
    """A program written by spell_oword / spell_assignments from nodes: rs274 runs it as intended."""
    sub = [SubStart("<twice>"), Return("<twice>", Binary("mul", V1, Num(2.0))), SubEnd("<twice>"),
           SubStart("100"), "(DEBUG, called #1 #2)", SubEnd("100")]
    nodes: list[Section | str] = [
        *sub, Assign([(V1, Num(0.0)), (V2, Num(0.0))]),
        While("1", LT3), Assign([(V1, Binary("add", V1, Num(1.0)))]), If("2", Binary("eq_tol", V1, Num(2.0))),
        Continue("1"), EndIf("2"), Assign([(V2, Binary("add", V2, V1))]), EndWhile("1"),
        "(DEBUG, while #1 #2)",
        Do("3"), Assign([(V1, Binary("sub", V1, Num(1.0)))]), DoWhile("3", Binary("gt", V1, Num(0.0))),
        "(DEBUG, do #1)",
        Assign([(V5, Num(0.0))]), Repeat("4", Num(3.0)), Assign([(V5, Binary("add", V5, Num(1.0)))]),
        EndRepeat("4"), "(DEBUG, repeat #5)",
        While("7", Num(1.0)), Assign([(V5, Binary("sub", V5, Num(1.0)))]), If("5", Binary("le", V5, Num(2.0))),
        Break("7"), EndIf("5"), EndWhile("7"), "(DEBUG, break #5)",
        If("6", Binary("lt", V5, Num(0.0))), "(DEBUG, no)", ElseIf("6", Binary("eq_tol", V5, Num(2.0))),
        "(DEBUG, elseif)", Else("6"), "(DEBUG, no)", EndIf("6"),
        Call("<twice>", {1: Num(21.0)}, None, "macro"), "(DEBUG, value #<_value>)",
        Assign([(Var(name="n"), Num(100.0))]), Call(Var(name="n"), {1: Num(4.0), 2: Unary("neg", V5)}, None, "macro"),
    ]
    text = []
    for n in nodes:
        if isinstance(n, str):
            text.append(n)
        elif isinstance(n, Assign):
            text.append(spell_assignments(n))
        else:
            text.append(spell_oword(n))
    assert _messages("\n".join(text + ["M2"])) == [
        "while 3.000000 4.000000", "do 0.000000", "repeat 3.000000", "break 2.000000", "elseif", "value 42.000000",
        "called 4.000000 -2.000000"]


@needs_rs274
def test_rs274_reads_the_other_spellings() -> None:
    """Every OTHER spelling is accepted by rs274 with the meaning the table gives it."""
    program = """
        O<MY SUB> SUB
        (DEBUG, mysub #1 #2)
        o<mysub> endsub[5]
        O<my sub> CALL[1][2]
        o<mysub> call (first) [3] (between) [4] (after)
        o 0 1 0 0 i f [1] (a comment)
        (DEBUG, if)
        o100 end if ; to the end (of the line
        #1 = 0
        o1.0 WHILE[#1lt3]
        #1 = [#1 + 1]
        o1. endwhile
        (DEBUG, while #1)
        #1=5#2=6
        (DEBUG, parallel #1 #2)
        #1 = 1
        #1 = 7 #2 = #1
        (DEBUG, read first #1 #2)
        M2
    """
    assert _messages("\n".join(line.strip() for line in program.strip().splitlines())) == [
        "mysub 1.000000 2.000000", "mysub 3.000000 4.000000", "if", "while 3.000000",
        "parallel 5.000000 6.000000", "read first 7.000000 1.000000"]


@needs_rs274
@pytest.mark.parametrize("program, error", [
    ("o100 while 1\no100 endwhile", "Left bracket missing after 'while'"),
    ("o100 if [1] + [0]\no100 endif", "Unexpected character after O-word"),
    ("o100 if [1]\no100 else [1]\no100 endif", "Unexpected character after O-word"),
    ("o100 (x) if [1]\no100 endif", "Unexpected character after O-word"),
    ("o<s> sub\no<s> endsub\no<s> call #5", "Unexpected character after O-word"),
    ("o<s> sub\no<s> endsub\no<s> call" + " [1]" * 31, "Too many subroutine parameters"),
    ("G0 X1 o100 if [1]\no100 endif", "Bad character 'o' used"),
    ("o100 foo", "Unknown control command in o word"),
    ("#1=1+2", "Bad character '+' used"),
    ("#0=1", "Parameter number out of range"),
    ("#5602=1", "Parameter number out of range"),
    ("#5420=1", "Parameter is readonly"),
    ("#5413=1", "Parameter is readonly"),
    ("#1 4", "Equal sign missing in parameter setting"),
    ("o4 repeat [3]\no4 break\no4 endrepeat", "no matching while/do label: 'o4 break' (found 'repeat' in line 1)"),
])
def test_rs274_refuses_what_the_parser_refuses(program: str, error: str) -> None:
    with pytest.raises(rs274.RS274Error) as info:
        rs274.run_rs274(program + "\nM2")
    assert info.value.stderr.splitlines()[0].endswith(error)


@needs_rs274
def test_rs274_settable_neighbours_of_the_readonly_parameters() -> None:
    assert _messages("#5414=1\n#5030=2\n#5419=3\n#5429=4\n(DEBUG, ok #5414 #5030 #5419 #5429)\nM2") == [
        "ok 1.000000 2.000000 3.000000 4.000000"]
