"""A computed spindle orientation angle (LinuxCNC ``M19 R#<a>``) towards grblHAL with expressions.

The program is kept symbolically where the target spells every construct; the grbl family's writer took
the angle as a number and stopped with an internal ``TypeError`` (found by the offsets engineer's random
draws). It now says the angle cannot be written, so the program is flattened: the operator's pause names
the evaluated angle."""

from __future__ import annotations

import io
from pathlib import Path

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import load_setup

SETUP = """<MachineSetup name="t"><Controller expressions="true"/><Cycles orientation="stop"/></MachineSetup>"""


def test_a_computed_angle_is_evaluated_not_crashed_on(tmp_path: Path) -> None:
    (tmp_path / "setup.xml").write_text(SETUP)
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    translate(io.StringIO("G21 G90 G17\n#<a>=30.\nM19 R#<a>\nG0 X1 Y1 Z5.\nM2\n"), out, file="t.ngc",
              source="linuxcnc", target="grblhal", setup=load_setup(tmp_path / "setup.xml"), diagnostics=diagnostics)
    assert "M0 (ORIENT THE SPINDLE TO 30. DEG BY HAND, THEN CYCLE START)" in out.getvalue().splitlines()
    assert "#" not in out.getvalue()
    assert any("computed angle" in str(w) for w in diagnostics.warnings)
