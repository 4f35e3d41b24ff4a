"""Differential test: tool nose radius compensation on a lathe (G18, G7 diameters) against LinuxCNC's
interpreter, which runs it in the ZX plane with the tool table's orientation ``Q`` [V: rs274 2.9].

A seeded generator writes LinuxCNC lathe programs that turn G41/G42 on over a profile of lines and arcs
(G2/G3 with I/K, tangent or not), inside and outside corners, rapids and coolant/dwell events under
compensation, entry moves straight or arcs, and a straight exit move after G40; every program has one
tool with a nose radius and a tip direction 0-9. postproc's ``toolpath`` (linuxcnc dialect, the set-up's
``<Tool radius tip>`` in Fanuc's numbers) and ``rs274`` (the same tool, ``Q`` the X-mirrored number,
``postproc.compensation.nose.mirrored``) must agree on every written point move by move (the imaginary
tool tip the machine positions), arc centres too; a program rs274 refuses (a gouge, an entry too short)
must be refused by postproc at the same block.

rs274 prints 4 decimals, so it runs the program scaled by ``SCALE`` (lengths and the tool table: every
rule it applies is an angle or a ratio) -- but one: LinuxCNC checks a moved arc end against its radius
within 0.01 program units, which the scale makes 1e-5 mm. An entry arc with a lathe tool queues a move
to the tip before the arc, and the corner after it reads that move as the one before (``qc().front()``:
a line), so its corner point leaves the arc's circle by about a thousandth of a mm: rs274 at scale
refuses it as a bug, unscaled it runs it. Such a program is compared unscaled (within ``UNSCALED``).
``POSTPROC_NOSE_PROGRAMS`` raises the number of programs.
"""

from __future__ import annotations

import io
import math
import os
import random
import re
from typing import Any

import pytest

from postproc.compensation.nose import mirrored
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from tests.support.compensation_rs274 import (assert_same, calls_before, compensated_moves, postproc_path,
                                              refused_line)
from tests.support.rs274 import RS274Error, available, run_rs274

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

PROGRAMS = int(os.environ.get("POSTPROC_NOSE_PROGRAMS", "120"))
BATCH = 30
SCALE = 1000.0
TOLERANCE = 1e-6
"""mm, every coordinate (radii: rs274 prints X as a radius in G7)."""
UNSCALED = 6e-5
"""mm, a program rs274 runs unscaled (it prints 4 decimals)."""
MISMATCH = "cutter compensation has generated an invalid arc with mismatched radii"
MM_PER_INCH = 25.4
SETUP = os.path.join(os.path.dirname(__file__), "..", "examples", "setups", "linuxcnc_lathe.xml")


class Program:
    """Blocks of words over a profile kept in (Z, X radius), mm; X written as a diameter."""

    def __init__(self) -> None:
        self.blocks: list[list[tuple[str, float | None]]] = []
        self.pos = (0.0, 0.0)
        self.last_dir = (-1.0, 0.0)
        self.radius = 0.4
        self.tip = 3

    def add(self, *words: tuple[str, float | None]) -> None:
        self.blocks.append(list(words))

    def text(self, scale: float = 1.0) -> str:
        out = []
        for n, words in enumerate(self.blocks, start=1):
            parts = [f"N{n}"]
            for letter, value in words:
                if value is None:
                    parts.append(letter)
                elif letter in "XZIK":
                    parts.append(f"{letter}{_number(value * scale)}")
                else:
                    parts.append(f"{letter}{_number(value)}")
            out.append(" ".join(parts))
        return "\n".join(out) + "\n"

    def tool_table(self, scale: float = SCALE) -> str:
        return f"T1 P1 D{2 * self.radius * scale / MM_PER_INCH!r} Q{mirrored(self.tip)} ;\n"

    def setup(self) -> MachineSetup:
        setup = load_setup(SETUP)
        setup.tools = {"1": ToolData(number=1, radius=self.radius, tip=self.tip)}
        return setup


def _number(v: float) -> str:
    text = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _grid(rng: random.Random, lo: float, hi: float, step: float = 0.5) -> float:
    return rng.randint(round(lo / step), round(hi / step)) * step


def _line(rng: random.Random, p: Program, code: str = "G1") -> None:
    dz, dx = p.last_dir
    if rng.random() < 0.15:  # straight on
        k = rng.choice([0.5, 1.0, 2.0])
        target = (round((p.pos[0] + k * dz) * 8) / 8, round((p.pos[1] + k * dx) * 8) / 8)
    else:
        target = (_grid(rng, -60, 5), _grid(rng, 4, 40))
    if target == p.pos:
        target = (target[0] - 5.0, target[1])
    p.add((code, None), ("X", 2 * target[1]), ("Z", target[0]))
    p.last_dir = (target[0] - p.pos[0], target[1] - p.pos[1])
    p.pos = target


def _arc(rng: random.Random, p: Program) -> None:
    """An arc ending exactly on its circle (quarter turns), sometimes tangent to the move before it."""
    if rng.random() < 0.35:
        dz, dx = p.last_dir
        m = rng.choice([-1.0, -0.5, 0.5, 1.0]) * (6.0 / max(abs(dz), abs(dx), 1e-9))
        m = round(m * 2.0) / 2.0 or 0.5
        k, i = round(-dx * m * 8) / 8, round(dz * m * 8) / 8
        ccw = m > 0
    else:
        k, i = _grid(rng, -10, 10), _grid(rng, -10, 10)
        if k == 0 and i == 0:
            k = 3.0
        ccw = rng.random() < 0.5
    quarters = rng.randint(1, 3)
    cz, cx = p.pos[0] + k, p.pos[1] + i
    vz, vx = -k, -i
    for _ in range(quarters):
        vz, vx = (-vx, vz) if ccw else (vx, -vz)
    end = (cz + vz, cx + vx)
    if end[1] < 1.0 or cx - math.hypot(k, i) < -30:  # keep the profile on the positive side
        _line(rng, p)
        return
    p.add(("G3" if ccw else "G2", None), ("X", 2 * end[1]), ("Z", end[0]), ("I", i), ("K", k))
    p.last_dir = (-vx, vz) if ccw else (vx, -vz)
    p.pos = end


def _other(rng: random.Random, p: Program) -> None:
    kind = rng.randrange(4)
    if kind == 0:
        _line(rng, p, "G0")
    elif kind == 1:
        p.add(("M8", None))
    elif kind == 2:
        p.add(("M9", None))
    else:
        p.add(("G4", None), ("P", 0.5))


def generate(seed: int) -> Program:
    rng = random.Random(seed)
    p = Program()
    p.radius = rng.choice([2, 4, 8, 16, 31]) * 0.0254  # whole thousandths of an inch: exact in rs274's table
    p.tip = rng.randint(0, 9)
    p.add(("G18", None), ("G21", None), ("G7", None), ("G90", None), ("G40", None), ("G94", None), ("F", 150.0))
    p.add(("T", 1.0), ("M6", None))
    start = (_grid(rng, 5, 15), _grid(rng, 20, 45))
    p.add(("G0", None), ("X", 2 * start[1]), ("Z", start[0]))
    p.pos = start
    for _ in range(rng.randint(1, 2)):
        p.add((rng.choice(["G41", "G42"]), None))
        compensated_moves(rng, p, _line, _arc, _other, (2, 8), 0.85)
        target = (_grid(rng, 5, 15), _grid(rng, 20, 45))
        p.add(("G40", None), ("G0", None), ("X", 2 * target[1]), ("Z", target[0]))
        p.pos = target
    p.add(("M2", None))
    return p


def rs274_path(calls: list[str], end: int, scale: float) -> list[dict[str, Any]]:
    """rs274's moves (X a radius), coolant and dwell events, mm; the M2 block left out."""
    mm = 1.0 / scale
    out: list[dict[str, Any]] = []
    pos = (0.0, 0.0)
    flood = False
    for name, _, nums in calls_before(calls, end):
        if name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            new = (nums[0] * mm, nums[2] * mm)
            if max(abs(a - b) for a, b in zip(new, pos)) > 1e-9:
                out.append({"move": "rapid" if name == "STRAIGHT_TRAVERSE" else "feed", "x": new[0], "z": new[1]})
            pos = new
        elif name == "ARC_FEED":  # in G18: first the Z end, then X; the centre likewise
            e1, e2, c1, c2, rotation = nums[:5]
            out.append({"move": "ccw" if rotation > 0 else "cw", "x": e2 * mm, "z": e1 * mm,
                        "cx": c2 * mm, "cz": c1 * mm})
            pos = (e2 * mm, e1 * mm)
        elif name in ("FLOOD_ON", "FLOOD_OFF"):
            if flood != (name == "FLOOD_ON"):
                flood = name == "FLOOD_ON"
                out.append({"event": "coolant", "on": flood})
        elif name == "DWELL":
            out.append({"event": "dwell", "seconds": nums[0]})
    return out


def check(seed: int) -> str:
    """Compare one program; what happened ("moves" or "refused")."""
    p = generate(seed)
    tolerance = TOLERANCE
    try:
        try:
            theirs: list[dict[str, Any]] | None = rs274_path(
                run_rs274(p.text(SCALE), tool_table=p.tool_table()), len(p.blocks), SCALE)
        except RS274Error as err:
            if MISMATCH not in str(err):
                raise
            theirs = rs274_path(run_rs274(p.text(), tool_table=p.tool_table(1.0)), len(p.blocks), 1.0)
            tolerance = UNSCALED
        refused_at = None
    except RS274Error as err:
        theirs = None
        refused_at = refused_line(err)
    ours, errors = postproc_path(p.text(), p.setup(), ("move", "x", "z", "cx", "cz"), radius_x=True)
    listing = f"seed {seed}:\n{p.text()}\nnose radius {p.radius} mm, tip {p.tip} (rs274 Q{mirrored(p.tip)})"
    return assert_same(ours, errors, theirs, refused_at, tolerance, listing)


@pytest.mark.parametrize("batch", range(math.ceil(PROGRAMS / BATCH)))
def test_nose_compensated_paths_equal_rs274(batch: int) -> None:
    outcomes = [check(seed) for seed in range(batch * BATCH, min(PROGRAMS, (batch + 1) * BATCH))]
    assert "moves" in outcomes  # the batch compared paths, not only refusals


DYNAMIC = """G18 G21 G7 G90 G94
G0 X60 Z5
G42.1 D1.6 L{orientation}
G1 X40 Z0 F100
G1 Z-20
G1 X60 Z-30
G3 X80 Z-40 K-10 I0
G1 X100
G2 X120 Z-50 I10 K0
G40 G0 X130 Z5
M2
"""


@pytest.mark.parametrize("orientation", range(10))
def test_dynamic_nose_compensation_equals_rs274(orientation: int) -> None:
    """G42.1 D.. L..: the diameter and orientation in the block (L in LinuxCNC's numbers) [V: rs274]."""
    text = DYNAMIC.format(orientation=orientation)
    scaled = "\n".join(re.sub(r"([XZIKD])(-?[\d.]+)", lambda m: m.group(1) + _number(float(m.group(2)) * SCALE), line)
                       for line in text.splitlines()) + "\n"
    theirs = rs274_path(run_rs274(scaled), 11, SCALE)
    setup = load_setup(SETUP)
    ours = []
    for ev in toolpath_events(io.StringIO(text), file="d.ngc", dialect="linuxcnc", setup=setup):
        if "move" in ev:
            point = {**ev, **ev.get("controlled", {})}
            ours.append({k: (point[k] / 2.0 if k in ("x", "cx") else point[k])
                         for k in ("move", "x", "z", "cx", "cz") if k in point})
    assert [m["move"] for m in ours] == [m["move"] for m in theirs]
    for a, b in zip(ours, theirs):
        assert a.keys() == b.keys()
        for key in a:
            if key != "move":
                assert a[key] == pytest.approx(b[key], abs=TOLERANCE), (key, ours, theirs)
