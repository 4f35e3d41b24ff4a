"""SINUMERIK programmable frames (issue 28 item 4 on the frames of issue 27): ``TRANS``/``ATRANS``,
``ROT``/``AROT``, ``SCALE``/``ASCALE``, ``MIRROR``/``AMIRROR`` (``dialects/siemens/frames.py``, the ``chain``
rules of ``postproc/frames/frame.py``).

Expected points are derived by hand in each test's comment: a replacing statement sets the whole
programmable frame to its one component, an additive one acts in the coordinates the frame already makes
(``w = F(c(p))``). The translations to LinuxCNC are run by rs274 and must move as the SINUMERIK toolpath.
"""

from __future__ import annotations

import io
import math
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.frame_programs import centre_arc, radius_arc
from tests.support.rs274 import assert_same_moves, available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
ZERO_TOOLS = ROOT / "tests" / "support" / "zero_tools.xml"
TOOL_TABLE = "".join(f"T{n} P{n} Z0 D0\n" for n in range(1, 10))
HEAD = "G710 G90 G17 G94 G0 X0 Y0 Z0\n"


def _tools() -> MachineSetup:
    return load_setup(str(ZERO_TOOLS))


def _translate(text: str, target: str, setup: MachineSetup | None = None) -> str:
    setup = setup or _tools()
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, target: str = "linuxcnc") -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, target)
    return [str(e) for e in caught.value.errors]


def _events(text: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens", setup=setup or _tools())
            if "move" in e]


def _points(body: str) -> list[tuple[Any, ...]]:
    """(move, x, y, z) of each move (the head's stays at the start: no move), rounded to 1e-9."""
    return [(e["move"], *(round(float(e[k]), 9) + 0.0 for k in "xyz")) for e in _events(HEAD + body + "M30\n")]


def _verify(a: str, b: str, target: str) -> None:
    report = verify_lines(io.StringIO(a), io.StringIO(b), file_in="a", file_out="b", source="siemens",
                          target=target, setup=_tools(), target_setup=_tools(), tolerance=1e-3)
    assert report.ok, report.summary() + "\n--- a\n" + a + "--- b\n" + b


# -- replacing and additive statements, by hand ------------------------------------------------------------

def test_a_replacing_statement_clears_the_other_components() -> None:
    # TRANS X10: (1, 0) -> (11, 0); ROT RPL=90 replaces it: (1, 0) -> (0, 1), no offset; SCALE X2 Y2 replaces the
    # rotation: (1, 0) -> (2, 0); MIRROR X0 replaces the scaling: (1, 0) -> (-1, 0); TRANS alone clears: (1, 0)
    body = ("TRANS X10\nG1 X1 Y0 F100\nROT RPL=90\nG1 X1 Y0\nSCALE X2 Y2\nG1 X1 Y0\nMIRROR X0\nG1 X1 Y0\n"
            "TRANS\nG1 X1 Y0\n")
    assert _points(body) == [("feed", 11, 0, 0), ("feed", 0, 1, 0), ("feed", 2, 0, 0), ("feed", -1, 0, 0),
                             ("feed", 1, 0, 0)]


def test_additive_statements_act_in_the_frame_in_force() -> None:
    # TRANS X10 Y5, AROT RPL=90 turns about (10, 5): program (1, 0) -> (0, 1) + (10, 5) = (10, 6).
    # AMIRROR X0 mirrors the turned X: (1, 0) -> (-1, 0) -> turned (0, -1) -> (10, 4).
    # ASCALE X2 Y2 scales before the mirror: (1, 0) -> (2, 0) -> (-2, 0) -> (0, -2) -> (10, 3).
    # ATRANS X1 is a vector of that frame: program (1, 1) -> (2, 1) -> (4, 2) -> (-4, 2) -> (-2, -4) -> (8, 1).
    body = ("TRANS X10 Y5\nAROT RPL=90\nG1 X1 Y0 F100\nAMIRROR X0\nG1 X1 Y0\nASCALE X2 Y2\nG1 X1 Y0\nATRANS X1\n"
            "G1 X1 Y1\n")
    assert _points(body) == [("feed", 10, 6, 0), ("feed", 10, 4, 0), ("feed", 10, 3, 0), ("feed", 8, 1, 0)]


def test_an_offset_after_a_scaling_is_scaled_and_after_a_rotation_turned() -> None:
    # SCALE X2 Y2, ATRANS X5: program (1, 0) -> (6, 0) -> (12, 0); ROT RPL=90, ATRANS X5: (0, 0) -> (5, 0) -> (0, 5)
    assert _points("SCALE X2 Y2\nATRANS X5\nG1 X1 Y0 F100\nROT RPL=90\nATRANS X5\nG1 X0 Y0\n") == [
        ("feed", 12, 0, 0), ("feed", 0, 5, 0)]


def test_unequal_scaling_after_a_rotation_acts_along_the_turned_axes() -> None:
    # ROT RPL=90, ASCALE X2: program (1, 1) -> (2, 1) -> turned (-1, 2)
    assert _points("ROT RPL=90\nASCALE X2\nG1 X1 Y1 F100\n") == [("feed", -1, 2, 0)]


def test_a_rotation_after_unequal_scaling_is_refused() -> None:
    assert "a rotation chained after unequal scale factors" in _errors(HEAD + "SCALE X2\nAROT RPL=30\nM30\n")[0]


def test_rpl_turns_in_the_active_plane_and_an_axis_angle_about_its_axis() -> None:
    # G18 (Z, X): RPL=90 turns Z toward X (right-handed about Y): program Z1 X0 -> X1 Z0.
    # ROT X90 turns Y toward Z: program Y1 -> Z1. ROT Y90 turns Z toward X: program Z1 -> X1. ROT Z90 = G17 RPL=90.
    assert _points("G18\nROT RPL=90\nG1 X0 Y0 Z1 F100\n") == [("feed", 1, 0, 0)]
    assert _points("ROT X90\nG1 X0 Y1 Z0 F100\n") == [("feed", 0, 0, 1)]
    assert _points("ROT Y90\nG1 X0 Y0 Z1 F100\n") == [("feed", 1, 0, 0)]
    assert _points("ROT Z90\nG1 X1 Y0 Z0 F100\n") == _points("ROT RPL=90\nG1 X1 Y0 Z0 F100\n") == [("feed", 0, 1, 0)]


def test_an_angle_of_zero_on_the_other_axes_is_one_rotation() -> None:
    assert _points("ROT X0 Y0 Z90\nG1 X1 Y0 Z0 F100\n") == [("feed", 0, 1, 0)]


# -- arcs, compensation, cycles ---------------------------------------------------------------------------

def test_an_arc_keeps_its_centre_and_a_mirror_turns_its_direction() -> None:
    # from program (1, 0) G2 to (0, 1) CR=1: the short clockwise arc about (1, 1).
    # TRANS X10 Y5, AROT RPL=90: centre (1, 1) -> (-1, 1) + (10, 5) = (9, 6), end (0, 1) -> (-1, 0) -> (9, 5), cw.
    # AMIRROR X0 after that: centre (1, 1) -> (-1, 1) -> (-1, -1) -> (9, 4), end (0, 1) -> (9, 5), ccw.
    body = "TRANS X10 Y5\nAROT RPL=90\nG1 X1 Y0 F100\nG2 X0 Y1 CR=1\nAMIRROR X0\nG1 X1 Y0\nG2 X0 Y1 I0 J1\n"
    arcs = [(e["move"], e["x"], e["y"], e["cx"], e["cy"]) for e in _events(HEAD + body + "M30\n")
            if e["move"] in ("cw", "ccw")]
    assert [tuple(round(v, 9) + 0.0 if isinstance(v, float) else v for v in a) for a in arcs] == [
        ("cw", 9, 5, 9, 6), ("ccw", 9, 5, 9, 4)]


def test_an_arc_that_leaves_its_plane_or_is_scaled_unequally_is_refused() -> None:
    assert "is not an arc" in _errors(HEAD + "ROT X30\nG1 X1 Y0 Z0 F100\nG2 X0 Y1 CR=1\nM30\n")[0]
    assert "is not an arc" in _errors(HEAD + "SCALE X2\nG1 X1 Y0 F100\nG2 X0 Y1 CR=1\nM30\n")[0]


def test_a_mirror_swaps_the_side_of_cutter_compensation() -> None:
    text = HEAD + "MIRROR X0\nT1 D1 M6\nG1 X0 Y0 F100\nG41 G1 X10 Y0\nG1 X10 Y10\nG40 G1 X20 Y20\nM30\n"
    out = _translate(text, "linuxcnc", load_setup(str(ZERO_TOOLS)))
    assert "G42" in out and "G41" not in out, out
    _verify(text, out, "linuxcnc")


def test_a_frame_change_with_compensation_on_is_refused() -> None:
    text = HEAD + "T1 D1 M6\nG41 G1 X10 Y0 F100\nAROT RPL=10\nG1 X20\nG40 G1 X0 Y0\nM30\n"
    assert "with cutter compensation on cannot be run" in _errors(text)[0]


def test_a_modal_cycle_drills_at_the_turned_holes() -> None:
    # ROT RPL=90: the holes at program (10, 0) and (20, 0) are drilled at (0, 10) and (0, 20), to Z-5
    text = HEAD + "ROT RPL=90\nG0 X0 Y0 Z10\nF100\nMCALL CYCLE81(2,0,2,-5)\nX10 Y0\nX20 Y0\nMCALL\nM30\n"
    depths = [(round(e["x"], 9) + 0.0, round(e["y"], 9) + 0.0) for e in _events(text)
              if e["move"] == "feed" and abs(e["z"] + 5) < 1e-9]
    assert depths == [(0, 10), (0, 20)]
    for target in ("fanuc", "linuxcnc", "grbl"):
        _verify(text, _translate(text, target), target)


# -- the first incremental move, positions -----------------------------------------------------------------

def test_the_first_incremental_move_after_a_frame_change_is_refused_until_the_axis_is_programmed() -> None:
    assert "SD42440" in _errors(HEAD + "TRANS X10\nG91 G1 X1 F100\nM30\n")[0]
    # X programmed absolutely first: (0 + 10), then 1 further
    assert _points("TRANS X10\nG1 X0 F100\nG91 G1 X1\n") == [("feed", 10, 0, 0), ("feed", 11, 0, 0)]


def test_an_omitted_axis_the_rotation_mixes_in_must_be_programmed() -> None:
    assert "program Y absolutely" in _errors(HEAD + "ROT RPL=30\nG1 X1 F100\nM30\n")[0]


# -- per target ----------------------------------------------------------------------------------------------

PATTERN = """%_N_PATTERN_MPF
G710 G90 G17 G94
T1 D1 M6
S1000 M3
G0 X0 Y0 Z5
TRANS X50 Y40
FOR R1=1 TO 6
AROT RPL=60
G0 X20 Y0
G1 Z-2 F100
G1 X25 Y0
G3 X25 Y5 CR=5
G0 Z5
ENDFOR
MIRROR X0
G0 X20 Y0
G2 X10 Y10 I-10 J0
SCALE X0.5 Y0.5 Z1
G1 X20 Y0
ATRANS X4 Y-2
G1 X20 Y0 Z-1
TRANS
G0 Z50
M30
"""
"""A pattern turned by 60 degrees six times about (50, 40), then a mirrored arc and a scaled offset."""


def test_a_frames_program_is_written_back_byte_for_byte() -> None:
    assert _translate(PATTERN, "siemens") == PATTERN


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_a_rotated_pattern_is_evaluated_for_other_controls_and_verifies(target: str) -> None:
    out = _translate(PATTERN, target)
    code = [line.split("(")[0].split(";")[0] for line in out.splitlines()]
    assert not any(word in line for line in code for word in ("TRANS", "ROT", "SCALE", "MIRROR")), out
    _verify(PATTERN, out, target)


def test_the_pattern_is_drawn_where_it_was_turned() -> None:
    # pass k turns 60k degrees about (50, 40): program (20, 0) is plunged (line 10) at (50 + 20 cos 60k,
    # 40 + 20 sin 60k); the toolpath prints 6 decimals
    plunges = [(e["x"], e["y"]) for e in _events(PATTERN) if e["line"] == 10]
    expected = [(50 + 20 * math.cos(math.radians(60 * k)), 40 + 20 * math.sin(math.radians(60 * k)))
                for k in range(1, 7)]
    assert len(plunges) == 6
    for (x, y), (ex, ey) in zip(plunges, expected):
        assert abs(x - ex) < 1e-6 and abs(y - ey) < 1e-6, (plunges, expected)


# -- rs274 -----------------------------------------------------------------------------------------------------

def _compare(text: str, file: str) -> None:
    setup = load_setup(str(ZERO_TOOLS))
    out = _translate(text, "linuxcnc", setup)
    theirs = [e for e in canonical_moves(run_rs274(out, tool_table=TOOL_TABLE), start=(0.0, 0.0, 0.0))
              if "move" in e]
    assert_same_moves(_events(text, setup), theirs, text, out)


def _frame(rng: random.Random) -> str:
    kind = rng.choice(["TRANS", "ATRANS", "ROT", "AROT", "SCALE", "ASCALE", "MIRROR", "AMIRROR", "ROTAXIS"])
    if kind in ("TRANS", "ATRANS"):
        return f"{kind} X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} Z{rng.randint(-3, 3)}"
    if kind in ("ROT", "AROT"):
        return f"{kind} RPL={rng.uniform(-180, 180):.3f}"
    if kind == "ROTAXIS":
        return f"{rng.choice(['ROT', 'AROT'])} Z{rng.uniform(-180, 180):.3f}"
    if kind in ("SCALE", "ASCALE"):
        s = rng.choice(["0.5", "1.5", "2", "0.8"])
        return f"{kind} X{s} Y{s}" + (f" Z{rng.choice(['1', '2'])}" if rng.random() < 0.5 else "")
    return f"{kind} " + " ".join(f"{a}0" for a in rng.sample("XYZ", rng.randint(1, 2)))


def _program(seed: int) -> str:
    rng = random.Random(seed)
    lines = ["%_N_FRAMES_MPF", "G710 G90 G17 G94", "T1 D1 M6", "G0 X0 Y0 Z5"]
    for _ in range(rng.randint(3, 6)):
        lines.append(_frame(rng))
        x, y = rng.randint(-20, 20), rng.randint(-20, 20)
        lines.append(f"G1 X{x} Y{y} Z{rng.randint(-3, 3)} F{rng.randint(50, 500)}")
        kind = rng.choice(["cr", "ij", "line", "incremental"])
        if kind == "cr":
            ex, ey, radius = radius_arc(rng, x, y)
            lines.append(f"G{rng.choice('23')} X{ex} Y{ey} CR={rng.choice(['', '-'])}{radius:.4f}")
        elif kind == "ij":
            fx, fy, i, j = centre_arc(rng, x, y)
            lines.append(f"G{rng.choice('23')} X{fx:.4f} Y{fy:.4f} I{i} J{j}")
        elif kind == "incremental":
            lines.append(f"G91 G1 X{rng.randint(-5, 5)} Y{rng.randint(-5, 5)}\nG90")
        else:
            lines.append(f"G0 X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} Z{rng.randint(0, 5)}")
    lines += ["TRANS", "G0 X0 Y0 Z50", "M30"]
    return "\n".join(lines) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_pattern_moves_in_rs274_as_its_siemens_toolpath() -> None:
    _compare(PATTERN, "pattern.mpf")


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(16))
def test_a_random_frames_program_moves_in_rs274_as_its_siemens_toolpath(seed: int) -> None:
    text = _program(seed)
    _compare(text, f"frames{seed}.mpf")
    _verify(text, _translate(text, "grbl", load_setup(str(ZERO_TOOLS))), "grbl")
