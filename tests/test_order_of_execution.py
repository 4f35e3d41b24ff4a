"""A moving block that stops the spindle or the coolant: Fanuc does it after the motion, LinuxCNC and grbl
before it (their order of execution). Written for them, the stop goes in a block of its own after the
move, so the cut is never made with the spindle or the coolant already off."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from tests.support.rs274 import available, run_rs274

PROGRAM = "G21 G90 G00 X0 Y0 Z5. S1000 M03 M08\nG01 Z-1. F100.\nG01 X10. M05 M09\nG00 Z5.\nM30\n"


def _out(target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="t.nc", source="fanuc", target=target)
    return out.getvalue()


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_spindle_stop_and_coolant_off_follow_the_move(target: str) -> None:
    lines = _out(target).splitlines()
    move = lines.index("G1 X10.")
    assert lines[move + 1] == "M5 M9"


def test_fanuc_keeps_them_in_the_block() -> None:
    assert "G01 X10. M05 M09\n" in _out("fanuc")


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_linuxcnc_stops_the_spindle_after_the_cut() -> None:
    calls = [c.split(" ", 1)[1] for c in run_rs274(_out("linuxcnc"))]
    cut = next(i for i, c in enumerate(calls) if c.startswith("STRAIGHT_FEED(10.0000"))
    stop = next(i for i, c in enumerate(calls) if c.startswith("STOP_SPINDLE_TURNING"))
    flood = next(i for i, c in enumerate(calls) if c.startswith("FLOOD_OFF"))
    assert cut < stop and cut < flood


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_a_stop_moved_after_the_move_still_comes_before_the_program_end(target: str) -> None:
    """make fuzz: 'X0.0005 M30 M05' wrote M5 after M30, where it never runs."""
    out = io.StringIO()
    translate(io.StringIO("G21 G90 G0 X0. Y0. Z10.\nX0.0005 M30 M05\n"), out, file="t.nc", source="fanuc",
              target=target)
    assert out.getvalue().splitlines()[-2:] == ["G0 X0.0005", "M5 M30"]
