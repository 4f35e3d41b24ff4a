"""Fanuc-family controller variants and the input a shop meets (issue 12, items 2 and 3): the Haas dwell
P in seconds, Fanuc 0M's ``G42 H19``, rotary axes, a UTF-8 byte order mark and the DOS end-of-file
byte, and the warning for axis words written with and without a decimal point under least-increment
input. Expected values are derived by hand in each test."""

from __future__ import annotations

import io
import re
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.setup.machine_setup import ControllerSettings, InputSettings, MachineSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274

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
    assert errors("G04 P0.5") == ["t.nc:1:5: error: address P takes no decimal point (P0.5): a dwell P counts "
                                  "milliseconds; if it means seconds (Haas), set <Controller dwellSeconds=\"true\"/> "
                                  "(or variant=\"haas\") in the machine set-up"]


def test_haas_dwell_translates_to_linuxcnc_seconds_and_stays_verbatim_for_fanuc() -> None:
    assert translated("G04 P0.5\n", "linuxcnc", HAAS) == "G21 G4 P0.5\nM2\n"  # (a fragment: no end, M2; G21: tests/test_units_at_start.py)
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
        "t.nc:2:5: error: G42 takes its radius register from D, not H19; if the controller takes it from H (Fanuc "
        "0M), set <Controller cutterRegisterH=\"true\"/> (or variant=\"fanuc-0m\") in the machine set-up"]


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


# -- G10 data setting ------------------------------------------------------------------------------

G10 = """%
O3000
G21 G90 G17
G10 L2 P1 X100. Y50. Z-200.
G10 L2 P2 X-20.
G54 G00 X0 Y0
Z10.
G01 Z-1. F300.
X10.
G55 G00 X0
G53 G00 Z0
M30
%"""


def test_g10_work_offsets_shift_the_simulated_path() -> None:
    # G54 = (100, 50, -200), G55 = (-20, 0, 0); G53 is machine coordinates; the start is machine (0, 0, 0)
    assert [e for e in events(G10) if "move" in e] == [
        {"line": 6, "move": "rapid", "x": 100, "y": 50, "z": 0},
        {"line": 7, "move": "rapid", "x": 100, "y": 50, "z": -190},
        {"line": 8, "move": "feed", "x": 100, "y": 50, "z": -201, "f": 300},
        {"line": 9, "move": "feed", "x": 110, "y": 50, "z": -201, "f": 300},
        {"line": 10, "move": "rapid", "x": -20, "y": 50, "z": -201},
        {"line": 11, "move": "rapid", "x": -20, "y": 50, "z": 0},
    ]


def test_an_incremental_g10_adds_to_the_offset() -> None:
    got = events("G21 G90\nG10 L2 P1 X100.\nG91 G10 L2 P1 X5.\nG90 G54 G00 X1.")
    assert got == [{"line": 4, "move": "rapid", "x": 106, "y": 0, "z": 0}]


def test_g10_stays_verbatim_for_fanuc_and_maps_to_g10_l2_for_linuxcnc_and_grbl() -> None:
    assert translated(G10, "fanuc") == G10 + "\n"
    assert translated(G10, "linuxcnc").splitlines()[3:5] == ["G10 L2 P1 X100. Y50. Z-200.", "G10 L2 P2 X-20."]
    assert translated(G10, "grbl").splitlines()[3:5] == ["G10 L2 P1 X100. Y50. Z-200.", "G10 L2 P2 X-20."]


def test_g10_translation_verifies_at_zero() -> None:
    out = translated(G10, "linuxcnc")
    report = verify_lines(lines(G10), io.StringIO(out), file_in="t.nc", file_out="t.ngc", source="fanuc",
                          target="linuxcnc")
    assert report.ok and report.max_deviation == 0, report.summary()


@pytest.mark.parametrize("text, target, message", [
    ("G21 G90\nG91 G10 L2 P1 X5.\nM30", "linuxcnc",
     "t.nc:2:1: error: the linuxcnc dialect cannot express G10 L2 P1 X5. (setting work offset 1): it sets offsets "
     "absolutely only (the source adds to the offset in incremental mode)"),
    ("G21 G90\nG10 L2 P0 X5.\nM30", "linuxcnc",
     "t.nc:2:1: error: the linuxcnc dialect cannot express G10 L2 P0 X5. (setting work offset 0): P0 here is not "
     "the offset common to all work systems"),
    ("G21 G90\nG10 L11 P5 R-123.4\nM30", "linuxcnc",  # a wear register (G10 L10, the geometry, is G10 L1 P5 Z)
     "t.nc:2:1: error: the linuxcnc dialect cannot express G10 L11 P5 R-123.4 (setting tool length wear 5): no "
     "such table can be set from a program"),
    ("G21 G90\nG10 L10 P5 R-123.4\nM30", "linuxcnc",  # the default set-up lists no tools
     "t.nc:2:1: error: the linuxcnc dialect cannot express G10 L10 P5 R-123.4 (setting tool length 5): it sets "
     "only a tool its table holds, and the set-up's <Tools> has no tool 5 (add <Tool number=\"5\" .../>)"),
    ("G21 G90\nG10 L2 P1 X5. A90.\nM30", "grbl",
     "t.nc:2:1: error: the grbl dialect cannot express G10 L2 P1 X5. A90. (setting work offset 1): it sets axes "
     "XYZ only"),
])
def test_g10_without_an_equivalent_is_a_located_error(text: str, target: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        translated(text, target)
    assert [str(e) for e in info.value.errors] == [message]


@pytest.mark.parametrize("text, message", [
    ("G10 L2 P7 X1.", "t.nc:1:8: error: G10 L2 P7: the entry is P0-P6"),
    ("G10 L2 X1.", "t.nc:1:1: error: G10 L2 needs the entry it sets, P0-P6"),
    ("G10 L12 P3", "t.nc:1:1: error: G10 L12 P3 sets nothing (no R)"),
])
def test_bad_g10_words_are_located(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        read_program(lines(text), file="t.nc", dialect="fanuc")
    assert [str(e) for e in info.value.errors] == [message]


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_g10_translation_runs_in_linuxcnc_as_the_fanuc_program_moves() -> None:
    """rs274 prints points in the active work system and each offset as SET_G5X_OFFSET: adding the offset
    gives the machine position, which the simulation reports."""
    theirs = []
    offset = [0.0, 0.0, 0.0]
    for call in rs274.run_rs274(translated(G10, "linuxcnc")):
        m = re.search(r"SET_G5X_OFFSET\(\d+, ([^)]*)\)", call)
        if m:
            offset = [float(v) for v in m.group(1).split(",")[:3]]
        m = re.search(r"STRAIGHT_(TRAVERSE|FEED)\(([^)]*)\)", call)
        if m:
            point = [float(v) + o for v, o in zip(m.group(2).split(",")[:3], offset)]
            theirs.append({"move": "rapid" if m.group(1) == "TRAVERSE" else "feed", **dict(zip("xyz", point))})
    ours = [e for e in events(G10) if "move" in e]
    assert len(theirs) == len(ours), theirs
    for a, b in zip(ours, theirs):
        assert a["move"] == b["move"] and all(abs(float(a[k]) - b[k]) < 1e-3 for k in "xyz"), (a, b)


def test_a_g10_or_a_machine_code_inside_an_active_cycle_drills_no_hole() -> None:
    # G81 at (5,5); the G10 moves G54 by X5 and is no hole position; M77 P2 keeps its P; X10. drills at
    # machine X15
    got = events("G21 G90 G00 X0 Y0 Z10.\nG81 X5. Y5. Z-1. R2. F100.\nG10 L2 P1 X5.\nM77 P2\nX10.\nG80")
    holes = [(e["line"], e["x"]) for e in got if e.get("move") == "feed"]
    assert holes == [(2, 5), (5, 15)]
    assert {"line": 4, "event": "machine", "code": "M77"} in got


def test_linuxcnc_g10_l2_reaches_fanuc_by_meaning() -> None:
    source = "G21 G90\nG10 L2 P2 X5. Y-3.\nG55 G0 X1. Y1.\nG91 G10 L2 P1 X1.\nG90\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(source), out, file="t.ngc", source="linuxcnc", target="fanuc", on_unsupported="warn",
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    # LinuxCNC's G10 L2 sets absolutely even under G91; Fanuc's would add there: refused, as a comment
    assert out.getvalue().splitlines()[1:4] == [
        "G10 L2 P2 X5. Y-3.", "G55 G00 X1. Y1.", "(UNSUPPORTED LINE 4: G91 G10 L2 P1 X1.)"]
    report = verify_lines(io.StringIO(source), io.StringIO(out.getvalue()), file_in="t.ngc", file_out="t.nc",
                          source="linuxcnc", target="fanuc")
    assert report.ok and report.max_deviation == 0 and report.moves == 1  # G55 X1 Y1 = machine (6, -2)
