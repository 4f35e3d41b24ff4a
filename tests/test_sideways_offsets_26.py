"""A tool's offsets across the spindle (issue 26, task 4: the X and Y of a LinuxCNC tool table entry, which rs274's
``G43`` applies as it applies Z) written into the path for targets without them
(``postproc.lowering.sideways_offsets``).

* Seeded LinuxCNC programs (``G10 L1`` entries with X, Y, Z for two tools, ``G43 H``/``G49``, absolute and
  incremental moves, arcs, metric or inch) translated to Fanuc and grbl: the translation's own simulation
  moves the controlled point where rs274, run with the same tool table, moves it, and ``verify`` passes.
* Hand-derived text for one program; LinuxCNC back to LinuxCNC keeps the entry as written; what the step
  does not rewrite while an offset is in force (a frame command, a cycle kept for the target) is a
  located error, never a dropped offset.
"""

from __future__ import annotations

import io
import random

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274
from tests.test_tool_entry_at_point_26 import SETUP, TOLERANCE_MM, TOOL_TABLE, TOOLS, machine_points, needs_rs274

PROGRAMS = 24


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def to(target: str, text: str) -> str:
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target=target, setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def controlled(text: str, dialect: str) -> list[tuple[float, float, float]]:
    evs = toolpath_events(_lines(text), file="t.nc", dialect=dialect, setup=SETUP)
    return [(p["x"], p["y"], p["z"]) for e in evs if e.get("move") in ("rapid", "feed")
            for p in [e.get("controlled", e)]]


def _program(rng: random.Random) -> str:
    inch = rng.random() < 0.25
    u = 1 / 25.4 if inch else 1.0

    def n(size: float = 20.0) -> str:
        return f"{rng.uniform(-size, size) * u:.4f}"

    lines = [f"{'G20' if inch else 'G21'} G90 G17 G94", f"F{300 * u:.4f}"]
    for tool in TOOLS:
        lines.append(f"G10 L1 P{tool} X{n(3)} Y{n(3)} Z{n(30)}")
    tool = rng.choice(TOOLS)
    lines += [f"T{tool} M6", f"G43 H{tool}", f"G0 X{n()} Y{n()} Z{n()}"]
    for _ in range(rng.randint(6, 12)):
        kind = rng.random()
        if kind < 0.15:
            lines.append(rng.choice(["G49", f"G43 H{rng.choice(TOOLS)}"]))
        elif kind < 0.3:
            lines.append(f"G91 G1 X{n(5)} Y{n(5)}")
            lines.append("G90")
        elif kind < 0.45:
            lines.append(f"G10 L1 P{rng.choice(TOOLS)} X{n(3)} Y{n(3)}")  # read where G43 is next programmed
        else:
            axes = [a + n() for a in "XYZ" if rng.random() < 0.6] or [f"X{n()}"]
            lines.append(f"G{rng.choice((0, 1))} {' '.join(axes)}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


@needs_rs274
@pytest.mark.parametrize("target", ["fanuc", "grbl"])
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_offsets_across_the_spindle_reach_the_path_as_rs274_moves(seed: int, target: str) -> None:
    text = _program(random.Random(2640 + seed))
    scale = 25.4 if "G20" in text else 1.0
    theirs = machine_points(rs274.run_rs274(text, tool_table=TOOL_TABLE), scale)
    assert len(controlled(text, "linuxcnc")) == len(theirs)
    out = to(target, text)
    ours = controlled(out, target)
    assert len(ours) == len(theirs), (text, out)
    for a, b in zip(ours, theirs):
        assert max(abs(p - q) for p, q in zip(a, b)) <= TOLERANCE_MM, (text, out, a, b)
    report = verify_lines(_lines(text), _lines(out), file_in="t.ngc", file_out="t.nc", source="linuxcnc",
                          target=target, setup=SETUP)
    assert report.ok, report.summary()


def test_the_offset_is_added_to_absolute_x_and_y_alone_hand_derived() -> None:
    # entry 3: X0.5 Y-0.25 Z10. G43 H3 then X5 Y6 is X5.5 Y5.75; Z alone and the increment X1 unchanged;
    # Y2 is Y1.75; after G49 X0 Y0 is X0 Y0 (the length's cancel goes with the next Z on Fanuc)
    text = ("G21 G90 G17\nG10 L1 P3 X0.5 Y-0.25 Z10\nT3 M6\nG43 H3\nG0 X5 Y6 Z7\nG1 Z1 F100\nG91 G1 X1\n"
            "G90 G1 Y2\nG49\nG0 X0 Y0\nG0 Z20\nM2\n")
    assert to("fanuc", text) == ("G17 G21 G90\nG10 L10 P3 R10.\nT3 M06\nG43 H03 G00 X5.5 Y5.75 Z7.\nG01 Z1. F100.\n"
                                 "G91 G01 X1.\nG90 G01 Y1.75\nG00 X0. Y0.\nG49 G00 Z20.\nM02\n")
    assert to("linuxcnc", text) == text


def test_a_program_coordinate_set_under_an_offset_moves_as_linuxcnc() -> None:
    # G92 X0 at X5 (machine 5.5): the origin moves by 5, X1 is machine 6.5 (rs274's X1.5 plus its G92 offset 5)
    text = "G21 G90 G17\nG10 L1 P3 X0.5 Y1\nT3 M6\nG43 H3\nG0 X5 Y6 Z7\nG92 X0\nG0 X1 Y1\nG92.1\nG0 X0\nM2\n"
    out = to("fanuc", text)
    assert controlled(out, "fanuc") == controlled(text, "linuxcnc") == [(5.5, 7, 7), (6.5, 2, 7), (0.5, 2, 7)]
    report = verify_lines(_lines(text), _lines(out), file_in="t.ngc", file_out="t.nc", source="linuxcnc",
                          target="fanuc", setup=SETUP)
    assert report.ok, report.summary()


def test_an_expanded_cycle_under_an_offset_drills_at_the_offset_points() -> None:
    text = "G21 G90 G17\nG10 L1 P3 X0.5 Y1\nT3 M6\nG43 H3\nG0 X5 Y6 Z7\nG81 X1 Y1 Z-1 R1 F100\nX2\nG80\nG0 X0\nM2\n"
    out = to("fanuc", text)
    assert "G00 X1.5 Y2. Z7.\n" in out and "G00 X2.5 Y2. Z1.\n" in out, out  # rs274's G81 is expanded for Fanuc
    report = verify_lines(_lines(text), _lines(out), file_in="t.ngc", file_out="t.nc", source="linuxcnc",
                          target="fanuc", setup=SETUP)
    assert report.ok, report.summary()


def test_a_computed_coordinate_under_an_offset_is_a_located_error() -> None:
    text = "G21 G90 G17\nG10 L1 P3 X0.5 Y1\nT3 M6\nG43 H3\n#1=4\nG0 X#1 Y6 Z7\nM2\n"
    with pytest.raises(ErrorList) as info:
        to("fanuc", text)
    error = info.value.errors[0]
    assert error.location is not None and "across the spindle" in str(error)



INCREMENTS_BEFORE_THE_FIRST_ENTRY = "G21 G17 G91\nG10 L1 P3 X1 Y2 Z10\nT3 M6\nG43 H3\nG0 X5 Y6\nG90 G0 X5 Y6\nM2\n"
INCHES_BEFORE_THE_FIRST_ENTRY = "G20 G90 G17\nG10 L1 P3 X0.1 Y0.05 Z0.5\nT3 M6\nG43 H3\nG0 X1 Y1 Z1\nG21\nG0 X10 Y10 Z10\nM2\n"
"""The units and the distance mode set before a program's first entry are in force at it and after it (the step once
followed them only from its first entry on: the increments got the offset, the entry's inches were taken for mm)."""


@needs_rs274
def test_increments_set_before_the_first_entry_move_as_rs274_runs_them() -> None:
    text = INCREMENTS_BEFORE_THE_FIRST_ENTRY  # (Fanuc refuses a G10 under G91: grbl)
    theirs = machine_points(rs274.run_rs274(text, tool_table=TOOL_TABLE), 1.0)
    ours = controlled(to("grbl", text), "grbl")
    assert len(ours) == len(theirs)
    for a, b in zip(ours, theirs):
        assert max(abs(p - q) for p, q in zip(a, b)) <= TOLERANCE_MM, (a, b)


def test_an_entry_in_inches_keeps_its_size_after_g21_hand_derived() -> None:
    # entry 3: X0.1 Y0.05 (inches: 2.54 mm, 1.27 mm); after G21, X10 Y10 is X12.54 Y11.27
    out = to("fanuc", INCHES_BEFORE_THE_FIRST_ENTRY)
    assert out.splitlines()[-2:] == ["G00 X12.54 Y11.27 Z10.", "M02"], out
    report = verify_lines(_lines(INCHES_BEFORE_THE_FIRST_ENTRY), _lines(out), file_in="t.ngc", file_out="t.nc",
                          source="linuxcnc", target="fanuc", setup=SETUP)
    assert report.ok, report.summary()
