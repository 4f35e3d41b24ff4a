"""Random LinuxCNC G70/G71/G72 programs for the differential against rs274 (``tests/test_ngc_g7x.py``).

A profile is drawn as an outside turning one (Z falling, X at or above 0, a pocket where X dips and rises
again), its lines and arcs sometimes with a fillet (A) or chamfer (C) at their end, then put in one of the
eight orientations (mirrored in X, in Z, X and Z swapped for a facing cycle) so that every frame of the
controller's algorithm is met. Arcs are given by I/K (incremental) or R, as a programmer writes them.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

CODES = ("70", "71", "71.1", "71.2", "72", "72.1", "72.2")


@dataclass
class Step:
    """One profile block: G0-G3 to (x, z); ``words`` its I/K or R and A or C."""

    g: int
    x: float
    z: float
    words: dict[str, float] = field(default_factory=dict)

    def text(self) -> str:
        extra = "".join(f" {k}{v:.4f}" for k, v in self.words.items())
        return f"G{self.g} X{self.x:.4f} Z{self.z:.4f}{extra}"


@dataclass
class Case:
    code: str
    x: float
    z: float
    steps: list[Step]
    words: dict[str, float]

    def program(self) -> str:
        lines = ["G18 G21 G8 G90 G40", "F400", "O100 SUB", *("  " + s.text() for s in self.steps), "O100 ENDSUB",
                 f"G0 X{self.x:.4f} Z{self.z:.4f}",
                 f"G{self.code} Q100 X{self.x:.4f} Z{self.z:.4f}" + "".join(f" {k}{v:g}" for k, v in self.words.items()),
                 "M2"]
        return "\n".join(lines) + "\n"


def _r(rng: random.Random, lo: float, hi: float) -> float:
    return round(rng.uniform(lo, hi), 3)


def draw(rng: random.Random, code: str | None = None) -> Case:
    """A random cycle over a random profile (module docstring)."""
    code = code or rng.choice(CODES)
    pockets = rng.random() < 0.5
    n = rng.randint(2, 7)
    z = _r(rng, -2.0, 0.0)
    x = _r(rng, 0.0, 3.0)
    pts = [(x, z)]
    for _ in range(n):
        z = round(z - _r(rng, 1.0, 6.0), 3)
        if pockets and rng.random() < 0.35:
            x = round(max(0.0, x - _r(rng, 0.5, 3.0)), 3)
        else:
            x = round(x + _r(rng, 0.0, 4.0) * (rng.random() < 0.8), 3)
        pts.append((x, z))
    top = max(p[0] for p in pts)
    end_x = round(top + _r(rng, 0.5, 3.0), 3) if rng.random() < 0.7 else pts[-1][0]
    steps: list[Step] = [Step(0, *pts[0])]
    x0, z0 = pts[0]
    for x1, z1 in pts[1:]:
        kind = rng.random()
        chord = math.hypot(x1 - x0, z1 - z0)
        if kind < 0.35 and chord > 0.5:
            g = rng.choice((2, 3))
            radius = round(chord / 2 * rng.uniform(1.05, 3.0), 4)
            words: dict[str, float] = {}
            if rng.random() < 0.5:
                words["R"] = radius
            else:
                mid = complex((z0 + z1) / 2, (x0 + x1) / 2)
                d = complex(z1 - z0, x1 - x0)
                h = math.sqrt(radius * radius - chord * chord / 4) / chord
                centre = mid + (1j * h * d if g == 3 else -1j * h * d)
                words["I"] = round(centre.imag - x0, 4)
                words["K"] = round(centre.real - z0, 4)
                # the endpoint put back on the rounded centre's circle, as the controller checks it
                rad = abs(complex(words["K"], words["I"]))
                c = complex(z0 + words["K"], x0 + words["I"])
                e = c + (complex(z1, x1) - c) / abs(complex(z1, x1) - c) * rad
                z1, x1 = round(e.real, 4), round(e.imag, 4)
            step = Step(g, x1, z1, words)
        else:
            step = Step(1, x1, z1, {})
        if rng.random() < 0.2:
            step.words["A" if rng.random() < 0.5 else "C"] = _r(rng, 0.1, 0.4)
        steps.append(step)
        x0, z0 = x1, z1
    last = steps[-1]
    if end_x != last.x:
        steps.append(Step(1, end_x, last.z))
    cx = round(max(s.x for s in steps) + _r(rng, 0.5, 2.0), 3)
    cz = round(steps[0].z + _r(rng, 0.5, 2.0), 3)
    words = {}
    if code == "70":
        if rng.random() < 0.6:
            words["D"] = _r(rng, 0.0, 1.0)
        if rng.random() < 0.4:
            words["E"] = _r(rng, 0.0, 0.3)
        if rng.random() < 0.5:
            words["P"] = rng.randint(1, 3)
    else:
        if rng.random() < 0.7:
            words["D"] = _r(rng, 0.0, 0.8)
        if rng.random() < 0.7:
            words["I"] = _r(rng, 0.3, 1.5)
        if rng.random() < 0.6:
            words["R"] = _r(rng, 0.1, 0.6)
    case = Case(code, cx, cz, steps, words)
    return orient(case, rng.randrange(4), code.startswith("72"))


def orient(case: Case, mirror: int, facing: bool) -> Case:
    """Mirror the case in X (bit 1) and Z (bit 2); swap X and Z for a facing cycle (then the profile runs
    along X, falling)."""
    sx = -1.0 if mirror & 1 else 1.0
    sz = -1.0 if mirror & 2 else 1.0
    flips = (mirror & 1) + (mirror >> 1 & 1) + int(facing)

    def point(x: float, z: float) -> tuple[float, float]:
        x, z = sx * x, sz * z
        return (z, x) if facing else (x, z)

    steps = []
    for s in case.steps:
        x, z = point(s.x, s.z)
        words = dict(s.words)
        g = s.g
        if "I" in words:
            words["I"], words["K"] = point(words["I"], words["K"])
        if g in (2, 3) and flips % 2:
            g = 5 - g
        steps.append(Step(g, x, z, words))
    cx, cz = point(case.x, case.z)
    return Case(case.code, cx, cz, steps, case.words)
