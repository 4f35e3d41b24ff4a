"""``translate --arcs`` against LinuxCNC's interpreter: seeded random LinuxCNC programs with arcs in every
plane (centre and R form, over half a turn, full circles, helices, G91 and G20 ones) are translated with
``--arcs ijk``, ``--arcs r`` and ``--arcs lines:TOL`` back to LinuxCNC; rs274 runs the source and each
translation, and postproc's comparison of toolpaths (``verify.compare``, with ``chord_tolerance`` for
lines) must find them equal. The arcs rs274 computes are its own: centres from R by its own rules.

rs274 prints 4 decimals, so positions agree to 1e-4 mm: ``TOLERANCE`` allows that.
``POSTPROC_ARCS_PROGRAMS`` raises the number of programs (25 by default).
"""

from __future__ import annotations

import io
import math
import os
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.lowering.arcs import parse_arc_option
from postproc.simulate.verify import compare
from tests.support.rs274 import available, canonical_moves, run_rs274

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

PROGRAMS = int(os.environ.get("POSTPROC_ARCS_PROGRAMS", "25"))
TOLERANCE = 0.001
"""mm: rs274 prints 4 decimals of the unit (2.5e-3 mm in inches: ``TOLERANCE_INCH``)."""
TOLERANCE_INCH = 0.006
CHORDS = 0.02
PLANES = {"G17": ("X", "Y", "Z", "I", "J"), "G18": ("Z", "X", "Y", "K", "I"), "G19": ("Y", "Z", "X", "J", "K")}


def _program(rng: random.Random) -> str:
    """A LinuxCNC program of random arcs (lengths in program units, 4 decimals)."""
    inch = rng.random() < 0.25
    unit = 1 / 25.4 if inch else 1.0
    lines = [f"{'G20' if inch else 'G21'} G90 G94 F{rng.choice((100, 250, 800)) * unit:.4f}"]
    pos = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    lines.append("G0 X0 Y0 Z0")
    incremental = False
    for _ in range(rng.randint(3, 8)):
        plane = rng.choice(tuple(PLANES))
        a1, a2, normal, l1, l2 = PLANES[plane]
        want_incremental = rng.random() < 0.3
        mode = ""
        if want_incremental != incremental:
            mode = "G91 " if want_incremental else "G90 "
            incremental = want_incremental
        r = round(rng.uniform(1, 40) * unit, 4)
        start_angle = rng.uniform(-math.pi, math.pi)
        centre = (pos[a1] - r * math.cos(start_angle), pos[a2] - r * math.sin(start_angle))
        clockwise = rng.random() < 0.5
        kind = rng.choice(("ijk", "ijk", "r", "full"))
        sweep = rng.uniform(0.05, 2 * math.pi - 0.05)
        end_angle = start_angle + (-sweep if clockwise else sweep)
        end = {a1: round(centre[0] + r * math.cos(end_angle), 4), a2: round(centre[1] + r * math.sin(end_angle), 4)}
        if kind == "full":
            end = {a1: pos[a1], a2: pos[a2]}
        words = []
        for axis in (a1, a2):
            value = end[axis] - pos[axis] if incremental else end[axis]
            if kind != "full" or rng.random() < 0.5:
                words.append(f"{axis}{value:.4f}")
        helix = rng.random() < 0.3
        if helix:
            dz = round(rng.uniform(-5, 5) * unit, 4)
            words.append(f"{normal}{dz if incremental else pos[normal] + dz:.4f}")
            pos[normal] = round(pos[normal] + dz, 4)
        if kind == "r":
            if math.hypot(end[a1] - pos[a1], end[a2] - pos[a2]) < 0.5 * unit:
                kind = "ijk"  # R is badly conditioned for a tiny chord: centre form then
            else:  # the radius rs274 computes back must reach: the chord's half at least
                half = math.hypot(end[a1] - pos[a1], end[a2] - pos[a2]) / 2
                radius = max(r, half + 1e-4)
                words.append(f"R{-radius if sweep > math.pi else radius:.4f}")
        if kind != "r":
            words.append(f"{l1}{centre[0] - pos[a1]:.4f} {l2}{centre[1] - pos[a2]:.4f}")
        lines.append(f"{mode}{plane} {'G2' if clockwise else 'G3'} " + " ".join(words))
        pos[a1], pos[a2] = end[a1], end[a2]
        if rng.random() < 0.3:
            step = {a: round(rng.uniform(-20, 20) * unit, 4) for a in ("X", "Y")}
            if incremental:
                lines.append(f"G1 X{step['X']:.4f} Y{step['Y']:.4f}")
                pos["X"], pos["Y"] = round(pos["X"] + step["X"], 4), round(pos["Y"] + step["Y"], 4)
            else:
                pos["X"], pos["Y"] = round(pos["X"] + step["X"], 4), round(pos["Y"] + step["Y"], 4)
                lines.append(f"G1 X{pos['X']:.4f} Y{pos['Y']:.4f}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


def _events(text: str) -> list[dict[str, Any]]:
    events = canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0), feeds=True)
    return [{"toolpath": 1, "units": "mm"}] + [dict(ev, line=k) for k, ev in enumerate(events, 1)]


def _translated(text: str, arcs: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="random.ngc", source="linuxcnc", target="linuxcnc",
              arcs=parse_arc_option(arcs))
    return out.getvalue()


@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_rs274_runs_the_rewritten_arcs_as_the_source(seed: int) -> None:
    rng = random.Random(seed)
    text = _program(rng)
    source = _events(text)
    tolerance = TOLERANCE_INCH if text.startswith("G20") else TOLERANCE
    origin = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    for arcs in ("ijk", "r", f"lines:{CHORDS}"):
        out = _translated(text, arcs)
        chords = CHORDS if arcs.startswith("lines") else None
        report = compare(source, _events(out), start_in=origin, start_out=origin, tolerance=tolerance,
                         chord_tolerance=chords)
        assert report.ok, f"--arcs {arcs}\n{text}\n{out}\n{report.summary()}"
