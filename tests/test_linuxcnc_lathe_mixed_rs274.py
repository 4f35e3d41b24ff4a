"""A seeded random differential of whole LinuxCNC lathe programs against rs274 (its lathe mode), move by move:
what ``tests/test_lathe_rs274.py`` (G7 turning and G33 threads) and ``tests/test_linuxcnc_lathe_g76.py`` (one
G76 a program) do not cover together: LinuxCNC's own ``G76`` among turning and facing moves, arcs, straight and
tapered ``G33``, ``G96 S.. D..``/``G97``, ``G95``/``G94`` changes and ``G91`` stretches, in diameter mode
(``G7``, the set-up's X diameters) and in radius mode (``G8``, a set-up with ``xProgramming="radius"``), metric
and inch.

The oracle is rs274 2.9 (``tests/support/rs274.py``), compared as in ``tests/test_lathe_rs274.py`` (end points
and arc centres as radii, the feed of a feed move, a thread move's lead along its major axis). Programs that
switch G7/G8 mid-way: ``tests/test_linuxcnc_x_mode_switch.py``.
"""

from __future__ import annotations

import io
import math
import os
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available
from tests.test_lathe_rs274 import INCH_TOLERANCE, TOLERANCE, difference, theirs

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

ROOT = Path(__file__).resolve().parents[1]
SEEDS = int(os.environ.get("POSTPROC_LATHE_DIFFERENTIAL", "60"))


def _setup(radius: bool) -> MachineSetup:
    setup = load_setup(str(ROOT / "examples" / "setups" / "linuxcnc_lathe.xml"))
    if radius:
        setup.input.x_programming = "radius"
    return setup


def _ours(text: str, setup: MachineSetup) -> list[dict[str, Any]]:
    """Our moves with X and an arc centre's X as radii, whichever mode the toolpath reports X in."""
    events = list(toolpath_events(io.StringIO(text), file="prog", dialect="linuxcnc", setup=setup))
    half = 0.5 if events[0].get("x_mode") == "diameter" else 1.0
    return [{k: float(v) * half if k in ("x", "cx") else v for k, v in ev.items()} for ev in events[1:]
            if "move" in ev]


def _n(value: float) -> str:
    text = f"{value:.4f}".rstrip("0")
    return "0." if text in ("-0.", "0.") else text


def program(seed: int) -> tuple[str, bool, bool]:
    """(text, radius mode, inch): a random lathe program on grid values (radius below is the true distance from
    the axis; ``k`` scales it to the program's X: 2 in G7, 1 in G8)."""
    rng = random.Random(seed)
    radius_mode, inch = rng.random() < 0.4, rng.random() < 0.25
    k = 1.0 if radius_mode else 2.0
    s = 0.04 if inch else 1.0  # a program unit in "mm of the grid" (inch programs on a 0.02 in grid)
    per_rev = rng.random() < 0.6
    lines = ["G18 " + ("G8" if radius_mode else "G7") + (" G20" if inch else " G21") + " G90 " +
             ("G95" if per_rev else "G94")]
    lines.append(rng.choice(("S600 M3", f"G96 S{120 if not inch else 400} D2500 M3", "G97 S800 M4")))
    r, z = rng.randint(18, 30), rng.randint(1, 4)

    def feed() -> str:
        return _n(rng.choice((0.05, 0.1, 0.2)) * (s if inch else 1.0)) if per_rev else _n(rng.choice((60, 150)) * s)

    def xz(radius: float, zz: float) -> str:
        return f"X{_n(radius * k * s)} Z{_n(zz * s)}"

    lines.append("G0 " + xz(r, z))
    incremental = False
    for _ in range(rng.randint(4, 8)):
        op = rng.choice(("feed", "feed", "rapid", "arc", "thread", "taper", "g76", "mode", "g91"))
        if op == "g91":
            incremental = not incremental
            lines.append("G91" if incremental else "G90")
            continue
        if incremental and op in ("g76", "arc"):
            incremental = False
            lines.append("G90")
        if op in ("feed", "rapid"):
            r1, z1 = rng.randint(8, 32), rng.randint(-30, 3)
            words = (f"X{_n((r1 - r) * k * s)} Z{_n((z1 - z) * s)}" if incremental else xz(r1, z1))
            lines.append(("G1 " if op == "feed" else "G0 ") + words + (f" F{feed()}" if op == "feed" else ""))
            r, z = r1, z1
        elif op == "arc":
            q = rng.choice((1, 2, 3))
            if r <= 2 * q + 1:
                continue
            out = rng.choice((-1, 1))
            # a quarter circle to (z - q, r + out q), about the centre below its start or beside it
            i, kk = (0.0, -q) if rng.random() < 0.5 else (out * q, 0.0)
            r1, z1 = r + out * q, z - q
            assert abs(math.hypot(z1 - (z + kk), r1 - (r + i)) - q) < 1e-9
            turn = rng.choice(("G2", "G3"))
            lines.append(f"{turn} {xz(r1, z1)} I{_n(i * s)} K{_n(kk * s)} F{feed()}")
            r, z = r1, z1
        elif op == "thread":
            z1 = rng.randint(-30, z - 2) if z > -28 else z - 2
            words = f"Z{_n((z1 - z) * s)}" if incremental else f"Z{_n(z1 * s)}"
            lines.append(f"G33 {words} K{_n(rng.choice((1.0, 1.5, 2.0)) * s)}")
            z = z1
        elif op == "taper":
            dz = rng.randint(4, 12)
            dr = rng.randint(-2, 2) if r > 12 else rng.randint(0, 2)
            words = (f"X{_n(dr * k * s)} Z{_n(-dz * s)}" if incremental else xz(r + dr, z - dz))
            lines.append(f"G33 {words} K{_n(rng.choice((1.0, 2.0)) * s)}")
            r, z = r + dr, z - dz
        elif op == "g76":
            r0 = rng.randint(14, 26)
            z0 = rng.randint(1, 4)
            lines.append("G0 " + xz(r0 + 3, z0))
            depth = rng.choice((0.6, 1.0))
            j = rng.choice((0.1, 0.2))
            words = [f"P{_n(rng.choice((1.0, 1.5)) * s)}", f"Z{_n(rng.randint(-25, -8) * s)}",
                     f"I{_n(-3 * k * s)}", f"J{_n(j * k * s)}", f"K{_n((j + depth) * k * s)}"]
            if rng.random() < 0.5:
                words.append(f"R{rng.choice((1.5, 2.))}")
            if rng.random() < 0.5:
                words.append(f"Q{rng.choice((0., 29.5))}")
            if rng.random() < 0.4:
                words.append(f"H{rng.choice((0, 1))}")
            if rng.random() < 0.3:
                words.append(f"E{_n(1.0 * k * s)} L{rng.choice((1, 2, 3))}")
            lines.append("G76 " + " ".join(words))
            r, z = r0 + 3, round(float(words[1][1:]) / s)
            lines.append("G0 " + xz(r, z))  # (where the cycle ends depends on its words: a known point after it)
        else:
            per_rev = not per_rev
            lines.append(("G95" if per_rev else "G94") + f" F{feed()} " +
                         rng.choice(("G97 S700", f"G96 S{100 if not inch else 330} D1800", "")))
    if incremental:
        lines.append("G90")
    lines += ["M5", "M2"]
    return "\n".join(line.rstrip() for line in lines) + "\n", radius_mode, inch


@pytest.mark.parametrize("seed", range(SEEDS))
def test_linuxcnc_lathe_programs_move_as_rs274_runs_them(seed: int) -> None:
    text, radius_mode, inch = program(seed)
    problem = difference(_ours(text, _setup(radius_mode)), theirs(text), INCH_TOLERANCE if inch else TOLERANCE)
    assert problem is None, f"{problem}\n\n{text}"
