"""A turret lathe's T naming the station already at the cutting position (Fanuc T ``T0200`` after ``T0202``:
station 2, offset 00 = the offset cancelled) indexes nothing: the simulation counts no tool change there, and
a target that changes tools with M6 (LinuxCNC, grblHAL, grbl) gets only the offset's change, never ``T2 M6``
(LinuxCNC's M6 always runs a change and stops the spindle first [V: ``interp_convert.cc``
``convert_tool_change``; rs274 prints ``STOP_SPINDLE_TURNING`` and ``CHANGE_TOOL``]; grbl's is a pause).
A turret target (GSK) keeps the word. Expected points and lines are worked out by hand in the comments;
rs274 runs the LinuxCNC translation."""

from __future__ import annotations

import io
import re
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274

TABLE_INCH = {2: (0.1, 0.2), 3: (-0.05, 0.3)}
"""rs274's table: X (a radius) and Z in inches."""


def _setup() -> MachineSetup:
    """The same offsets in the set-up, mm, X a diameter: tool 2 X 5.08 Z 5.08, tool 3 X -2.54 Z 7.62."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe"))
    setup.controller.tool_table = True  # (a grblHAL build with its tool table; the others ignore it)
    setup.tools = {str(n): ToolData(number=n, x=round(2 * x * 25.4, 6), z=round(z * 25.4, 6))
                   for n, (x, z) in TABLE_INCH.items()}
    return setup


PROGRAM = ("O0001\nG21 G18 G98\nG0 X100. Z50.\nT0202\nM03 S1000\nG0 X50. Z5.\nG1 X40. F200.\nT0200\nG0 Z10.\n"
           "M05\nT0300\nG0 X60.\nT0303\nG0 X70.\nM30\n")
"""T0200 and T0303 name the station in position; T0300 (after M05) indexes to station 3."""

CONTROLLED = [(100.0, 50.0), (55.08, 10.08), (45.08, 10.08), (40.0, 10.0), (60.0, 10.0), (67.46, 17.62)]
"""By hand: offset 2 (+5.08 on the diameter, +5.08 in Z) from the X50 Z5 move; cancelled (T0200) from the Z10
move; offset 3 (-2.54, +7.62) from the X70 move (T0303)."""


def _events(text: str, dialect: str) -> list[dict[str, Any]]:
    return list(toolpath_events(io.StringIO(text), file="l.nc", dialect=dialect, setup=_setup()))


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="l.nc", source="fanuc", target=target, setup=_setup(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def test_the_simulation_counts_an_index_only_where_the_station_changes() -> None:
    events = _events(PROGRAM, "fanuc")
    assert [(e["line"], e["number"]) for e in events if e.get("event") == "tool"] == [(4, 2), (11, 3)]
    moves = [e.get("controlled", e) for e in events if "move" in e]
    assert [(round(m["x"], 4), round(m["z"], 4)) for m in moves] == CONTROLLED


@pytest.mark.parametrize("target", ["linuxcnc", "grblhal"])
def test_an_m6_lathe_gets_the_offset_change_alone(target: str) -> None:
    """T0200 with the spindle turning: no refusal (nothing indexes), no ``T2 M6``; its cancel goes to the next
    move with the X the tool stands at (LinuxCNC applies an offset where the axis is programmed). T0303:
    ``G43 H03`` on the X70 move, with Z10."""
    lines = _translate(PROGRAM, target).splitlines()
    assert [line for line in lines if "M6" in line] == ["T2 M6", "G49 T3 M6"]
    assert "G49 G0 Z10. X40." in lines
    assert "G43 H03 G0 X70. Z10." in lines
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO("\n".join(lines) + "\n"), file_in="l.nc",
                          file_out="out", source="fanuc", target=target, setup=_setup(), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_grbl_gets_no_pause_for_the_offset_cancel() -> None:
    """grbl's tool change is a pause (M0): only the two indexes make one."""
    written = _translate(PROGRAM, "grbl")
    assert re.findall(r"^T(\d+) M0", written, re.M) == ["2", "3"]


def test_a_turret_target_keeps_the_word() -> None:
    written = _translate(PROGRAM, "gsk")
    assert "\nT0200\n" in written and "\nT0303\n" in written


def test_an_index_with_the_spindle_turning_is_still_refused() -> None:
    """T0300 while the spindle turns is an index: towards an M6 control it is refused, as before."""
    text = PROGRAM.replace("M05\n", "")
    with pytest.raises(ErrorList, match=r"l.nc:10:1: error: a turret index \(T0300\) with the spindle turning"):
        translate(io.StringIO(text), io.StringIO(), file="l.nc", source="fanuc", target="linuxcnc", setup=_setup(),
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))


_MOVE = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED)\(([^)]*)\)")
_OFFSET = re.compile(r"USE_TOOL_LENGTH_OFFSET\(\s*([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)")


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_translation_with_two_changes_and_the_same_points() -> None:
    """rs274 (its table the set-up's offsets) changes tools twice, keeps the spindle turning across T0200, and
    runs the hand-derived controlled points."""
    table = "".join(f"T{n} P{n} X{x} Z{z} D0\n" for n, (x, z) in TABLE_INCH.items())
    calls = run_rs274(_translate(PROGRAM, "linuxcnc"), tool_table=table)
    assert sum("CHANGE_TOOL(" in c for c in calls) == 2  # (it prints the table's slot, not the tool)
    ox = oz = 0.0
    turning = False
    points: list[tuple[float, float]] = []
    turning_at: dict[tuple[float, float], bool] = {}
    for call in calls:
        if "START_SPINDLE_CLOCKWISE" in call or "STOP_SPINDLE_TURNING" in call:
            turning = "START" in call
        offset = _OFFSET.search(call)
        if offset:
            ox, oz = float(offset.group(1)), float(offset.group(3))
            continue
        move = _MOVE.search(call)
        if move:
            x, _, z = (float(v) for v in move.group(2).split(",")[:3])
            point = (round(2 * (x + ox), 4), round(z + oz, 4))
            if not points or points[-1] != point:
                points.append(point)
                turning_at[point] = turning
    assert points == CONTROLLED
    assert turning_at[(40.0, 10.0)], "the spindle still turns at the move after T0200 (no M6 stopped it)"
