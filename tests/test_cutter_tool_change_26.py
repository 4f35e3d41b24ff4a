"""A tool change and cutter compensation in one block (issue 26): the translation refuses what the simulation
refuses, by one check (``CutterRadius.tool_change``), and both follow rs274's order of execution.

[V] rs274 2.9 (run here, ``tests/support/rs274``): ``G41 M6 T1`` changes the tool, then turns compensation on;
``G40 M6 T1`` under G41 is "Cannot change tools with cutter radius compensation on" (the tool change comes
first); ``T1 M6`` .. ``G41 M6 T2`` compensates by T1's radius. Expected points are derived by hand: from (0, 0)
along +X to (10, 0) with the tool on the left, then +Y, an inside corner: LinuxCNC's entry move ends where the
offset lines meet, (10 - r, r)."""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.plugins import default_registry
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274

RADII = {1: 1.0, 2: 2.0}
TABLE = "T1 P1 D0.0787401575 Z0\nT2 P2 D0.157480315 Z0\n"
"""The same radii for rs274 (diameters in inches)."""


def _setup() -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {str(n): ToolData(number=n, length=0.0, radius=r) for n, r in RADII.items()}
    return setup


def _program(change: str) -> str:
    return f"G21 G17 G90 G94\nT1 M6\nG0 X0 Y0 Z5\n{change}\nG1 X10 Y0 F100\nY10\nG40 X0 Y0\nM2\n"


def _translate(text: str, target: str) -> str:
    if target not in default_registry().dialects:
        pytest.skip(f"the {target} plugin is not installed")
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.ngc", source="linuxcnc", target=target, setup=_setup(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _feeds(text: str, dialect: str) -> list[tuple[float, float]]:
    events = toolpath_events(io.StringIO(text), file="t", dialect=dialect, setup=_setup())
    moves = [{**e, **e.get("controlled", {})} for e in events if e.get("move") == "feed"]
    return [(round(m["x"], 6), round(m["y"], 6)) for m in moves]


def _rs274_feeds(text: str) -> list[tuple[float, float]]:
    lines = rs274.run_rs274(text, tool_table=TABLE)
    found = [re.search(r"STRAIGHT_FEED\(([-\d.]+), ([-\d.]+),", line) for line in lines]
    return [(float(m.group(1)), float(m.group(2))) for m in found if m]


def _close(got: list[tuple[float, float]], expected: list[tuple[float, float]], tolerance: float) -> None:
    assert len(got) == len(expected), got
    for (x, y), (ex, ey) in zip(got, expected):
        assert abs(x - ex) <= tolerance and abs(y - ey) <= tolerance, (got, expected)


@pytest.mark.parametrize("change, r", [("G41 M6 T1", 1.0), ("G41 M6 T2", 1.0), ("M6 T2\nG41", 2.0)])
@pytest.mark.parametrize("target", ["grblhal", "grbl"])
def test_compensation_turned_on_in_the_block_of_a_tool_change_is_written_as_its_moves(change: str, r: float,
                                                                                     target: str) -> None:
    """The tool changes first, then compensation starts; in the block of the change it reads the radius of the
    tool before it (T1's), after it the new tool's."""
    text = _program(change)
    hand = [(10 - r, r), (10 - r, 10.0), (0.0, 0.0)]
    _close(_feeds(text, "linuxcnc"), hand, 1e-9)
    if rs274.available():
        _close(_rs274_feeds(text), hand, 1e-3)
    out = _translate(text, target)
    assert "G41" not in out, out
    _close(_feeds(out, target), hand, 1e-6)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.ngc", file_out="out", source="linuxcnc",
                          target=target, setup=_setup())
    assert report.ok, report.summary()


@pytest.mark.parametrize("change", ["G40 M6 T1", "G40 G0 X0 Y0 M6 T1"])
def test_a_tool_change_with_compensation_in_force_is_refused_where_the_simulation_refuses_it(change: str) -> None:
    text = "G21 G17 G90 G94\nT1 M6\nG0 X0 Y0 Z5\nG41 G1 X10 Y0 F100\nY10\n" + change + "\nG0 X0 Y0\nM2\n"
    message = "in.ngc:6:1: error: a tool change with cutter compensation on cannot be run (cancel it first)"
    with pytest.raises(ErrorList) as simulated:
        list(toolpath_events(io.StringIO(text), file="in.ngc", dialect="linuxcnc", setup=_setup()))
    assert str(simulated.value.errors[0]) == message
    with pytest.raises(ErrorList) as translated:
        _translate(text, "grblhal")
    assert [str(e) for e in translated.value.errors] == [message]
    if rs274.available():
        with pytest.raises(rs274.RS274Error) as theirs:
            rs274.run_rs274(text, tool_table=TABLE)
        assert "Cannot change tools with cutter radius compensation on" in str(theirs.value)
