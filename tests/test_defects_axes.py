"""Defects: axis words the set-up's machine lacks, and LinuxCNC's X reading modes on a mill.

A word for an axis the machine has not is refused where it is read, so ``translate`` never writes it (the
simulator refused it before, and ``verify`` with it: translate alone wrote a Y on an XZ lathe).
G7 on a LinuxCNC mill set-up was kept verbatim: the target then reads every later X as a diameter
(rs274 moves ``G7 G0 X10`` to X5, checked below), while the translation read radii.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from tests.support.rs274 import available, canonical_moves, run_rs274

from pathlib import Path

SETUPS = Path(__file__).resolve().parent.parent / "examples" / "setups"
FANUC_LATHE = load_setup(SETUPS / "fanuc_0i_tf.xml")


def errors(text: str, source: str, target: str, setup: MachineSetup, file: str = "in.nc") -> list[str]:
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(text), io.StringIO(), file=file, source=source, target=target, setup=setup)
    return [str(e) for e in caught.value.errors]


def written(text: str, source: str, target: str, setup: MachineSetup, file: str = "in.nc") -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file=file, source=source, target=target, setup=setup)
    return out.getvalue()


LATHE_Y = "%\nO1\nG21 G99\nM03 S500\nG00 X20. Y5. Z2.\nG01 Z-10. F0.1\nM30\n%\n"


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "gsk"])
def test_a_y_word_on_an_xz_lathe_is_refused_at_its_column(target: str) -> None:
    assert errors(LATHE_Y, "fanuc", target, FANUC_LATHE) == [
        "in.nc:5:10: error: axis Y is not on this machine (axes XZ)"]


def test_an_increment_names_the_axis_it_moves_and_the_lathe_increments_still_read() -> None:
    ok = "%\nO1\nG21 G99\nM03 S500\nG00 X20. Z2.\nG01 U-2. W-3. F0.1\nM30\n%\n"
    assert written(ok, "fanuc", "fanuc", FANUC_LATHE) == ok
    assert errors("%\nO1\nG21 G99\nM03 S500\nG00 X20. Z2.\nG01 V1. F0.1\nM30\n%\n", "fanuc", "fanuc",
                  FANUC_LATHE)[0].startswith("in.nc:6:5: error: ")


def test_a_rotary_word_on_a_three_axis_mill_is_refused() -> None:
    assert errors("G21 G90\nG0 X0 Y0 Z5\nG0 A90.\nM30\n", "fanuc", "fanuc", MachineSetup()) == [
        "in.nc:3:4: error: axis A is not on this machine (axes XYZ)"]
    four = MachineSetup()
    four.machine.axes = "XYZA"
    assert "A90." in written("G21 G90\nG0 X0 Y0 Z5\nG0 A90.\nM30\n", "fanuc", "fanuc", four)


@pytest.mark.skipif(not available(), reason="rs274 not installed")
def test_rs274_reads_x_as_a_diameter_after_g7_on_a_mill() -> None:
    moves = canonical_moves(run_rs274("G21 G90 G17\nG7\nG0 X10 Y0 Z0\nM2\n"))
    assert moves[0] == {"move": "rapid", "x": 5.0, "y": 0.0, "z": 0.0}


def test_g7_on_a_linuxcnc_mill_set_up_is_refused_at_its_code() -> None:
    assert errors("G21 G90\nG0 X0 Y0 Z5\nG7\nG0 X10\nM2\n", "linuxcnc", "linuxcnc", MachineSetup(), "in.ngc") == [
        'in.ngc:3:1: error: G7 (diameter mode) on a mill set-up, which reads X as a radius (a lathe set-up with '
        '<Input xProgramming="diameter"> reads diameters)']


def test_g8_on_a_linuxcnc_mill_set_up_is_what_the_mill_reads_already() -> None:
    text = "G21 G90\nG0 X0 Y0 Z5\nG8\nG0 X10\nM2\n"
    assert written(text, "linuxcnc", "linuxcnc", MachineSetup(), "in.ngc") == text


@pytest.mark.parametrize("line, error", [
    ("G33 Z-10 K1.5", "G33 (spindle-synchronised motion) cannot be simulated"),
    ("G96 D2000 S100", "G96 (constant surface speed) cannot be simulated"),
    ("G97 S500", "G97 (spindle speed in rpm) cannot be simulated"),
])
def test_linuxcnc_lathe_codes_kept_on_a_mill_are_a_located_error_where_they_would_be_simulated(
        line: str, error: str) -> None:
    from postproc.errors import Diagnostics
    from postproc.simulate.toolpath import toolpath_events
    text = f"G21 G90 G17\nS500 M3\nG0 X0 Y0 Z5\n{line}\nM2\n"
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(text), file="in.ngc", dialect="linuxcnc", setup=MachineSetup(),
                             diagnostics=Diagnostics(warn_stream=io.StringIO())))
    assert [str(e) for e in caught.value.errors] == [f"in.ngc:4:1: error: {error}"]
    assert written(text, "linuxcnc", "linuxcnc", MachineSetup(), "in.ngc") == text  # native LinuxCNC, copied
