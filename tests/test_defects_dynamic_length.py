"""LinuxCNC's ``G43.1`` (dynamic tool length offset) read as the neutral tool length offset, not kept verbatim
(issue 30, one meaning per class): grbl's ``G43.1 Z..`` already read into ``ToolLengthOffset("dynamic")``,
LinuxCNC's same code stayed a native code, so LinuxCNC -> grbl was refused and grbl -> LinuxCNC too.

Oracles: rs274 2.9 (the program's points and the length of each ``USE_TOOL_LENGTH_OFFSET``, as
tests/test_length_timing_rs274.py compares them), hand-derived points, and ``verify`` of each translation
against the simulation of its source. Facts: [V] rs274 2.9 run here: ``G43.1 Z2.5`` prints
``USE_TOOL_LENGTH_OFFSET(0 0 2.5, ...)``, under G91 too (the value is the length, not an increment), a bare
``G43.1`` keeps the offsets in force, ``G43.1 X1 Z3`` offsets X too (an axis word of the block is the offset's);
[V] grbl ``gcode.c`` "[G43.1 Errors]": a missing Z or another axis word is an error.
"""

from __future__ import annotations

import io
import random

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274, straight_moves_with_length

PROGRAM = "G21 G90 G17\nG0 X0 Y0 Z40\nG43.1 Z2.5\nG1 X10 F100\nG1 Z-1\nG49\nG0 X5\nM2\n"


def _translate(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target, setup=MachineSetup(),
              on_unsupported="error", diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, source: str, target: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, source, target)
    return [str(e) for e in caught.value.errors]


def _our_moves(text: str, dialect: str = "linuxcnc") -> list[tuple[float, float, float, float]]:
    """Programmed X, Y, Z and the controlled Z of each move of postproc's toolpath (mm)."""
    out = []
    for ev in toolpath_events(io.StringIO(text).readlines(), file="t.ngc", dialect=dialect, setup=MachineSetup()):
        if "move" in ev:
            controlled = ev.get("controlled", ev)
            out.append((float(ev["x"]), float(ev["y"]), float(ev["z"]), round(float(controlled["z"]), 4)))
    return out


def _rs274_moves(text: str) -> list[tuple[float, float, float, float]]:
    """rs274's moves: programmed X, Y, Z and the controlled Z (programmed + the length in force), mm."""
    out: list[tuple[float, float, float, float]] = []
    for x, y, z, _, length in straight_moves_with_length(run_rs274(text)):
        point = (x, y, z, round(z + length, 4))
        if out and (out[-1][0], out[-1][1], out[-1][3]) == (x, y, point[3]):
            continue  # the machine does not move (rs274 prints it; a toolpath leaves it out)
        out.append(point)
    return out


def test_linuxcnc_g43_1_is_the_neutral_dynamic_offset_hand_derived() -> None:
    """Length 2.5 from Z40: ``G1 X10`` keeps the machine Z (40, read as 37.5), ``G1 Z-1`` drives it to 1.5,
    after ``G49`` the X move keeps 1.5 (LinuxCNC applies a change at the programmed axis)."""
    assert _our_moves(PROGRAM) == [(0, 0, 40, 40), (10, 0, 37.5, 40), (10, 0, -1, 1.5), (5, 0, 1.5, 1.5)]


@pytest.mark.parametrize("target", ["grbl", "grblhal", "linuxcnc"])
def test_linuxcnc_g43_1_reaches_the_targets_that_have_it_exactly(target: str) -> None:
    out = _translate(PROGRAM, "linuxcnc", target)
    assert "G43.1 Z2.5" in out.splitlines()
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(out), file_in="a.ngc", file_out="b.nc",
                          source="linuxcnc", target=target, tolerance=0.001, setup=MachineSetup())
    assert report.ok and report.max_deviation < 1e-9, report.summary()


def test_grbl_g43_1_reaches_linuxcnc() -> None:
    """Was: "the linuxcnc dialect cannot express tool length offset dynamic"."""
    text = "G21 G90 G17\nG0 X0 Y0 Z40\nG43.1 Z2.5\nG1 X10 F100\nG1 Z-1\nG49\nG0 X5\nM2\n"
    out = _translate(text, "grbl", "linuxcnc")
    assert "G43.1 Z2.5" in out.splitlines()
    assert _our_moves(out) == _our_moves(text, "grbl")


@pytest.mark.parametrize("target", ["fanuc", "isg", "siemens", "fagor"])
def test_a_target_without_a_dynamic_offset_refuses_it_by_name(target: str) -> None:
    errors = _errors(PROGRAM, "linuxcnc", target)
    assert len(errors) == 1 and "dynamic tool length offset" in errors[0], errors


@pytest.mark.parametrize(("text", "column", "letter"), [
    ("G21\nG43.1 X1 Z3\nM2\n", 7, "X"), ("G21\nG43.1 Z3 A1\nM2\n", 10, "A"), ("G21\nG43.1 Y1 Z3\nM2\n", 7, "Y"),
])
def test_an_offset_along_another_axis_is_refused_not_read_as_a_move(text: str, column: int, letter: str) -> None:
    assert _errors(text, "linuxcnc", "linuxcnc") == [
        f"in.nc:2:{column}: error: G43.1 with an {letter} word: only a tool length along Z is modelled (an offset "
        f"along {letter} is not; the {letter} word is the offset's, not a move)"]


@pytest.mark.parametrize(("source", "text", "column", "code"), [
    ("linuxcnc", "G21\nG91 G43.1 Z4 G0\nM2\n", 14, "G0"), ("linuxcnc", "G21\nG0 G43.1 Z1\nM2\n", 1, "G0"),
    ("grbl", "G21\nG43.1 Z1 G1 F100\nM2\n", 10, "G1"),
])
def test_a_motion_code_beside_g43_1_is_refused(source: str, text: str, column: int, code: str) -> None:
    """rs274 takes the Z word for the length and the move's end: ``G91 G43.1 Z4 G1 F200`` moves Z by 4 (run here)."""
    assert _errors(text, source, source) == [
        f"in.nc:2:{column}: error: G43.1 with {code} in one block: the Z word would be the tool length and the "
        "move's too (write the motion in a block of its own)"]


def test_grbl_refuses_another_axis_word_and_a_missing_z() -> None:
    assert _errors("G21\nG43.1 Z1 X2\nM2\n", "grbl", "grbl")[0].startswith("in.nc:2:10: error: G43.1 with an X word")
    assert _errors("G21\nG43.1\nM2\n", "grbl", "grbl") == ["in.nc:2:1: error: G43.1 needs the tool length as its Z word"]


def test_a_bare_linuxcnc_g43_1_keeps_the_length_in_force() -> None:
    """rs274: ``G43.1 Z3`` then ``G43.1`` prints ``USE_TOOL_LENGTH_OFFSET(0 0 3, ...)`` again (run here)."""
    text = "G21 G90\nG0 X0 Y0 Z5\nG43.1 Z2\nG0 Z1\nG43.1\nG0 Z0\nM2\n"
    assert [m[3] for m in _our_moves(text)] == [5.0, 3.0, 2.0]
    out = _translate(text, "linuxcnc", "grbl")
    assert "G43.1 Z2." in out.splitlines() and "G43.1 Z0." not in out.splitlines()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_hand_derived_program_equals_rs274() -> None:
    assert _rs274_moves(PROGRAM)[1:] == _our_moves(PROGRAM)[1:]  # rs274's first move starts from its own zero


def _program(rng: random.Random) -> str:
    lines = ["G21 G90 G17", "G0 X0 Y0 Z40"]
    for _ in range(rng.randint(6, 16)):
        op = rng.random()
        if op < 0.25:
            lines.append(f"G43.1 Z{rng.randint(-40, 40) / 4:g}")
        elif op < 0.32:
            lines.append(rng.choice(["G49", "G43.1"]))
        elif op < 0.5:
            lines.append(f"G1 X{rng.randint(-20, 20)} F300")
        elif op < 0.6:
            lines.append(f"G0 Y{rng.randint(-20, 20)}")
        elif op < 0.8:
            lines.append(f"G1 Z{rng.randint(-5, 60)} F200")
        elif op < 0.9:
            lines.append(f"G91 G43.1 Z{rng.randint(1, 8)}")  # the length is no increment under G91
            lines.append(f"G1 Z{rng.randint(-5, 5) or 1} F200")
            lines.append("G90")
        else:
            lines.append(f"G43.1 Z{rng.randint(0, 9)}")
            lines.append(f"G0 X{rng.randint(-9, 9)}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_dynamic_length_changes_equal_rs274_and_reach_grbl() -> None:
    for seed in range(40):
        text = _program(random.Random(seed))
        ours, theirs = _our_moves(text), _rs274_moves(text)
        assert ours[1:] == theirs[1:], f"seed {seed}\n{text}\nours   {ours}\nrs274  {theirs}"
        out = _translate(text, "linuxcnc", "grbl")
        report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a.ngc", file_out="b.nc",
                              source="linuxcnc", target="grbl", tolerance=0.001, setup=MachineSetup())
        assert report.ok and report.max_deviation < 1e-9, f"seed {seed}\n{text}\n{out}\n{report.summary()}"
