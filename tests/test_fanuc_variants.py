"""Fanuc-family controller variants and the input a shop meets (issue 12, items 2 and 3): the Haas dwell
P in seconds, Fanuc 0M's ``G42 H19``, rotary axes, a UTF-8 byte order mark and the DOS end-of-file
byte, and the warning for axis words written with and without a decimal point under least-increment
input. Expected values are derived by hand in each test."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.setup import ControllerSettings, InputSettings, MachineSettings, MachineSetup
from postproc.toolpath import toolpath_events
from postproc.verify import verify_lines

HAAS = MachineSetup(controller=ControllerSettings(variant="haas"))
FANUC_0M = MachineSetup(controller=ControllerSettings(variant="fanuc-0m"))


def lines(text: str) -> list[str]:
    return [line + "\n" for line in text.strip("\n").splitlines()]


def events(text: str | list[str], setup: MachineSetup | None = None,
           warnings: io.StringIO | None = None) -> list[dict[str, Any]]:
    diag = Diagnostics(ErrorLevel.RAISE, warn_stream=warnings if warnings is not None else io.StringIO())
    source = lines(text) if isinstance(text, str) else text
    return list(toolpath_events(source, file="t.nc", dialect="fanuc", setup=setup, diagnostics=diag))[1:]


def errors(text: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        events(text, setup)
    return [str(e) for e in info.value.errors]


def translated(text: str | list[str], target: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO()
    source = lines(text) if isinstance(text, str) else text
    translate(source, out, file="t.nc", source="fanuc", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


# -- Haas: a dwell P with a decimal point is in seconds ---------------------------------------------

def test_haas_dwell_p_with_a_point_is_seconds_and_without_milliseconds() -> None:
    assert events("G04 P0.5\nG04 P1500", HAAS) == [{"line": 1, "event": "dwell", "seconds": 0.5},
                                                     {"line": 2, "event": "dwell", "seconds": 1.5}]


def test_haas_cycle_dwell_p_in_seconds() -> None:
    # G82 at X5 Y5 from Z10: rapid to R2, feed to Z-3, dwell 0.25 s, rapid back to the initial Z10
    got = events("G21 G90 G00 X0 Y0 Z10.\nG98 G82 X5. Y5. Z-3. R2. P0.25 F100.\nG80", HAAS)
    assert got == [{"line": 1, "move": "rapid", "x": 0, "y": 0, "z": 10},
                   {"line": 2, "move": "rapid", "x": 5, "y": 5, "z": 10},
                   {"line": 2, "move": "rapid", "x": 5, "y": 5, "z": 2},
                   {"line": 2, "move": "feed", "x": 5, "y": 5, "z": -3, "f": 100},
                   {"line": 2, "event": "dwell", "seconds": 0.25},
                   {"line": 2, "move": "rapid", "x": 5, "y": 5, "z": 10}]


def test_haas_dwell_finer_than_a_millisecond_and_fanuc_points_are_refused() -> None:
    assert errors("G04 P0.0005", HAAS) == ["t.nc:1:5: error: dwell P0.0005 (seconds) is finer than a millisecond"]
    assert errors("G04 P0.5") == ["t.nc:1:5: error: address P takes no decimal point (P0.5)"]


def test_haas_dwell_translates_to_linuxcnc_seconds_and_stays_verbatim_for_fanuc() -> None:
    assert translated("G04 P0.5\n", "linuxcnc", HAAS) == "G4 P0.5\n"
    assert translated("G04 P0.5\n", "fanuc", HAAS) == "G04 P0.5\n"


# -- Fanuc 0M: cutter compensation takes its register from H ---------------------------------------

def test_fanuc_0m_g42_h_is_the_cutter_register() -> None:
    block = read_program(lines("G42 H19 G01 X10. F100."), file="t.nc", dialect="fanuc", setup=FANUC_0M)[0]
    comp = block.get("CutterCompensation")
    assert (comp.mode, comp.register) == ("right", 19)
    assert translated("G21 G90\nG00 X0 Y0\nG42 H19 G01 X10. F100.\nG40 G00 X0", "linuxcnc", FANUC_0M).splitlines()[2] \
        == "G42 D19 G1 X10. F100."


def test_h_beside_a_length_offset_stays_the_length_register_on_0m() -> None:
    block = read_program(lines("G43 G42 H19 G01 X10. F100."), file="t.nc", dialect="fanuc", setup=FANUC_0M)[0]
    assert block.get("ToolLengthOffset").register == 19 and block.get("CutterCompensation").register is None


def test_g42_h_is_an_error_on_other_variants() -> None:
    assert errors("G21 G90 G00 X0 Y0\nG42 H19 G01 X10. F100.") == [
        "t.nc:2:5: error: address H has no meaning in this block"]


# -- rotary axes -----------------------------------------------------------------------------------

FIVE_AXES = MachineSetup(machine=MachineSettings(axes="XYZABC"))
ROTARY = "G20 G90 G17\nG00 X0. Y0. Z1. A0.\nG01 A90. F500.\nG01 X1. B45. C30. F20.\nG91 G01 A-45.\nG90\nM30"


def test_rotary_axes_are_simulated_as_degrees_whatever_the_length_unit() -> None:
    got = events(ROTARY, FIVE_AXES)
    # inch: X1. = 25.4 mm and Z1. = 25.4 mm; A, B, C stay degrees; F20. in/min = 508 mm/min
    assert got[2] == {"line": 4, "move": "feed", "x": 25.4, "y": 0, "z": 25.4, "a": 90, "b": 45, "c": 30, "f": 508}
    assert got[3] == {"line": 5, "move": "feed", "x": 25.4, "y": 0, "z": 25.4, "a": 45, "b": 45, "c": 30, "f": 508}


def test_rotary_axes_translate_to_linuxcnc_and_verify_at_zero() -> None:
    out = translated(ROTARY, "linuxcnc", FIVE_AXES)
    assert "G1 X1. B45. C30. F20." in out.splitlines()
    report = verify_lines(lines(ROTARY), io.StringIO(out), file_in="t.nc", file_out="t.ngc", source="fanuc",
                          target="linuxcnc", setup=FIVE_AXES)
    assert report.ok and report.max_deviation == 0 and report.moves == 4, report.summary()


# -- byte order mark and end-of-file byte --------------------------------------------------------

DOS = ["\ufeff%\r\n", "O1000\r\n", "G21 G90 G00 X1.\r\n", "M30\r\n", "%\r\n", "\x1a"]


def test_a_byte_order_mark_and_an_end_of_file_byte_are_read_past_and_written_back() -> None:
    assert events(DOS) == [{"line": 3, "move": "rapid", "x": 1, "y": 0, "z": 0}, {"line": 4, "event": "end"}]
    assert translated(DOS, "fanuc") == "".join(DOS)


def test_the_eof_byte_ends_its_line_and_a_bom_elsewhere_is_refused() -> None:
    assert events(["G21 G90 G00 X1.\x1a"]) == [{"line": 1, "move": "rapid", "x": 1, "y": 0, "z": 0}]
    assert errors("G21\n\ufeffG00 X1.") == [
        "t.nc:2:1: error: character '\\ufeff' (U+FEFF) is not ASCII: outside comments a program is ASCII"]


# -- least-increment input: axis words with and without a decimal point -----------------------------

def test_a_point_less_axis_word_beside_pointed_ones_is_warned_about_once() -> None:
    warned = io.StringIO()
    got = events("G21 G90\nG00 X10. Y5. Z20.\nG01 Z16 F100.\nZ-1.\nX20\n", warnings=warned)
    assert got[1] == {"line": 3, "move": "feed", "x": 10, "y": 5, "z": 0.016, "f": 100}  # 16 x 0.001 mm
    assert warned.getvalue() == (
        "t.nc:3:5: warning: Z16 has no decimal point, so it counts least input increments (0.016 mm), while "
        "line 2 writes Z with one: if the program means 16 mm, set <Input decimalPoint=\"calculator\"/> in the "
        "machine set-up\n")


def test_the_warning_comes_when_the_pointed_word_follows_and_names_inches() -> None:
    warned = io.StringIO()
    events("G20 G90\nG00 Z16\nG01 Z-1. F10.\n", warnings=warned)
    assert warned.getvalue().startswith("t.nc:2:5: warning: Z16 has no decimal point, so it counts least input "
                                        "increments (0.0016 in), while line 3 writes Z with one: ")


@pytest.mark.parametrize("text, setup", [
    ("G21 G90\nG00 X0 Y0 Z20.\nG01 Z-1. F100.\n", None),  # zero is zero either way
    ("G21 G90\nG00 X1000 Y5000\nG01 X2000 F100.\n", None),  # consistent least-increment input
    ("G21 G90\nG00 X10. Z20.\nG01 Z16 F100.\n", MachineSetup(input=InputSettings(decimal_point="calculator"))),
])
def test_no_warning_without_a_mix(text: str, setup: MachineSetup | None) -> None:
    warned = io.StringIO()
    events(text, setup, warned)
    assert warned.getvalue() == ""
