"""LinuxCNC ``G10 L1 P- Z- R-`` towards other targets (issue 26, ``postproc.lowering.tool_entries``): the entry's
length and radius become the target's own register settings (Fanuc ``G10 L10``/``L12``) or, on grbl without
a tool table, are taken into the path (``G43.1 Z<length>``, the compensated moves). Seeded programs: each
translation's controlled points are rs274's (its canonical points, cutter compensation applied, plus the Z
length of its last ``USE_TOOL_LENGTH_OFFSET``); hand-derived outputs; refusals by name."""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine import ToolData
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274, straight_moves_with_length
from tests.support.tools import with_tools

SETUP = with_tools(lengths={1: 50.8, 2: 63.5}, radii={1: 3.81, 2: 5.08})
"""The machine's own registers differ from every value a program here writes: a write lost is seen."""
RS274_TABLE = "T1 P1 Z2 D0.3\nT2 P2 Z2.5 D0.4\n"
"""The same registers as rs274 reads them (inches, diameters)."""
TARGETS = ("fanuc", "grbl", "grblhal")


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def translated(text: str, target: str, setup: Any = SETUP) -> str:
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


HAND = """G21 G17 G90 G40
G10 L1 P1 Z12.5 R2
T1 M6 G43
G0 X0 Y0 Z5
G1 Z-1 F100
G41 G1 X10 Y0
Y10
X0
G40 G1 X-5 Y-5
G0 Z5
G10 L1 P1 Z7
G43
G0 Z6
M2
"""
"""By hand: tool 1 is 12.5 long, radius 2; the square X10 Y0 - X10 Y10 - X0 Y10 with the tool on its left
runs X8 Y2 (the entry ends square to the next side), X8 Y8, X0 Y8; then the length 7."""


def test_fanuc_writes_the_entry_into_its_offset_memory_c() -> None:
    lines = translated(HAND, "fanuc").splitlines()
    assert lines[1:3] == ["G10 L10 P1 R12.5", "G10 L12 P1 R2."]
    assert "G10 L10 P1 R7." in lines and lines[lines.index("G10 L10 P1 R7.") + 1] == "G43 H01"


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
def test_grbl_takes_the_entry_into_the_path(target: str) -> None:
    lines = translated(HAND, target).splitlines()
    assert [line for line in lines if line.startswith("G43.1")] == ["G43.1 Z12.5", "G43.1 Z7."]
    assert ["G1 X8. Y2.", "G1 X8. Y8.", "G1 X0. Y8."] == [line for line in lines if line.startswith("G1 X")][:3]
    assert not any(line.startswith("G10") for line in lines)


@pytest.mark.parametrize("target", TARGETS)
def test_the_hand_derived_translations_verify(target: str) -> None:
    report = verify_lines(_lines(HAND), _lines(translated(HAND, target)), file_in="t.ngc", file_out="out",
                          source="linuxcnc", target=target, setup=SETUP)
    assert report.ok, report.summary()


def _program(rng: random.Random) -> str:
    """Entries written (lengths and radii in whole hundredths of a mm: exact in rs274's printed mm), tools
    changed, G43 with a Z move, straight moves, and a square cut with compensation on either side."""
    lines = ["G21 G90 G17 G40 F300", "G0 X0 Y0 Z40"]
    for _ in range(rng.randint(2, 5)):
        tool = rng.choice((1, 2))
        words = [f"Z{rng.randint(0, 3000) / 100:.2f}" if rng.random() < 0.8 else "",
                 f"R{rng.randint(50, 300) / 100:.2f}" if rng.random() < 0.6 else ""]
        lines.append(f"G10 L1 P{tool} {' '.join(w for w in words if w) or 'Z1'}")
        lines += [f"T{tool} M6", f"G43 G0 Z{rng.randint(20, 40)}"]
        for _ in range(rng.randint(1, 3)):
            lines.append(f"G{rng.choice((0, 1))} X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} Z{rng.randint(5, 30)}")
        if rng.random() < 0.6:
            side, size = rng.choice(("G41", "G42")), rng.randint(15, 30)
            lines += ["G0 X-40 Y-40", "G1 Z-1", f"{side} G1 X0 Y0", f"X{size}", f"Y{size}", "X0", "Y0",
                      "G40 G1 X-40 Y-40", "G0 Z30"]
    lines.append("M2")
    return "\n".join(lines) + "\n"


def _rs274_points(text: str) -> list[tuple[float, float, float]]:
    """rs274's controlled points: its canonical X and Y (compensated), Z plus the length in force, mm."""
    out: list[tuple[float, float, float]] = []
    for x, y, z, _, length in straight_moves_with_length(run_rs274(text, tool_table=RS274_TABLE)):
        point = (round(x, 3), round(y, 3), round(z + length, 3))
        if not out or out[-1] != point:
            out.append(point)
    return out


def _our_points(text: str, dialect: str) -> list[tuple[float, float, float]]:
    out: list[tuple[float, float, float]] = []
    for ev in toolpath_events(_lines(text), file="out", dialect=dialect, setup=SETUP):
        if ev.get("move") in ("rapid", "feed"):
            c: dict[str, Any] = ev.get("controlled", ev)
            point = (round(float(c["x"]), 3), round(float(c["y"]), 3), round(float(c["z"]), 3))
            if not out or out[-1] != point:
                out.append(point)
    return out


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(12))
def test_translations_cut_where_rs274_cuts(seed: int) -> None:
    text = _program(random.Random(seed))
    theirs = _rs274_points(text)[1:]  # rs274's first move starts from its own zero
    for target in TARGETS:
        ours = _our_points(translated(text, target), target)[1:]
        assert ours == theirs, f"seed {seed} -> {target}\n{text}\nours   {ours}\nrs274  {theirs}"


def _refusal(text: str, target: str, setup: Any = SETUP) -> str:
    with pytest.raises(ErrorList) as info:
        translated(text, target, setup)
    return "\n".join(str(e) for e in info.value.errors)


def test_an_offset_across_the_spindle_goes_into_the_path() -> None:
    # the entry's X goes into the next absolute X under G43 (postproc.lowering.sideways_offsets), its Z into G10 L10
    out = translated("G21\nG10 L1 P1 X1 Z3\nT1 M6\nG43 G0 Z5\nX2\nM2\n", "fanuc").splitlines()
    assert out[1] == "G10 L10 P1 R3." and out[-2] == "G00 X3.", out


def test_an_entry_of_zero_offsets_across_the_spindle_is_left_out() -> None:
    out = translated("G21\nG10 L1 P1 X0 Y0 Z3\nT1 M6\nG43 G0 Z5\nM2\n", "fanuc").splitlines()
    assert out[1] == "G10 L10 P1 R3."


def test_fanuc_refuses_the_entry_in_incremental_mode() -> None:
    assert "incremental mode" in _refusal("G21 G91\nG10 L1 P1 Z3\nM2\n", "fanuc")


def test_one_register_for_length_and_radius_takes_one_value() -> None:
    memory_a = with_tools(SETUP)
    memory_a.tools = dict(memory_a.tools)
    memory_a.tools["1"] = ToolData(number=1, offset=9.0)
    memory_b = with_tools(SETUP)
    memory_b.tools = dict(memory_b.tools)
    memory_b.tools["1"] = ToolData(number=1, offset=9.0, offset_wear=0.0)
    assert "one value for both" in _refusal("G21\nG10 L1 P1 Z3 R1\nM2\n", "fanuc", memory_a)
    assert translated("G21\nG10 L1 P1 Z3\nM2\n", "fanuc", memory_a).splitlines()[1] == "G10 L11 P1 R3."
    assert translated("G21\nG10 L1 P1 Z3\nM2\n", "fanuc", memory_b).splitlines()[1] == "G10 L10 P1 R3."


def test_isg_refuses_the_entry_by_name() -> None:
    assert "G10 L1 P1 Z3 (setting tool length 1)" in _refusal("G21\nG10 L1 P1 Z3\nM2\n", "isg")


FANUC = """%
O0001
G21 G17 G90 G40
G10 L10 P1 R12.5
G10 L12 P1 R2.
T1 M06
G43 H01 G00 X-5. Y-5. Z5.
G01 Z-1. F100.
G41 D01 G01 X0. Y0.
X10.
Y10.
X0.
Y0.
G40 G01 X-5. Y-5.
G00 Z5.
M30
%
"""
"""By hand (Fanuc's compensation C, radius 2 on the left of the square X0 Y0 - X10 - Y10 - X0 - Y0): X0 Y2
(the start-up ends square to the next side), X8 Y2, X8 Y8, X2 Y8, X2 Y0, then X-5 Y-5; Z plus 12.5."""
FANUC_POINTS = [(-5.0, -5.0, 17.5), (-5.0, -5.0, 11.5), (0.0, 2.0, 11.5), (8.0, 2.0, 11.5), (8.0, 8.0, 11.5),
                (2.0, 8.0, 11.5), (2.0, 0.0, 11.5), (-5.0, -5.0, 11.5), (-5.0, -5.0, 17.5)]


def _from_fanuc(target: str) -> str:
    out = io.StringIO(newline="")
    translate(_lines(FANUC), out, file="t.nc", source="fanuc", target=target, setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_fanuc_registers_become_linuxcnc_entries_that_rs274_runs() -> None:
    text = _from_fanuc("linuxcnc")
    assert [line for line in text.splitlines() if line.startswith("G10")] == ["G10 L1 P1 Z12.5", "G10 L1 P1 R2."]
    assert _rs274_points(text) == FANUC_POINTS  # rs274's table says tool 1 is 2 in long: the program's wins


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_fanuc_registers_translate_where_the_target_cuts_them(target: str) -> None:
    text = _from_fanuc(target)
    assert _our_points(text, target) == FANUC_POINTS
    report = verify_lines(_lines(FANUC), _lines(text), file_in="t.nc", file_out="out", source="fanuc",
                          target=target, setup=SETUP)
    assert report.ok, report.summary()


def test_a_wear_register_has_no_linuxcnc_column() -> None:
    text = "%\nO0001\nG21 G90\nG10 L11 P1 R0.1\nM30\n%\n"
    with pytest.raises(ErrorList, match="no such table can be set from a program"):
        translate(_lines(text), io.StringIO(), file="t.nc", source="fanuc", target="linuxcnc", setup=SETUP)
