"""Words of real LinuxCNC posts the reader once refused, against LinuxCNC's interpreter (rs274):

* ``G90.1``/``G91.1``: seeded programs of arcs in the three planes (helices too), centres given absolutely or as
  offsets, metric or inch: the simulated moves and centres are rs274's ``ARC_FEED`` ones, and the program
  translated to Fanuc (offsets only) simulates the same;
* ``G10 L1 P Z R``: a tool table entry written by the program is the one ``G43`` and ``G41`` then use
  (rs274's ``USE_TOOL_LENGTH_OFFSET`` length, and its compensated path); ``G10 L10``/``L11``: the length
  measured where the tool stands, as rs274 works it out;
* ``G64 P Q``: read, written back for LinuxCNC, and it moves nothing.
"""

from __future__ import annotations

import io
import math
import random
import re
from typing import Any

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.machine import ToolData
from postproc.simulate.toolpath import toolpath_events
from tests.support import rs274

TOLERANCE_MM = 3e-3
"""rs274 prints 4 decimals in program units (1e-4 in = 0.00254 mm)."""
PROGRAMS = 24
PLANES = {"G17": ("X", "Y", "Z"), "G18": ("Z", "X", "Y"), "G19": ("Y", "Z", "X")}
CENTRE = {"X": "I", "Y": "J", "Z": "K"}

needs_rs274 = pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def events(text: str, dialect: str = "linuxcnc", setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    return list(toolpath_events(_lines(text), file="t.ngc", dialect=dialect, setup=setup or MachineSetup()))[1:]


def moves(evs: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [e for e in evs if "move" in e]


def same(ours: list[dict[str, Any]], theirs: list[dict[str, Any]], keys: str = "xyz") -> None:
    assert [e["move"] for e in ours] == [e["move"] for e in theirs], (ours, theirs)
    for a, b in zip(ours, theirs):
        names = list(keys) + (["cx", "cy", "cz"] if a["move"] in ("cw", "ccw") else [])
        assert max(abs(float(a[k]) - float(b[k])) for k in names) <= TOLERANCE_MM, (a, b)


# -- G90.1 / G91.1 -----------------------------------------------------------------------------------------

def _arc_program(rng: random.Random) -> str:
    inch = rng.random() < 0.25
    plane = rng.choice(list(PLANES))
    a1, a2, normal = PLANES[plane]
    pos = {"X": rng.uniform(-20, 20), "Y": rng.uniform(-20, 20), "Z": rng.uniform(-20, 20)}
    lines = ["G20" if inch else "G21", f"G90 {plane} G91.1 F100",
             "G0 " + " ".join(f"{a}{v:.4f}" for a, v in pos.items())]
    absolute = False
    for _ in range(rng.randint(2, 6)):
        want = rng.random() < 0.6
        mode = ""
        if want != absolute:
            mode = "G90.1 " if want else "G91.1 "
            absolute = want
            if rng.random() < 0.3:
                lines.append(mode.strip())  # the mode on a line of its own
                mode = ""
        radius = rng.uniform(2, 30)
        start_angle = rng.uniform(0, 2 * math.pi)
        c1, c2 = pos[a1] - radius * math.cos(start_angle), pos[a2] - radius * math.sin(start_angle)
        clockwise = rng.random() < 0.5
        sweep = rng.uniform(0.3, 5.5) * (-1 if clockwise else 1)
        end1 = c1 + radius * math.cos(start_angle + sweep)
        end2 = c2 + radius * math.sin(start_angle + sweep)
        end1, end2 = round(end1, 4), round(end2, 4)
        c1, c2 = round(c1, 4), round(c2, 4)
        words = [f"{a1}{end1:.4f}", f"{a2}{end2:.4f}"]
        if rng.random() < 0.3:
            pos[normal] = round(pos[normal] + rng.uniform(-5, 5), 4)
            words.append(f"{normal}{pos[normal]:.4f}")
        i1, i2 = (c1, c2) if absolute else (c1 - pos[a1], c2 - pos[a2])
        words += [f"{CENTRE[a1]}{i1:.4f}", f"{CENTRE[a2]}{i2:.4f}"]
        lines.append(f"{mode}{'G2' if clockwise else 'G3'} " + " ".join(words))
        pos[a1], pos[a2] = end1, end2
        if rng.random() < 0.3:
            pos[a1] = round(pos[a1] + rng.uniform(-3, 3), 4)
            lines.append(f"G1 {a1}{pos[a1]:.4f}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_arc_centre_modes_move_as_rs274(seed: int) -> None:
    text = _arc_program(random.Random(seed))
    theirs = [e for e in rs274.canonical_moves(rs274.run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = moves(events(text))
    same(ours, theirs)
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=MachineSetup(),
              on_unsupported="warn")
    assert not re.search(r"^[^(]*G90\.1", out.getvalue(), re.M)  # a comment names it
    same(moves(events(out.getvalue(), "fanuc")), ours)


def test_an_absolute_centre_where_the_start_is_unknown_is_refused() -> None:
    from postproc.errors import ErrorList
    with pytest.raises(ErrorList) as info:
        events("G21 G90 G0 X0 Y0 Z0\nG28 X0\nG90.1 G2 X10 Y0 I5 J0 F100\nM2\n")
    assert [str(e) for e in info.value.errors][:1] == [
        "t.ngc:3:17: error: an arc with absolute centres (G90.1) where the tool's X position is unknown (after a "
        "reference return, a move in machine coordinates or a computed position): program a move to a known "
        "point first"]


def test_g90_1_is_written_as_offsets_with_a_comment() -> None:
    text = "G21 G90 G17\nG0 X10 Y0 Z0\nG90.1\nG2 X20 Y0 I15 J0 F100\nG91.1\nM2\n"
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="linuxcnc", setup=MachineSetup())
    assert out.getvalue() == ("G21 G90 G17\nG0 X10 Y0 Z0\n(G90.1: absolute arc centres, written as offsets from each "
                              "arc's start)\nG2 X20. Y0. I5. J0. F100.\nG91.1\nM2\n")


# -- G10 L1 ---------------------------------------------------------------------------------------------------

TOOL_TABLE = "T3 P3 Z0 D0\nT4 P4 Z0 D0\n"
"""The tool table rs274 starts with (every entry zero: the program's G10 L1 writes the values)."""
SETUP = MachineSetup()
SETUP.tools = {"3": ToolData(number=3, length=0.0, radius=0.0), "4": ToolData(number=4, length=0.0, radius=0.0)}


@needs_rs274
@pytest.mark.parametrize("inch", [False, True])
def test_a_tool_entry_set_by_the_program_is_used_as_rs274_uses_it(inch: bool) -> None:
    u = 1 / 25.4 if inch else 1.0
    text = (f"{'G20' if inch else 'G21'} G90 G17\nT3 M6\nG10 L1 P3 Z{12.5 * u:.5f} R{2 * u:.5f}\nG43 H3\n"
            f"G0 X{-10 * u:.5f} Y0 Z{5 * u:.5f}\nG41 D3 G1 X0 F100\nY{10 * u:.5f}\nX{10 * u:.5f}\n"
            f"G40 G0 X{20 * u:.5f}\nG10 L1 P3 R{1 * u:.5f}\nG42 D3 G1 Y{20 * u:.5f}\nX{30 * u:.5f}\nG40 G0 Y{30 * u:.5f}\n"
            "M2\n")
    calls = rs274.run_rs274(text, tool_table=TOOL_TABLE)
    length = next(float(m.group(1)) for c in calls
                  if (m := re.search(r"USE_TOOL_LENGTH_OFFSET\(\S+ \S+ (\S+),", c))) * (25.4 if inch else 1.0)
    assert abs(length - 12.5) < 1e-3
    theirs = [e for e in rs274.canonical_moves(calls, start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = [{**e, **{k: v for k, v in e.get("controlled", {}).items() if k in "xy"}} for e in moves(events(text, setup=SETUP))]
    same(ours, theirs)
    written = float(f"{12.5 * u:.5f}") * (25.4 if inch else 1.0)  # the length as the program writes it, mm
    assert all(abs(e["controlled"]["z"] - e["z"] - written) < 1e-6 for e in moves(events(text, setup=SETUP)))


def _machine_z(calls: list[str]) -> list[float]:
    """rs274's Z of each straight move in machine terms (mm programs): the point + the G5x offset + the tool
    length offset in force (both as it prints them)."""
    g5x = tlo = 0.0
    out = []
    for call in calls:
        if m := re.search(r"SET_G5X_OFFSET\(\d+, \S+, \S+, (\S+),", call):
            g5x = float(m.group(1))
        elif m := re.search(r"USE_TOOL_LENGTH_OFFSET\(\S+ \S+ (\S+),", call):
            tlo = float(m.group(1))
        elif m := re.search(r"STRAIGHT_(?:TRAVERSE|FEED)\(\S+, \S+, (\S+),", call):
            out.append(float(m.group(1)) + g5x + tlo)
    return out


@needs_rs274
def test_a_tool_entry_measured_where_the_tool_stands_is_rs274s() -> None:
    # G10 L10 (the active work system, G54 Z3) and L11 (G59.3 Z-4), with and without a length in force
    text = ("G21 G90\nG10 L2 P1 Z3\nG10 L2 P9 Z-4\nT3 M6\nG43 H3\nG0 X0 Y0 Z5\nG10 L10 P3 Z7 R1.5\nG43 H3\n"
            "G0 Z6\nG10 L11 P3 Z2\nG43 H3\nG0 Z8\nG49\nG0 Z9\nG91 G10 L10 P3 Z1\nG90 G43 H3\nG0 Z3\nM2\n")
    theirs = _machine_z(rs274.run_rs274(text, tool_table=TOOL_TABLE))
    ours = [e.get("controlled", e)["z"] for e in moves(events(text, setup=SETUP))]
    assert ours == pytest.approx(theirs, abs=1e-4) and len(ours) == 5


def test_g10_l1_round_trips_and_is_refused_where_no_tool_table_is_written() -> None:
    from postproc.errors import ErrorList
    text = "G21 G90\nG10 L1 P3 Z12.5 R2\nM2\n"
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="linuxcnc", setup=MachineSetup())
    assert out.getvalue() == text
    with pytest.raises(ErrorList, match=r"V.G.WZ\[j\].L, V.G.WZ\[j\].R\) only with an internal tool table"):
        translate(_lines(text), io.StringIO(), file="t.ngc", source="linuxcnc", target="isg", setup=MachineSetup())


# -- G64 P Q ------------------------------------------------------------------------------------------------

def test_g64_tolerances_round_trip_and_move_nothing() -> None:
    text = "G21 G90\nG64 P0.01 Q0.02\nG0 X1\nG64 P0.05\nG1 X2 F100\nG64\nM2\n"
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="linuxcnc", setup=MachineSetup())
    assert out.getvalue() == text
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=MachineSetup())
    assert out.getvalue() == "G21 G90\nG64\nG00 X1.\nG64\nG01 X2. F100.\nG64\nM02\n"  # Fanuc's G64 has no tolerance
    assert [(e["move"], e["x"]) for e in moves(events(text))] == [("rapid", 1), ("feed", 2)]
