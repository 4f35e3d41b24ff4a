"""Issue 29: a Fanuc T or GSK coordinate setting (``G50 X.. Z..``) translated to LinuxCNC as ``G92 X.. Z..``
(``postproc.rs274.ngc_lathe_writer.NgcLatheWriting.coordinate_set_words``).

Independent of the tool: the machine positions are derived here by hand from the rule "the tool's present point
gets the given coordinates, the tool does not move" (DIALECTS.md 1.1/1.2, G50 coordinate setting), and rs274 runs
the translation: its program coordinates plus the ``SET_G92_OFFSET`` in force must be those machine positions
(X as a radius, as rs274 prints it in G7).
"""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274

ROOT = Path(__file__).resolve().parents[1]
SETUP = ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"

PROGRAM = """O1000
G21 G98
M03 S500
G00 X40. Z2.
G50 X100. Z50.
G01 X90. Z40. F100.
G50 X60.
G01 X50. Z30.
G00 X100. Z50.
M30
"""
MACHINE = [(20.0, 2.0), (15.0, -8.0), (10.0, -18.0), (35.0, 2.0)]
"""By hand, radii (mm), the work offset zero: the rapid to X40 Z2 stands at (20, 2); G50 X100 Z50 names that point
(50, 50), so the frame is the machine less (-30, -48); X90 Z40 is (45 - 30, 40 - 48) = (15, -8); G50 X60 names
X 30 there, the X shift becoming 15 - 30 = -15 (Z's stays); X50 Z30 is (25 - 15, 30 - 48) = (10, -18); X100 Z50 is
(50 - 15, 50 - 48) = (35, 2)."""


def linuxcnc(text: str, source: str = "fanuc") -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target="linuxcnc", setup=load_setup(SETUP))
    return out.getvalue()


@pytest.mark.parametrize("source", ["fanuc", "gsk"])
def test_g50_coordinate_setting_is_written_as_g92(source: str) -> None:
    ngc = linuxcnc(PROGRAM, source)
    lines = [line.strip() for line in ngc.splitlines()]
    assert "G92 X100. Z50." in lines and "G92 X60." in lines, ngc
    assert any(line.startswith("G18 G7") for line in lines)  # X is a diameter there, as in the source
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc", source=source,
                          target="linuxcnc", setup=load_setup(SETUP), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_grblhal_gets_the_same_g92() -> None:
    """grblHAL halves every X axis word in diameter mode before it runs the block's command, G92 included, and
    its G92 is grbl's (the offset that makes the current point read the words given) [V: grblHAL core
    ``gcode.c``, ``if(gc_state.modal.diameter_mode && bit_istrue(axis_words.mask, bit(X_AXIS)))``]."""
    out = io.StringIO()
    machine = load_setup(SETUP)
    translate(io.StringIO(PROGRAM), out, file="in.nc", source="fanuc", target="grblhal", setup=machine)
    lines = [line.strip() for line in out.getvalue().splitlines()]
    assert "G92 X100. Z50." in lines and "G92 X60." in lines, out.getvalue()
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(out.getvalue()), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target="grblhal", setup=machine, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_moves_the_machine_where_g50_would() -> None:
    calls = run_rs274(linuxcnc(PROGRAM), tool_table="".join(f"T{t} P{t} X0 Z0 D0 ;\n" for t in range(1, 10)))
    offset = (0.0, 0.0)
    machine: list[tuple[float, float]] = []
    for call in calls:
        name, _, args = call.partition("(")
        numbers = [float(v) for v in re.findall(r"-?\d+\.\d+", args)]
        if name.endswith("SET_G92_OFFSET"):
            offset = (numbers[0], numbers[2])
        elif name.endswith("STRAIGHT_TRAVERSE") or name.endswith("STRAIGHT_FEED"):
            machine.append((numbers[0] + offset[0], numbers[2] + offset[1]))
    assert len(machine) == len(MACHINE), machine
    for got, expected in zip(machine, MACHINE):
        assert got == pytest.approx(expected, abs=1e-4), machine


def test_a_coordinate_setting_before_a_machine_move_leaves_the_gsk_resolution_refused() -> None:
    """After a G50 the frame holds a shift only the run knows (where the tool stood): a G53 move cannot be put
    in work coordinates from the set-up's offsets (``postproc.lowering.machine_positions``)."""
    text = "O1000\nG21 G98\nG00 X40. Z2.\nG50 X100. Z50.\nG00 G53 X0 Z0\nM30\n"
    machine = load_setup(SETUP)
    from postproc.setup.machine import WorkOffsetData
    machine.work_offsets = {"1": WorkOffsetData(number=1, x=-200.0, z=-300.0)}
    from postproc.errors import ErrorList
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(text), io.StringIO(), file="in.nc", source="fanuc", target="gsk", setup=machine)
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:5:1: error: the gsk dialect has no motion in machine coordinates, and this move cannot be put in work "
        "coordinates after a coordinate setting or a frame change in the program (its values are the run's)"]
    out = io.StringIO()
    translate(io.StringIO(text.replace("G50 X100. Z50.\n", "")), out, file="in.nc", source="fanuc", target="gsk",
              setup=machine)
    assert "G00 X200. Z300." in out.getvalue()  # 0 - (-200) (X a diameter), 0 - (-300): by hand


STANDING = "G21 G0 X40. Z5.\nS500 M3\nG50 X20.\nX20.\nG1 X10. F0.2\nM30\n"
"""Found by the fuzz (variable words, Fanuc lathe to LinuxCNC): a move to the point a G50 just named."""


def _machine_moves(calls: list[str]) -> list[tuple[float, float]]:
    """rs274's straight moves as machine points (program coordinates plus the G92 offset in force), X a radius."""
    offset = (0.0, 0.0)
    machine: list[tuple[float, float]] = []
    for call in calls:
        name, _, args = call.partition("(")
        numbers = [float(v) for v in re.findall(r"-?\d+\.\d+", args)]
        if name.endswith("SET_G92_OFFSET"):
            offset = (numbers[0], numbers[2])
        elif name.endswith("STRAIGHT_TRAVERSE") or name.endswith("STRAIGHT_FEED"):
            machine.append((numbers[0] + offset[0], numbers[2] + offset[1]))
    return machine


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_move_to_the_point_a_g92_names_stands_still_on_both_sides() -> None:
    """rs274 runs the translation's ``G92 X20.`` then ``G0 X20.``: the machine stays where it stood, so the
    simulation of the LinuxCNC program counts the moves rs274 makes (the Fanuc side's G50 drops that move too);
    before, the lathe simulation ignored the G92 and counted a rapid that verify called a structure change."""
    ngc = linuxcnc(STANDING)
    assert "G92 X20." in [line.strip() for line in ngc.splitlines()], ngc
    machine = _machine_moves(run_rs274(ngc))
    moving = [b for a, b in zip(machine, machine[1:]) if b != pytest.approx(a, abs=1e-6)]
    assert len(machine) == 3 and len(moving) == 1, machine  # the G0 X20. stands still, the feed moves
    events = [e for e in toolpath_events(io.StringIO(ngc), file="out.ngc", dialect="linuxcnc",
                                         setup=load_setup(SETUP)) if "move" in e]
    assert len(events) == 1 + len(moving), events  # the first rapid, then the moves rs274 makes
    assert (events[-1]["x"], events[-1]["z"]) == (10, 5)  # X10. read from the point G92 named X20.
    report = verify_lines(io.StringIO(STANDING), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=load_setup(SETUP), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


@pytest.mark.parametrize("code, kind", [("G92.1", "origin clear"), ("G92.2", "origin suspend"), ("G52 X5.", "local")])
def test_a_frame_command_a_lathe_simulation_does_not_model_is_refused(code: str, kind: str) -> None:
    """The lathe simulation keeps program coordinates: a command that moves them by an offset it does not keep is
    a located error, not a toolpath in other coordinates."""
    text = f"G18 G7\nG21 G95 G0 X40. Z5.\nS500 M3\nG92 X20.\n{code}\nG0 X30.\nM2\n"
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(text), file="p.ngc", dialect="linuxcnc", setup=load_setup(SETUP)))
    assert [str(e) for e in caught.value.errors] == [
        f"p.ngc:5:1: error: {code} ({kind}) cannot be simulated on a lathe (its frame is not modelled there)"]


COMPUTED = """G21 G0 X40. Z5.
S500 M3
#1=30.
#2=2.
#100=30.
G50 X[#1*1] Z[#2*1]
G0 X[0+#100] Z2.
G4 P100
G1 X10. F0.2
G50 X20. Z[5.]
G0 X20. Z5.
G0 X10. Z5.
M30
"""
"""The fuzz's whole program: it computes after the spindle starts, and feeds per revolution."""
COMPUTED_MACHINE = [(20.0, 5.0), (20.0, 5.0), (10.0, 5.0), (10.0, 5.0), (5.0, 5.0)]
"""By hand, radii: X40 Z5 stands at (20, 5); G50 X30 Z2 names that point (15, 2), a shift of (5, 3); X30 Z2 is
there; X10 is (5 + 5, 2 + 3); G50 X20 Z5 names (10, 5) so, the shift (0, 0); X20 Z5 stays, X10 Z5 is (5, 5)."""


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_lathe_program_computing_after_its_spindle_start_stays_symbolic() -> None:
    """The symbolic text is read back from the spindle where the program stands (it was read from a stopped one,
    so its feed per revolution was refused and the program flattened), and rs274 runs it as the G50s would."""
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    translate(io.StringIO(COMPUTED), out, file="in.nc", source="fanuc", target="linuxcnc", setup=load_setup(SETUP),
              diagnostics=diagnostics)
    ngc = out.getvalue()
    assert diagnostics.warnings == [] and "G92 X[#1*1.] Z[#2*1.]" in ngc, (diagnostics.warnings, ngc)
    machine = _machine_moves(run_rs274(ngc))
    assert len(machine) == len(COMPUTED_MACHINE), machine
    for got, expected in zip(machine, COMPUTED_MACHINE):
        assert got == pytest.approx(expected, abs=1e-4), machine
    report = verify_lines(io.StringIO(COMPUTED), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=load_setup(SETUP), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
