"""Another family's tool table write (LinuxCNC ``G10 L1``, Fanuc ``G10 L10``) towards ISG, Fagor 8070, SINUMERIK
and Mach3 (issue 26): each of those controllers can write tool data from a program, so the refusal no longer says
there is no such table; it names the controller's own means with its source and what is not known ([?]) that
keeps this translation from writing it: which entry a register is, and when a written entry acts on the tool in
use. A located error at the setting's line, never a silent drop."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup

NAMED = {
    "isg": ("V.G.WZ[j].L", "[V: TF5200"),
    "siemens": ("$TC_DP3[t,d]", "[K: SINUMERIK"),
    "fagor": ("V.G.TOOL", "[?]"),
    "mach3": ("G10 L1", "[?]"),
}


@pytest.mark.parametrize("target", sorted(NAMED))
@pytest.mark.parametrize("source, text", [
    ("linuxcnc", "G21 G90\nG10 L1 P3 Z12.5 R2\nG0 X1\nM2\n"),
    ("fanuc", "O0001\nG21 G90\nG10 L10 P3 R12.5\nG0 X1.\nM30\n"),
])
def test_tool_table_write_is_refused_with_the_controllers_reason(source: str, text: str, target: str) -> None:
    with pytest.raises(ErrorList) as err:
        translate(io.StringIO(text), io.StringIO(), file="t.nc", source=source, target=target, setup=MachineSetup())
    messages = [str(e) for e in err.value.errors]
    means, tag = NAMED[target]
    found = [m for m in messages if m.startswith(("t.nc:2:", "t.nc:3:")) and means in m]
    assert found and tag in found[0] and "not written here" in found[0], messages
