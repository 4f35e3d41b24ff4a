"""An arc in a plane the lathe set-up's machine lacks an axis of (an XY or YZ arc on ``<Machine axes="XZ"/>``) is
refused by ``translate``, located at the arc, as ``verify`` refuses both sides ("needs axis Y, not on this
machine"): written out, it would sweep an axis the machine does not have. Before, ``G2 X1 I0.5 J0`` (an XY arc
naming no Y, well defined on grbl: the plane's axis not named keeps its position [V: gnea/grbl ``gcode.c``,
"[G2/3 Offset-Mode Errors]" needs one axis word of the plane, the missing one is the current position]) was
translated with exit 0 from grbl, grblHAL, LinuxCNC and Fanuc T alike.

A mill program on a lathe set-up whose machine has Y (no ``<Machine axes>``: XYZ) translated to LinuxCNC or
grblHAL opens with ``G17 G8``, not ``G18 G8``: the source starts in the XY plane, so its XY arc stays an XY arc
(before, the target read it in ZX and verify refused the output: "arc centre offset along Y is outside the ZX
plane").
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Callable

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines
from tests.conftest import CliResult

ROOT = Path(__file__).resolve().parents[1]
XZ_LATHE = ROOT / "tests" / "corpus" / "setups" / "linuxcnc_lathe_radius.xml"  # lathe, axes XZ, X radii
FANUC_T = ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"  # Fanuc 0i-TF, axes XZ
LATHE_WITH_Y = ROOT / "tests" / "corpus" / "setups" / "grblhal_lathe.xml"  # lathe, no <Machine axes>: XYZ

MILL_ARC = "G21 G90\nG1 X0 Z0 F100\nG2 X1 I0.5 J0\nM30\n"
"""The grbl program: an XY arc (G17 from power-on) naming no Y."""
PLANE_ARC = "G18 G21 G90\nG1 X0 Z0 F100\nG17 G2 X1 I0.5 J0\nM30\n"
"""An RS274/NGC lathe program that selects G17 for its arc."""
FANUC_ARC = "O1\nG18 G21 G98\nG1 X0. Z0. F100.\nG17 G2 X1. R0.5\nM30\n"
"""A Fanuc T program that selects G17 for an R arc."""


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "grblhal"])
@pytest.mark.parametrize(("source", "text", "machine"), [
    ("grbl", MILL_ARC, XZ_LATHE), ("grblhal", PLANE_ARC, XZ_LATHE), ("linuxcnc", PLANE_ARC, XZ_LATHE),
    ("fanuc", FANUC_ARC, FANUC_T)])
def test_an_arc_out_of_the_machines_axes_is_refused_at_the_arc(
        cli: Callable[..., CliResult], tmp_path: Path, source: str, text: str, machine: Path, target: str) -> None:
    program = tmp_path / "in.nc"
    program.write_text(text)
    line = next(n for n, t in enumerate(text.splitlines(), 1) if "X1" in t)  # the arc
    result = cli("translate", program, "--from", source, "--to", target, "--machine", machine)
    assert result.status == 1, result.err
    assert f"{program}:{line}:1: error: an arc in the XY plane needs axis Y, not on this machine (axes XZ)" \
        in result.err_lines, result.err
    assert "Traceback" not in result.err


@pytest.mark.parametrize("target", ["linuxcnc", "grblhal"])
def test_a_mill_programs_xy_arc_on_a_lathe_with_y_stays_in_xy(target: str) -> None:
    setup = load_setup(str(LATHE_WITH_Y))
    out = io.StringIO()
    translate(io.StringIO(MILL_ARC), out, file="in.nc", source="grbl", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    written = out.getvalue()
    assert written.splitlines()[0] == "G17 G8", written
    report = verify_lines(io.StringIO(MILL_ARC), io.StringIO(written), file_in="in.nc", file_out="out.nc",
                          source="grbl", target=target, setup=load_setup(str(LATHE_WITH_Y)), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
