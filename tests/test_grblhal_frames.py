"""grblHAL ``G92``/``G92.1``/``G92.2`` on the frame model under LinuxCNC's rules [V: grblHAL core ``gcode.c``
(stored commit f80fc34), NonModal_SetCoordinateOffset: ``G92 = MPos - WCS - TLO - WPos`` on each named axis,
absolute whatever G91; G92.1 zeroes the offset in force and the stored one; G92.2 the one in force only].
``G92.3`` restores the stored offset, which depends on the ``$384`` setting: kept verbatim [?].

A grblHAL program of these words is RS274/NGC that rs274 reads, so rs274 runs the grblHAL program itself as the
oracle, and again its translation to LinuxCNC and to grbl (the frame evaluated into the coordinates there).
"""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.test_grbl_frames import _same_moves

HEAD = "G21 G90 G17 G0 X0 Y0 Z0\n"


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="grblhal", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _events(text: str) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect="grblhal") if "move" in e]


def test_g92_g92_2_and_g92_1_by_hand() -> None:
    # at (10, 10) G92 X0 Y0: offset (10, 10), X5 Y5 -> (15, 15); G91 G92 X1 reads absolute: offset 5 + 10 - 1 = 14,
    # G90 X5 -> 19; G92.2 zeroes the offset: X2 Y2 -> (2, 2); at X2 G92 X1: offset 1, X3 -> 4; G92.1: X2 -> 2
    text = HEAD + ("G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG91 G92 X1\nG90 G1 X5\nG92.2\nG1 X2 Y2\nG92 X1\nG1 X3\n"
                   "G92.1\nG1 X2 Y2\nM2\n")
    assert [(e["x"], e["y"]) for e in _events(text)] == [(10, 10), (15, 15), (19, 15), (2, 2), (4, 2), (2, 2)]
    assert _translate(text, "grblhal") == text


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "fanuc"])
def test_g92_is_evaluated_for_other_controls(target: str) -> None:
    text = HEAD + "G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG2 X5 Y-5 I0 J-5\nG92.2\nG1 X2 Y2\nM2\n"
    out = _translate(text, target)
    assert "G92" not in "".join(line.split("(")[0] for line in out.splitlines()), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="grblhal",
                          target=target, tolerance=1e-3)
    assert report.ok, report.summary()


def test_g92_3_stays_verbatim_and_is_refused_elsewhere_by_name() -> None:
    text = HEAD + "G92 X1\nG92.2\nG92.3\nG1 X5 F100\nM2\n"
    assert _translate(text, "grblhal") == text
    with pytest.raises(ErrorList) as caught:
        _translate(text, "linuxcnc")
    assert "in.nc:4:1: error: G92.3 (restore G92 offsets from storage" in str(caught.value.errors[0])


def _program(seed: int) -> str:
    rng = random.Random(seed)
    lines = ["G21 G90 G17 G94", "G0 X0 Y0 Z0"]
    for _ in range(rng.randint(3, 7)):
        kind = rng.choice(["g92", "g92", "clear", "suspend", "arc", "incremental"])
        if kind == "g92":
            axes = rng.sample("XYZ", rng.randint(1, 3))
            lines.append(f"{rng.choice(['G90', 'G91'])} G92 " + " ".join(f"{a}{rng.randint(-20, 20)}" for a in axes))
            lines.append("G90")
        elif kind in ("clear", "suspend"):
            lines.append("G92.1" if kind == "clear" else "G92.2")
        elif kind == "arc":
            x, y = rng.randint(-20, 20), rng.randint(-20, 20)
            lines.append(f"G1 X{x} Y{y} F{rng.randint(50, 500)}")
            lines.append(f"G{rng.choice('23')} X{x + 10} Y{y} I5 J0")
        else:
            lines.append(f"G91 G1 X{rng.randint(-5, 5)} Y{rng.randint(-5, 5)} Z{rng.randint(-2, 2)} F200\nG90")
        lines.append(f"G0 X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} Z{rng.randint(0, 5)}")
    lines += ["G92.1", "G0 X0 Y0 Z10", "M2"]
    return "\n".join(lines) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(16))
def test_a_random_g92_program_moves_as_rs274_runs_it_and_its_translations(seed: int) -> None:
    program = _program(seed)
    ours = _events(program)
    _same_moves(ours, program, program)
    _same_moves(ours, _translate(program, "linuxcnc"), program)
    _same_moves(ours, _translate(program, "grbl"), program)
