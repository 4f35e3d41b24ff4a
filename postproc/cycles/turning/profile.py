"""Lathe cycle geometry: the profile segments a cycle reads, the moves it makes, and the plane maths.

Every coordinate is a radius (true distance from the spindle axis) in program units: ``x`` radial,
``z`` axial. Arcs are G02/G03 as programmed in G18 on a lathe: the plane's first axis is Z and its
second X, so ``cw`` is clockwise in the (z, x) frame (the angle atan2(x - cx, z - cz) decreases);
centres are absolute.

The roughing cycles work in a *canonical frame* (``Frame``): the axes reflected (and, for facing,
swapped) so that every cycle infeeds toward -x and cuts toward -z. One algorithm then serves OD and ID,
toward and away from the chuck, turning and facing; ``Frame`` maps the result back.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Literal, Sequence

from postproc.errors import ProgramError

EPS = 1e-9
"""Coordinates closer than this are the same point (well under the 1 nm a toolpath prints)."""


@dataclass(frozen=True)
class Seg:
    """One profile block between P (ns) and Q (nf), from (x0, z0) to (x1, z1).

    ``rapid`` marks a G00 block (the ns block of G71/G72 says with it whether the infeed is rapid);
    ``feed`` is the F the block itself programs or inherits inside the profile (used by G70 only).
    """

    kind: Literal["line", "cw", "ccw"]
    x0: float
    z0: float
    x1: float
    z1: float
    cx: float | None = None
    cz: float | None = None
    feed: float | None = None
    line: int = 0
    rapid: bool = False


@dataclass(frozen=True)
class TurnMove:
    """One move of a cycle's toolpath, to the absolute end point (x, z); arcs carry their centre.

    ``note`` says what the move is for (``rough``, ``retract``, ``contour``, ``thread``...); a
    ``thread`` feed is spindle-synchronised with ``feed`` = the lead per revolution.
    """

    kind: Literal["rapid", "feed", "cw", "ccw"]
    x: float
    z: float
    cx: float | None = None
    cz: float | None = None
    feed: float | None = None
    note: str = ""


Point = tuple[float, float]
"""(x, z)."""


def finite(cycle: str, **values: float | None) -> None:
    """Refuse an inf or nan word: it would silently turn into a move to nowhere."""
    for name, value in values.items():
        if value is not None and not math.isfinite(value):
            raise ProgramError(f"{cycle}: {name} must be a finite number, not {value}")


def same(a: float, b: float, tol: float = EPS) -> bool:
    return abs(a - b) <= tol


def sign(value: float) -> float:
    """+1, -1, or 0 within EPS."""
    return 0.0 if abs(value) <= EPS else math.copysign(1.0, value)


# --- arcs --------------------------------------------------------------------------------------------

def arc_angle(seg: Seg, x: float, z: float) -> float:
    """Angle of (x, z) about the arc's centre in the (z, x) plane frame."""
    assert seg.cx is not None and seg.cz is not None
    return math.atan2(x - seg.cx, z - seg.cz)


def arc_radius(seg: Seg) -> float:
    assert seg.cx is not None and seg.cz is not None
    return math.hypot(seg.x0 - seg.cx, seg.z0 - seg.cz)


def arc_sweep(seg: Seg) -> float:
    """Unsigned angle the arc turns through, in (0, 2 pi]; equal end points are a full circle."""
    a0, a1 = arc_angle(seg, seg.x0, seg.z0), arc_angle(seg, seg.x1, seg.z1)
    sweep = (a0 - a1) if seg.kind == "cw" else (a1 - a0)
    sweep %= 2.0 * math.pi
    return 2.0 * math.pi if sweep < 1e-12 else sweep


def arc_contains(seg: Seg, angle: float, strict: bool) -> bool:
    """Whether the arc passes through ``angle`` (strictly inside when ``strict``)."""
    a0 = arc_angle(seg, seg.x0, seg.z0)
    turned = (a0 - angle) if seg.kind == "cw" else (angle - a0)
    turned %= 2.0 * math.pi
    sweep = arc_sweep(seg)
    if strict:
        tol = 1e-12
        return tol < turned < sweep - tol
    return turned <= sweep + 1e-12 or turned >= 2.0 * math.pi - 1e-12


def check_arc(seg: Seg, cycle: str) -> None:
    """An arc must have its centre and equal start and end radii (within 1 um), or the cycle refuses it."""
    if seg.cx is None or seg.cz is None:
        raise ProgramError(f"{cycle}: the arc at line {seg.line} has no centre")
    r0 = arc_radius(seg)
    r1 = math.hypot(seg.x1 - seg.cx, seg.z1 - seg.cz)
    if abs(r0 - r1) > 1e-3 or r0 <= EPS:
        raise ProgramError(f"{cycle}: the arc at line {seg.line} has start radius {r0:.6g} and end radius "
                           f"{r1:.6g}")


def arc_level_points(seg: Seg, level: float) -> list[float]:
    """Angles on the arc where x == level."""
    assert seg.cx is not None and seg.cz is not None
    r = arc_radius(seg)
    s = (level - seg.cx) / r
    if abs(s) > 1.0:
        return []
    base = math.asin(max(-1.0, min(1.0, s)))
    return [a for a in {base, math.pi - base} if arc_contains(seg, a, strict=False)]


# --- the canonical frame -----------------------------------------------------------------------------

@dataclass(frozen=True)
class Frame:
    """Reflections (``fx``, ``fz`` = +1 or -1) after an optional X/Z swap; its own inverse's recipe."""

    swap: bool
    fx: float
    fz: float

    def flips_arcs(self) -> bool:
        """A swap or one reflection mirrors the plane, turning G02 into G03."""
        return self.swap != (self.fx * self.fz < 0)

    def point(self, x: float, z: float) -> Point:
        if self.swap:
            x, z = z, x
        return self.fx * x, self.fz * z

    def back(self, x: float, z: float) -> Point:
        x, z = self.fx * x, self.fz * z
        return (z, x) if self.swap else (x, z)

    def seg(self, seg: Seg) -> Seg:
        x0, z0 = self.point(seg.x0, seg.z0)
        x1, z1 = self.point(seg.x1, seg.z1)
        cx = cz = None
        if seg.cx is not None and seg.cz is not None:
            cx, cz = self.point(seg.cx, seg.cz)
        kind = seg.kind
        if kind != "line" and self.flips_arcs():
            kind = "ccw" if kind == "cw" else "cw"
        return replace(seg, kind=kind, x0=x0, z0=z0, x1=x1, z1=z1, cx=cx, cz=cz)

    def move(self, move: TurnMove) -> TurnMove:
        x, z = self.back(move.x, move.z)
        cx = cz = None
        if move.cx is not None and move.cz is not None:
            cx, cz = self.back(move.cx, move.cz)
        kind = move.kind
        if kind in ("cw", "ccw") and self.flips_arcs():
            kind = "ccw" if kind == "cw" else "cw"
        return replace(move, kind=kind, x=x, z=z, cx=cx, cz=cz)


def shifted(seg: Seg, dx: float, dz: float) -> Seg:
    """The segment translated by (dx, dz): the profile offset by a finishing allowance."""
    cx = None if seg.cx is None else seg.cx + dx
    cz = None if seg.cz is None else seg.cz + dz
    return replace(seg, x0=seg.x0 + dx, z0=seg.z0 + dz, x1=seg.x1 + dx, z1=seg.z1 + dz, cx=cx, cz=cz)


def contour_moves(segs: Sequence[Seg], feed: float | None, note: str,
                  rapid_as_rapid: bool = True) -> list[TurnMove]:
    """The moves that trace ``segs``: a G00 block stays a rapid (when ``rapid_as_rapid``), others feed at
    ``feed`` (the cycle's F), or at the block's own F when ``feed`` is None."""
    moves: list[TurnMove] = []
    for seg in segs:
        f = seg.feed if feed is None else feed
        if seg.kind == "line":
            if seg.rapid and rapid_as_rapid:
                moves.append(TurnMove("rapid", seg.x1, seg.z1, note=note))
            else:
                moves.append(TurnMove("feed", seg.x1, seg.z1, feed=f, note=note))
        else:
            moves.append(TurnMove(seg.kind, seg.x1, seg.z1, seg.cx, seg.cz, feed=f, note=note))
    return moves


def check_chain(segs: Sequence[Seg], start: Point, cycle: str) -> None:
    """The profile must start at the cycle's start point and each block where the last one ended."""
    if not segs:
        raise ProgramError(f"{cycle}: the profile has no blocks")
    x, z = start
    for seg in segs:
        finite(cycle, x0=seg.x0, z0=seg.z0, x1=seg.x1, z1=seg.z1, cx=seg.cx, cz=seg.cz, feed=seg.feed)
        if not (same(seg.x0, x, 1e-6) and same(seg.z0, z, 1e-6)):
            raise ProgramError(f"{cycle}: the profile block at line {seg.line} starts at X{seg.x0:g} Z{seg.z0:g}, "
                               f"not where the block before it ends (X{x:g} Z{z:g})")
        if seg.kind != "line":
            check_arc(seg, cycle)
        x, z = seg.x1, seg.z1


def drop_still(moves: list[TurnMove], start: Point) -> list[TurnMove]:
    """Remove moves that go nowhere (a straight move to exactly where the tool already is: a move of
    float noise stays, so every cycle ends exactly where it says)."""
    out: list[TurnMove] = []
    x, z = start
    for move in moves:
        if move.kind in ("rapid", "feed") and move.x == x and move.z == z:
            continue
        out.append(move)
        x, z = move.x, move.z
    return out
