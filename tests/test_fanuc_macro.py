"""Fanuc Custom Macro B and subprograms through the Fanuc reader and writer.

Every expected spelling and message here was written by hand from the Fanuc rules (argument
specification I, the packed M98 P form, canonical numbers with an explicit point); the moves are
checked against LinuxCNC's rs274 in tests/test_macro_oracle.py.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, assume, given, settings

from postproc.api import read_program, translate
from postproc.context import Context
from postproc.interp.control import Assign, Call, EndWhile, Goto, ModalCall, ModalCallCancel, Return, While
from postproc.errors import Diagnostics, ErrorLevel, ErrorList, UnsupportedError
from postproc.ir.expr import Binary, Expr, Num, Unary, Var
from postproc.plugins import default_registry
from postproc.commands.program_xml import dump_program, load_program
from postproc.rs274.expressions import FANUC_SPELLING, spell_word_value
from postproc.rs274.lexer import lex_block
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.test_rs274_expressions import _has_round, trees

ROOT = Path(__file__).resolve().parents[1]
MACROS = sorted((ROOT / "tests" / "golden" / "macro").glob("*.nc"))
HEAD = "G21 G90 G00 X0 Y0 Z0\n"


def v(n: int) -> Var:
    return Var(Num(float(n)))


def _read(text: str, level: ErrorLevel = ErrorLevel.RAISE) -> list:
    return read_program(io.StringIO(HEAD + text + "\n", newline=""), file="t.nc", dialect="fanuc", level=level)


def _statement(text: str) -> Any:
    """The block of one statement read alone: a lone ``WHILE`` or ``END`` is a malformed program (the
    structure check refuses it, ``test_program_structure.py``), but its statement is what is tested here."""
    return _read(text, ErrorLevel.IGNORE)[-1]


def _regenerate(text: str) -> str:
    """The block read, then written from its sections (not copied)."""
    fanuc = default_registry().dialect("fanuc")
    block = _statement(text)
    block.changed()
    writer = fanuc.WRITER(Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.RAISE), "fanuc"), "fanuc", fanuc)
    return writer.write_block(block).rstrip("\n")


# (as read, the control/assign section or the word values, as written from the sections)
TABLE = [
    ("#1=2", Assign([(v(1), Num(2.0))]), "#1=2."),
    ("#3=#1+#2*2", Assign([(v(3), Binary("add", v(1), Binary("mul", v(2), Num(2.0))))]), "#3=#1+#2*2."),
    ("#[#2+1]=5.", Assign([(Var(Binary("add", v(2), Num(1.0))), Num(5.0))]), "#[#2+1.]=5."),
    ("N10 #1=#1+1", Assign([(v(1), Binary("add", v(1), Num(1.0)))]), "N10 #1=#1+1."),
    ("IF [#1 GT 2] GOTO 10", Goto(Num(10.0), Binary("gt", v(1), Num(2.0))), "IF [#1 GT 2.] GOTO 10"),
    ("GOTO #5", Goto(v(5)), "GOTO #5"),
    ("GOTO [#5+10]", Goto(Binary("add", v(5), Num(10.0))), "GOTO [#5+10.]"),
    ("WHILE [#1 LT 10] DO1", While("1", Binary("lt", v(1), Num(10.0))), "WHILE [#1 LT 10.] DO1"),
    ("END1", EndWhile("1"), "END1"),
    ("M98 P2100 L4", Call("2100", repeat=Num(4.0)), "M98 P2100 L4"),
    ("M98 P00032100", Call("2100", repeat=Num(3.0)), "M98 P2100 L3"),
    ("M98 P00012100", Call("2100"), "M98 P2100"),
    ("M98 P#1", Call(v(1)), "M98 P#1"),
    ("M99", Return(), "M99"),
    ("M99 P30", Return(target=Num(30.0)), "M99 P30"),
    ("G65 P9100 X30. Y20. A6. B15. L2",
     Call("9100", {24: Num(30.0), 25: Num(20.0), 1: Num(6.0), 2: Num(15.0)}, Num(2.0), "macro"),
     "G65 P9100 L2 A6. B15. X30. Y20."),
    ("G65 P9100 I1. H2. Z-#3", Call("9100", {4: Num(1.0), 11: Num(2.0), 26: Unary("neg", v(3))}, None, "macro"),
     "G65 P9100 I1. H2. Z-#3"),
    ("G66 P9020 Z-5. R1.", ModalCall("9020", {26: Num(-5.0), 18: Num(1.0)}), "G66 P9020 R1. Z-5."),
    ("G67", ModalCallCancel(), "G67"),
]


@pytest.mark.parametrize("text, section, written", TABLE, ids=[t[0] for t in TABLE])
def test_validate_all(text: str, section: object, written: str) -> None:
    block = _statement(text)
    found = block.get("Control") or block.get("Assign")
    assert found == section
    assert _regenerate(text) == written


WORDS = [
    # (as read, the computed word values, as written from the sections)
    ("G00 X#1 Y-#2", {"X": v(1), "Y": Unary("neg", v(2))}, "G00 X#1 Y-#2"),
    ("G01 X[#1*2] F#9", {"X": Binary("mul", v(1), Num(2.0)), "F": v(9)}, "G01 X[#1*2.] F#9"),
    ("S#19 M03", {"S": v(19)}, "S#19 M03"),
    ("T#20", {"T": v(20)}, "T#20"),
]


@pytest.mark.parametrize("text, values, written", WORDS, ids=[w[0] for w in WORDS])
def test_computed_words(text: str, values: dict, written: str) -> None:
    block = _read(text)[-1]
    assert {k: val for k, val in block.values.items() if isinstance(val, Expr)} == values
    assert _regenerate(text) == written


def test_negated_variable_word_is_a_negation() -> None:
    block = _read("G00 X-#3")[-1]
    assert repr(block.values["X"]) == "Unary('neg', Var(Num(3.0)))"


def test_computed_g_code_is_kept_verbatim_and_flattened_for_another_dialect() -> None:
    block = _read("G#10 X1.")[-1]
    assert block.get("NativeCode").what == "a computed G code"
    out = io.StringIO()
    diagnostics = translate(io.StringIO(HEAD + "G#10 X1.\n"), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert [str(w) for w in diagnostics.warnings] == [
        "t.nc:2:1: warning: the program is flattened (its evaluated motion is written): line 2: a computed G "
        "code from fanuc has no equivalent in linuxcnc",
        "t.nc:2:1: warning: the program has no end (M2/M30): M2 written after its last block, as LinuxCNC "
        "refuses a program that runs out"]
    # #10 is vacant: the G word is omitted (Fanuc's rule), the move stays in G00
    assert out.getvalue() == "G21 G90 G0 X0. Y0. Z0.\nG0 X1.\nM2\n"


LOOP = "#1=0\nWHILE [#1 LT 3] DO1\nG01 X#1 F100.\n#1=#1+1\nEND1\nM30\n"


def test_a_loop_reaches_grbl_flattened_with_a_comment_per_iteration() -> None:
    out = io.StringIO()
    translate(io.StringIO(HEAD + LOOP), out, file="t.nc", source="fanuc", target="grbl")
    lines = out.getvalue().splitlines()
    assert [line for line in lines if not line.startswith("(")] == [
        "G21 G90 G0 X0. Y0. Z0.", "G1 X0. F100.", "G1 X1. F100.", "G1 X2. F100.", "M30"]
    assert sum(line.startswith("(LINE 3: WHILE [#1 LT 3] DO1") for line in lines) == 3


def test_a_loop_reaches_linuxcnc_as_a_loop() -> None:
    out = io.StringIO()
    translate(io.StringIO(HEAD + LOOP), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert out.getvalue() == ("G21 G90 G0 X0. Y0. Z0.\n#1=0.\no1 while [#1 LT 3.]\nG1 X#1 F100.\n"
                              "#1=[#1+1.]\no1 endwhile\nM30\n")


# -- round trips ---------------------------------------------------------------------------------

@pytest.mark.parametrize("path", MACROS, ids=lambda p: p.stem)
def test_macro_program_round_trips_byte_for_byte(path: Path) -> None:
    out = io.StringIO(newline="")
    with open(path, encoding="utf-8", newline="") as src:
        translate(src, out, file=str(path), source="fanuc", target="fanuc")
    assert out.getvalue() == path.read_text(encoding="utf-8")


@pytest.mark.parametrize("path", MACROS, ids=lambda p: p.stem)
def test_ir_xml_round_trip(tmp_path: Path, path: Path) -> None:
    with open(path, encoding="utf-8", newline="") as src:
        blocks = read_program(src, file=str(path), dialect="fanuc")
    xml = tmp_path / "ir.xml"
    with open(xml, "wb") as out:
        dump_program(blocks, out, dialect="fanuc", file=str(path))
    dialect, back = load_program(xml)
    assert dialect == "fanuc" and back == blocks
    assert any(isinstance(val, Expr) for b in back for val in b.values.values()) or "subprogram" in path.stem


# -- errors --------------------------------------------------------------------------------------

def _error(tmp_path: Path, text: str, setup: MachineSetup | None = None) -> str:
    path = tmp_path / "m.nc"
    path.write_text(text)
    with pytest.raises(ErrorList) as info:
        with open(path, newline="") as src:
            list(toolpath_events(src, file="m.nc", dialect="fanuc", setup=setup))
    return str(info.value.errors[0])


def test_end_without_while(tmp_path: Path) -> None:
    assert _error(tmp_path, "G21 G90\nEND1\n") == "m.nc:2:1: error: 'END1' does not close an open While 1"


def test_end_is_not_an_address_for_the_plain_lexer() -> None:
    with pytest.raises(Exception) as info:
        lex_block("t.nc", 1, "END1", "\n", macro=False)
    assert "address E needs a value" not in str(info.value)


def test_unknown_label(tmp_path: Path) -> None:
    assert _error(tmp_path, "G21 G90\n#1=1\nGOTO 99\nM30\n") == "m.nc:3:1: error: 'GOTO 99': no block numbered 99 in m.nc"


def test_loop_bound_from_the_setup(tmp_path: Path) -> None:
    setup = MachineSetup()
    setup.limits.loop_iterations = 5
    assert _error(tmp_path, "G21 G90\n#1=0\nWHILE [#1 LT 10] DO1\n#1=#1+1\nEND1\nM30\n", setup) == (
        "m.nc:5:1: error: loop 'END1' exceeds the set-up's bound of 5 loop iterations, jumps and calls in total "
        "(<Limits loopIterations=\"5\"/>)")


def test_machine_position_is_unknown(tmp_path: Path) -> None:
    assert _error(tmp_path, HEAD + "#1=#5021\nM30\n") == (
        "m.nc:2:1: error: #5021 (current machine position) is known only to the machine: the program cannot "
        "be simulated or flattened")


def test_division_by_zero_names_the_call(tmp_path: Path) -> None:
    text = HEAD + "#100=0\nG65 P9000 A1. B3. L3\nM30\nO9000\n#100=#100+1\nG00 X[#1/[#2-#100]]\nM99\n"
    assert _error(tmp_path, text) == (
        "m.nc:7:5: error: division by zero in #1/[#2-#100] (in O9000, called from m.nc line 3, call 3 of 3)")


def test_argument_without_decimal_point(tmp_path: Path) -> None:
    assert _error(tmp_path, HEAD + "G65 P9000 X10\nM30\n") == (
        "m.nc:2:11: error: G65 argument X10 has no decimal point: its value would be least input increments, "
        "which depend on the machine (write X10.)")


def test_statement_after_words(tmp_path: Path) -> None:
    assert _error(tmp_path, HEAD + "G01 X1. #1=2\n") == (
        "m.nc:2:9: error: a macro statement must start its block (only N may come before it)")


# -- property: generated expressions in words ----------------------------------------------------

@settings(max_examples=300, suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(trees(FANUC_SPELLING))
def test_generated_word_expressions_round_trip(tree: Expr) -> None:
    assume(not _has_round(tree))
    try:
        word = spell_word_value(tree, FANUC_SPELLING)
    except UnsupportedError:
        assume(False)
        return
    text = f"G01 X{word} F100."
    block = lex_block("t.nc", 1, text, "\n")
    if isinstance(tree, Num):
        assert block.words[1] == ("X", word) and "X" not in block.values
        return
    assert block.values["X"] == tree
    assert block.words == [("G", "01"), ("X", word), ("F", "100.")]


@pytest.mark.parametrize("on_unsupported", ["error", "warn"])
def test_renumbering_a_program_that_jumps_rewrites_its_target(on_unsupported: str) -> None:
    """The GOTO names N10, which the renumbering writes N110: the GOTO follows it (before: refused; before that,
    a broken loop). ``tests/test_renumber_references.py`` holds the rest."""
    from postproc.setup.machine_setup import MachineSetup, OutputSettings
    program = HEAD + "#1=0\nN10 #1=#1+1\nIF [#1 LT 3] GOTO 10\nM30\n"
    setup = MachineSetup(output=OutputSettings(renumber_start=100))
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="fanuc", setup=setup,
              on_unsupported=on_unsupported)
    assert out.getvalue() == "N100 G21 G90 G00 X0. Y0. Z0.\n#1=0.\nN110 #1=#1+1.\nIF [#1 LT 3.] GOTO 110\nN120 M30\n"
