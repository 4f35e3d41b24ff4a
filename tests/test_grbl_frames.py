"""grbl ``G92``/``G92.1`` on the frame model under LinuxCNC's rules [V: grbl 1.1 ``gcode.c``,
NON_MODAL_SET_COORDINATE_OFFSET: ``G92 = MPos - WCS - TLO - WPos`` on each named axis, absolute whatever G91,
kept through a work system change until G92.1].

A grbl program is RS274/NGC that rs274 reads, so rs274 runs the grbl program itself as the oracle, and again
its translation to LinuxCNC (the frame evaluated into the coordinates there).
"""

from __future__ import annotations

import pytest

from tests.support.g92_frames import HEAD, assert_evaluated, moves, random_program, same_moves, translated
from tests.support.rs274 import available


def test_g92_makes_the_current_point_read_its_words_until_g92_1() -> None:
    # at (10, 10) G92 X0 Y0: offset (10, 10), X5 Y5 -> (15, 15); G91 G92 X1 reads absolute: the point (program 5)
    # reads 1, offset 5 + 10 - 1 = 14, G90 X5 -> 19; G92.1 clears it: X2 Y2 -> (2, 2)
    text = HEAD + "G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG91 G92 X1\nG90 G1 X5\nG92.1\nG1 X2 Y2\nM2\n"
    assert [(e["x"], e["y"]) for e in moves(text, "grbl")] == [(10, 10), (15, 15), (19, 15), (2, 2)]
    assert translated(text, "grbl", "grbl") == text


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "grblhal"])
def test_g92_is_evaluated_for_other_controls(target: str) -> None:
    text = HEAD + "G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG2 X5 Y-5 I0 J-5\nG92.1\nG1 X2 Y2\nM2\n"
    assert_evaluated(text, "grbl", target)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(12))
def test_a_random_g92_program_moves_as_rs274_runs_it_and_its_linuxcnc_translation(seed: int) -> None:
    program = random_program(seed, ("g92", "g92", "clear", "arc", "incremental"), {"clear": "G92.1"})
    ours = moves(program, "grbl")
    same_moves(ours, program, program)
    same_moves(ours, translated(program, "grbl", "linuxcnc"), program)
