"""verify says what it did not compare (issue 12, item 5): settings the simulation does not apply
(cutter compensation, tool length and work offsets, path control, spindle speed, tool offset data) are
compared as settings; one that moves the tool and differs fails the check unless --allow-ignored."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

from postproc.simulate.verify import verify_lines

FANUC = """G21 G90 G17
G00 X0 Y0 S1000 M03
G41 D01 G01 X10. F100.
Y10.
G40 G00 X0 Y0
M30
"""


def verify(source: str, target: str, dialect: str = "linuxcnc", allow: bool = False) -> Any:
    return verify_lines(io.StringIO(source), io.StringIO(target), file_in="a.nc", file_out="b.ngc",
                        source="fanuc", target=dialect, allow_ignored=allow)


def test_the_same_compensation_on_both_sides_is_a_note() -> None:
    out = "G17 G21 G90\nG0 X0. Y0. S1000 M3\nG41 D01 G1 X10. F100.\nG1 Y10.\nG40 G0 X0. Y0.\nM30\n"
    report = verify(FANUC, out)
    assert report.ok
    assert report.ignored == ["cutter compensation: not simulated, the same on both sides (left D1 (line 3), off "
                              "(line 5))"]
    assert report.summary().splitlines()[1:] == ["not compared:", "  " + report.ignored[0]]


def test_compensation_left_out_fails_unless_allowed() -> None:
    out = "G17 G21 G90\nG0 X0. Y0. S1000 M3\nG1 X10. F100.\nG1 Y10.\nG0 X0. Y0.\nM30\n"
    report = verify(FANUC, out)
    assert not report.ok and report.left_out_moves and report.max_deviation == 0
    assert report.ignored == ["cutter compensation differs: IN left D1 (line 3), off (line 5); OUT never set"]
    assert report.summary().splitlines()[0] == (
        "max deviation 0.0000 mm over 3 moves (IN:3 / OUT:3): settings that move the tool differ (listed below; "
        "--allow-ignored accepts them)")
    allowed = verify(FANUC, out, allow=True)
    assert allowed.ok
    assert allowed.summary().splitlines()[0].endswith(": ok, with settings that move the tool left out (--allow-ignored)")


def test_a_different_spindle_speed_is_listed_but_moves_nothing() -> None:
    source = "G21 G90\nG00 X1. S500 M03\nM30\n"
    report = verify(source, "G21 G90\nG0 X1. S800 M3\nM30\n")
    assert report.ok
    assert report.ignored == ["spindle speed differs: IN S500 (line 2); OUT S800 (line 2)"]


def test_tool_length_data_is_simulated_where_an_offset_reads_it() -> None:
    # a register written and never read moves nothing: nothing to compare
    source = "G21 G90\nG10 L10 P1 R-100.\nG00 X1.\nM30\n"
    report = verify(source, "G21 G90\n(G10 L10 P1 R-100.)\nG0 X1.\nM30\n")
    assert report.ok and report.ignored == []
    # read by G43 H1, its loss moves the tool: Z5 + (-100) against Z5 (no set-up length needed: the program's)
    source = "G21 G90\nG10 L10 P1 R-100.\nG00 X1.\nG43 H1 Z5.\nM30\n"
    report = verify(source, "G21 G90\n(G10 L10 P1 R-100.)\nG0 X1.\nG0 Z5.\nM30\n")
    assert not report.ok and report.max_deviation == 100 and report.where == (4, 4)


def test_cli_allow_ignored(cli: Any, tmp_path: Path) -> None:
    a, b = tmp_path / "a.nc", tmp_path / "b.ngc"
    a.write_text(FANUC)
    b.write_text("G17 G21 G90\nG0 X0. Y0. S1000 M3\nG1 X10. F100.\nG1 Y10.\nG0 X0. Y0.\nM30\n")
    plain = cli("verify", a, b, "--from", "fanuc", "--to", "linuxcnc")
    assert plain.status == 1
    assert plain.out.decode().splitlines()[1:] == [
        "not compared:", "  cutter compensation differs: IN left D1 (line 3), off (line 5); OUT never set"]
    allowed = cli("verify", a, b, "--from", "fanuc", "--to", "linuxcnc", "--allow-ignored")
    assert allowed.status == 0 and allowed.out.decode().splitlines()[1:] == plain.out.decode().splitlines()[1:]
