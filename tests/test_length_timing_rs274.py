"""When a LinuxCNC tool length change applies, against rs274: seeded random programs with ``G43 H``/``G49``
in the middle, moves of X or Y only after a change, absolute and incremental Z. rs274 keeps the machine Z
until Z is programmed ([V] its canonical calls: after ``G43 H1`` a ``G1 X10`` prints Z = old - length);
postproc's toolpath must print the same programmed points, and its controlled Z must be rs274's
programmed Z plus the length of its last ``USE_TOOL_LENGTH_OFFSET``. Lengths are whole hundredths of an
inch (exact in the table rs274 reads in inches and in its 4 printed decimals of mm)."""

from __future__ import annotations

import io
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, run_rs274, straight_moves_with_length

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

PROGRAMS = 100
LENGTHS_INCH = {1: 1.0, 2: 0.25, 3: 2.5, 4: 0.0}


def _program(rng: random.Random) -> str:
    lines = ["G21 G90 G17", "G0 X0 Y0 Z40"]
    for _ in range(rng.randint(6, 16)):
        op = rng.random()
        if op < 0.25:
            lines.append(f"G43 H{rng.choice(list(LENGTHS_INCH))}")
        elif op < 0.32:
            lines.append("G49")
        elif op < 0.5:
            lines.append(f"G1 X{rng.randint(-20, 20)} F300")
        elif op < 0.6:
            lines.append(f"G0 Y{rng.randint(-20, 20)}")
        elif op < 0.8:
            lines.append(f"G1 Z{rng.randint(-5, 60)} F200")
        elif op < 0.9:
            lines.append(f"G91 G1 Z{rng.randint(-5, 5) or 1} F200")
            lines.append("G90")
        else:
            lines.append(f"G43 H{rng.choice(list(LENGTHS_INCH))} G0 X{rng.randint(-9, 9)}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


def _rs274_moves(text: str) -> list[tuple[float, float, float, float]]:
    """rs274's moves: programmed X, Y, Z and the controlled Z (programmed + the length in force), mm."""
    table = "".join(f"T{n} P{n} Z{v} D0.1\n" for n, v in LENGTHS_INCH.items())
    out: list[tuple[float, float, float, float]] = []
    for x, y, z, _, length in straight_moves_with_length(run_rs274(text, tool_table=table)):
        point = (x, y, z, round(z + length, 4))
        if out and (out[-1][0], out[-1][1], out[-1][3]) == (x, y, point[3]):
            continue  # the machine does not move (rs274 prints it; a toolpath leaves it out)
        out.append(point)
    return out


def _our_moves(text: str) -> list[tuple[float, float, float, float]]:
    setup = MachineSetup()
    setup.tools = {str(n): ToolData(number=n, length=v * 25.4, radius=0.0) for n, v in LENGTHS_INCH.items()}
    out = []
    for ev in toolpath_events(io.StringIO(text).readlines(), file="t.ngc", dialect="linuxcnc", setup=setup):
        if "move" not in ev:
            continue
        controlled: dict[str, Any] = ev.get("controlled", ev)
        out.append((float(ev["x"]), float(ev["y"]), float(ev["z"]), round(float(controlled["z"]), 4)))
    return out


def test_hand_derived_length_change_without_z() -> None:
    """H1 = 25.4 mm: at ``G1 X10`` the machine Z stays at 40, so the programmed Z reads 40 - 25.4 = 14.6;
    ``G1 Z-1`` then drives the machine to -1 + 25.4 = 24.4; after ``G49`` an X move keeps 24.4, read as Z."""
    text = "G21 G90\nG0 X0 Y0 Z40\nG43 H1\nG1 X10 F100\nG1 Z-1\nG49\nG1 X5\nM2\n"
    assert _our_moves(text) == [(0, 0, 40, 40), (10, 0, 14.6, 40), (10, 0, -1, 24.4), (5, 0, 24.4, 24.4)]
    assert _rs274_moves(text)[1:] == _our_moves(text)[1:]  # rs274's first move starts from its own zero


@pytest.mark.parametrize("batch", range(4))
def test_length_changes_equal_rs274(batch: int) -> None:
    for seed in range(batch * PROGRAMS // 4, (batch + 1) * PROGRAMS // 4):
        text = _program(random.Random(seed))
        ours, theirs = _our_moves(text), _rs274_moves(text)
        assert ours == theirs, f"seed {seed}\n{text}\nours   {ours}\nrs274  {theirs}"


def test_a_cancel_before_an_incremental_reference_return_moves_in_rs274_as_in_fanuc() -> None:
    """Fanuc's G49, then G91 G28 Z0 (the next-move model: the return's intermediate point takes the controlled Z
    from 10 + 25.4 to 10), translated for LinuxCNC: rs274 runs the written ``G90 G49 G28 Z10.`` through the
    same controlled Z, 35.4 -> 10, then to its home (machine 0 standalone: Z0 with no length)."""
    fanuc = "G21 G90 G0 X0 Y0 Z40.\nG43 H01 Z40.\nG1 Z10. F100.\nG49\nG91 G28 Z0\nG90\nM30\n"
    setup = MachineSetup()
    setup.tools = {str(n): ToolData(number=n, length=v * 25.4, radius=0.0) for n, v in LENGTHS_INCH.items()}
    out = io.StringIO()
    translate(io.StringIO(fanuc), out, file="in.nc", source="fanuc", target="linuxcnc", setup=setup)
    theirs = [point[3] for point in _rs274_moves(out.getvalue())]
    assert theirs[-3:] == [35.4, 10.0, 0.0]
    ours = [round(float(e.get("controlled", e)["z"]), 4)
            for e in toolpath_events(io.StringIO(fanuc), file="in.nc", dialect="fanuc", setup=setup) if "move" in e]
    assert ours[2:4] == theirs[-3:-1]


def test_an_incremental_return_from_an_unknown_z_moves_in_rs274_as_in_fanuc() -> None:
    """No absolute Z before the length changes: ``G91 G43 H01 G28 Z0`` is written with Z25.4 (the increment plus
    the new length minus the old, ``length_timing``), ``G49`` then ``G91 G28 X0 Y0 Z2.`` with Z-23.4. rs274's
    controlled Z through both returns equals the Fanuc model's: 25.4 then its home (0), -23.4 then 0."""
    fanuc = "G21 G90 G0 X0 Y0\nG91 G43 H01 G28 Z0\nG90 G1 X5. F100.\nG49\nG91 G28 X0 Y0 Z2.\nG90\nM30\n"
    setup = MachineSetup()
    setup.tools = {str(n): ToolData(number=n, length=v * 25.4, radius=0.0) for n, v in LENGTHS_INCH.items()}
    out = io.StringIO()
    translate(io.StringIO(fanuc), out, file="in.nc", source="fanuc", target="linuxcnc", setup=setup)
    assert "G91 G43 H01 G28 Z25.4" in out.getvalue() and "G91 G49 G28 X0. Y0. Z-23.4" in out.getvalue()
    theirs = [point[3] for point in _rs274_moves(out.getvalue())]
    ours = [round(float(e.get("controlled", e)["z"]), 4)
            for e in toolpath_events(io.StringIO(fanuc), file="in.nc", dialect="fanuc", setup=setup) if "move" in e]
    assert theirs[-5:] == ours[-5:] == [25.4, 0.0, 0.0, -23.4, 0.0]  # (rs274 also prints G0 X0 Y0 from its start)
