"""ISG: typed ``#VAR`` declarations, ``EXIST``, and the no-break spaces of programs copied from Beckhoff's
documentation pages.

Expectations come from the ISG programming manual ("Self-defined variables (#VAR, #ENDVAR, #DELETE)":
syntax, data types, initial values, the example ``$IF EXIST[V.S.EXAMPLE[0]] == TRUE``) and from hand
derivation; what the manual leaves open (a non-whole value stored into UNS32) must be refused, not guessed.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.ir.expr import Binary, Func, Num, Var
from postproc.isg_family.expressions import spell_expr
from postproc.setup.machine_setup import MachineSetup, OutputSettings
from postproc.simulate.toolpath import toolpath_events

NBSP = "\u00a0"

# The manual's own example of declarations with and without types (its first program).
MANUAL_DECLARATIONS = (
    "%test_var_def_1\n#VAR\n  V.P.VAR_1\n  V.P.VAR_2 = 10.67\n  V.P.VAR_3 : UNS32 = 10\n"
    "  V.L.NAME_1 : STRING[20] = \"GRUNDPLATTE\"\n  V.L.VAR_1 : REAL = 23.45\n  V.L.VAR_2 : SGN08\n#ENDVAR\n"
)


def _translate(text: str, target: str, source: str = "isg") -> tuple[str, str]:
    out, warnings = io.StringIO(newline=""), io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def _errors(text: str, target: str = "isg", source: str = "isg") -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, target, source)
    return [str(e) for e in caught.value.errors]


def _moves(text: str, dialect: str = "isg") -> list[tuple[float, float, float]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="in.nc", dialect=dialect)
    return [(float(e["x"]), float(e["y"]), float(e["z"])) for e in events if "move" in e]  # type: ignore[arg-type]


def _toolpath_errors(text: str, dialect: str = "isg") -> list[str]:
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(text, newline=""), file="in.nc", dialect=dialect))
    return [str(e) for e in caught.value.errors]


# -- declarations ------------------------------------------------------------------------------------------

def test_the_manuals_declarations_round_trip_byte_for_byte() -> None:
    text = MANUAL_DECLARATIONS + "G01 X[V.P.VAR_3] Y[V.L.VAR_1] Z[V.L.VAR_2] F100\nM30\n"
    assert _translate(text, "isg")[0] == text


def test_declared_values_move_the_tool() -> None:
    """UNS32 = 10 holds 10; REAL = 23.45 holds 23.45; SGN08 without a value holds its type's 0; an untyped
    declaration without a value is REAL64 0.0 (manual: "the initial value of each data type")."""
    text = MANUAL_DECLARATIONS + "G01 X[V.P.VAR_3] Y[V.L.VAR_1] Z[V.L.VAR_2 + V.P.VAR_1] F100\nM30\n"
    assert _moves(text) == [(10.0, 23.45, 0.0)]


def test_a_boolean_holds_true_as_one() -> None:
    text = "%1\n#VAR\n  V.P.ON : BOOLEAN = TRUE\n  V.P.OFF : BOOLEAN = FALSE\n#ENDVAR\nG01 X[V.P.ON] Y[V.P.OFF] F100\nM30\n"
    assert _moves(text) == [(1.0, 0.0, 0.0)]


@pytest.mark.parametrize("declaration, assignment, message", [
    ("V.P.U : UNS32 = 2.5", "", "in.nc:3:1: error: 2.5 does not fit the variable's type (whole numbers 0 to 4294967295)"),
    ("V.P.U : UNS08 = 256", "", "in.nc:3:1: error: 256 does not fit the variable's type (whole numbers 0 to 255)"),
    ("V.P.U : SGN08 = 100", "V.P.U = V.P.U + 28\n", "in.nc:5:1: error: 128 does not fit the variable's type "
                                                    "(whole numbers -128 to 127)"),
    ("V.P.U : UNS32 = 2", "V.P.U = V.P.U - 3\n", "in.nc:5:1: error: -1 does not fit the variable's type"),
    ("V.P.U : BOOLEAN", "V.P.U = 2\n", "in.nc:5:1: error: 2 does not fit the variable's type (whole numbers 0 to 1)"),
])
def test_a_value_an_integer_type_cannot_hold_is_refused(declaration: str, assignment: str, message: str) -> None:
    """How ISG converts 2.5 into UNS32 (or wraps 128 in SGN08) is not published: refused, not guessed."""
    text = f"%1\n#VAR\n  {declaration}\n#ENDVAR\n{assignment}G01 X[V.P.U] F100\nM30\n"
    errors = _toolpath_errors(text)
    assert errors[0].startswith(message), errors


def test_whole_numbers_in_range_count_in_an_integer_variable() -> None:
    text = ("%1\n#VAR\n  V.P.I : UNS16 = 0\n#ENDVAR\n$WHILE V.P.I < 3\nV.P.I = V.P.I + 1\nG01 X[V.P.I] F100\n"
            "$ENDWHILE\nM30\n")
    assert _moves(text) == [(1.0, 0.0, 0.0), (2.0, 0.0, 0.0), (3.0, 0.0, 0.0)]


def test_a_string_variable_is_kept_for_isg_and_refused_elsewhere_by_name() -> None:
    text = "%1\n#VAR\n  V.L.NAME : STRING[20] = \"PLATE\"\n#ENDVAR\nG01 X1 F100\nM30\n"
    assert _translate(text, "isg")[0] == text
    assert _moves(text) == [(1.0, 0.0, 0.0)]  # the declaration moves nothing: the simulation passes it
    errors = _errors(text, "fanuc")
    assert errors == ["in.nc:3:1: error: V.L.NAME : STRING[20] (a string variable: strings are not modelled) "
                      "from isg has no equivalent in fanuc"], errors


@pytest.mark.parametrize("use, message", [
    ("G01 X[V.L.NAME] F100", "in.nc:5:1: error: the value of X: V.L.NAME is a STRING[20] variable (declared at "
                             "line 3): it has no numeric value"),
    ("V.P.A = V.L.NAME * 2", "in.nc:5:1: error: the value assigned to V.P.A: V.L.NAME is a STRING[20] variable"),
    ("V.L.NAME = 5", "in.nc:5:1: error: V.L.NAME is a STRING[20] variable (declared at line 3): a number cannot "
                     "be assigned to it"),
    ("$IF EXIST[V.L.NAME] == TRUE\n$ENDIF", "in.nc:5:1: error: a condition: EXIST[V.L.NAME]: V.L.NAME is a "
                                            "STRING[20] variable (declared at line 3), and string variables"),
])
def test_a_string_variable_where_a_number_is_needed_is_a_located_error(use: str, message: str) -> None:
    text = f"%1\n#VAR\n  V.L.NAME : STRING[20]\n#ENDVAR\n{use}\nM30\n"
    errors = _errors(text)
    assert errors[0].startswith(message), errors


@pytest.mark.parametrize("line, message", [
    ("V.P.A : FLOAT = 1", "in.nc:3:11: error: unknown data type 'FLOAT'"),
    ("V.P.A : STRING[127]", "in.nc:3:17: error: a STRING holds at most 126 characters"),
    ("V.P.A : STRING", "in.nc:3:17: error: STRING needs its length: STRING[<0..126>]"),
    ("V.P.A : STRING[5] = 5", "in.nc:3:23: error: a STRING[5] variable starts with a string in double quotes"),
    ("V.P.A : UNS32 = 1 2", "in.nc:3:21: error: unexpected '2' after the declaration of V.P.A"),
    ("V.E.A : UNS32", "in.nc:3:3: error: a declaration names a self-defined variable"),
])
def test_malformed_declarations_give_located_errors(line: str, message: str) -> None:
    errors = _errors(f"%1\n#VAR\n  {line}\n#ENDVAR\nM30\n")
    assert errors[0].startswith(message), errors


def test_declared_variables_are_flattened_for_a_target_without_them() -> None:
    text = "%1\n#VAR\n  V.P.N : UNS32 = 3\n  V.P.R : REAL64 = 1.5\n#ENDVAR\nG01 X[V.P.N * V.P.R] F100\nM30\n"
    out, _ = _translate(text, "fanuc")
    assert "G01 X4.5 F100." in out, out


def test_an_array_declaration_is_kept_verbatim() -> None:
    text = "%1\n#VAR\n  V.P.ARR[3] = [1,2,3]\n  V.P.T[2] : UNS32\n#ENDVAR\nM30\n"
    assert _translate(text, "isg")[0] == text
    assert "V. variable arrays (not modelled) from isg has no equivalent" in _errors(text, "fanuc")[0]


# -- EXIST ------------------------------------------------------------------------------------------------

def test_exist_tells_a_declared_variable_from_an_unknown_one() -> None:
    """The manual's form ``$IF EXIST[..] == TRUE``: declared -> 1, never declared or set -> 0."""
    text = ("%1\n#VAR\n  V.P.A : UNS32\n#ENDVAR\n$IF EXIST[V.P.A] == TRUE\nG01 X1 F100\n$ENDIF\n"
            "$IF EXIST[V.S.NONE] == FALSE\nG01 Y2 F100\n$ENDIF\nG01 X[5 + EXIST[V.L.X]] F100\nV.L.X = 4\n"
            "G01 Z[EXIST[V.L.X]]\nM30\n")
    assert _moves(text) == [(1.0, 0.0, 0.0), (1.0, 2.0, 0.0), (5.0, 2.0, 0.0), (5.0, 2.0, 1.0)]
    assert _translate(text, "isg")[0] == text


def test_exist_of_a_machine_variable_cannot_be_simulated() -> None:
    errors = _toolpath_errors("%1\nG01 X[EXIST[V.A.ACS.X]] F100\nM30\n")
    assert "V.A.ACS.X is known only to the machine" in errors[0], errors


def test_exist_on_the_fagor_8070_is_refused_when_simulated() -> None:
    """The family reads EXIST; whether the 8070 has it is not known [?]."""
    errors = _toolpath_errors("%1\nP1=1\nG01 X[EXIST[P1]] F100\nM30\n", "fagor")
    assert "EXIST is not known on the Fagor 8070" in errors[0], errors


# -- no-break spaces ------------------------------------------------------------------------------------------

PASTED = f"%1\nN10{NBSP}G01{NBSP}X10{NBSP}F100\nN20 G01 X20{NBSP}Y5{NBSP}\\\n{NBSP}Z-1\nM30\n"


def test_a_pasted_program_reads_as_with_blanks_and_warns_once() -> None:
    out, warnings = _translate(PASTED, "isg")
    assert out == PASTED  # byte for byte: the no-break spaces stay
    assert warnings.count("warning:") == 1 and "in.nc:2:4: warning: U+00A0" in warnings, warnings
    assert _moves(PASTED) == _moves(PASTED.replace(NBSP, " ")) == [(10.0, 0.0, 0.0), (20.0, 5.0, -1.0)]


def test_other_dialects_still_refuse_a_no_break_space() -> None:
    errors = _errors("N10\u00a0G01 X1. F100.\n", "fanuc", "fanuc")
    assert errors == ["in.nc:1:4: error: character '\\xa0' (U+00A0) is not ASCII: outside comments a program "
                      "is ASCII"], errors


def test_a_regenerated_assignment_to_a_typed_variable_is_plain_isg() -> None:
    """ISG stores into a declared type by assigning: ``whole_in`` has no spelling of its own there."""
    value = Binary("add", Var(name="V.P.U"), Num(1.0))
    assert spell_expr(Func("whole_in", [value, Num(0.0), Num(4294967295.0)])) == "V.P.U+1"


# -- declarations before the first construct, normalising, warnings of text read again ----------------------

UNVALUED = "%1\nG71 G90 G00 X0 Y0 Z10\n#VAR\n  V.P.A : UNS32\n  V.P.B\n#ENDVAR\nG01 X[V.P.A + 4] Y[V.P.B] F100\nM30\n"
"""Declared without initial values: each holds its type's 0 (the manual's rule), so the move is to X4 Y0."""


UNUSED = "%1\nG71 G90 G00 X0 Y0 Z10\n#VAR\n  V.P.A : UNS32\n#ENDVAR\nP1 = 4\nG01 X[P1] F100\nM30\n"
"""The declaration is the only construct the target cannot name: it is read back as one all the same."""


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc"])
@pytest.mark.parametrize("program", [UNVALUED, UNUSED], ids=["used", "unused"])
def test_declarations_without_values_flatten_for_a_target_that_cannot_name_them(target: str, program: str) -> None:
    out, warnings = _translate(program, target)
    assert "the program is flattened" in warnings and "error" not in warnings, warnings
    assert _moves(out, target) == _moves(program) == [(0.0, 0.0, 10.0), (4.0, 0.0, 10.0)]


def test_normalising_isg_keeps_the_header_and_the_declarations_as_written() -> None:
    text = ("%1\n#COMMENT BEGIN\n  notes (with a parenthesis\n#COMMENT END\nN10 #VAR\n  V.P.A : UNS32 = 3\n  V.P.B\n"
            "#ENDVAR\nG01 X[V.P.A] Y[V.P.B] F100\nM30\n")
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="isg", target="isg",
              setup=_normalizing(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert out.getvalue() == text.replace("F100", "F100."), out.getvalue()


def test_text_read_again_does_not_warn_again(capsys: pytest.CaptureFixture[str]) -> None:
    """The interpreter step reads the program from its first construct again (the keep check, the
    flattening run): the no-break space was reported when the program was read."""
    text = UNVALUED.replace("  V.P.B", f"  V.P.B{NBSP}")
    _, warnings = _translate(text, "linuxcnc")
    assert warnings.count("U+00A0") == 1 and "in.nc:5:8: warning: U+00A0" in warnings, warnings
    assert capsys.readouterr().err == ""


def _normalizing() -> MachineSetup:
    return MachineSetup(output=OutputSettings(normalize=True))
