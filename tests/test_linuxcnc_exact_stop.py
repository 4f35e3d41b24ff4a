"""A one-shot exact stop (Fanuc ``G09``) translated for LinuxCNC, whose rs274 refuses ``G9`` ("Unknown g code
used" [V: /usr/bin/rs274]): the block in exact-stop mode (``G61``), then the mode before on a line of its own
(``postproc_linuxcnc.exact_stop``). Expected texts are written out by hand; rs274 runs them, switching to
``CANON_EXACT_PATH`` for that block only, and ``verify`` passes."""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274

HEAD = "O1000\nG21 G90 G17\nG00 X0 Y0 Z5.\n"


def _translated(body: str) -> list[str]:
    text = HEAD + body + "M30\n"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="linuxcnc", setup=MachineSetup(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="in.nc", file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=MachineSetup())
    assert report.ok, (out.getvalue(), report)
    return out.getvalue().splitlines()[3:-1]


def test_a_one_shot_stop_is_exact_stop_mode_for_its_block_then_cutting_again() -> None:
    """No path mode set: cutting mode (G64) after the block, the power-on mode of both controllers [K]."""
    assert _translated("G01 X10. F100.\nG09 X20.\nG01 X30.\n") == [
        "G1 X10. F100.", "G61 G1 X20.", "G64", "G1 X30."]


def test_the_mode_before_comes_back_with_its_tolerance() -> None:
    """Fanuc's G64 (no tolerance) stays G64; under G61 the block already stops: the one-shot is left out."""
    assert _translated("G64\nG01 X10. F100.\nG09 X20.\nG61\nG09 X30.\nG01 X40.\n") == [
        "G64", "G1 X10. F100.", "G61 G1 X20.", "G64", "G61", "G1 X30.", "G1 X40."]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_written_stop_for_its_block_only() -> None:
    lines = _translated("G01 X10. F100.\nG09 X20.\nG01 X30.\n")
    calls = [re.sub(r"^N\.+ ", "", c) for c in run_rs274("G21 G90 G17\n" + "\n".join(lines) + "\nM2\n")]
    wanted = [re.split(r"[,)]", c)[0] for c in calls if c.startswith(("STRAIGHT_FEED", "SET_MOTION_CONTROL_MODE"))]
    assert wanted == ["STRAIGHT_FEED(10.0000", "SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH", "STRAIGHT_FEED(20.0000",
                      "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS", "STRAIGHT_FEED(30.0000"]


def test_a_stop_in_a_loop_that_changes_the_mode_is_flattened() -> None:
    """Inside a loop that sets G61 and G64, the mode to come back to depends on the iteration: kept as o-words the
    one-shot is refused (a located reason), so the program is flattened, each iteration's stop resolved."""
    body = "#1=0\nWHILE [#1 LT 2] DO1\nG09 G01 X[#1*10+10] F100.\nG61\nG01 Y[#1]\nG64\n#1=#1+1\nEND1\n"
    lines = [line for line in _translated(body) if not line.startswith("(")]
    assert lines == ["G61 G1 X10. F100.", "G64", "G61", "G1 Y0.", "G64"] * 1 + [
        "G61 G1 X20. F100.", "G64", "G61", "G1 Y1.", "G64"]
