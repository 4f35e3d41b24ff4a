"""Lathe programs against the real LinuxCNC interpreter (``rs274``) in lathe mode.

Standalone rs274 has no ini, so a program puts it in lathe mode itself: ``G18`` (the ZX plane) and ``G7``
(diameter mode: X is a diameter, rs274 prints the radius, arc I stays a radius) [V: rs274 2.9]. Two
seeded random differentials, ``SEEDS`` programs each (``POSTPROC_LATHE_DIFFERENTIAL`` raises it):

* LinuxCNC lathe programs (G0/G1, G2/G3 in ZX with I/K, straight and tapered ``G33 K``, G94/G95,
  ``G96 S D``/``G97``, G4) read by our linuxcnc dialect with a lathe set-up, move by move against rs274;
* Fanuc T and GSK 980TDc programs (U/W, G02/G03 with R, ``G32``, ``G90``, ``G92``, ``G94``, the two-block
  ``G76`` with and without its pull-out chamfer, ``G50 S`` with ``G96``, G98/G99 at the start and switched in
  mid-program), translated to LinuxCNC:
  the source's toolpath against rs274 running the translation, and our reading of the translation too.

Compared per move: end points and arc centres as radii (ours are diameters, ``x_mode``), the feed of a
feed move (mm/rev or mm/min as programmed) and its mode (per revolution or not: rs274's ``SET_FEED_MODE``),
and a thread move's lead: ours along its major axis (F, or ``ThreadLead``), rs274's ``START_SPEED_FEED_SYNC``
along the path, converted with the move's own geometry (``postproc.geometry.thread_lead``). The done-when programs (the bundled Fanuc T and GSK examples) go the same way.
"""

from __future__ import annotations

import io
import math
import os
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.geometry.thread_lead import lead_along_major
from tests.support.rs274 import available, canonical_moves, run_rs274

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

ROOT = Path(__file__).resolve().parents[1]
SETUPS = ROOT / "examples" / "setups"
SEEDS = int(os.environ.get("POSTPROC_LATHE_DIFFERENTIAL", "100"))
"""Programs per differential (two differentials: 200 in the suite)."""
TOOLS = "".join(f"T{t} P{t} X0 Z0 D0 ;\n" for t in range(1, 100))
"""rs274's tool table: every turret position a program may index, without offsets (the toolpath compares
programmed points)."""
TOLERANCE = 2e-4
"""mm: rs274 prints 4 decimals (radii from diameters on a 0.5 grid, and computed cycle points)."""
INCH_TOLERANCE = 1.3e-3
"""mm: in an inch program rs274 prints 4 decimals of an inch (0.00254 mm)."""


def _setup(name: str) -> MachineSetup:
    return load_setup(str(SETUPS / name))


# -- comparing ---------------------------------------------------------------------------------------

def ours(text: str, dialect: str, setup: MachineSetup) -> list[dict[str, Any]]:
    """Our toolpath's moves as radii."""
    events = list(toolpath_events(io.StringIO(text), file="prog", dialect=dialect, setup=setup))
    assert events[0].get("x_mode") == "diameter"
    header_mode = events[0].get("feed_mode", "per_min")
    moves = []
    for ev in events[1:]:
        if "move" not in ev:
            continue
        move = {k: float(v) / 2.0 if k in ("x", "cx") else v for k, v in ev.items()}
        if move["move"] != "rapid":  # its feed mode: the one it states, else the header's
            move["per_rev"] = move.pop("feed_mode", header_mode) == "per_rev"
        moves.append(move)
    return moves


def theirs(ngc: str) -> list[dict[str, Any]]:
    """rs274's moves, a synchronised move's lead along its major axis as ``f``."""
    moves: list[dict[str, Any]] = []
    pos: tuple[float, float] | None = None
    for ev in canonical_moves(run_rs274(ngc, tool_table=TOOLS), start=(0.0, 0.0, 0.0), feeds=True, synced=True,
                              modes=True):
        if "move" not in ev:
            continue
        if "sync" in ev and pos is not None:
            ev["f"] = lead_along_major(ev.pop("sync"), ev["x"] - pos[0], ev["z"] - pos[1])
        pos = (ev["x"], ev["z"])
        moves.append(ev)
    return moves


def difference(a: list[dict[str, Any]], b: list[dict[str, Any]], tolerance: float = TOLERANCE) -> str | None:
    """The first move where ``a`` and ``b`` differ by more than ``tolerance`` mm, or None."""
    for n, (x, y) in enumerate(zip(a, b)):
        if x["move"] != y["move"]:
            return f"move {n}: ours {x}, rs274 {y}"
        keys = ["x", "z"] + (["cx", "cz"] if x["move"] in ("cw", "ccw") else []) + \
            (["f"] if x["move"] != "rapid" else [])
        if x["move"] != "rapid" and "per_rev" in x and "per_rev" in y and x["per_rev"] != y["per_rev"]:
            return f"move {n}: feeds per {'revolution' if x['per_rev'] else 'minute'} in ours, not in rs274's: " \
                   f"ours {x}, rs274 {y}"
        dev = max(abs(float(x[k]) - float(y[k])) for k in keys)
        if dev > tolerance or math.isnan(dev):
            return f"move {n}: {dev:.6f} apart: ours {x}, rs274 {y}"
    if len(a) != len(b):
        return f"ours has {len(a)} moves, rs274 {len(b)}"
    return None


def to_linuxcnc(text: str, dialect: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="prog", source=dialect, target="linuxcnc", setup=setup)
    return out.getvalue()


# -- LinuxCNC lathe programs -------------------------------------------------------------------------

def d(rng: random.Random, lo: float, hi: float) -> float:
    """A diameter or Z on a 0.5 grid."""
    return rng.randint(int(lo * 2), int(hi * 2)) / 2.0


def n(value: float) -> str:
    text = f"{value:.4f}".rstrip("0")
    return "0." if text in ("-0.", "0.") else text


def ngc_program(seed: int) -> str:
    rng = random.Random(seed)
    per_rev = rng.random() < 0.6
    lines = ["G18 G7 G21 G90 " + ("G95" if per_rev else "G94")]
    feed = (lambda: n(rng.choice((0.05, 0.1, 0.15, 0.2, 0.25)))) if per_rev else (lambda: n(rng.choice((60, 120, 250))))
    lines.append(rng.choice(("S600 M3", "G96 S150 D2500 M3", "G96 S120 M4")))
    x, z = d(rng, 30, 60), d(rng, 1, 5)
    lines.append(f"G0 X{n(x)} Z{n(z)}")
    for _ in range(rng.randint(4, 9)):
        op = rng.choice(("feed", "feed", "rapid", "arc", "thread", "taper", "mode", "dwell"))
        if op in ("feed", "rapid"):
            x, z = d(rng, 10, 70), d(rng, -60, 5)
            lines.append(("G1" if op == "feed" else "G0") + f" X{n(x)} Z{n(z)}" + (f" F{feed()}" if op == "feed" else ""))
        elif op == "arc":
            r = rng.choice((1.0, 2.0, 2.5, 4.0))  # a quarter (or three quarters) of a circle through grid points
            out = rng.choice((-1, 1)) if x / 2.0 > 2 * r + 1 else 1
            centre = rng.choice(("below", "beside"))
            i, k = (0.0, -r) if centre == "below" else (out * r, 0.0)
            x, z = x + 2 * out * r, z - r
            lines.append(f"{rng.choice(('G2', 'G3'))} X{n(x)} Z{n(z)} I{n(i)} K{n(k)} F{feed()}")
        elif op == "thread":
            z = d(rng, min(-50, z - 11), z - 1)
            lines.append(f"G33 Z{n(z)} K{n(rng.choice((0.75, 1.0, 1.5, 2.0)))}")
        elif op == "taper":
            dz = d(rng, 3, 20)
            dx = d(rng, -dz / 2, dz / 2) if x > dz + 12 else d(rng, 0, dz / 2)  # diameter change under the Z travel
            x, z = x + dx * 2 if x + dx * 2 > 8 else x, z - dz
            lines.append(f"G33 X{n(x)} Z{n(z)} K{n(rng.choice((1.0, 1.5, 2.5)))}")
        elif op == "mode":
            per_rev = not per_rev
            feed = (lambda: n(rng.choice((0.05, 0.1, 0.2)))) if per_rev else (lambda: n(rng.choice((60, 120, 250))))
            lines.append(("G95" if per_rev else "G94") + f" F{feed()} " + rng.choice(("G97 S800", "G96 S100 D1800", "")))
        else:
            lines.append("G4 P0.5")
    lines += ["M5", "M2"]
    return "\n".join(line.rstrip() for line in lines) + "\n"


@pytest.mark.parametrize("seed", range(SEEDS))
def test_linuxcnc_lathe_reading_matches_rs274(seed: int) -> None:
    text = ngc_program(seed)
    problem = difference(ours(text, "linuxcnc", _setup("linuxcnc_lathe.xml")), theirs(text))
    assert problem is None, f"{problem}\n\n{text}"


# -- Fanuc T / GSK programs, translated ----------------------------------------------------------------

def fanuc_program(seed: int, gsk: bool) -> str:
    rng = random.Random(seed)
    per_rev = rng.random() < 0.7
    lines = ["G21 " + ("G99" if per_rev else "G98")]
    feed = (lambda: n(rng.choice((0.1, 0.15, 0.2, 0.3)))) if per_rev else (lambda: n(rng.choice((80., 150., 300.))))
    if rng.random() < 0.5:
        lines += ["G50 S2000", "G96 S160 M03"]
    else:
        lines.append("G97 S700 M03")
    x0, z0 = d(rng, 50, 70), d(rng, 2, 6)
    lines.append(f"G00 X{n(x0)} Z{n(z0)}")
    x, z = x0, z0
    for _ in range(rng.randint(3, 6)):
        op = rng.choice(("feed", "incremental", "arc", "g32", "g90", "g94", "g92", "g76", "mode"))
        if op == "mode":  # the feed mode switched in mid-program, a feed in the new mode at once
            per_rev = not per_rev
            feed = (lambda: n(rng.choice((0.1, 0.2)))) if per_rev else (lambda: n(rng.choice((80., 300.))))
            x, z = d(rng, 20, 70), d(rng, -50, 4)
            lines += ["G99" if per_rev else "G98", f"G01 X{n(x)} Z{n(z)} F{feed()}"]
            continue
        if op in ("g90", "g94", "g92", "g76"):
            lines.append(f"G00 X{n(x0)} Z{n(z0)}")
            x, z = x0, z0
            end_x, end_z = d(rng, 20, x0 - 4), d(rng, -45, -10)
            if op == "g90":
                lines.append(f"G90 X{n(end_x)} Z{n(end_z)} F{feed()}")
            elif op == "g94":
                lines.append(f"G94 X{n(end_x)} Z{n(d(rng, -6, z0 - 1))} F{feed()}")
            elif op == "g92":
                lines.append(f"G92 X{n(end_x)} Z{n(end_z)} F{n(rng.choice((1.0, 1.5, 2.0)))}")
            else:
                lead = rng.choice((1.0, 1.5, 2.0))
                chamfer = rng.choice((0, 0, 10))
                height = rng.choice((600, 900, 1200))
                root = d(rng, 20, x0 - 6)
                lines.append(f"G76 P01{chamfer:02d}60 Q{rng.choice((50, 100))} R{n(rng.choice((0.0, 0.05)))}")
                lines.append(f"G76 X{n(root)} Z{n(end_z)} P{height} Q{rng.choice((300, 450))} F{n(lead)}")
            if op != "g76":
                lines.append(f"G00 X{n(x0)} Z{n(z0)}" if op == "g94" else "G00 W0.")
            continue
        if op == "feed":
            x, z = d(rng, 20, 70), d(rng, -50, 4)
            lines.append(f"G01 X{n(x)} Z{n(z)} F{feed()}")
        elif op == "incremental":
            u, w = d(rng, -6, 6), d(rng, -8, 0)
            if x + u < 10:
                u = 0.0
            x, z = x + u, z + w
            lines.append(f"G01 U{n(u)} W{n(w)} F{feed()}")
        elif op == "arc":
            r = rng.choice((2.0, 3.0, 5.0))
            x, z = x + 2 * r, z - r
            lines.append(f"{rng.choice(('G02', 'G03'))} X{n(x)} Z{n(z)} R{n(r)} F{feed()}")
        else:
            z = d(rng, min(-50, z - 12), z - 2)
            lines.append(f"G32 Z{n(z)} F{n(rng.choice((1.0, 1.5)))}")
            lines.append(f"G01 X{n(x + 2.0)}")  # fed at the lead: F is the lead now, on both controls
            x += 2.0
    lines += ["G00 X100. Z50.", "M05", "M30"]
    if gsk:
        lines = [line.replace("G50 S", "G50 S") for line in lines]
    return "\n".join(["%", "O1234", *lines, "%"]) + "\n"


@pytest.mark.parametrize("seed", range(SEEDS))
def test_fanuc_and_gsk_lathe_translation_matches_rs274(seed: int) -> None:
    gsk = seed % 2 == 1
    dialect = "gsk" if gsk else "fanuc"
    setup = _setup("gsk_980tdc.xml" if gsk else "fanuc_0i_tf.xml")
    text = fanuc_program(seed, gsk)
    ngc = to_linuxcnc(text, dialect, setup)
    rs274 = theirs(ngc)
    problem = difference(ours(text, dialect, setup), rs274)
    assert problem is None, f"{dialect} source: {problem}\n\n{text}\n\n{ngc}"
    problem = difference(ours(ngc, "linuxcnc", _setup("linuxcnc_lathe.xml")), rs274)
    assert problem is None, f"linuxcnc reading of the translation: {problem}\n\n{ngc}"
