"""SINUMERIK subprograms with parameters: ``PROC NAME(REAL A, INT B, BOOL C)`` called as ``NAME(1, R2, 0)``
(call by value). Expected moves are worked out by hand from the programs (comments beside them)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

POCKET = """%_N_POCKET_SPF
PROC POCKET(REAL LEN, INT TURNS, BOOL DEEP)
DEF REAL Z1
Z1=-1
IF DEEP
Z1=-2
ENDIF
G1 Z=Z1 F100
G1 X=LEN
LEN=0
G1 X=LEN Y=TURNS
RET
"""
MAIN = "G710 G17 G90 G0 X0 Y0 Z5\nR1=10\nPOCKET(R1*2, 2.6, 1)\nG0 X=R1\nPOCKET(5, 1, 0)\nM30\n"


def _library(tmp_path: Path, **files: str) -> MachineSetup:
    (tmp_path / "POCKET.SPF").write_text(POCKET)
    (tmp_path / "PLAIN.SPF").write_text("%_N_PLAIN_SPF\nPROC PLAIN\nG1 X1 F100\nRET\n")
    (tmp_path / "REC.SPF").write_text("%_N_REC_SPF\nPROC REC(INT N)\nG1 X=N F100\nREC(N+1)\nRET\n")
    for name, text in files.items():
        (tmp_path / f"{name}.SPF").write_text(text)
    return MachineSetup(library=[str(tmp_path)])


def _translate(text: str, target: str, setup: MachineSetup) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, setup: MachineSetup) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, "linuxcnc", setup)
    return [str(e) for e in caught.value.errors]


def _moves(text: str, setup: MachineSetup) -> list[tuple[object, ...]]:
    return [(e["move"], e["x"], e["y"], e["z"])
            for e in toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens", setup=setup) if "move" in e]


def test_parameters_take_the_arguments_in_their_places_by_value(tmp_path: Path) -> None:
    setup = _library(tmp_path)
    assert _moves(MAIN, setup) == [
        ("rapid", 0, 0, 5),
        # LEN = R1*2 = 20, TURNS = 2.6 rounded = 3 (INT), DEEP = 1: Z1 = -2
        ("feed", 0, 0, -2), ("feed", 20, 0, -2), ("feed", 0, 3, -2),
        # R1 is still 10 (LEN=0 set the subprogram's own copy)
        ("rapid", 10, 3, -2),
        # LEN 5, TURNS 1, DEEP 0: Z1 stays -1
        ("feed", 10, 3, -1), ("feed", 5, 3, -1), ("feed", 0, 1, -1)]


def test_a_variable_passed_is_not_changed_by_the_callee(tmp_path: Path) -> None:
    setup = _library(tmp_path, SET="%_N_SET_SPF\nPROC SET(REAL V)\nV=V+100\nG1 X=V F100\nRET\n")
    text = "G710 G90 G0 X0 Y0 Z0\nDEF REAL W=7\nSET(W)\nG0 Y=W\nM30\n"
    # the callee moves to 7+100, the caller's W is still 7
    assert _moves(text, setup) == [("feed", 107, 0, 0), ("rapid", 107, 7, 0)]


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "grbl"])
def test_a_program_calling_with_arguments_translates_flattened_and_verifies(tmp_path: Path, target: str) -> None:
    setup = _library(tmp_path)
    out = _translate(MAIN, target, setup)
    report = verify_lines(io.StringIO(MAIN), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target=target, setup=setup, target_setup=setup, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out


def test_the_call_and_the_proc_are_written_back_byte_for_byte(tmp_path: Path) -> None:
    setup = _library(tmp_path)
    assert _translate(MAIN, "siemens", setup) == MAIN
    assert _translate(POCKET, "siemens", setup) == POCKET


@pytest.mark.parametrize("call, message", [
    ("POCKET(1, 2, 1, 4)", "POCKET.SPF:2:1: error: the call passes 4 arguments, the PROC takes 3"),
    ("POCKET(1, 2)", "POCKET.SPF:2:1: error: argument 3 (the call passes none in its place) is read before it is set"),
    ("POCKET(1, , 1)", "in.mpf:3:11: error: an empty argument of POCKET"),
    ("POCKET(1, 2, 1", "in.mpf:3:15: error: ',' or ')' expected in the arguments of POCKET"),
    ("POCKET(" + ", ".join(["1"] * 65) + ")", "a call of POCKET has more than 64 arguments"),
    ("PLAIN(1)", "PLAIN.SPF:4:1: error: the call passes 1 arguments to a subprogram without PROC parameters"),
    ("REC(1)", "exceeds the set-up's bound of 64 nested calls"),
    ("POCKET(1, 2, 1) P2", "a call of POCKET with arguments and more after them (P repetitions)"),
])
def test_a_bad_call_is_a_located_error(tmp_path: Path, call: str, message: str) -> None:
    errors = _errors(f"G710 G17 G90 G0 X0 Y0 Z5\nR1=1\n{call}\nM30\n", _library(tmp_path))
    assert any(message in e for e in errors), errors


@pytest.mark.parametrize("proc, message", [
    ("PROC BAD(VAR REAL DIA)", "a parameter by reference (VAR) (not modelled)"),
    ("PROC BAD(REAL DIA[3])", "array parameters (not modelled)"),
    ("PROC BAD(STRING[8] DIA)", "a PROC parameter of type STRING"),
    ("PROC BAD(REAL DIA) SAVE", "PROC with attributes (SAVE, DISPLOF)"),
])
def test_what_a_proc_line_has_beyond_values_is_kept_verbatim(tmp_path: Path, proc: str, message: str) -> None:
    text = f"%_N_BAD_SPF\n{proc}\nG1 X1 F100\nRET\n"
    setup = _library(tmp_path)
    assert _translate(text, "siemens", setup) == text
    assert any(message in e for e in _errors(text, setup))


@pytest.mark.parametrize("proc, message", [
    ("PROC BAD(REAL X)", "2:15: error: a PROC parameter needs a name that is no address or R parameter"),
    ("PROC BAD(REAL R2)", "2:15: error: a PROC parameter needs a name"),
    ("PROC BAD(REAL DIA B)", "2:19: error: ',' or ')' expected in the PROC parameters"),
    ("PROC BAD(" + ", ".join(f"REAL P{n}" for n in range(65)) + ")", "PROC has more than 64 parameters"),
])
def test_a_malformed_proc_line_is_a_located_error(tmp_path: Path, proc: str, message: str) -> None:
    errors = _errors(f"%_N_BAD_SPF\n{proc}\nG1 X1 F100\nRET\n", _library(tmp_path))
    assert any(message in e for e in errors), errors


# -- T="name" ------------------------------------------------------------------------------------------------

def _named_tools() -> MachineSetup:
    from postproc.setup.machine_setup import load_setup
    return load_setup(str(Path(__file__).resolve().parents[1] / "tests" / "support" / "named_tools.xml"))


def test_a_tool_by_name_is_the_set_ups_tool_of_that_name() -> None:
    setup = _named_tools()
    text = 'G710 G17 G90 G0 X0 Y0 Z5\nT="DRILL_8" D1\nM6\nG0 X10\nM30\n'
    numbered = 'G710 G17 G90 G0 X0 Y0 Z5\nT3 D1\nM6\nG0 X10\nM30\n'
    assert _translate(text, "siemens", setup) == text
    for target in ("fanuc", "linuxcnc"):  # named tool 3 is T3 (the set-up says so), nothing else changes
        assert _translate(text, target, setup) == _translate(numbered, target, setup)
        assert "T3" in _translate(text, target, setup)


@pytest.mark.parametrize("line, message", [
    ('T="NOPE"', '2:1: error: T="NOPE" (no tool of the set-up has this name'),
    ('T="drill_8"', '2:1: error: T="drill_8" (no tool of the set-up has this name'),
    ('T="DRILL_8', "2:3: error: the tool's name has no closing '\"'"),
])
def test_a_tool_name_the_set_up_lacks_is_a_located_error(line: str, message: str) -> None:
    if "NOPE" in line:  # kept verbatim: a SINUMERIK program is still copied
        assert _translate(f"G710 G90 G0 X0\n{line}\nM30\n", "siemens", _named_tools()) == f"G710 G90 G0 X0\n{line}\nM30\n"
    with pytest.raises(ErrorList) as caught:
        _translate(f"G710 G90 G0 X0\n{line}\nM30\n", "linuxcnc", _named_tools())
    assert message in str(caught.value.errors[0])


def test_a_tool_name_with_a_quote_or_too_long_is_refused_by_the_set_up(tmp_path: Path) -> None:
    from postproc.errors import ConfigError
    from postproc.setup.machine_setup import load_setup
    for name in ("A" * 33, "A&quot;B"):
        path = tmp_path / "bad.xml"
        path.write_text(f'<MachineSetup><Tools><Tool number="1" name="{name}"/></Tools></MachineSetup>')
        with pytest.raises(ConfigError):
            load_setup(str(path))


# -- against LinuxCNC's interpreter ----------------------------------------------------------------------------

def test_a_program_calling_with_arguments_moves_in_rs274_as_its_siemens_toolpath(tmp_path: Path) -> None:
    from tests.support.rs274 import available, canonical_moves, run_rs274
    if not available():
        pytest.skip("the LinuxCNC interpreter rs274 is not installed")
    setup = _library(tmp_path)
    out = _translate(MAIN, "linuxcnc", setup)
    theirs = [e for e in canonical_moves(run_rs274(out), start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = [e for e in toolpath_events(io.StringIO(MAIN), file="in.mpf", dialect="siemens", setup=setup)
            if "move" in e]
    assert [(e["move"], e["x"], e["y"], e["z"]) for e in ours] == [
        (e["move"], round(e["x"], 4), round(e["y"], 4), round(e["z"], 4)) for e in theirs], out
