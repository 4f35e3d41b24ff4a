"""LinuxCNC G41.1/G42.1 (cutter compensation by the diameter D; issue 26, corpus ``inside_corners_trimmed``,
``inverse_time_with_comp``): simulated as rs274 runs them (the controlled points are rs274's, move by
move), kept verbatim for LinuxCNC, and a located refusal for targets without them. The expected points of
the first program are also derived by hand."""

from __future__ import annotations

import io
import math
from pathlib import Path
import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import RS274Error, available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
CORPUS = ROOT / "tests" / "corpus" / "linuxcnc"
TOLERANCE_MM = 2e-4
needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _controlled(text: str, file: str = "t.ngc") -> list[tuple[str, float, float, float]]:
    out = []
    for e in toolpath_events(io.StringIO(text, newline=""), file=file, dialect="linuxcnc"):
        if "move" in e:
            point = e.get("controlled", e)
            out.append((e["move"], point["x"], point["y"], point["z"]))
    return out


def _theirs(text: str) -> list[tuple[str, float, float, float]]:
    return [(e["move"], e["x"], e["y"], e["z"]) for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0))
            if "move" in e]


def _same(ours: list[tuple[str, float, float, float]], theirs: list[tuple[str, float, float, float]],
          tolerance: float = TOLERANCE_MM) -> None:
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a[0] == b[0] and math.dist(a[1:], b[1:]) <= tolerance, (n, a, b)


SQUARE = """G21 G17 G90 G0 X0 Y0 Z1
G1 Z0 F100
G41.1 D4
G1 X20 Y0
G1 X20 Y20
G3 X0 Y20 R10
G40
G1 X0 Y0
G42.1 D-2
G1 X10 Y-5
G1 X30 Y-5
G40 G1 X40 Y0
M2
"""
"""G41.1 D4 (radius 2 on the left), then G42.1 D-2 (radius 1, the negative diameter puts it on the left)."""

PROGRAMS = {
    "square": SQUARE,
    "right side, o-word diameter": ("G21 G90 G0 X0 Y0 Z1\n#100=6\nG42.1 D#100\nG1 X10 Y0 F100\nG1 X10 Y10\n"
                                    "G1 X0 Y10\nG40 G1 X-5 Y5\nM2\n"),
    "zero diameter": "G21 G90 G0 X0 Y0 Z1\nG41.1 D0\nG1 X10 Y0 F100\nG1 X10 Y10\nG40\nG1 X0 Y0\nM2\n",
    "inch": "G20 G90 G0 X0 Y0 Z0.1\nG41.1 D0.25\nG1 X1 Y0 F10\nG2 X2 Y-1 R1\nG1 Y-2\nG40 G1 X3\nM2\n",
}


def test_the_square_is_compensated_as_derived_by_hand() -> None:
    """Radius 2 on the left: the entry move ends 2 left of the first side at its end corner, offset back
    along the inside corner (X18 Y2); the arc of radius 10 about X10 Y20 becomes one of 8 ending at X2;
    the exit move goes to the programmed point. Then radius 1 left of the X10 Y-5 -> X30 Y-5 side: Y-4."""
    moves = _controlled(SQUARE)
    assert [m[1:3] for m in moves[2:5]] == [(18, 2), (18, 20), (2, 20)]
    assert moves[5][1:3] == (0, 0)
    assert moves[7][2] == -4 and moves[7][1] == 30


@needs_rs274
@pytest.mark.parametrize("name", PROGRAMS)
def test_dynamic_compensation_moves_as_rs274_runs_it(name: str) -> None:
    text = PROGRAMS[name]
    _same(_controlled(text), _theirs(text), 0.0018 if "G20" in text else TOLERANCE_MM)


@needs_rs274
@pytest.mark.parametrize("program", ["inside_corners_trimmed.ngc", "inverse_time_with_comp.ngc"])
def test_the_corpus_programs_move_as_rs274_runs_them(program: str) -> None:
    text = (CORPUS / program).read_text()
    _same(_controlled(text, program), _theirs(text), 0.0018)


def test_linuxcnc_gets_the_block_back_and_other_targets_a_located_refusal() -> None:
    out = io.StringIO(newline="")
    translate(io.StringIO(SQUARE, newline=""), out, file="t.ngc", source="linuxcnc", target="linuxcnc")
    assert out.getvalue() == SQUARE
    for target in ("fanuc", "grbl", "isg", "fagor", "mach3"):
        with pytest.raises(ErrorList) as info:
            translate(io.StringIO(SQUARE, newline=""), io.StringIO(), file="t.ngc", source="linuxcnc", target=target)
        assert str(info.value.errors[0]).startswith("t.ngc:3:1: error: G41.1"), (target, str(info.value.errors[0]))


REFUSED = {
    "no D": ("G21 G90 G0 X0 Y0\nG41.1\nG1 X1 F10\nM2\n", "t.ngc:2:1: error: G41.1 with no D word"),
    "L outside G18": ("G21 G90 G0 X0 Y0\nG41.1 D1 L2\nG1 X1 F10\nM2\n", "t.ngc:2:10: error: G41.1 with an L word"),
    "on while on": ("G21 G90 G0 X0 Y0\nG41.1 D1\nG1 X1 F10\nG42.1 D1\nG1 X5\nM2\n", "t.ngc:4:"),
}


@pytest.mark.parametrize("name", REFUSED)
def test_what_rs274_refuses_is_a_located_error(name: str) -> None:
    source, message = REFUSED[name]
    with pytest.raises(ErrorList) as info:
        _controlled(source)
    assert str(info.value.errors[0]).startswith(message), str(info.value.errors[0])
    if available():
        with pytest.raises(RS274Error):
            run_rs274(source)


def test_a_block_that_also_moves_is_not_simulated_past() -> None:
    """rs274 runs ``G41.1 D2 G1 X10``; here the whole block stays verbatim, so the simulation refuses it
    rather than lose the move."""
    with pytest.raises(ErrorList) as info:
        _controlled("G21 G90 G0 X0 Y0\nG41.1 D2 G1 X10 F100\nG40 G1 X20\nM2\n")
    assert "t.ngc:2:" in str(info.value.errors[0]) and "cannot be simulated" in str(info.value.errors[0])
