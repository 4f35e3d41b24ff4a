"""Differential test: postproc's tool length and cutter radius compensation against LinuxCNC's interpreter.

A seeded generator writes LinuxCNC programs that run G41/G42 (with a D register, or without one after a
tool change: the spindle tool's radius, whatever T was selected since) over lines and arcs, both sides, entry and exit moves, inside and
outside corners (tangent ones too), moves along Z only and rapids under compensation, coolant and dwell
events that wait behind a queued move, and G43 tool length offsets (with H, or without: the spindle tool); each is run through postproc's
``toolpath`` (linuxcnc dialect) and through ``rs274`` with the same tool table. The controlled points must
agree within ``TOLERANCE`` move by move (arc centres and feeds too), the events in the same order, and a program
rs274 refuses (a gouge, an entry move too short, an arc after G40) must be refused by postproc at the
same block.

A quarter of the programs run in the ZX plane (G18): the same program with its words renamed (X Y Z I J ->
Z X Y K I), the plane's first axis Z and its second X as LinuxCNC's ``comp_get_current`` has them, and its
arcs' ``ARC_FEED`` read back as (Z, X) with Y along the normal.

A quarter of the programs are in inches (G20: the same numbers read as inches, the radii the same
lengths). rs274 prints 4 decimals, so it runs the program scaled by ``SCALE`` (every length word and the
tool table; ten times more in inches): its output divided back resolves 1e-7 mm (2.5e-7 mm in inches). Every rule it checks is an angle or a ratio, so the
scaled program takes the same decisions. Its tool table is in inches (RS274_NOTES.md); its canonical
moves leave the tool length out (``USE_TOOL_LENGTH_OFFSET`` says it), so this test adds it.

``POSTPROC_COMPENSATION_PROGRAMS`` raises the number of programs (200 by default) for a longer run.
"""

from __future__ import annotations

import math
import os
import random
from dataclasses import dataclass, field
from typing import Any, Iterator

import pytest

from postproc.setup.machine_setup import MachineSetup
from postproc.setup.machine import ToolData
from tests.support.compensation_rs274 import (assert_same, calls_before, compensated_moves, postproc_path,
                                              refused_line)
from tests.support.rs274 import RS274Error, available, run_rs274

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

PROGRAMS = int(os.environ.get("POSTPROC_COMPENSATION_PROGRAMS", "200"))
BATCH = 25
SCALE = 1000.0
"""rs274 runs every length times this (4 printed decimals -> 1e-7 mm here)."""
TOLERANCE = 1e-6
"""mm, on every coordinate of every move."""
MM_PER_INCH = 25.4
RESULTS = {"programs": 0, "agreed_moves": 0, "agreed_errors": 0}


@pytest.fixture(scope="module", autouse=True)
def _report(request: pytest.FixtureRequest) -> Iterator[None]:
    yield
    line = (f"cutter compensation vs rs274: {RESULTS['programs']} programs, {RESULTS['agreed_moves']} moves "
            f"equal within {TOLERANCE:g} mm, {RESULTS['agreed_errors']} refused at the same block by both")
    reporter = request.config.pluginmanager.get_plugin("terminalreporter")
    capture = request.config.pluginmanager.get_plugin("capturemanager")
    if reporter is None or capture is None:
        print(line)
        return
    with capture.global_and_fixture_disabled():
        reporter.write_line("\n" + line)


# -- programs ----------------------------------------------------------------------------------------

LENGTH_WORDS = frozenset("XYZIJKR")
ZX_WORDS = {"X": "Z", "Y": "X", "Z": "Y", "I": "K", "J": "I", "G17": "G18"}
"""A program in the XY plane renamed into the ZX plane: its first axis Z, its second X, its normal Y."""


@dataclass
class Program:
    """Blocks of (letter, value) words; lengths in mm, rendered at any scale."""

    blocks: list[list[tuple[str, float | None]]] = field(default_factory=list)
    radii: dict[int, float] = field(default_factory=dict)
    lengths: dict[int, float] = field(default_factory=dict)
    """Tool radii and lengths by register, mm."""
    unit: float = 1.0
    """mm per program unit (25.4 in a G20 program)."""
    plane: str = "XY"
    """"ZX": the words are renamed by ``ZX_WORDS`` when written."""
    pos: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    """The programmed point (first plane axis, second, normal), mm."""
    last_dir: tuple[float, float] = (1.0, 0.0)

    def add(self, *words: tuple[str, float | None]) -> None:
        self.blocks.append(list(words))

    def text(self, scale: float = 1.0) -> str:
        out = []
        for n, words in enumerate(self.blocks, start=1):
            parts = [f"N{n}"]
            for letter, value in words:
                if self.plane == "ZX":
                    letter = ZX_WORDS.get(letter, letter)
                if value is None:
                    parts.append(letter)
                elif letter in LENGTH_WORDS:
                    parts.append(f"{letter}{_number(value * scale)}")
                else:
                    parts.append(f"{letter}{_number(value)}")
            out.append(" ".join(parts))
        return "\n".join(out) + "\n"

    @property
    def scale(self) -> float:
        """How much larger rs274 runs it."""
        return SCALE * (10.0 if self.unit != 1.0 else 1.0)

    def tool_table(self) -> str:
        """rs274's table, in inches, at ``scale``."""
        return "".join(f"T{n} P{n} D{2 * self.radii[n] * self.scale / MM_PER_INCH!r} "
                       f"Z{self.lengths.get(n, 0.0) * self.scale / MM_PER_INCH!r} ;\n" for n in sorted(self.radii))

    def setup(self) -> MachineSetup:
        setup = MachineSetup()
        setup.tools = {str(n): ToolData(number=n, length=self.lengths.get(n, 0.0), radius=r)
                       for n, r in self.radii.items()}
        return setup


def _number(v: float) -> str:
    text = f"{v:.6f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _q(v: float) -> float:
    """On a 1/8 mm grid: three decimals, written exactly at any scale (both runs read the same numbers)."""
    return round(v * 8.0) / 8.0


def _grid(rng: random.Random, lo: float, hi: float, step: float = 0.5) -> float:
    return rng.randint(round(lo / step), round(hi / step)) * step


def _line(rng: random.Random, p: Program, code: str = "G1") -> None:
    choice = rng.random()
    dx, dy = p.last_dir
    if choice < 0.15:  # straight on
        k = rng.choice([0.5, 1.0, 2.0])
        target = [_q(p.pos[0] + k * dx), _q(p.pos[1] + k * dy)]
    elif choice < 0.22:  # straight back (a zero-degree corner)
        k = rng.choice([0.25, 0.5])
        target = [_q(p.pos[0] - k * dx), _q(p.pos[1] - k * dy)]
    else:
        target = [_grid(rng, -40, 40), _grid(rng, -40, 40)]
    if target == p.pos[:2]:
        target[0] += 5.0
    incremental = rng.random() < 0.15
    if incremental:  # G91: the words are distances from the programmed point (as rs274's program_x)
        words: list[tuple[str, float | None]] = [("G91", None), (code, None), ("X", target[0] - p.pos[0]),
                                                 ("Y", target[1] - p.pos[1])]
    else:
        words = [(code, None), ("X", target[0]), ("Y", target[1])]
    if rng.random() < 0.2:
        z = _grid(rng, -5, 5)
        words.append(("Z", z - p.pos[2] if incremental else z))
        p.pos[2] = z
    if code == "G1" and rng.random() < 0.3:
        words.append(("F", float(rng.choice([100, 250, 400]))))
    p.add(*words)
    if incremental:
        p.add(("G90", None))
    p.last_dir = (target[0] - p.pos[0], target[1] - p.pos[1])
    p.pos[0], p.pos[1] = target


def _arc(rng: random.Random, p: Program) -> None:
    """An arc ending exactly on its circle; sometimes tangent to the move before it."""
    if rng.random() < 0.35:
        dx, dy = p.last_dir
        m = rng.choice([-1.0, -0.5, 0.5, 1.0]) * (8.0 / max(abs(dx), abs(dy), 1e-9))
        m = round(m * 2.0) / 2.0 or 0.5
        i, j = _q(-dy * m), _q(dx * m)
        ccw = m > 0  # the centre on the left of the motion: counter-clockwise continues tangent
    else:
        i, j = _grid(rng, -15, 15), _grid(rng, -15, 15)
        if i == 0 and j == 0:
            i = 3.0
        ccw = rng.random() < 0.5
    if abs(i) > 60 or abs(j) > 60:
        i, j = 4.0, 0.0
    quarters = rng.randint(1, 4)
    cx, cy = p.pos[0] + i, p.pos[1] + j
    vx, vy = -i, -j
    for _ in range(quarters):
        vx, vy = (-vy, vx) if ccw else (vy, -vx)
    end = (cx + vx, cy + vy)
    words: list[tuple[str, float | None]] = [("G3" if ccw else "G2", None), ("X", end[0]), ("Y", end[1])]
    if quarters in (1, 3) and (i == 0 or j == 0) and rng.random() < 0.5:  # the R form (a radius on the grid)
        words.append(("R", math.hypot(i, j) * (-1.0 if quarters == 3 else 1.0)))
    else:
        words += [("I", i), ("J", j)]
    if rng.random() < 0.15:  # a helix
        p.pos[2] = _grid(rng, -5, 5)
        words.append(("Z", p.pos[2]))
    p.add(*words)
    p.last_dir = (-vy, vx) if ccw else (vy, -vx)
    p.pos[0], p.pos[1] = end


def _other(rng: random.Random, p: Program) -> None:
    kind = rng.randrange(5)
    if kind == 0:
        z = _grid(rng, -5, 5)
        p.add(("G1", None), ("Z", z))
        p.pos[2] = z
    elif kind == 1:
        _line(rng, p, "G0")
    elif kind == 2:
        p.add(("M8", None))
    elif kind == 3:
        p.add(("M9", None))
    else:
        p.add(("G4", None), ("P", 0.5))


def generate(seed: int) -> Program:
    rng = random.Random(seed)
    p = Program()
    # whole thousandths of an inch: rs274's table (inches) holds them exactly, so neither side rounds
    p.radii = {n: rng.choice([2, 4, 8, 12, 16, 20, 24, 32]) * 0.127 for n in range(1, 7)}
    p.lengths = {n: rng.choice([0, 500, 1000, 1625]) * 0.0254 for n in range(1, 7)}
    if rng.random() < 0.25:
        p.unit = MM_PER_INCH
    if random.Random(-1 - seed).random() < 0.25:  # its own stream: the XY programs stay those of earlier runs
        p.plane = "ZX"
    p.add(("G20" if p.unit != 1.0 else "G21", None), ("G17", None), ("G90", None), ("G40", None), ("G49", None),
          ("G94", None), ("F", 200.0))
    tool = None
    if rng.random() < 0.6:
        tool = rng.randint(1, 6)
        p.add(("T", float(tool)), ("M6", None))
        if rng.random() < 0.3:
            p.add(("T", float(rng.randint(1, 6))))  # selected, not loaded: G43 and G41 without H/D ignore it
        if rng.random() < 0.7:
            p.add(("G43", None), *([("H", float(tool))] if rng.random() < 0.5 else []))
    start = [_grid(rng, -20, 20), _grid(rng, -20, 20), _grid(rng, 0, 10)]
    p.add(("G0", None), ("X", start[0]), ("Y", start[1]), ("Z", start[2]))
    p.pos = list(start)
    for _ in range(rng.randint(1, 3)):
        side = rng.choice(["G41", "G42"])
        on: list[tuple[str, float | None]] = [(side, None)]
        if tool is None or rng.random() < 0.6:
            on.append(("D", float(rng.randint(1, 6))))
        p.add(*on)
        compensated_moves(rng, p, _line, _arc, _other, (2, 9), 0.8)
        target = (_grid(rng, -40, 40), _grid(rng, -40, 40))
        if rng.random() < 0.5:
            p.add(("G40", None))
            if rng.random() < 0.05:
                _arc(rng, p)  # refused: the move after G40 must be straight
            p.add(("G1", None), ("X", target[0]), ("Y", target[1]))
        else:
            p.add(("G40", None), ("G1", None), ("X", target[0]), ("Y", target[1]))
        p.pos[0], p.pos[1] = target
    p.add(("M2", None))
    return p


# -- running both --------------------------------------------------------------------------------------

def rs274_path(calls: list[str], end: int, scale: float, unit: float, plane: str = "XY") -> list[dict[str, Any]]:
    """rs274's moves with the tool length added (controlled points), coolant and dwell, in mm (its calls
    are in program units times ``scale``); the block ``end`` (M2) is left out: what M2 resets (coolant
    off...) is no part of the path. An arc's ``ARC_FEED`` gives (first, second) plane axis, then the
    normal: (X, Y), Z in the XY plane, (Z, X), Y in the ZX plane."""
    mm = unit / scale
    out: list[dict[str, Any]] = []
    pos = (0.0, 0.0, 0.0)
    dz = 0.0
    feed = 0.0
    units = 1.0  # mm per unit of the calls made so far (rs274 sets a block's F before its G20/G21)
    flood = False
    for name, args, nums in calls_before(calls, end):
        if name == "USE_TOOL_LENGTH_OFFSET":
            dz = nums[2] * mm
        elif name == "USE_LENGTH_UNITS":
            units = MM_PER_INCH if "INCHES" in args else 1.0
        elif name == "SET_FEED_RATE":
            feed = nums[0] * units  # mm/min (the F word is not scaled)
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            new = (nums[0] * mm, nums[1] * mm, nums[2] * mm)
            if max(abs(a - b) for a, b in zip(new, pos)) > 1e-9:
                out.append({"move": "rapid" if name == "STRAIGHT_TRAVERSE" else "feed",
                            "x": new[0], "y": new[1], "z": new[2] + dz})
                if name == "STRAIGHT_FEED":
                    out[-1]["f"] = feed
            pos = new
        elif name == "ARC_FEED":
            e1, e2, c1, c2, rotation, e3 = nums[:6]
            if plane == "ZX":
                end_point, centre = (e2 * mm, e3 * mm, e1 * mm), (c2 * mm, pos[1], c1 * mm)
            else:
                end_point, centre = (e1 * mm, e2 * mm, e3 * mm), (c1 * mm, c2 * mm, pos[2])
            out.append({"move": "ccw" if rotation > 0 else "cw", "x": end_point[0], "y": end_point[1],
                        "z": end_point[2] + dz, "cx": centre[0], "cy": centre[1], "cz": centre[2] + dz, "f": feed})
            pos = end_point
        elif name in ("FLOOD_ON", "FLOOD_OFF"):
            if flood != (name == "FLOOD_ON"):
                flood = name == "FLOOD_ON"
                out.append({"event": "coolant", "on": flood})
        elif name == "DWELL":
            out.append({"event": "dwell", "seconds": nums[0]})
    return out


def check(seed: int) -> None:
    p = generate(seed)
    try:
        theirs: list[dict[str, Any]] | None = rs274_path(run_rs274(p.text(p.scale), tool_table=p.tool_table()),
                                                       len(p.blocks), p.scale, p.unit, p.plane)
        refused_at = None
    except RS274Error as err:
        theirs = None
        refused_at = refused_line(err)
    ours, errors = postproc_path(p.text(), p.setup(), ("move", "x", "y", "z", "cx", "cy", "cz", "f"))
    listing = f"seed {seed}:\n{p.text()}\ntool table (mm): radii {p.radii}, lengths {p.lengths}"
    RESULTS["programs"] += 1
    if assert_same(ours, errors, theirs, refused_at, TOLERANCE, listing) == "refused":
        RESULTS["agreed_errors"] += 1
    else:
        RESULTS["agreed_moves"] += sum(1 for e in ours if "move" in e)


@pytest.mark.parametrize("batch", range(math.ceil(PROGRAMS / BATCH)))
def test_compensated_paths_equal_rs274(batch: int) -> None:
    for seed in range(batch * BATCH, min(PROGRAMS, (batch + 1) * BATCH)):
        check(seed)
