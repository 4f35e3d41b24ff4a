"""Numbers at the edge of the float range: set-ups, toolpaths and verify stay finite or fail located (issue 8)."""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest

from postproc.errors import ConfigError, ErrorList, ProgramError
from postproc.setup.machine_setup import load_setup
from postproc.commands.export import write_jsonl
from postproc.geometry.arcs import MAX_ARC_POINTS, arc_points, centre_from_radius
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

BIG = "1" + "0" * 29 + "."
"""1e200 written out: finite, but its square overflows."""
BEYOND = "1" + "0" * 400 + "."
"""1e400: beyond the float range (reads as inf)."""


@pytest.mark.parametrize("element, value", [
    ("<Cycles orientAngle=\"{}\"/>", "nan"), ("<Machine startZ=\"{}\"/>", "inf"),
    ("<Machine startX=\"{}\"/>", "-inf"), ("<Cycles peckRetract=\"{}\"/>", "Infinity"),
])
def test_setup_floats_must_be_finite(tmp_path: Path, element: str, value: str) -> None:
    path = tmp_path / "m.xml"
    path.write_text("<MachineSetup name=\"t\">\n" + element.format(value) + "\n</MachineSetup>\n")
    with pytest.raises(ConfigError) as exc:
        load_setup(path)
    tag, attr = element[1:].split(" ")[0], element.split(" ")[1].split("=")[0]
    assert str(exc.value) == f"{path}:2:1: error: <{tag}> {attr}: Input should be a finite number"


def test_a_coordinate_beyond_the_float_range_cannot_be_simulated() -> None:
    with pytest.raises(ErrorList) as exc:
        list(toolpath_events(io.StringIO(f"G21 G90\nG0 X{BEYOND}\n"), file="big.nc", dialect="fanuc"))
    # refused before it is read: no number of more than 30 digits reaches the simulator (postproc.syntaxes.lines)
    assert [str(e) for e in exc.value.errors] == [
        "big.nc:2:5: error: a number with more than 30 digits cannot be read"]


def test_toolpath_json_is_strict_and_a_non_finite_value_is_located() -> None:
    out = io.StringIO()
    events = [{"toolpath": 1}, {"line": 7, "move": "rapid", "x": float("inf"), "y": 0, "z": float("nan")}]
    with pytest.raises(ProgramError) as exc:
        write_jsonl(events, out, "t.nc")
    assert str(exc.value) == "t.nc:7:1: error: the toolpath has a value beyond the range of a float (x, z)"
    assert [json.loads(line) for line in out.getvalue().splitlines()] == [{"toolpath": 1}]


def _verify(a: str, b: str) -> tuple[float, int, bool, str | None]:
    report = verify_lines(io.StringIO(a), io.StringIO(b), file_in="a.nc", file_out="b.nc",
                          source="fanuc", target="fanuc")
    return report.max_deviation, report.moves, report.ok, report.mismatch


TWO = "2" + "0" * 29 + "."


def test_verify_near_the_float_range_gives_the_right_answer() -> None:
    """The largest numbers a program can hold (30 digits): verify measures them exactly (its distances
    are overflow-safe: squares of 1e200 used to raise OverflowError)."""
    line = f"G21 G90 G1 F100.\nX{BIG} Y{BIG}\nX{TWO} Y{TWO}\n"
    assert _verify(line, line)[::2] == (0.0, True)
    assert _verify(f"G21 G90 G1 F100. X{BIG}\n", f"G21 G90 G1 F100. X{TWO}\n") == (1e29, 1, False, None)


def test_verify_does_not_merge_a_corner_near_the_float_range() -> None:
    """The distance from the line was a difference of overflowed squares (nan), which merged any corner."""
    corner = f"G21 G90 G1 F100.\nX{BIG}\nX{TWO} Y{BIG}\n"
    direct = f"G21 G90 G1 F100.\nX{TWO} Y{BIG}\n"
    deviation, moves, ok, mismatch = _verify(corner, direct)
    assert not ok and mismatch is not None and mismatch.startswith("OUT has no more moves or events, IN has")


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "-1", "x"])
def test_verify_tolerance_must_be_a_finite_non_negative_number(cli, tmp_path: Path, value: str) -> None:
    program = tmp_path / "p.nc"
    program.write_text("G0 X1.\n")
    result = cli("verify", program, program, "--from", "fanuc", "--to", "fanuc", f"--tolerance={value}")
    assert result.status == 2
    assert result.err_lines[-1].startswith("postproc verify: error: argument --tolerance: ")
    assert repr(value) in result.err_lines[-1]


def test_an_r_arc_near_the_float_range_has_the_right_centre() -> None:
    """r*r overflowed to inf: the centre became inf and the block a (located) error; now it is exact:
    (0, 1e200) is 1e200 from both (1e200, 1e200) and (0, 0), on the clockwise side."""
    cx, cy = centre_from_radius((1e200, 1e200), (0.0, 0.0), 1e200, True)
    assert abs(cx) <= 1e188 and cy == pytest.approx(1e200, rel=1e-12)


@pytest.mark.parametrize("radius", [1e9, 1e200])
def test_an_arc_of_a_huge_radius_is_drawn_with_bounded_points(radius: float) -> None:
    """A 1e9 mm radius took 350,000 points per half circle (1e200: a division by zero)."""
    points = list(arc_points((radius, 0.0, 0.0), (-radius, 0.0, 0.0), (0.0, 0.0, 0.0), "XY", False))
    assert len(points) <= MAX_ARC_POINTS
    assert points[-1] == (-radius, 0.0, 0.0)


def test_a_backplot_near_the_float_range(cli, tmp_path: Path) -> None:
    program = tmp_path / "huge.nc"
    program.write_text(f"G21 G90\nG1 X{BIG} Y{BIG} F100.\nG2 X0. Y0. R{BIG}\nG1 X5.\n")
    for fmt in ("svg", "png"):
        result = cli("toolpath", program, "--dialect", "fanuc", "--format", fmt, "-o", tmp_path / f"o.{fmt}")
        assert (result.status, result.err) == (0, "")
