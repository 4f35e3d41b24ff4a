"""grblHAL ``G92``/``G92.1``/``G92.2`` on the frame model under LinuxCNC's rules [V: grblHAL core ``gcode.c``
(stored commit f80fc34), NonModal_SetCoordinateOffset: ``G92 = MPos - WCS - TLO - WPos`` on each named axis,
absolute whatever G91; G92.1 zeroes the offset in force and the stored one; G92.2 the one in force only].
``G92.3`` restores the stored offset, which depends on the ``$384`` setting: kept verbatim [?].

A grblHAL program of these words is RS274/NGC that rs274 reads, so rs274 runs the grblHAL program itself as the
oracle, and again its translation to LinuxCNC and to grbl (the frame evaluated into the coordinates there).
"""

from __future__ import annotations

import pytest

from postproc.errors import ErrorList
from tests.support.g92_frames import HEAD, assert_evaluated, moves, random_program, same_moves, translated
from tests.support.rs274 import available


def test_g92_g92_2_and_g92_1_by_hand() -> None:
    # at (10, 10) G92 X0 Y0: offset (10, 10), X5 Y5 -> (15, 15); G91 G92 X1 reads absolute: offset 5 + 10 - 1 = 14,
    # G90 X5 -> 19; G92.2 zeroes the offset: X2 Y2 -> (2, 2); at X2 G92 X1: offset 1, X3 -> 4; G92.1: X2 -> 2
    text = HEAD + ("G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG91 G92 X1\nG90 G1 X5\nG92.2\nG1 X2 Y2\nG92 X1\nG1 X3\n"
                   "G92.1\nG1 X2 Y2\nM2\n")
    assert [(e["x"], e["y"]) for e in moves(text, "grblhal")] == [(10, 10), (15, 15), (19, 15), (2, 2), (4, 2),
                                                                 (2, 2)]
    assert translated(text, "grblhal", "grblhal") == text


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "fanuc"])
def test_g92_is_evaluated_for_other_controls(target: str) -> None:
    text = HEAD + "G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG2 X5 Y-5 I0 J-5\nG92.2\nG1 X2 Y2\nM2\n"
    assert_evaluated(text, "grblhal", target)


def test_g92_3_stays_verbatim_and_is_refused_elsewhere_by_name() -> None:
    text = HEAD + "G92 X1\nG92.2\nG92.3\nG1 X5 F100\nM2\n"
    assert translated(text, "grblhal", "grblhal") == text
    with pytest.raises(ErrorList) as caught:
        translated(text, "grblhal", "linuxcnc")
    assert "in.nc:4:1: error: G92.3 (restore G92 offsets from storage" in str(caught.value.errors[0])


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(16))
def test_a_random_g92_program_moves_as_rs274_runs_it_and_its_translations(seed: int) -> None:
    program = random_program(seed, ("g92", "g92", "clear", "suspend", "arc", "incremental"),
                             {"clear": "G92.1", "suspend": "G92.2"})
    ours = moves(program, "grblhal")
    same_moves(ours, program, program)
    same_moves(ours, translated(program, "grblhal", "linuxcnc"), program)
    same_moves(ours, translated(program, "grblhal", "grbl"), program)
