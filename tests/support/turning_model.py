"""An independent model of turning for the lathe-cycle property tests: the part's outline as a
function of z, the air the tool has cleared, and reflections of a case. It shares no code with
``postproc.cycles.turning`` (its own arc maths), so it can judge that package's toolpaths.

Canonical frame: the tool infeeds toward -x and cuts toward -z; the part lies below the outline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Iterable, Sequence

from postproc.cycles.turning import Seg, TurnMove

def on_arc(seg: Seg, x: float, z: float) -> bool:
    """Whether (x, z), on the arc's circle, lies within its sweep."""
    assert seg.cx is not None and seg.cz is not None
    a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
    a1 = math.atan2(seg.x1 - seg.cx, seg.z1 - seg.cz)
    a = math.atan2(x - seg.cx, z - seg.cz)
    cw = seg.kind == "cw"
    sweep = ((a0 - a1) if cw else (a1 - a0)) % (2 * math.pi)
    turned = ((a0 - a) if cw else (a - a0)) % (2 * math.pi)
    return turned <= sweep + 1e-12 or turned >= 2 * math.pi - 1e-12


def x_at(seg: Seg, z: float) -> float | None:
    """The highest x of the segment at z, exactly, or None where it does not reach z (or is a wall)."""
    if seg.kind == "line":
        lo, hi = min(seg.z0, seg.z1), max(seg.z0, seg.z1)
        if hi - lo <= 1e-12 or not lo <= z <= hi:  # exact: near a wall, a z tolerance is a big x error
            return None
        return seg.x0 + (z - seg.z0) / (seg.z1 - seg.z0) * (seg.x1 - seg.x0)
    assert seg.cx is not None and seg.cz is not None
    if not min(seg.z0, seg.z1) <= z <= max(seg.z0, seg.z1):
        return None  # every arc of a profile here is monotonic in z (the cycles refuse others)
    r = math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz)
    d2 = r * r - (z - seg.cz) ** 2
    if d2 < -1e-9:
        return None
    h = math.sqrt(max(d2, 0.0))
    xs = [x for x in (seg.cx + h, seg.cx - h) if on_arc(seg, x, z)]
    return max(xs) if xs else None


class Outline:
    """The offset profile as the highest x of the part at each z (walls in X are left to their sides)."""

    def __init__(self, segs: Iterable[Seg]) -> None:
        self.segs = list(segs)

    def at(self, z: float) -> float:
        best = -math.inf
        for s in self.segs:
            x = x_at(s, z)
            if x is not None and x > best:
                best = x
        return best


class Air:
    """What is known to be clear: above ``top`` from the start, and above every fed move since."""

    def __init__(self, top: float) -> None:
        self.top = top
        self.cuts: list[tuple[float, float, Seg]] = []

    def at(self, z: float) -> float:
        best = self.top
        for lo, hi, s in self.cuts:
            if lo - 1e-12 <= z <= hi + 1e-12:
                x = x_at(s, z)
                if x is not None and x < best:
                    best = x
        return best

    def cut(self, x: float, z: float, move: TurnMove) -> None:
        seg = as_seg(x, z, move)
        lo, hi = min(seg.z0, seg.z1), max(seg.z0, seg.z1)
        if seg.kind != "line":
            lo, hi = -math.inf, math.inf  # x_at decides
        if hi - lo > 1e-12:
            self.cuts.append((lo, hi, seg))


def as_seg(x: float, z: float, move: TurnMove) -> Seg:
    kind = "line" if move.kind in ("rapid", "feed") else move.kind
    return Seg(kind, x, z, move.x, move.z, cx=move.cx, cz=move.cz)  # type: ignore[arg-type]


@dataclass(frozen=True)
class Mirror:
    """A reflection (and swap) applied by the test to a canonical case and undone on the moves."""

    swap: bool
    fx: float
    fz: float

    def flips(self) -> bool:
        return self.swap != (self.fx * self.fz < 0)

    def pt(self, x: float, z: float) -> tuple[float, float]:
        x, z = self.fx * x, self.fz * z
        return (z, x) if self.swap else (x, z)

    def unpt(self, x: float, z: float) -> tuple[float, float]:
        if self.swap:
            x, z = z, x
        return self.fx * x, self.fz * z

    def seg(self, s: Seg) -> Seg:
        x0, z0 = self.pt(s.x0, s.z0)
        x1, z1 = self.pt(s.x1, s.z1)
        cx, cz = (None, None) if s.cx is None or s.cz is None else self.pt(s.cx, s.cz)
        kind = s.kind if s.kind == "line" or not self.flips() else ("ccw" if s.kind == "cw" else "cw")
        return replace(s, kind=kind, x0=x0, z0=z0, x1=x1, z1=z1, cx=cx, cz=cz)

    def unmove(self, m: TurnMove) -> TurnMove:
        x, z = self.unpt(m.x, m.z)
        cx, cz = (None, None) if m.cx is None or m.cz is None else self.unpt(m.cx, m.cz)
        kind = m.kind if m.kind in ("rapid", "feed") or not self.flips() else ("ccw" if m.kind == "cw" else "cw")
        return replace(m, kind=kind, x=x, z=z, cx=cx, cz=cz)


def shift(s: Seg, dx: float, dz: float) -> Seg:
    return replace(s, x0=s.x0 + dx, z0=s.z0 + dz, x1=s.x1 + dx, z1=s.z1 + dz,
                   cx=None if s.cx is None else s.cx + dx, cz=None if s.cz is None else s.cz + dz)


def arc_between(x0: float, z0: float, x1: float, z1: float, sweep: float, ccw: bool, line: int) -> Seg:
    """An arc of ``sweep`` radians from (x0, z0) to (x1, z1) in the (z, x) plane."""
    dz, dx = z1 - z0, x1 - x0
    chord = math.hypot(dz, dx)
    r = chord / (2 * math.sin(sweep / 2))
    h = r * math.cos(sweep / 2)
    # Left normal of the chord in the (z, x) plane: rotate (dz, dx) by +90 degrees -> (-dx, dz).
    nz, nx = -dx / chord, dz / chord
    side = 1.0 if ccw else -1.0
    cz = (z0 + z1) / 2 + side * h * nz
    cx = (x0 + x1) / 2 + side * h * nx
    return Seg("ccw" if ccw else "cw", x0, z0, x1, z1, cx=cx, cz=cz, line=line)


def chord_angle(dx: float, dz: float) -> float:
    """Direction of a chord in the (z, x) plane, in [0, 2 pi)."""
    return math.atan2(dx, dz) % (2 * math.pi)


def samples(x: float, z: float, move: TurnMove, n: int = 3) -> list[tuple[float, float, bool]]:
    """Interior points of a move (never its end points, which may touch a wall): (x, z, vertical)."""
    if move.kind in ("rapid", "feed"):
        vertical = abs(move.z - z) <= 1e-12
        return [(x + (i + 0.5) / n * (move.x - x), z + (i + 0.5) / n * (move.z - z), vertical) for i in range(n)]
    assert move.cx is not None and move.cz is not None
    a0 = math.atan2(x - move.cx, z - move.cz)
    a1 = math.atan2(move.x - move.cx, move.z - move.cz)
    cw = move.kind == "cw"
    sweep = ((a0 - a1) if cw else (a1 - a0)) % (2 * math.pi)
    r = math.hypot(x - move.cx, z - move.cz)
    out = []
    for i in range(4 * n):
        a = a0 + (-1 if cw else 1) * (i + 0.5) / (4 * n) * sweep
        out.append((move.cx + r * math.sin(a), move.cz + r * math.cos(a), False))
    return out


def replay(start: tuple[float, float], moves: Sequence[TurnMove]) -> Iterable[tuple[float, float, TurnMove]]:
    """Each move with the point it starts from."""
    x, z = start
    for m in moves:
        yield x, z, m
        x, z = m.x, m.z
