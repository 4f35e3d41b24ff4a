"""LinuxCNC's G41/G42 without D takes the radius of the tool in the spindle [K: LinuxCNC G-code reference;
V: rs274]. Reading fills in that tool's number as the register, so translation and simulation take the
same radius; before the program's first tool change the tool is the machine's, which only the set-up's
``<Machine startTool>`` can say: without it both refuse the block, at the same place.

Expected paths: rs274 runs the program (standalone it starts with no tool loaded, so a ``T1 M6`` line
stands in for a set-up's ``startTool="1"``); the Fanuc output, whose compensation is not simulated, goes
back to LinuxCNC for rs274.
"""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.groups import MachineSettings
from postproc.setup.machine import ToolData
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

BODY = "G41 G1 X10 Y0 F100\nG1 X20\nG40 G1 X30 Y-5\nM2\n"
HEAD = "G21 G0 X0 Y0 Z10\n"
RADIUS_MM = 2.54
RS274_TOOLS = "T1 P1 D0.2 Z0 ;\n"
"""rs274's standalone table is in inches: tool 1 of 0.2 in diameter is the 2.54 mm radius."""


def _setup(start_tool: int | None = None) -> MachineSetup:
    setup = MachineSetup()
    setup.machine = MachineSettings(start_tool=start_tool)
    setup.tools = {"1": ToolData(number=1, length=0.0, radius=RADIUS_MM)}
    return setup


def _path(text: str, setup: MachineSetup, dialect: str = "linuxcnc") -> list[tuple[Any, ...]]:
    """The controlled points (the compensated path)."""
    events = toolpath_events(io.StringIO(text), file="c.ngc", dialect=dialect, setup=setup)
    points = [{**e, **e.get("controlled", {})} for e in events if "move" in e]
    return [(p["move"], round(p["x"], 3), round(p["y"], 3)) for p in points]


def _rs274(text: str) -> list[tuple[Any, ...]]:
    return [(e["move"], round(e["x"], 3), round(e["y"], 3))
            for e in canonical_moves(run_rs274(text, tool_table=RS274_TOOLS), start=(0.0, 0.0, 0.0)) if "move" in e]


def _translate(text: str, setup: MachineSetup, target: str = "fanuc") -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="c.ngc", source="linuxcnc", target=target, setup=setup)
    return out.getvalue()


def _back(fanuc: str) -> str:
    """Fanuc's compensation is not simulated: its output goes back to LinuxCNC for rs274 to run."""
    out = io.StringIO()
    translate(io.StringIO(fanuc), out, file="c.nc", source="fanuc", target="linuxcnc", setup=_setup())
    return out.getvalue()


def test_without_a_known_spindle_tool_translation_and_simulation_refuse_the_same_block() -> None:
    program = HEAD + BODY
    with pytest.raises(ErrorList) as translated:
        _translate(program, _setup())
    with pytest.raises(ErrorList) as simulated:
        _path(program, _setup())
    first = str(translated.value.errors[0])
    assert first == str(simulated.value.errors[0])
    assert first.startswith("c.ngc:2:1: error: cutter compensation without D takes the radius of the tool in the "
                            "spindle"), first


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_after_a_tool_change_the_register_is_that_tools_for_every_target() -> None:
    program = HEAD + "T1 M6\n" + BODY
    expected = _rs274(program)
    assert expected[1] == ("feed", 10.0, RADIUS_MM)  # left of a move along +X: offset to +Y
    assert _path(program, _setup()) == expected
    fanuc = _translate(program, _setup())
    assert "G41 D01 G01 X10. Y0. F100.\n" in fanuc, fanuc
    assert _rs274(_back(fanuc)) == expected


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_set_ups_start_tool_is_the_spindle_tool_before_any_change() -> None:
    expected = _rs274(HEAD + "T1 M6\n" + BODY)
    program = HEAD + BODY
    assert _path(program, _setup(start_tool=1)) == expected
    fanuc = _translate(program, _setup(start_tool=1))
    assert "G41 D01 " in fanuc and _rs274(_back(fanuc)) == expected
    assert _translate(program, _setup(start_tool=1), "linuxcnc") == program  # its own dialect: as written


def test_a_fanuc_g41_without_d_takes_the_register_in_force_written_for_linuxcnc() -> None:
    """Fanuc's D is modal [K]: its bare G41 compensates by the D programmed last, which LinuxCNC's bare G41
    would not (it takes the spindle tool): the register is written, and refused where none is known."""
    fanuc = ("G21 G90 G0 X0. Y0. Z10.\nG41 D01 G1 X10. F100.\nG40 G1 X20. Y-5.\nG41 G1 X30. Y0.\nG40 G1 X40. Y-5.\n"
             "M30\n")
    out = io.StringIO()
    translate(io.StringIO(fanuc), out, file="f.nc", source="fanuc", target="linuxcnc")
    assert "G41 D01 G1 X30. Y0.\n" in out.getvalue(), out.getvalue()
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO("G21 G90 G0 X0. Y0. Z10.\nT1 M06\nG41 G1 X10. F100.\nM30\n"), io.StringIO(),
                  file="f.nc", source="fanuc", target="linuxcnc")
    assert str(caught.value.errors[0]).startswith("f.nc:3:1: error: cutter compensation without its register "
                                                  "takes the register programmed last, and none was"), caught.value
