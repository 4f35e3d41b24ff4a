"""A LinuxCNC lathe program's modal path control (G64, G61) towards a Fanuc lathe or a GSK: refused at its line,
by name, with the reason: whether those controls have a cutting mode that blends as LinuxCNC's G64 does is [?]
(no Fanuc T or GSK 980TDc manual found, issue 26), so the code is not written on a guess. A milling Fanuc keeps
its G64 (the milling table's [K] code): the reason is a lathe's only."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import InputSettings, MachineSetup

LATHE = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"))


@pytest.mark.parametrize("target", ["fanuc", "gsk"])
@pytest.mark.parametrize("code", ["G64", "G61"])
def test_lathe_path_control_is_refused_by_name(target: str, code: str) -> None:
    text = f"G18 G8\n{code}\nG0 X10 Z5\nM2\n"
    with pytest.raises(ErrorList) as err:
        translate(io.StringIO(text), io.StringIO(), file="p.ngc", source="linuxcnc", target=target, setup=LATHE)
    messages = [str(e) for e in err.value.errors]
    assert any(m.startswith("p.ngc:2:1: error: ") and "path control" in m and "[?]" in m for m in messages), messages


def test_milling_fanuc_keeps_g64() -> None:
    out = io.StringIO()
    translate(io.StringIO("G64\nG0 X10 Z5\nM2\n"), out, file="p.ngc", source="linuxcnc", target="fanuc")
    assert "G64" in out.getvalue()
