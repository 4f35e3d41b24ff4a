"""The SINUMERIK 840D sl / 828D dialect: lossless reading, expressions (a hypothesis round trip and hand-computed
values), the collisions with Fanuc's numbers in both directions (issue 28 item 5), control flow against
hand-derived toolpaths, and what is kept verbatim (refused elsewhere by name).

Expected values are written by hand from the facts in ``reference/USERS-AND-SIEMENS.md`` section 3 and the
sources each dialect module cites; the LinuxCNC translations are run by rs274 in ``test_siemens_oracle``.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.setup.machine_setup import Limits, MachineSetup, load_setup

from tests.support.paths import assert_verifies_exactly, moves_and_dwells

from dialects.siemens.expressions import FUNCTIONS, R_BASE, parse_expr, spell_expr

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples" / "siemens").glob("*.mpf"))
SETUP = ROOT / "examples" / "setups" / "siemens_840d_mill.xml"


def _setup() -> MachineSetup:
    return load_setup(str(SETUP))


def _translate(text: str, source: str, target: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source=source, target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, source: str, target: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, source, target, setup)
    return [str(e) for e in caught.value.errors]


def _moves(text: str, dialect: str = "siemens", setup: MachineSetup | None = None) -> list[tuple[object, ...]]:
    return moves_and_dwells(text, dialect, setup, file="in.mpf")


# -- lossless ------------------------------------------------------------------------------------------

LEXICAL = [
    "%_N_PART_7_MPF\n;$PATH=/_N_MPF_DIR\nN10 G17 G90 G710 G54 ; set-up\nM30\n",
    "N10 G0 X10 Y20 ; a comment ; runs to the end\n:20 G1 X10.5 F100\n/N30 M0\n/3 G0 Z5\n",
    "R1=10 R2=2.5EX1 R3=-1.5EX-2\nDEF REAL DEPTH=-5, STEP\nDEF INT N_PASS=3\nG1 X=R1 Y=R2*2 Z=DEPTH F=R1*20\n",
    "G0 X=SIN(30)*R1 Y=ATAN2(1,1) Z=POT(2)+TRUNC(2.7)\n",
    "START:\nR1=0\nWHILE R1<3\nR1=R1+1\nENDWHILE\nIF R1==3 GOTOB START\n",
    "FOR R5=1 TO 3\nREPEAT\nR6=R5\nUNTIL R6>=1\nENDFOR\nLOOP\nGOTOF OUT\nENDLOOP\nOUT: M30\n",
    "G1 F100\nG2 X10 Y10 CR=-10\nG3 X20 Y10 I=IC(5) J0\nG4 F2.5\nT1 D1 M6\nT=\"DRILL_10\"\n",
    "TRANS X10 Y5\nAROT RPL=30\nMCALL CYCLE81(10,0,2,-5,,0.5)\nG0 X10\nMCALL\nCYCLE832(0.01,1)\nSOFT\n",
    "G505 G1 X1 F100\nG599\nG500\nG53 G0 Z0\nG153\nG58 X10\nG641 ADIS=0.1\nG33 Z-10 K1.5\n",
    "G1X10Y20F100\n   N40   G0  X1\t; tabs and blanks\r\nIF (R1>1) AND (R2<2) GOTOF X_1\nX_1:\n",
]


@pytest.mark.parametrize("text", LEXICAL)
def test_a_siemens_program_is_written_back_byte_for_byte(text: str) -> None:
    assert _translate(text, "siemens", "siemens") == text


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_the_examples_are_written_back_byte_for_byte(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    assert _translate(text, "siemens", "siemens", _setup()) == text


_NAMES = st.sampled_from(["depth", "step", "cnt", "_tmp1", "x_ofs"])
_NUMBERS = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False).filter(lambda v: v != 0.0 or str(v) == "0.0")
_LEAVES = st.one_of(
    _NUMBERS.map(Num),
    st.integers(0, 499).map(lambda n: Var(Num(float(R_BASE + n)))),
    _NAMES.map(lambda n: Var(name=n)),
)


def _tree(children: st.SearchStrategy[Expr]) -> st.SearchStrategy[Expr]:
    non_num = children.filter(lambda e: not isinstance(e, Num))
    return st.one_of(
        st.tuples(st.sampled_from(["add", "sub", "mul", "div", "fmod", "and", "or", "xor"]), children, children)
        .map(lambda t: Binary(*t)),
        st.tuples(st.sampled_from(["eq", "ne", "lt", "gt", "le", "ge"]), children, children).map(lambda t: Binary(*t)),
        st.tuples(st.sampled_from(["neg", "not"]), non_num).map(lambda t: Unary(*t)),
        st.tuples(st.sampled_from(sorted(set(FUNCTIONS.values()) - {"atan2"})), children)
        .map(lambda t: Func(t[0], [t[1]])),
        st.tuples(children, children).map(lambda t: Func("atan2", [t[0], t[1]])),
    )


EXPRESSIONS = st.recursive(_LEAVES, _tree, max_leaves=12)


@settings(max_examples=300, deadline=None)
@given(EXPRESSIONS)
def test_an_expression_reads_back_as_it_was_spelt(expr: Expr) -> None:
    """Parentheses follow SINUMERIK's priorities: spelling then reading gives the same tree."""
    text = spell_expr(expr)
    end, back = parse_expr(text, 0)
    assert end == len(text), text
    assert back == expr, text


_WORD = st.sampled_from(["G0", "G1", "X10", "Y-2.5", "Z=R1", "F=R2*2", "X=SIN(R1)", "M3", "S1000", "T1 D1"])
_LINE = st.one_of(
    st.lists(_WORD, min_size=1, max_size=4).map(" ".join),
    st.integers(0, 99).map(lambda n: f"R{n}=R{n}+1.5EX2"),
    st.text(st.characters(min_codepoint=32, max_codepoint=126), max_size=20).map(lambda t: ";" + t),
)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["", "N10 ", "/", ":5 ", "LBL_1: "]), _LINE), max_size=8),
       st.sampled_from(["\n", "\r\n"]))
def test_generated_programs_are_written_back_byte_for_byte(lines: list[tuple[str, str]], eol: str) -> None:
    text = "".join(head + body + eol for head, body in lines)
    try:
        out = _translate(text, "siemens", "siemens")
    except ErrorList:
        return  # a program the reader refuses (a label twice...) is not written at all
    assert out == text


# -- expressions ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("expression, value", [
    ("SIN(30)*2", 1.0),  # degrees
    ("ATAN2(1,-1)", 135.0),  # -180..180
    ("POT(3)+TRUNC(-2.7)", 7.0),  # 9 - 2
    ("ROUND(2.5)+ROUND(-2.5)", 0.0),  # half away from zero
    ("1.5EX2+2EX-1", 150.2),
    ("7 MOD 3", 1.0),
    ("2+3*4-6/2", 11.0),
    ("SQRT(16)+ABS(-2)", 6.0),
    ("(R1>1) AND (R1<3)", 1.0),
    ("NOT (R1==2)", 0.0),
])
def test_an_expression_takes_the_value_the_manual_gives(expression: str, value: float) -> None:
    moves = _moves(f"G710 G90 G0 X0 Y0 Z0\nR1=2\nR9={expression}\nG1 X=R9+100 F100\nM30\n")
    assert moves[-1][0] == "feed"
    assert math.isclose(float(moves[-1][1]) - 100.0, value, abs_tol=1e-9)  # type: ignore[arg-type]


def test_a_comparison_inside_and_without_parentheses_is_refused_at_its_place() -> None:
    errors = _errors("G710 G90\nR1=1 R2=1\nIF R1>0 AND R2<2 GOTOF E\nE: M30\n", "siemens", "linuxcnc")
    assert errors[0].startswith("in.mpf:3:6: error: a comparison before AND/OR/XOR without parentheses")


def test_an_operator_the_ir_lacks_is_kept_verbatim_and_refused_elsewhere_by_name() -> None:
    text = "G710 G90\nR1=7 DIV 2\nM30\n"
    assert _translate(text, "siemens", "siemens") == text
    assert "the operator DIV (not modelled)" in _errors(text, "siemens", "linuxcnc")[0]


# -- collisions with Fanuc's numbers (issue 28 item 5), both ways ------------------------------------------

def test_g70_g71_are_units_on_siemens_and_g700_g710_are_written() -> None:
    assert _moves("G700 G90 G0 X1 Y0 Z0\nM30\n")[0][1] == 25.4  # inch program: 1 inch, in mm
    out = _translate("G20 G90 G0 X1.\nG21 X2.\nM30\n", "fanuc", "siemens")
    assert out.splitlines()[:2] == ["G700 G90 G0 X1.", "G710 G0 X2."]
    # (G61: the SINUMERIK's power-on exact stop, G60, carried to LinuxCNC, which powers on blending:
    # tests/test_defects_siemens_path_start.py)
    assert _translate("G70 G90 G0 X1\nM30\n", "siemens", "linuxcnc").startswith("G61 G20 G90 G0 X1.")


def test_a_feed_under_g70_on_a_metric_machine_is_refused_g700_is_not() -> None:
    errors = _errors("G70 G90 G1 X1 F10\nM30\n", "siemens", "linuxcnc")
    assert errors[0].startswith("in.mpf:1:15: error: F under G70/G71 is in the basic system's unit (mm)")
    assert "F10." in _translate("G700 G90\nG1 X1 F10\nM30\n", "siemens", "linuxcnc")
    assert "F10." in _translate("G71 G90\nG1 X1 F10\nM30\n", "siemens", "linuxcnc")  # mm on a mm machine


def test_g58_g59_are_axial_offsets_on_siemens_and_fanuc_g58_is_g505() -> None:
    errors = _errors("G710 G90\nG58 X10\nM30\n", "siemens", "fanuc")
    assert errors[0] == "in.mpf:2:1: error: G58 (axial programmable offset) from siemens has no equivalent in fanuc"
    assert _translate("G21 G90\nG58\nG59\nM30\n", "fanuc", "siemens").splitlines()[1:3] == ["G505", "G506"]
    assert _translate("G710 G90\nG505\nM30\n", "siemens", "fanuc").splitlines()[1] == "G58"


def test_g4_takes_seconds_in_f_which_is_no_feed() -> None:
    text = "G710 G90 G1 X0 Y0 Z0 F100\nG4 F2\nX10\nM30\n"
    out = _translate(text, "siemens", "linuxcnc")
    assert out.splitlines()[1:3] == ["G4 P2.", "G1 X10."]  # the feed stays 100: no F written
    assert _moves(text)[0] == ("dwell", 2)  # (the first block moves nothing)
    fanuc = _translate("G21 G90 G1 X0 F100.\nS1000 M3 G4 P2500\nM30\n", "fanuc", "siemens")
    assert fanuc.splitlines()[1:3] == ["S1000 M3", "G4 F2.5"]  # alone in its block, after what acts before it


def test_g33_is_threading_kept_verbatim() -> None:
    text = "G710 G90\nG33 Z-10 K1.5\nM30\n"
    assert _translate(text, "siemens", "siemens") == text
    assert "G33 (thread cutting)" in _errors(text, "siemens", "linuxcnc")[0]


def test_a_system_variable_is_a_located_error_when_its_value_is_needed() -> None:
    errors = _errors("G710 G90\nR1=$P_ACT_X\nG0 X=R1\nM30\n", "siemens", "linuxcnc")
    assert errors[0] == ("in.mpf:2:1: error: $P_ACT_X (a system variable) is known only to the machine: the program "
                         "cannot be simulated or flattened")


# -- words -------------------------------------------------------------------------------------------

def test_arcs_by_centre_and_by_cr_move_as_hand_derived() -> None:
    # from (0,0): a CW half circle to (20,0) about (10,0) (I incremental), then CR=-10 (more than 180
    # degrees) back to (0,0)... the centre of the second, left of the chord going -X, is (10,0) again
    moves = _moves("G710 G17 G90 G0 X0 Y0 Z0\nG2 X20 Y0 I10 J0 F100\nG3 X0 Y0 CR=10\nM30\n")
    assert moves == [("cw", 20, 0, 0), ("ccw", 0, 0, 0)]  # (the G0 to the start point moves nothing)
    out = _translate("G21 G17 G90 G0 X0 Y0\nG2 X20. Y0 R-10. F100.\nM30\n", "fanuc", "siemens")
    assert out.splitlines()[1] == "G2 X20. Y0. CR=-10. F100."


def test_ac_ic_are_read_where_the_blocks_own_mode_says_the_same() -> None:
    assert _moves("G710 G90 G0 X1 Y0 Z0\nG91 G0 X=IC(2)\nG90 X=AC(7)\nM30\n")[1:] == [
        ("rapid", 3, 0, 0), ("rapid", 7, 0, 0)]
    text = "G710 G90 G0 X1 Y0 Z0\nX=IC(2)\nM30\n"
    assert _translate(text, "siemens", "siemens") == text
    assert "X=IC(..) (a per-address distance mode" in _errors(text, "siemens", "linuxcnc")[0]
    assert "I=AC(..)" in _errors("G710 G90 G0 X0 Y0\nG2 X10 Y0 I=AC(5) J0 F1\nM30\n", "siemens", "linuxcnc")[0]


def test_d_selects_the_tool_data_and_fanuc_g43_h_becomes_d() -> None:
    setup = _setup()
    assert _translate("G710 G90\nT1 D1 M6\nM30\n", "siemens", "linuxcnc", setup).splitlines()[1] == "G43 H01 T1 M6"
    fanuc = "G21 G90 G0 X0 Y0\nT2 M6\nG43 H2 Z5.\nG1 Z0 F100.\nM30\n"
    out = _translate(fanuc, "fanuc", "siemens", setup)
    assert out.splitlines()[2].startswith("D02 ")
    assert_verifies_exactly(fanuc, out, "fanuc", "siemens", setup)


def test_a_name_as_a_tool_and_the_cycles_are_kept_verbatim() -> None:
    text = "G710 G90\nT=\"DRILL\"\nCYCLE83(10,0,2,-5)\nMCALL CYCLE86(10,0,2,-5,,1)\nMCALL\nM30\n"
    assert _translate(text, "siemens", "siemens") == text
    errors = _errors(text, "siemens", "fanuc")
    assert "T=\"DRILL\" (no tool of the set-up has this name" in errors[0]
    assert "CYCLE83 with VARI empty" in errors[1]
    assert "MCALL CYCLE86 (its lift-off RPA/RPO/RPAP in three axes has no neutral cycle)" in errors[2]


@pytest.mark.parametrize("text, message", [
    ("G710 G90 G0 X\nM30\n", "1:13: error: address X needs a value"),
    ("G710 G90\nX=R1+\n", "2:6: error: expression expected"),
    ("G710 G90\nR1000=1\n", "2:1: error: R1000: only R0-R499 have a neutral number here"),
    ("%_N_1_MPF\n", "1:1: error: a program header is %_N_<NAME>_MPF"),
    ("G710\nENDIF\n", "2:1: error: ENDIF does not close an open IF"),
    ("G710\nGOTOF NOWHERE\nM30\n", "2:7: error: GOTOF nowhere: no such target in this file"),
    ("L1:\nL1:\nGOTOB L1\n", "3:7: error: GOTOB l1: the target is on more than one line (1, 2)"),
    ("G710 G90 X1 @\n", "1:13: error: unexpected character '@'"),
    ("G710\nR1=" + "(" * 300 + "1" + ")" * 300 + "\n", "expression nested deeper than"),
])
def test_bad_input_is_a_located_error(text: str, message: str) -> None:
    errors = _errors(text, "siemens", "siemens") if "GOTO" in text or "ENDIF" in text or "%" in text \
        else _errors(text, "siemens", "linuxcnc")
    assert any(message in e for e in errors), errors


# -- control flow, against hand-derived toolpaths -------------------------------------------------------

def test_repeat_until_runs_its_body_at_least_once() -> None:
    moves = _moves("G710 G90 G0 X0 Y0 Z0\nR1=5\nREPEAT\nR1=R1+1\nG1 X=R1 F100\nUNTIL R1>=5\nM30\n")
    assert moves == [("feed", 6, 0, 0)]


def test_for_counts_up_to_and_including_its_end() -> None:
    moves = _moves("G710 G90 G0 X0 Y0 Z0\nFOR R1=1 TO 3\nG1 X=R1*10 F100\nENDFOR\nM30\n")
    assert moves == [("feed", 10, 0, 0), ("feed", 20, 0, 0), ("feed", 30, 0, 0)]


def test_loop_left_by_gotof_and_a_backward_gotob() -> None:
    text = ("G710 G90 G0 X0 Y0 Z0\nR1=0\nLOOP\nR1=R1+1\nIF R1>2 GOTOF OUT\nG1 Y=R1 F100\nENDLOOP\nOUT:\n"
            "R2=0\nBACK: R2=R2+1\nG1 Z=-R2\nIF R2<2 GOTOB BACK\nM30\n")
    assert _moves(text) == [("feed", 0, 1, 0), ("feed", 0, 2, 0), ("feed", 0, 2, -1), ("feed", 0, 2, -2)]


def test_if_else_and_def_int_rounds() -> None:
    text = "G710 G90 G0 X0 Y0 Z0\nDEF INT CNT=2.6\nIF CNT==3\nG1 X1 F100\nELSE\nG1 X2 F100\nENDIF\nM30\n"
    assert _moves(text) == [("feed", 1, 0, 0)]


def test_an_endless_loop_is_stopped_by_the_bound() -> None:
    """The set-up's bound on work run again stops a WHILE that never ends (a counter, so never the same
    state twice); a bound of 20,000, not the default million (8 s of CPU to reach, pure), which
    tests/test_interp_work.py holds."""
    errors = _errors("G710 G90 G0 X0\nR1=0\nWHILE R1>=0\nG1 X1 F10\nG1 X0\nR1=R1+1\nENDWHILE\nM30\n", "siemens",
                     "linuxcnc", MachineSetup(limits=Limits(repeated_work=20_000)))
    assert "repeats more than 20000 blocks" in errors[0]


def test_an_unset_r_parameter_is_an_error_not_zero() -> None:
    errors = _errors("G710 G90 G0 X0\nG1 X=R7 F100\nM30\n", "siemens", "linuxcnc")
    assert "R7 is read before it is set" in errors[0]


# -- translation both ways, verified ---------------------------------------------------------------------

@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "grbl"])
def test_the_pocket_example_translates_with_zero_deviation(target: str) -> None:
    path = ROOT / "examples" / "siemens" / "pocket_loops.mpf"
    text = path.read_text(encoding="utf-8")
    assert_verifies_exactly(text, _translate(text, "siemens", target, _setup()), "siemens", target, _setup())


FANUC_DRILLING = """%
O1001
G21 G17 G90 G54
T1 M6
G43 H1 Z50.
S1200 M3
G0 X10. Y10.
G99 G81 X10. Y10. Z-5. R2. F100.
X20.
G98 G83 X30. Q2. Z-9. R2.
G80
G0 Z50.
G2 X50. Y10. R10. F300.
G4 P500
M30
%
"""


def test_a_fanuc_program_with_cycles_reads_back_from_siemens_to_the_same_toolpath() -> None:
    setup = _setup()
    out = _translate(FANUC_DRILLING, "fanuc", "siemens", setup)
    assert out.startswith(";%\n%_N_PROG1001_MPF\n")  # the tape mark as a trace
    assert "G4 F0.5" in out
    assert_verifies_exactly(FANUC_DRILLING, out, "fanuc", "siemens", setup)
    again = _translate(out, "siemens", "linuxcnc", setup)
    assert_verifies_exactly(out, again, "siemens", "linuxcnc", setup)


# -- subprograms ---------------------------------------------------------------------------------------

def _library(tmp_path: Path) -> MachineSetup:
    (tmp_path / "STEP.SPF").write_text("%_N_STEP_SPF\nPROC STEP\nR1=R1+1\nG1 X=R1*10 F100\nRET\n")
    (tmp_path / "HOLE.SPF").write_text("G0 Z-1\nDEF REAL R\nR=2\nG0 Z=R\nM17\n")
    (tmp_path / "ENDS.SPF").write_text("G0 Z-1\nM30\n")
    return MachineSetup(library=[str(tmp_path)])


def test_a_subprogram_call_with_repetitions_runs_the_spf_file(tmp_path: Path) -> None:
    setup = _library(tmp_path)
    text = "%_N_MAIN_MPF\nG710 G90 G0 X0 Y0 Z0\nR1=0\nSTEP P3\nHOLE\nG0 X=R1\nM30\n"
    # STEP three times (X 10, 20, 30), HOLE once (its DEF variable R is its own), then X at R1 = 3
    assert _moves(text, setup=setup) == [("feed", 10, 0, 0), ("feed", 20, 0, 0), ("feed", 30, 0, 0),
                                         ("rapid", 30, 0, -1), ("rapid", 30, 0, 2), ("rapid", 3, 0, 2)]
    assert _translate(text, "siemens", "siemens", setup) == text
    assert_verifies_exactly(text, _translate(text, "siemens", "linuxcnc", setup), "siemens", "linuxcnc", setup)


def test_subprogram_ends_and_parameters_that_are_not_modelled(tmp_path: Path) -> None:
    setup = _library(tmp_path)
    assert "M30 in a subprogram: write RET or M17" in _errors("G710 G90 G0 X0\nENDS\nM30\n", "siemens",
                                                               "linuxcnc", setup)[0]
    assert "the call passes 2 arguments to a subprogram without PROC parameters" in _errors(
        "G710 G90 G0 X0\nR1=0\nSTEP(1, 2)\nM30\n", "siemens", "linuxcnc", setup)[0]
    assert "RET" in _errors("G710 G90 G0 X0\nRET\n", "siemens", "linuxcnc", setup)[0]


# -- frames --------------------------------------------------------------------------------------------

TRANS_PROGRAM = "G710 G90 G0 X0 Y0 Z0\nTRANS X10 Y5\nG1 X1 Y1 F100\nTRANS Z-2\nG1 X2 Y2 Z1\nTRANS\nG1 X3 Y3\nM30\n"


def test_trans_replaces_the_programmable_offset_and_trans_alone_clears_it() -> None:
    # (1,1) + (10,5); then the offset is Z-2 only (X, Y back to 0): (2,2,1-2); then none: (3,3) at Z -1 (Z not
    # programmed: the tool stays)
    assert _moves(TRANS_PROGRAM) == [("feed", 11, 6, 0), ("feed", 2, 2, -1), ("feed", 3, 3, -1)]
    assert _translate(TRANS_PROGRAM, "siemens", "siemens") == TRANS_PROGRAM


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_trans_is_evaluated_for_other_controls(target: str) -> None:
    assert_verifies_exactly(TRANS_PROGRAM, _translate(TRANS_PROGRAM, "siemens", target), "siemens", target)


def test_unmodelled_and_computed_frames_are_kept_verbatim() -> None:
    for line, name in (("ROT X30 Y10", "ROT about more than one axis"), ("TRANS X=R1", "TRANS with computed"),
                       ("TRANS A10", "TRANS with other than X, Y, Z"), ("ROTS X10 Y10", "ROTS (a frame rotation")):
        text = f"G710 G90 G0 X0\nR1=1\n{line}\nM30\n"
        assert _translate(text, "siemens", "siemens") == text
        assert name in _errors(text, "siemens", "fanuc")[0]


# -- the spelling of each construct, both ways (a validate_all-style table) ------------------------------

WRITE_TABLE = [
    # (Fanuc block after "G21 G90 G0 X0 Y0 Z0", the SINUMERIK line written), by the facts in codes.py
    ("G17", "G17"), ("G18", "G18"), ("G19", "G19"),
    ("G54", "G54"), ("G55", "G55"), ("G56", "G56"), ("G57", "G57"), ("G58", "G505"), ("G59", "G506"),
    ("G61", "G60"), ("G64", "G64"), ("G09 G01 X1. F10.", "G9 G1 X1. F10."),
    ("G91", "G91"), ("G94", "G94"), ("G20", "G700"),
    ("M03 S100", "S100 M3"), ("M04 S100", "S100 M4"), ("M05", "M5"), ("M08", "M8"), ("M09", "M9"),
    ("M00", "M0"), ("M01", "M1"),
    ("G04 P1500", "G4 F1.5"), ("/G01 X1. F10.", "/ G1 X1. F10."),
]


@pytest.mark.parametrize("fanuc, siemens", WRITE_TABLE)
def test_a_fanuc_construct_is_written_with_the_siemens_spelling_and_reads_back(fanuc: str, siemens: str) -> None:
    out = _translate(f"G21 G90 G0 X0 Y0 Z0\n{fanuc}\nM30\n", "fanuc", "siemens")
    assert out.splitlines()[1] == siemens
    back = _translate(out, "siemens", "fanuc")  # read back: the same meaning (G505 -> G58, G4 F -> G4 X)
    assert len(back.splitlines()) == 3


def test_a_line_longer_than_the_limit_is_a_located_error() -> None:
    errors = _errors("G710 G90 G0 X1 " + "Y1 " * 30000 + "\nM30\n", "siemens", "linuxcnc")
    assert errors[0].startswith("in.mpf:1:65537: error: the line is 90015 characters long")


# -- drilling cycles (MCALL CYCLE81/82) -------------------------------------------------------------------

CYCLES = ("G710 G17 G90 G0 X0 Y0 Z10\nG1 F100\nG0\nMCALL CYCLE81(10, 0, 2, -5)\nX10 Y10\nX20\nMCALL\nG0 Z50\n"
          "MCALL CYCLE82(5, 0, 5, , 3, 0.5)\nX30\nMCALL\nM30\n")


def test_mcall_cycles_move_as_the_manual_describes() -> None:
    # CYCLE81: rapid to RFP+SDIS = 2, feed to DP = -5, rapid to RTP = 10 (the Z at MCALL), at each position;
    # CYCLE82: RFP+SDIS = 5 = RTP, depth RFP-DPR = -3, dwell 0.5 s, rapid to RTP 5; nothing at MCALL itself
    assert _moves(CYCLES) == [
        ("rapid", 0, 0, 10),
        ("rapid", 10, 10, 10), ("rapid", 10, 10, 2), ("feed", 10, 10, -5), ("rapid", 10, 10, 10),
        ("rapid", 20, 10, 10), ("rapid", 20, 10, 2), ("feed", 20, 10, -5), ("rapid", 20, 10, 10),
        ("rapid", 20, 10, 50),
        ("rapid", 30, 10, 50), ("rapid", 30, 10, 5), ("feed", 30, 10, -3), ("dwell", 0.5), ("rapid", 30, 10, 5)]


def test_mcall_cycles_are_fanuc_cycles_natively_and_expanded_elsewhere() -> None:
    out = _translate(CYCLES, "siemens", "fanuc")
    assert "G98 G81 Z-5. R2. K0\nX10. Y10.\nX20.\nG80\n" in out
    assert "G99 G82 Z-3. R5. P500 K0\nX30.\nG80\n" in out
    for target in ("fanuc", "linuxcnc", "grbl"):
        assert_verifies_exactly(CYCLES, _translate(CYCLES, "siemens", target), "siemens", target)
    assert _translate(CYCLES, "siemens", "siemens") == CYCLES


@pytest.mark.parametrize("lines, message", [
    ("G0 Z20\nMCALL CYCLE81(10, 0, 2, -5)", "RTP 10 is neither RFP+SDIS (2) nor the tool's Z at MCALL (20)"),
    ("G1\nMCALL CYCLE81(10, 0, 2, -5)", "MCALL moves to each hole in the motion mode in force"),
    ("MCALL CYCLE81(10, 0, 2, -5)\nG1 X5", "G1 under MCALL"),
    ("MCALL CYCLE81(10, 0, 2, -5)\nX5 Z2", "Z under MCALL"),
    ("MCALL CYCLE81(10, 0, 2, -5, 3)", "give exactly one of DP and DPR"),
    ("MCALL CYCLE81(10, 0, , -5)", "SDIS is empty"),
    ("MCALL CYCLE82(10, 0, 2, -5, , 0.0005)", "DTB is a dwell of whole milliseconds"),
    ("G91\nMCALL CYCLE81(10, 0, 2, -5)", "read in G17 and G90 only"),
])
def test_a_cycle_call_fanuc_cannot_mean_is_a_located_error(lines: str, message: str) -> None:
    errors = _errors(f"G710 G17 G90 G1 X0 Y0 Z10 F100\nG0\n{lines}\nMCALL\nM30\n", "siemens", "fanuc")
    assert any(message in e for e in errors), errors


def test_other_cycle_calls_are_kept_verbatim() -> None:
    for line, name in (("CYCLE83(10, 0, 2, -5)", "CYCLE83 with VARI empty"),
                       ("MCALL CYCLE83(10, 0, 2, -20, , -5, , 2, 0, 0, 1, 0)", "MCALL CYCLE83 with VARI 0"),
                       ("MCALL CYCLE81(R1, 0, 2, -5)", "MCALL CYCLE81 with computed parameters"),
                       ("MCALL MYSUB", "MCALL MYSUB"),
                       ("MCALL CYCLE81(10, 0, 2, -5, , 0, 1, 0)", "MCALL CYCLE81 with parameters after DPR")):
        text = f"G710 G90 G0 X0 Z10\nR1=10\n{line}\nM30\n"
        assert _translate(text, "siemens", "siemens") == text
        assert name in _errors(text, "siemens", "fanuc")[0]
