"""grbl ``G92``/``G92.1`` on the frame model under LinuxCNC's rules [V: grbl 1.1 ``gcode.c``,
NON_MODAL_SET_COORDINATE_OFFSET: ``G92 = MPos - WCS - TLO - WPos`` on each named axis, absolute whatever G91,
kept through a work system change until G92.1].

A grbl program is RS274/NGC that rs274 reads, so rs274 runs the grbl program itself as the oracle, and again
its translation to LinuxCNC (the frame evaluated into the coordinates there).
"""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274
from tests.test_frames import _machine as machine_points

HEAD = "G21 G90 G17 G0 X0 Y0 Z0\n"


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="grbl", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _events(text: str) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect="grbl") if "move" in e]


def test_g92_makes_the_current_point_read_its_words_until_g92_1() -> None:
    # at (10, 10) G92 X0 Y0: offset (10, 10), X5 Y5 -> (15, 15); G91 G92 X1 reads absolute: the point (program 5)
    # reads 1, offset 5 + 10 - 1 = 14, G90 X5 -> 19; G92.1 clears it: X2 Y2 -> (2, 2)
    text = HEAD + "G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG91 G92 X1\nG90 G1 X5\nG92.1\nG1 X2 Y2\nM2\n"
    assert [(e["x"], e["y"]) for e in _events(text)] == [(10, 10), (15, 15), (19, 15), (2, 2)]
    assert _translate(text, "grbl") == text


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "grblhal"])
def test_g92_is_evaluated_for_other_controls(target: str) -> None:
    text = HEAD + "G0 X10 Y10\nG92 X0 Y0\nG1 X5 Y5 F100\nG2 X5 Y-5 I0 J-5\nG92.1\nG1 X2 Y2\nM2\n"
    out = _translate(text, target)
    assert "G92" not in "".join(line.split("(")[0] for line in out.splitlines()), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="grbl",
                          target=target, tolerance=1e-3)
    assert report.ok, report.summary()


def _program(seed: int) -> str:
    rng = random.Random(seed)
    lines = ["G21 G90 G17 G94", "G0 X0 Y0 Z0"]
    for _ in range(rng.randint(3, 7)):
        kind = rng.choice(["g92", "g92", "clear", "arc", "incremental"])
        if kind == "g92":
            axes = rng.sample("XYZ", rng.randint(1, 3))
            lines.append(f"{rng.choice(['G90', 'G91'])} G92 " + " ".join(f"{a}{rng.randint(-20, 20)}" for a in axes))
            lines.append("G90")
        elif kind == "clear":
            lines.append("G92.1")
        elif kind == "arc":
            x, y = rng.randint(-20, 20), rng.randint(-20, 20)
            lines.append(f"G1 X{x} Y{y} F{rng.randint(50, 500)}")
            lines.append(f"G{rng.choice('23')} X{x + 10} Y{y} I5 J0")
        else:
            lines.append(f"G91 G1 X{rng.randint(-5, 5)} Y{rng.randint(-5, 5)} Z{rng.randint(-2, 2)} F200\nG90")
        lines.append(f"G0 X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} Z{rng.randint(0, 5)}")
    lines += ["G92.1", "G0 X0 Y0 Z10", "M2"]
    return "\n".join(lines) + "\n"


def _machine_moves(text: str) -> list[dict[str, Any]]:
    """rs274's moves at machine points (its canonical calls leave the G92 offset out), straight moves that go
    nowhere left out as the toolpath leaves them."""
    out: list[dict[str, Any]] = []
    here = (0.0, 0.0, 0.0)
    for e in machine_points(run_rs274(text)):
        point = (e["x"], e["y"], e["z"])
        if e["move"] in ("rapid", "feed") and max(abs(a - b) for a, b in zip(point, here)) < 1e-9:
            continue
        out.append(e)
        here = point
    return out


def _same_moves(ours: list[dict[str, Any]], text: str, program: str) -> None:
    theirs = _machine_moves(text)
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274\n{program}\n{text}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b, program, text)
        assert max(abs(float(a[k]) - float(b[k])) for k in "xyz") <= 2e-4, (n, a, b, program, text)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(12))
def test_a_random_g92_program_moves_as_rs274_runs_it_and_its_linuxcnc_translation(seed: int) -> None:
    program = _program(seed)
    ours = _events(program)
    _same_moves(ours, program, program)
    _same_moves(ours, _translate(program, "linuxcnc"), program)
