"""LinuxCNC's ``G64 P Q`` blending tolerances: kept for LinuxCNC, and where another controller's cutting
mode cannot carry them the translation says so at the line (the path may deviate by what the machine's own
parameters allow instead): no word leaves silently."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import MachineSetup

PROGRAM = "G21 G90 G64 P0.05 Q0.02\nG1 X10 F100\nM2\n"


def _translate(target: str) -> tuple[str, str]:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="in.ngc", source="linuxcnc", target=target, setup=MachineSetup(),
              diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


def test_linuxcnc_keeps_the_tolerances_without_a_warning() -> None:
    text, warnings = _translate("linuxcnc")
    assert "G64 P0.05 Q0.02" in text and warnings == ""


@pytest.mark.parametrize("target", ["fanuc", "isg", "grbl", "mach3"])
def test_a_target_without_them_warns_at_the_line(target: str) -> None:
    text, warnings = _translate(target)
    assert "P0.05" not in text and "Q0.02" not in text
    assert "in.ngc:1:1: warning: the blending tolerance (path 0.05, naive-CAM 0.02) is not written" in warnings
