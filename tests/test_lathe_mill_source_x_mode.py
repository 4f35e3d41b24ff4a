"""A mill program (grbl, ISG: X read with mill meanings, a position) translated to LinuxCNC or grblHAL on a lathe
set-up (#20). Both read that set-up's programs as a lathe's, where X may be a diameter (LinuxCNC's lathe start-up
code may leave G7; the set-up's ``xProgramming`` says diameter by default): the translation opens with ``G17 G8``
(the mill program's plane at start: tests/test_lathe_set_up_plane_arcs.py) so X means there what it meant in the source (LinuxCNC G8 radius mode [V: rs274 2.9 run here]; grblHAL's G8 clears
``diameter_mode`` [V: grblHAL core ``gcode.c``]). Found by fuzzing: before, ``G1 X1`` was written bare and read
as a diameter, 1 mm off.

The oracle is rs274 2.9 started in G7 (``G7`` put before the output, as a lathe's start-up code may): its moves
are the source's positions; and ``verify`` against our simulation of the source, at tolerance 0.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.test_lathe_rs274 import theirs

ROOT = Path(__file__).resolve().parents[1]
MILL = "G21 G0 X0. Z10.\nG1 X1 F100\nX2\nG18 G2 X3 Z9 I0.5 K-0.5\nG1 Z5\nM2\n"
"""The fuzzer's program, with a ZX arc after it; X as positions (radii)."""
PROGRAMS = {"grbl": MILL, "isg": MILL.replace("G21 ", "").replace("M2", "M30")}
"""The program in each source's spelling (ISG: metric from the start, no G21)."""
POSITIONS = [(0.0, 10.0), (1.0, 10.0), (2.0, 10.0), (3.0, 9.0), (3.0, 5.0)]


def _setup() -> MachineSetup:
    return load_setup(str(ROOT / "examples" / "setups" / "linuxcnc_lathe.xml"))  # lathe, XZ, X as diameters


def _write(source: str, target: str, text: str = MILL) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target, setup=_setup(),
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("target", ["linuxcnc", "grblhal"])
@pytest.mark.parametrize("source", ["grbl", "isg"])
def test_a_mill_program_on_a_lathe_set_up_says_x_is_a_radius(source: str, target: str) -> None:
    out = _write(source, target, PROGRAMS[source])
    assert out.splitlines()[0] == "G17 G8", out  # the mill program starts in XY (G17)
    report = verify_lines(io.StringIO(PROGRAMS[source]), io.StringIO(out), file_in="in.nc", file_out="out.nc", source=source,
                          target=target, setup=_setup(), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("target", ["linuxcnc", "grblhal"])
def test_rs274_in_diameter_mode_runs_the_translation_at_the_source_positions(target: str) -> None:
    out = _write("grbl", target)
    moves = theirs("G7\n" + out)
    assert [(round(m["x"], 6), round(m["z"], 6)) for m in moves] == POSITIONS, out


def test_a_mill_set_up_writes_no_lathe_mode() -> None:
    """A mill set-up keeps the mill writer: no mode line."""
    out = io.StringIO()
    translate(io.StringIO(MILL.replace("G18 G2 X3 Z9 I0.5 K-0.5\n", "")), out, file="in.nc", source="grbl",
              target="linuxcnc", diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert "G8" not in out.getvalue() and "G7" not in out.getvalue()
