"""verify names the tool data a translation lost (issue 26, deliver 4: "verify fails on any ... tool data lost,
and says which"): a tool length, a cutter radius compensation, a tool selection in force in the source that the
translation lacks, with its register, value and source line. Hand-made pairs: the source, and the same program
with one word removed; the expected lines are derived by hand from the set-up's tools below."""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any

from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.events import CUTTER_RADIUS, TOOL_LENGTH, TOOL_SELECTION
from postproc.simulate.lost_tool_data import lost_tool_data
from postproc.simulate.verify import verify_lines

SOURCE = """O1000
G21 G17 G90 G40 G49 G80
T18 M06
G54 G00 X0 Y0
G43 H18 Z10. M08
G01 Z-1. F100.
X20.
G00 Z10.
G49 Z100.
M30
"""
"""A Fanuc program: tool 18's length (25.4 mm) in force from line 5 to line 9."""

COMPENSATED = """O1001
G21 G17 G90 G40 G49 G80
T18 M06
G54 G00 X0 Y0
G43 H18 Z10.
G01 Z-1. F100.
G41 D18 X10. Y5.
X30.
Y20.
G40 X40. Y30.
G00 Z10.
M30
"""
"""A Fanuc program cutting under tool 18's radius (5 mm) from line 7 to line 10."""


def setup() -> MachineSetup:
    out = MachineSetup()
    out.tools = {"18": ToolData(number=18, length=25.4, radius=5.0), "2": ToolData(number=2, length=30.0, radius=3.0)}
    return out


def verify(source: str, target: str, to: str = "fanuc") -> Any:
    return verify_lines(io.StringIO(source), io.StringIO(target), file_in="a.nc", file_out="b.nc",
                        source="fanuc", target=to, setup=setup())


def test_a_length_offset_left_out_is_named_with_its_register_value_and_line() -> None:
    report = verify(SOURCE, SOURCE.replace("G43 H18 Z10.", "Z10."))
    assert not report.ok and math.isclose(report.max_deviation, 25.4)  # Z10. + 25.4 against Z10.
    assert report.lost == ["tool length H18 (25.4 mm) in force in the source from a.nc:5 is not in the translation"]
    assert report.summary().splitlines()[1] == "lost: " + report.lost[0]


def test_a_register_zero_is_no_length() -> None:
    # a LinuxCNC translation whose G43 reads register 0 (no offset) instead of 18
    out = SOURCE.replace("O1000\n", "").replace("G43 H18", "G43 H0").replace("M06", "M6")
    report = verify(SOURCE, out, "linuxcnc")
    assert report.lost == ["tool length H18 (25.4 mm) in force in the source from a.nc:5 is not in the translation"]


def test_a_cancel_left_out_names_the_length_still_in_force() -> None:
    report = verify(SOURCE, SOURCE.replace("G49 Z100.", "Z100."))
    assert not report.ok and math.isclose(report.max_deviation, 25.4)  # Z100. against Z100. + 25.4
    assert report.lost == ["tool length off in the source from a.nc:9 is not in the translation: H18 (25.4 mm) is "
                           "in force there (from b.nc:5)"]


def test_another_length_is_named_with_both_values() -> None:
    # grbl's dynamic offset written with the wrong length: G43.1 Z20. where H18 holds 25.4
    out = "G21 G17 G90 G40 G49\nT18 M0\nG54 G0 X0 Y0\nG43.1 Z20.\nG0 Z10. M8\nG1 Z-1. F100.\nX20.\nG0 Z10.\nG49\nG0 Z100.\nM30\n"
    report = verify(SOURCE, out, "grbl")
    assert not report.ok and math.isclose(report.max_deviation, 5.4)
    assert report.lost == ["tool length H18 (25.4 mm) in force in the source from a.nc:5 is 20 mm in the translation "
                           "(a length given in the block, b.nc:4)"]


def test_a_cutter_compensation_left_out_is_named_with_its_radius() -> None:
    report = verify(COMPENSATED, COMPENSATED.replace("G41 D18 ", ""))
    assert not report.ok
    assert report.lost == ["cutter radius compensation left D18 (radius 5 mm) in force in the source from a.nc:7 is "
                           "not in the translation"]


def test_another_radius_is_named() -> None:
    report = verify(COMPENSATED, COMPENSATED.replace("G41 D18", "G41 D2"))
    assert not report.ok
    assert report.lost == ["cutter radius compensation left D18 (radius 5 mm) in force in the source from a.nc:7 is "
                           "radius 3 mm in the translation (left D2, b.nc:7)"]


def test_a_tool_selection_left_out_is_named() -> None:
    report = verify(SOURCE, SOURCE.replace("T18 M06", "M06"))
    assert report.mismatch == "IN has tool change to T18, OUT a tool change with no tool selected"
    assert report.lost[0] == "tool selection T18 in the source at a.nc:3 is not in the translation"


def test_isg_names_the_length_by_its_d() -> None:
    # ISG's D18 selects tool 18's length and radius together; the translation lost the D18 block's D
    out = "%1000\nG17 G71 G90 G40 D0\nT18 M06\nG54 G00 X0. Y0.\nG00 Z10. M08\nG01 Z-1. F100.\nG01 X20.\nG00 Z10.\nD0 G00 Z100.\nM30\n"
    report = verify(SOURCE, out, "isg")
    assert report.lost == ["tool length H18 (25.4 mm) in force in the source from a.nc:5 is not in the translation"]
    back = verify_lines(io.StringIO(out.replace("G00 Z10. M08", "D18 G00 Z10. M08")), io.StringIO(out), file_in="a.nc",
                        file_out="b.nc", source="isg", target="isg", setup=setup())
    assert back.lost == ["tool length D18 (25.4 mm) in force in the source from a.nc:5 is not in the translation"]


# -- no false alarm ------------------------------------------------------------------------------------

def test_translations_that_keep_the_tool_data_verify() -> None:
    linuxcnc = SOURCE.replace("O1000\n", "").replace("M06", "M6")  # G43 H18 and G41 D18 are LinuxCNC's too
    grbl = SOURCE.replace("O1000\n", "").replace("T18 M06", "T18 M0").replace("G43 H18 Z10.", "G43.1 Z25.4\nZ10.")
    grbl = grbl.replace("G49 G80", "G49").replace("G49 Z100.", "G49\nZ100.")
    # ISG selects tool 18's data (its length) with D18, D0 deselects it; Fagor's G43 D18 applies its length, G44
    # cancels it (postproc.isg_family.tool_data)
    isg = ("%1000\nG17 G71 G90 G40 D0\nT18 M06\nG54 G00 X0 Y0\nD18 G00 Z10. M08\nG01 Z-1. F100.\nX20.\n"
           "G00 Z10.\nD0 G00 Z100.\nM30\n")
    fagor = ("%1000\nG17 G71 G90 G40 G44\nT18 M06\nG54 G00 X0 Y0\nG43 D18 G00 Z10. M08\nG01 Z-1. F100.\nX20.\n"
             "G00 Z10.\nG44 G00 Z100.\nM30\n")
    for text, to in ((SOURCE, "fanuc"), (linuxcnc, "linuxcnc"), (grbl, "grbl"), (isg, "isg"), (fagor, "fagor")):
        report = verify(SOURCE, text, to)
        assert report.ok, (to, report.summary())
        assert report.lost == []


def test_a_length_written_into_the_coordinates_is_not_lost() -> None:
    # the translation moves the tool as the source does, with the length added to each Z: nothing lost
    out = SOURCE.replace("G43 H18 Z10.", "Z35.4").replace("Z-1.", "Z24.4").replace("G00 Z10.", "G00 Z35.4")
    out = out.replace("G49 Z100.", "Z100.")
    report = verify(SOURCE, out)
    assert report.ok, report.summary()
    assert report.lost == []


def test_cli_prints_the_lost_data(cli: Any, tmp_path: Path) -> None:
    a, b, machine = tmp_path / "a.nc", tmp_path / "b.nc", tmp_path / "m.xml"
    a.write_text(COMPENSATED)
    b.write_text(COMPENSATED.replace("G43 H18 ", ""))
    machine.write_text('<MachineSetup name="m"><Tools><Tool number="18" length="25.4" radius="5"/></Tools>'
                       "</MachineSetup>")
    run = cli("verify", a, b, "--from", "fanuc", "--to", "fanuc", "--machine", machine)
    assert run.status == 1
    assert run.out.decode().splitlines()[1] == (
        f"lost: tool length H18 (25.4 mm) in force in the source from {a}:5 is not in the translation")


# -- the account itself, on sequences given by hand ----------------------------------------------------

def test_data_only_the_translation_has_is_named() -> None:
    lines = lost_tool_data([(3, TOOL_SELECTION, "T1", 1.0)],
                           [(3, TOOL_SELECTION, "T1", 1.0), (5, TOOL_LENGTH, "positive 1", 40.0)],
                           file_in="a", file_out="b")
    assert lines == ["tool length H1 (40 mm) in force in the translation from b:5 is not in the source"]


def test_a_repeated_value_is_no_change() -> None:
    # G43 H1 then G43.1 with H1's length: one length in force, as in the source
    lines = lost_tool_data([(5, TOOL_LENGTH, "positive 1", 40.0)],
                           [(5, TOOL_LENGTH, "positive 1", 40.0), (7, TOOL_LENGTH, "dynamic", 40.0)],
                           file_in="a", file_out="b")
    assert lines == []


def test_an_unknown_radius_is_said_so() -> None:
    lines = lost_tool_data([(4, CUTTER_RADIUS, "right D7", math.nan), (9, CUTTER_RADIUS, "off", 0.0)], [],
                           file_in="a", file_out="b")
    assert lines == ["cutter radius compensation right D7 (a radius the set-up does not give) in force in the source "
                     "from a:4 is not in the translation"]


def test_a_subtracted_length_and_the_other_side_cancelling() -> None:
    lines = lost_tool_data([(5, TOOL_LENGTH, "negative 2", -30.0)],
                           [(5, TOOL_LENGTH, "negative 2", -30.0), (8, TOOL_LENGTH, "off", 0.0)],
                           file_in="a", file_out="b")
    assert lines == ["tool length H2 subtracted (-30 mm) in force in the source from a:5 is off in the translation "
                     "from b:8"]
