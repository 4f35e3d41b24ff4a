"""Defects: Siemens ``T1 D1`` is written for LinuxCNC as ``G43 H01 T1`` -- the length offset before the tool
change on the same line? In NGC the order of the words is not the order of execution: a line runs its tool
select (T), then its tool change (M6), then its length offset (G43) [V: LinuxCNC G-code overview "Order of
Execution", items 7 (T), 8 (M6), 15 (G43/G49); rs274 prints ``SELECT_TOOL`` before ``USE_TOOL_LENGTH_OFFSET``
for ``G43 H01 T1``]. And ``G43 H01`` names its register: the length of table entry 1 applies whatever tool
is in the spindle (rs274 prints entry 1's length with no tool loaded), as the source's ``D1`` selects
set-up register 1 (``postproc.isg_family.tool_data``). So the written line is right; these tests prove it
against rs274: the source's controlled points (postproc's Siemens toolpath, set-up lengths) equal the
written program's in rs274 (its programmed Z plus the length of its last ``USE_TOOL_LENGTH_OFFSET``), with
the length changed before the change, between T and M6, and on the M6 line itself.
Lengths are whole hundredths of an inch (exact in the inch table rs274 reads and in its 4 decimals of mm)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, run_rs274, straight_moves_with_length
from tests.support.tools import with_tools

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

LENGTHS_INCH = {1: 2.0, 2: 0.75, 3: 1.25}
SETUP = with_tools(lengths={n: v * 25.4 for n, v in LENGTHS_INCH.items()})

PROGRAMS = {
    "change on the next line": "G17 G90 G71\nT1 D1\nM6\nG0 X10 Y10 Z5\nG1 Z-1 F100\nG1 X20\nM30\n",
    "moves between T and M6": "G17 G90 G71\nT1 D1\nM6\nG0 X10 Y10 Z5\nT2 D2\nG0 X15 Z40\nM6\nG1 Z-1 F100\n"
                              "G1 X20\nM30\n",
    "T, D and M6 on one line": "G17 G90 G71\nG0 X0 Y0 Z50\nT3 D3 M6\nG0 X5 Z20\nT1 D1 M6\nG1 Z2 F200\nM30\n",
    "a D alone, then no length": "G17 G90 G71\nT2 D2\nM6\nG0 X1 Y2 Z30\nD1\nG1 Z10 F100\nD0\nG1 Z12\nM30\n",
}


def _written(text: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.mpf", source="siemens", target="linuxcnc", setup=SETUP,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _source_points(text: str) -> list[tuple[float, float, float]]:
    """The controlled points of the source's moves (mm)."""
    out = []
    for ev in toolpath_events(io.StringIO(text).readlines(), file="in.mpf", dialect="siemens", setup=SETUP,
                              diagnostics=Diagnostics(warn_stream=io.StringIO())):
        if "move" in ev:
            c = ev.get("controlled", ev)
            out.append((round(float(c["x"]), 4), round(float(c["y"]), 4), round(float(c["z"]), 4)))
    return out


def _rs274_points(text: str) -> tuple[list[tuple[float, float, float]], list[str]]:
    """rs274's controlled points (programmed point, Z plus the length in force) and its calls."""
    table = "".join(f"T{n} P{n} Z{v} D0.1\n" for n, v in LENGTHS_INCH.items())
    calls = run_rs274(text, tool_table=table)
    out: list[tuple[float, float, float]] = []
    for x, y, z, _, length in straight_moves_with_length(calls):
        point = (round(x, 4), round(y, 4), round(z + length, 4))
        if not out or out[-1] != point:  # rs274 prints a move that moves nothing; a toolpath leaves it out
            out.append(point)
    return out, calls


def test_t_and_its_length_on_one_line_run_select_then_length() -> None:
    """The line in question, and rs274's order of execution for it."""
    written = _written(PROGRAMS["change on the next line"])
    assert "G43 H01 T1\nM6\n" in written
    _, calls = _rs274_points(written)
    names = [c.split()[1].split("(")[0] for c in calls
             if any(k in c for k in ("SELECT_TOOL", "USE_TOOL_LENGTH", "CHANGE_TOOL(", "STRAIGHT_"))]
    assert names[:4] == ["SELECT_TOOL", "USE_TOOL_LENGTH_OFFSET", "CHANGE_TOOL", "STRAIGHT_TRAVERSE"]
    assert "USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 50.8000," in "\n".join(calls)  # entry 1's 2 inch, no tool loaded


def test_hand_derived_points() -> None:
    """T1 (50.8 mm) then G0 X10 Y10 Z5: the controlled point is 50.8 above the programmed one."""
    assert _source_points(PROGRAMS["change on the next line"]) == [
        (10.0, 10.0, 55.8), (10.0, 10.0, 49.8), (20.0, 10.0, 49.8)]


@pytest.mark.parametrize("name", sorted(PROGRAMS))
def test_the_written_program_moves_as_the_source(name: str) -> None:
    text = PROGRAMS[name]
    theirs, _ = _rs274_points(_written(text))
    ours = _source_points(text)
    assert theirs[-len(ours):] == ours, f"{name}\n{_written(text)}"
