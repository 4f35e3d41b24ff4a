"""Issue 29: a Fanuc T move in machine coordinates (``G53``) written for GSK, which has none, as the same move in
work coordinates (``postproc.lowering.machine_positions``).

Expected values by hand, from the rule the simulation and the controller share: the programmed point is the machine
point less the active work system's offset, the external offset and the lathe tool offset the T code put in force
(X a diameter on both sides of the subtraction, as the set-up gives it). A property over random offsets, work
systems and tools: the written line is that point, and ``verify`` finds the GSK program moving where the source
does (the source's G53 simulated as a machine move, the GSK line as a work move).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine import ToolData, WorkOffsetData
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.verify import verify_lines

SETUP = Path(__file__).resolve().parents[1] / "examples" / "setups" / "fanuc_0i_tf.xml"

halves = st.integers(-1200, 1200).map(lambda n: n / 2.0)
"""Millimetres on a 0.5 grid: every difference below is exact in binary and in three decimals."""


def machine(offsets: dict[int, tuple[float, float]], tools: dict[int, tuple[float, float]]) -> MachineSetup:
    setup = load_setup(SETUP)
    setup.work_offsets = {str(n): WorkOffsetData(number=n, x=x, z=z) for n, (x, z) in offsets.items()}
    setup.tools = {str(n): ToolData(number=n, x=x, z=z) for n, (x, z) in tools.items()}
    return setup


def gsk(text: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="gsk", setup=setup)
    return out.getvalue()


def number(word: str) -> float:
    return float(word[1:])


@settings(max_examples=40, deadline=None)
@given(system=st.sampled_from([1, 2]), tool=st.sampled_from([0, 1, 2]), external=st.booleans(),
       values=st.lists(halves, min_size=10, max_size=10), target=st.tuples(halves, halves))
def test_a_machine_move_is_written_where_the_machine_goes(system: int, tool: int, external: bool,
                                                          values: list[float], target: tuple[float, float]) -> None:
    offsets = {1: (values[0], values[1]), 2: (values[2], values[3])}
    if external:
        offsets[0] = (values[4], values[5])
    tools = {1: (values[6], values[7]), 2: (values[8], values[9])}
    text = (f"O1000\nG21 G98\nG{53 + system} T{tool:02d}{tool:02d}\nM03 S500\nG00 X100. Z50.\n"
            f"G00 G53 X{target[0]:.1f} Z{target[1]:.1f}\nG00 X80. Z20.\nM30\n")
    setup = machine(offsets, tools)
    out = gsk(text, setup)
    lines = out.splitlines()
    line = lines[lines.index("G00 X100. Z50.") + 1]
    words = line.split()
    shift_x = offsets[system][0] + offsets.get(0, (0.0, 0.0))[0] + (tools[tool][0] if tool else 0.0)
    shift_z = offsets[system][1] + offsets.get(0, (0.0, 0.0))[1] + (tools[tool][1] if tool else 0.0)
    assert "G53" not in out
    assert number(words[1]) == pytest.approx(target[0] - shift_x, abs=1e-9), (line, offsets, tools)
    assert number(words[2]) == pytest.approx(target[1] - shift_z, abs=1e-9), (line, offsets, tools)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="out.nc", source="fanuc",
                          target="gsk", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_by_hand() -> None:
    """G55 at X-300 Z-400, the external offset X10 Z-5, T0202 at X-20 Z15 (mm, X diameters): ``G53 X0 Z-10.`` is
    X 0 - (-300 + 10 - 20) = 310, Z -10 - (-400 - 5 + 15) = 380."""
    setup = machine({2: (-300.0, -400.0), 0: (10.0, -5.0)}, {2: (-20.0, 15.0)})
    out = gsk("O1000\nG21 G98\nG55 T0202\nG00 X100. Z50.\nG00 G53 X0 Z-10.\nM30\n", setup)
    assert "G00 X310. Z380." in out.splitlines()


@pytest.mark.parametrize("offsets, text, message", [
    ({}, "O1000\nG21 G98\nG00 X100. Z50.\nG00 G53 X0 Z0\nM30\n",
     "the set-up gives work system 1 no offset for X (<WorkOffsets><Offset number=\"1\" x=...>) and the program sets "
     "none"),
    ({1: (-200.0, -300.0)}, "O1000\nG21 G98\nG56\nG00 X100. Z50.\nG00 G53 Z0\nM30\n",
     "the set-up gives work system 3 no offset for Z (<WorkOffsets><Offset number=\"3\" z=...>) and the program sets "
     "none"),
    ({1: (-200.0, -300.0)}, "O1000\nG21 G98\nT0303\nG00 X100. Z50.\nG00 G53 X0\nM30\n",
     "the set-up gives tool offset 3 no X and Z (<Tools><Tool number=\"3\" x=... z=...>)"),
])
def test_what_the_set_up_lacks_is_named(offsets: dict[int, tuple[float, float]], text: str, message: str) -> None:
    setup = machine(offsets, {1: (0.0, 0.0)})
    with pytest.raises(ErrorList) as caught:
        gsk(text, setup)
    line = text.count("\n", 0, text.index("G53")) + 1
    assert [str(e) for e in caught.value.errors] == [
        f"in.nc:{line}:1: error: the gsk dialect has no motion in machine coordinates, and this move cannot be put in "
        f"work coordinates: {message}"]


def test_a_copy_for_fanuc_keeps_g53() -> None:
    """Fanuc has the move: nothing is resolved for it (the step is GSK's)."""
    text = "O1000\nG21 G98\nG00 X100. Z50.\nG00 G53 X0 Z0\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="fanuc", setup=load_setup(SETUP))
    assert out.getvalue() == text


def test_a_linuxcnc_lathe_tool_offset_counts_as_the_turret_offset_it_becomes(tmp_path: Path) -> None:
    """LinuxCNC's ``T2 M6 G43 H2`` reaches GSK as ``T0202``: the G53 move under it is less tool 2's offset, and
    after ``G49`` (``T0000``) less none. By hand (mm, X diameters; G54 X-300 Z-400, tool 2 X-20 Z15):
    ``G53 X0 Z0`` is X 0 - (-300 - 20) = 320, Z 0 - (-400 + 15) = 385; ``G53 X0 Z-10`` without the tool's offset
    is X 300, Z -10 + 400 = 390."""
    path = tmp_path / "lathe.xml"
    path.write_text('<MachineSetup name="t" dialect="linuxcnc"><Input machineType="lathe"/><Machine axes="XZ"/>'
                    '<WorkOffsets><Offset number="1" x="-300.0" z="-400.0"/></WorkOffsets>'
                    '<Tools><Tool number="2" x="-20.0" z="15.0"/></Tools></MachineSetup>')
    setup = load_setup(path)
    text = ("G7 G18 G21 G90 G94\nT2 M6 G43 H2\nG0 X100 Z50\nG53 G0 X0 Z0\nT0 M6 G49\nG0 X100 Z50\n"
            "G53 G0 X0 Z-10\nM2\n")
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.ngc", source="linuxcnc", target="gsk", setup=setup)
    lines = out.getvalue().splitlines()
    assert "T0202" in lines and "G00 X320. Z385." in lines and "G00 X300. Z390." in lines, lines
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="in.ngc", file_out="out.nc",
                          source="linuxcnc", target="gsk", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
