"""grbl's power-on path mode is the exact path (G61) (issue 26/29, defects).

grbl runs one path control mode, the exact path, and it is the mode in force at power-on [V: grbl 1.1 ``gcode.h``
``CONTROL_MODE_EXACT_PATH // G61 (Default: Must be zero)``; grblHAL core ``gcode.h`` ``ControlMode_ExactPath``
"G61 - Default"]. The dialects said so only for verify's sake (``PATH_CONTROL``) and took a grbl program as
starting in the cutting mode: towards a controller that powers on blending (Fanuc, LinuxCNC: G64 [K]) nothing was
written, and the target blended the corners grbl reaches. Now ``PATH_CONTROL_AT_START`` says G61, so the exact stop
is written before the first move (``postproc.lowering.path_at_start``), and the simulation records it there.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup
from tests.support.pair_checks import PairChecks

SQUARE = "G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F100\nG1 X10\nG1 Y10\nG0 Z5\nM30\n"


@pytest.mark.parametrize(("source", "target", "first"), [
    ("grbl", "fanuc", "G61 G00 X0. Y0. Z5."), ("grbl", "linuxcnc", "G61 G0 X0. Y0. Z5."),
    ("grblhal", "fanuc", "G61 G00 X0. Y0. Z5."), ("grblhal", "linuxcnc", "G61 G0 X0. Y0. Z5."),
])
def test_a_grbl_program_keeps_its_exact_path_on_a_blending_controller(source: str, target: str, first: str) -> None:
    check = PairChecks(MachineSetup())
    out = check.translate(SQUARE, source, target)
    assert out.splitlines()[1] == first, out
    check.verify(SQUARE, out, source, target)


@pytest.mark.parametrize("name", ["grbl", "grblhal"])
def test_the_dialect_says_g61_at_power_on(name: str) -> None:
    dialect = default_registry().dialect(name)
    assert dialect.PATH_CONTROL_AT_START == "exact_stop" == dialect.PATH_CONTROL


def test_a_grbl_copy_writes_no_g61() -> None:
    out = io.StringIO()
    translate(io.StringIO(SQUARE), out, file="in.nc", source="grbl", target="grbl",
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert out.getvalue() == SQUARE
