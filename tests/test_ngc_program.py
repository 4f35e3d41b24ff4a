"""LinuxCNC programs that compute, through the LinuxCNC reader and writer.

* A ``validate_all``-style table: each o-word, assignment and expression line read by the LinuxCNC
  reader and written back normalised (the canonical spelling, derived by hand from LinuxCNC's syntax:
  explicit decimal points, operator words with a blank each side, labels lower-cased), or, for a
  construct built as IR that LinuxCNC cannot spell, the ``UnsupportedError`` naming it.
* Byte-for-byte round trips of the hand-written ``tests/golden/macro/*.ngc`` programs.
* Located errors with pinned messages (break outside a loop, unknown subprogram, the loop bound of
  ``<Limits>``, an unset named parameter, ...).
* hypothesis: generated expressions round-trip through the reader and the writer.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from postproc.api import read_program, translate
from postproc.context import Context
from postproc.interp.control import Assign, Call, Goto, If, IfThen, ModalCall, Return, While
from postproc.interp.evaluation import certain_failure
from postproc.errors import Diagnostics, ErrorLevel, ErrorList, UnsupportedError
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.rs274.expressions import LINUXCNC_SPELLING, spell_word_value
from postproc.rs274.ngc_lexer import lex_block
from postproc.rs274.oword import OwordParser
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events

ROOT = Path(__file__).resolve().parents[1]
MACRO = sorted((ROOT / "tests" / "golden" / "macro").glob("*.ngc"))


def normalised(text: str) -> str:
    """``text`` read as LinuxCNC and written back as LinuxCNC, normalised (canonical spelling)."""
    setup = MachineSetup()
    setup.output.normalize = True
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="t.ngc", source="linuxcnc", target="linuxcnc", setup=setup)
    return out.getvalue()


# -- read -> write table ---------------------------------------------------------------------------

SPELLINGS = [
    # subprograms
    ("o100 sub\no100 endsub", "o100 sub\no100 endsub"),
    ("O0100 Sub\nO0100 ENDSUB [#1+1]", "o100 sub\no100 endsub [#1+1.]"),
    ("o<Probe Tip> sub\no<probetip> return [2]\no<PROBETIP> endsub", "o<probetip> sub\no<probetip> return [2.]\n"
     "o<probetip> endsub"),
    ("o<probe> call [1] [#2] [-#<x>]", "o<probe> call [1.] [#2] [-#<x>]"),
    ("o<probe> call", "o<probe> call"),
    ("o[#5+1] call [3]", "o[#5+1.] call [3.]"),
    ("N10 o100 call (comment)", "N10 o100 call (comment)"),
    # conditions
    ("o1 if [#1 EQ 2]\no1 elseif [#1 GT 2 AND #2 LT 1]\no1 else\no1 endif",
     "o1 if [#1 EQ 2.]\no1 elseif [#1 GT 2. AND #2 LT 1.]\no1 else\no1 endif"),
    ("o1 if[#1 ne 0]\no1 endif", "o1 if [#1 NE 0.]\no1 endif"),
    # loops
    ("o2 while [#1 LT 10]\no2 break\no2 continue\no2 endwhile",
     "o2 while [#1 LT 10.]\no2 break\no2 continue\no2 endwhile"),
    ("o3 do\no3 continue\no3 while [#1 LE 3]", "o3 do\no3 continue\no3 while [#1 LE 3.]"),
    ("o4 repeat [3]\no4 endrepeat", "o4 repeat [3.]\no4 endrepeat"),
    ("o 1 0 0 while [1]\no 1 0 0 end while", "o100 while [1.]\no100 endwhile"),
    # assignments
    ("#1=5", "#1=5."),
    ("#1 = 0.50", "#1=0.5"),
    ("#<Depth>=[#1*2]", "#<depth>=[#1*2.]"),
    ("#<_g>=1 #2=#1", "#<_g>=1. #2=#1"),
    ("#[#1+1]=-#2", "#[#1+1.]=-#2"),
    ("##1=3", "#[#1]=3."),
    # operators (LinuxCNC precedence: ** > * / MOD > + - > comparisons > AND OR XOR)
    ("#1=[2**3]", "#1=[2.**3.]"),
    ("#1=[7 mod 3]", "#1=[7. MOD 3.]"),
    ("#1=[#1 XOR #2 OR #3]", "#1=[#1 XOR #2 OR #3]"),
    ("#1=[[1+2]*3]", "#1=[[1.+2.]*3.]"),
    ("#1=[1+2*3]", "#1=[1.+2.*3.]"),
    ("#1=[-2**2]", "#1=[-2.**2.]"),
    ("#1=[2-[3-4]]", "#1=[2.-[3.-4.]]"),
    # functions
    ("#1=ATAN[1]/[2]", "#1=ATAN[1.]/[2.]"),
    ("#1=EXISTS[#<x>]", "#1=EXISTS[#<x>]"),
    ("#1=[FIX[#2]+FUP[#3]]", "#1=[FIX[#2]+FUP[#3]]"),
    ("#1=sqrt[4]", "#1=SQRT[4.]"),
    ("#1=ABS[-2]", "#1=ABS[-2.]"),
    ("#1=[ROUND[2.5]+LN[1]+EXP[0]]", "#1=[ROUND[2.5]+LN[1.]+EXP[0.]]"),
    ("#1=[SIN[30]+COS[30]+TAN[30]+ASIN[1]+ACOS[1]]", "#1=[SIN[30.]+COS[30.]+TAN[30.]+ASIN[1.]+ACOS[1.]]"),
]


@pytest.mark.parametrize("text, expected", SPELLINGS, ids=[s[0].split("\n")[0] for s in SPELLINGS])
def test_read_write_spelling(text: str, expected: str) -> None:
    assert normalised(text + "\n") == expected + "\n"


@pytest.mark.parametrize("text", [s[0] for s in SPELLINGS] + [s[1] for s in SPELLINGS])
def test_unchanged_lines_are_copied_byte_for_byte(text: str) -> None:
    out = io.StringIO(newline="")
    translate(io.StringIO(text + "\r\n", newline=""), out, file="t.ngc", source="linuxcnc", target="linuxcnc")
    assert out.getvalue() == text + "\r\n"


V1, V2 = Var(Num(1.0)), Var(Num(2.0))

UNSPELLABLE = [
    (Goto(Num(10.0)), "linuxcnc has no o-word for Goto"),
    (IfThen(V1, Assign([(V2, Num(1.0))])), "linuxcnc has no o-word for IfThen"),
    (Call("2000", {1: Num(1.0)}, None, "sub"), "the linuxcnc dialect cannot express a subprogram call with arguments (M98 passes none)"),
    (Call("<x>", {}, None, "sub"), "the linuxcnc dialect cannot express a call of the named subprogram <x> with M98 (it calls program numbers)"),
    (Call("2000", {}, Num(3.0), "macro"), "an o-word call has no repeat count"),
    (Call("2000", {1: Num(1.0), 3: Num(2.0)}, None, "macro"),
     "an o-word call sets #1 to #n in order (at most #30); this call sets #1, #3"),
    (ModalCall("9010", {}, None), "linuxcnc has no o-word for ModalCall"),
    (Return(None, None, Num(50.0)), "the linuxcnc dialect cannot express a return to a block number (M99 P: rs274 refuses it)"),
    (Return(None, Num(1.0), None), "a LinuxCNC return names its subprogram: o<name> return (this Return has no name)"),
    (While("1", Binary("bitand", V1, V2)), "linuxcnc has no operator for 'bitand'"),
    (If("1", Func("asin_360", [V1])), "linuxcnc has no function for 'asin_360'"),
    (Assign([(Var(Num(5021.0)), Num(1.0))]), "LinuxCNC cannot set #5021 (settable: #1-#5601, not the read-only ones)"),
    (Assign([(V1, Binary("rem_int", V1, V2))]), "linuxcnc has no operator for 'rem_int'"),
]


def test_subprogram_calls_and_plain_returns_are_m98_and_m99() -> None:
    dialect = default_registry().dialect("linuxcnc")
    ctx = Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.RAISE), "fanuc")
    assert dialect.WRITER is not None
    writer = dialect.WRITER(ctx, "fanuc", dialect)
    for section, text in [(Call("2000", {}, Num(3.0), "sub"), "M98 P2000 L3\n"), (Call("7", {}, None, "sub"), "M98 P7\n"),
                          (Call(V1, {}, V2, "sub"), "M98 P#1 L#2\n"), (Return(None, None, None), "M99\n")]:
        block = Block(7, None)
        block.add(section)
        assert writer.write_block(block) == text


@pytest.mark.parametrize("section, message", UNSPELLABLE, ids=[type(s).__name__ for s, _ in UNSPELLABLE])
def test_what_linuxcnc_cannot_spell_is_unsupported(section: object, message: str) -> None:
    dialect = default_registry().dialect("linuxcnc")
    ctx = Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.RAISE), "fanuc")
    assert dialect.WRITER is not None
    writer = dialect.WRITER(ctx, "fanuc", dialect)
    block = Block(7, None)
    block.add(section)  # type: ignore[arg-type]
    with pytest.raises(UnsupportedError) as info:
        writer.write_block(block)
    assert str(info.value) == f"t.nc:7:1: error: {message}"


# -- fixtures round trip ---------------------------------------------------------------------------

@pytest.mark.parametrize("path", [p for p in MACRO if p.stem != "subprogram_repeat"], ids=lambda p: p.stem)
def test_macro_fixture_with_computed_words_round_trips_byte_for_byte(path: Path) -> None:
    _round_trip(path)


def test_macro_fixture_of_subprograms_round_trips_byte_for_byte() -> None:
    _round_trip(ROOT / "tests" / "golden" / "macro" / "subprogram_repeat.ngc")


def _round_trip(path: Path) -> None:
    data = path.read_bytes()
    out = io.StringIO(newline="")
    translate(io.StringIO(data.decode(), newline=""), out, file=str(path), source="linuxcnc", target="linuxcnc")
    assert out.getvalue().encode() == data


# -- reading ---------------------------------------------------------------------------------------

def test_assignments_anywhere_in_a_line_become_one_assign_in_order() -> None:
    block = lex_block("t.ngc", 1, "#1=2 G0 X#1 #2=[#1+1] (c)", "\n", "linuxcnc", OwordParser())
    assert block.words == [("G", "0"), ("X", "#1")]
    assert block.values == {"X": V1}
    assert block.sections["Assign"] == Assign([(V1, Num(2.0)), (V2, Binary("add", V1, Num(1.0)))])


@pytest.mark.parametrize("text, letter, raw, value", [
    ("G0 X[#1*2]", "X", "[#1*2]", Binary("mul", V1, Num(2.0))),
    ("G0 X-#<depth>", "X", "-#<depth>", Unary("neg", Var(name="depth"))),
    ("G0 X - [1]", "X", "- [1]", Unary("neg", Num(1.0))),
    ("G#10", "G", "#10", Var(Num(10.0))),
    ("G0 X SIN[30]", "X", "SIN[30]", Func("sin", [Num(30.0)])),
    ("G0 Y#<_g>", "Y", "#<_g>", Var(name="_g")),
])
def test_expression_words_keep_their_text_and_tree(text: str, letter: str, raw: str, value: Expr) -> None:
    block = lex_block("t.ngc", 1, text, "\n", "linuxcnc", OwordParser())
    assert (letter, raw) in block.words
    assert block.values[letter] == value


def test_a_computed_g_code_keeps_its_block_verbatim() -> None:
    blocks = read_program(io.StringIO("G21\nG#10 X1\n"), file="t.ngc", dialect="linuxcnc")
    native = blocks[1].sections["NativeCode"]
    assert native.what == "a computed G code (G#10)"  # type: ignore[attr-defined]
    assert native.text == "G#10 X1"  # type: ignore[attr-defined]


@pytest.mark.parametrize("text, message", [
    ("G0 X#1", "t.ngc:1:5: error: parameters (#) are not supported by the grbl reader"),
    ("#1=2", "t.ngc:1:1: error: parameters (#) are not supported by the grbl reader"),
    ("G0 X[1+2]", "t.ngc:1:5: error: expressions ([...]) are not supported by the grbl reader"),
    ("o100 sub", "t.ngc:1:1: error: O-words (subprograms, loops, conditions) are not supported by the grbl reader"),
    ("O100", "t.ngc:1:1: error: O-words (subprograms, loops, conditions) are not supported by the grbl reader"),
])
def test_grbl_refuses_what_grbl_has_not(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        read_program(io.StringIO(text + "\n"), file="t.ngc", dialect="grbl")
    assert [str(e) for e in info.value.errors] == [message]


# -- located errors when the program runs ----------------------------------------------------------

def run_errors(text: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(text), file="t.ngc", dialect="linuxcnc", setup=setup))
    return [str(e) for e in info.value.errors]


def test_break_outside_a_loop() -> None:
    assert run_errors("G21\no1 break\nM30\n") == [
        "t.ngc:2:2: error: break leaves a while or do loop only: no loop o1 is open"]
    assert run_errors("G21\no1 repeat [2]\no1 break\no1 endrepeat\nM30\n") == [
        "t.ngc:3:2: error: break leaves a while or do loop only: o1 is the repeat on line 2"]


def test_unknown_subprogram() -> None:
    assert run_errors("G21\no<nosuch> call [1]\nM30\n") == [
        "t.ngc:2:1: error: subprogram o<nosuch> not found (called by 'o<nosuch> call [1]')"]


def test_loop_bound_from_the_set_up() -> None:
    setup = MachineSetup()
    setup.limits = Limits(loop_iterations=10)
    text = "G21\n#1=0\no1 while [#1 LT 100]\n#1=[#1+1]\no1 endwhile\nM30\n"
    assert run_errors(text, setup) == [
        "t.ngc:5:1: error: loop 'o1 endwhile' exceeds the set-up's bound of 10 loop iterations, jumps and calls "
        "in total (<Limits loopIterations=\"10\"/>)"]


def test_call_depth_bound_from_the_set_up() -> None:
    setup = MachineSetup()
    setup.limits = Limits(call_depth=3)
    text = "G21\no<r> sub\no<r> call\no<r> endsub\no<r> call\nM30\n"
    assert run_errors(text, setup) == [
        "t.ngc:3:1: error: 'o<r> call' exceeds the set-up's bound of 3 nested calls (<Limits callDepth=\"3\"/>) "
        "(in o<r>, called from t.ngc line 3; in o<r>, called from t.ngc line 3; in o<r>, called from t.ngc line 5)"]


def test_unset_named_parameter() -> None:
    assert run_errors("G21\nG0 X#<depth>\nM30\n") == ["t.ngc:2:4: error: named parameter #<depth> is not defined"]


def test_unclosed_loop_and_division_by_zero_inside_a_call() -> None:
    assert run_errors("G21\no1 while [1]\nM30\n") == ["t.ngc:2:1: error: 'o1 while [1]' is never closed"]
    assert run_errors("G21\no<s> sub\nG0 X[1/#1]\no<s> endsub\no<s> call [0]\nM30\n") == [
        "t.ngc:3:4: error: division by zero in 1/#1 (in o<s>, called from t.ngc line 5)"]


def test_a_computed_word_that_is_not_an_integer() -> None:
    assert run_errors("G21\n#1=1.5\nT#1 M6\nM30\n") == [
        "t.ngc:3:1: error: address T takes an integer, the expression gives 1.5 (T#1)"]


# -- hypothesis ------------------------------------------------------------------------------------

_LEAVES = st.one_of(
    st.integers(0, 999).map(lambda n: Num(float(n))),
    st.sampled_from([0.5, 2.25, 10.125]).map(Num),
    st.integers(1, 30).map(lambda n: Var(Num(float(n)))),
    st.sampled_from(["a", "depth", "_g"]).map(lambda n: Var(name=n)),
)
_BINARY = [op for op, _ in LINUXCNC_SPELLING.binary.values()]
_FUNCS = [n for n in LINUXCNC_SPELLING.functions.values() if n != "exists"]


def _grow(children: st.SearchStrategy[Expr]) -> st.SearchStrategy[Expr]:
    return st.one_of(
        st.builds(Binary, st.sampled_from(_BINARY), children, children),
        st.builds(lambda f, a: Func(f, [a]), st.sampled_from(_FUNCS), children),
        st.builds(lambda a, b: Func("atan2", [a, b]), children, children),
        st.builds(lambda a: Unary("neg", a), children),
        st.builds(Var, children.filter(_a_parameter)),
    )


def _a_parameter(index: Expr) -> bool:
    """LinuxCNC has no #0 (rs274: "Parameter number out of range"): a literal index names #1 and up."""
    return not (isinstance(index, Num) and index.value == 0.0)


EXPRS = st.recursive(_LEAVES, _grow, max_leaves=8)


@settings(max_examples=150, deadline=None)
@given(EXPRS)
def test_generated_expressions_round_trip_through_reader_and_writer(expr: Expr) -> None:
    """An assignment and a word holding ``expr``, spelt by the writer's spelling, read back to ``expr``
    by the reader; writing the read program again gives the same text (an expression certain to fail,
    ``14**269``, is refused when read: ``test_program_structure.py``)."""
    assume(certain_failure(expr) is None)
    value = spell_word_value(expr, LINUXCNC_SPELLING)
    block = lex_block("t.ngc", 1, f"#1={value} G0 X{value}", "\n", "linuxcnc", OwordParser())
    assert block.sections["Assign"] == Assign([(V1, expr)])
    if isinstance(expr, Num):
        assert block.words[-1] == ("X", value) and not block.values  # a plain number: the fast reading
    else:
        assert block.values["X"] == expr
        assert block.words[-1] == ("X", value)
    assert normalised(f"#1={value}\n") == f"#1={value}\n"


def test_a_taken_branch_skips_the_later_branches() -> None:
    """Found by the random differential: after a branch runs, its elseif and else do not."""
    text = ("G21 G0 X0 Y0 Z0\n#1=1\no1 if [#1 EQ 1]\nG0 X1\no1 elseif [#1 EQ 1]\nG0 X2\no1 else\nG0 X3\no1 endif\n"
            "o2 if [#1 EQ 0]\nG0 Y1\no2 elseif [#1 EQ 1]\nG0 Y2\no2 else\nG0 Y3\no2 endif\n"
            "o3 if [0]\nG0 Z1\no3 else\nG0 Z3\no3 endif\nM30\n")
    moves = [(e["x"], e["y"], e["z"]) for e in toolpath_events(io.StringIO(text), file="t.ngc", dialect="linuxcnc")
             if "move" in e]
    assert moves[-3:] == [(1, 0, 0), (1, 2, 0), (1, 2, 3)] and (2, 0, 0) not in moves and (1, 3, 0) not in moves
