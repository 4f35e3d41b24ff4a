"""The finishing shape of a roughing cycle whose profile compensates the tool nose: the imaginary tool tip's
path while the nose touches the profile, which the cycle roughs to (plus its finishing allowance).

A profile that turns tool nose radius compensation on in its first block and off in its last (``G42`` in
the P block, ``G40`` in the Q block: the Haas form) is a finished shape the tool's round nose must touch.
The cycle then roughs along the shape offset by the nose, not along the programmed one: it applies the
compensation to the finishing shape and roughs along the offset shape [?: Fanuc 0i-TC B-64114EN / 0i-TF
B-64604EN, "tool nose radius compensation in multiple repetitive canned cycle", as the task that asked
for this cites them; the manuals' text was not reached in this session (the search corpora hold none of
it)]. The form itself is the Haas one [K: Haas lathe operator's manual, G71 with TNC: G41/G42 in the P
block, G40 in the Q block, as known, not re-read here; the public Haas ST programs of tests/heldout,
enier290188/cnc, are written so]. What is modelled here, each point assumed [?]:

* the nose centre runs one nose radius beside each block between the first and the last (left for G41,
  right for G42, looking along the motion in the ZX plane with Z first: ``cutter_radius``'s convention);
* at an inside corner the offset blocks are cut short where they meet; around an outside corner the
  nose centre rolls on an arc about the programmed corner (the path on which the nose keeps touching the
  shape, so the roughing leaves exactly the allowance everywhere) [?];
* the point the cycle positions is the imaginary tool tip: the nose centre moved by the radius in the
  tip's direction (``postproc.compensation.nose``);
* the approach (the first block, which turns compensation on) ends where the offset of the block after
  it starts (perpendicular to that block: Fanuc's start-up type A) and the departure (the last block,
  which turns it off) is no part of the shape [?].

Coordinates are the turning library's: radii (x) and z in program units, arcs in the (z, x) frame.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Sequence

from postproc.errors import ProgramError

from .profile import EPS, Seg, arc_radius, arc_sweep

Vec = tuple[float, float]
"""(z, x): the plane's first axis, then its second."""

NO_CORNER = 1e-9
"""The sine of the angle between two directions under which they count as one (no corner)."""


def nose_path(segs: Sequence[Seg], side: str, radius: float, tip: tuple[int, int], name: str) -> list[Seg]:
    """The imaginary tip's path along ``segs`` (the blocks between the approach and the departure) for a
    nose of ``radius`` (program units, > 0) on ``side`` ('left' or 'right'); ``tip``: the (Z, X) signs
    from the nose centre to the imaginary tip (``nose.TIPS``). Refused where the nose cannot follow the
    shape (a concave arc tighter than the nose, a block shorter than an inside corner takes, a reversal)."""
    if side not in ("left", "right"):
        raise ProgramError(f"{name}: tool nose radius compensation {side!r} is not left or right")
    if not radius > 0.0 or not math.isfinite(radius):
        raise ProgramError(f"{name}: the tool nose radius must be positive, not {radius:g}")
    if not segs:
        raise ProgramError(f"{name}: the compensated profile has no block between its first and its last")
    offset = [_offset(seg, side, radius, name) for seg in segs]
    path: list[Seg] = [offset[0]]
    for i in range(1, len(segs)):
        before, after = segs[i - 1], segs[i]
        t1, t2 = tangent(before, at_end=True), tangent(after, at_end=False)
        cross = t1[0] * t2[1] - t1[1] * t2[0]
        dot = t1[0] * t2[0] + t1[1] * t2[1]
        nxt = offset[i]
        if abs(cross) <= NO_CORNER:
            if dot < 0.0:
                raise ProgramError(f"{name}: the profile turns back on itself at line {after.line}: the nose "
                                   "cannot follow it")
            path.append(nxt)
            continue
        outside = cross > 0.0 if side == "right" else cross < 0.0
        if outside:
            prev = path[-1]
            path.append(Seg("ccw" if cross > 0.0 else "cw", prev.x1, prev.z1, nxt.x0, nxt.z0, before.x1, before.z1,
                            after.feed, after.line, after.rapid))
            path.append(nxt)
            continue
        prev = path[-1]
        meet = _meet(prev, nxt, (before.z1, before.x1), name, after.line)
        path[-1] = _trimmed(prev, meet, at_end=True, name=name)
        path.append(_trimmed(nxt, meet, at_end=False, name=name))
    dz, dx = tip[0] * radius, tip[1] * radius
    return [_moved(seg, dx, dz) for seg in path]


def tangent(seg: Seg, at_end: bool) -> Vec:
    """The unit direction of motion at the segment's start or end, (z, x)."""
    if seg.kind == "line":
        dz, dx = seg.z1 - seg.z0, seg.x1 - seg.x0
        length = math.hypot(dz, dx)
        if length <= EPS:
            raise ProgramError(f"the profile block at line {seg.line} does not move")
        return dz / length, dx / length
    assert seg.cx is not None and seg.cz is not None
    x, z = (seg.x1, seg.z1) if at_end else (seg.x0, seg.z0)
    r = math.hypot(z - seg.cz, x - seg.cx)
    uz, ux = (z - seg.cz) / r, (x - seg.cx) / r
    return (-ux, uz) if seg.kind == "ccw" else (ux, -uz)


def normal(direction: Vec, side: str) -> Vec:
    """The unit normal toward ``side`` of a direction of motion, (z, x): left is a quarter turn
    counter-clockwise in the (z, x) frame."""
    tz, tx = direction
    return (-tx, tz) if side == "left" else (tx, -tz)


def _offset(seg: Seg, side: str, r: float, name: str) -> Seg:
    n0 = normal(tangent(seg, at_end=False), side)
    n1 = normal(tangent(seg, at_end=True), side)
    moved = replace(seg, x0=seg.x0 + r * n0[1], z0=seg.z0 + r * n0[0], x1=seg.x1 + r * n1[1], z1=seg.z1 + r * n1[0])
    inward = (seg.kind == "ccw") == (side == "left")  # a counter-clockwise arc has its centre on its left
    if seg.kind != "line" and inward and arc_radius(seg) <= r + EPS:
        raise ProgramError(f"{name}: the arc at line {seg.line} (radius {arc_radius(seg):g}) is no wider than the "
                           f"tool nose (radius {r:g}) on the side it compensates")
    return moved


def _moved(seg: Seg, dx: float, dz: float) -> Seg:
    cx = None if seg.cx is None else seg.cx + dx
    cz = None if seg.cz is None else seg.cz + dz
    return replace(seg, x0=seg.x0 + dx, z0=seg.z0 + dz, x1=seg.x1 + dx, z1=seg.z1 + dz, cx=cx, cz=cz)


def _meet(a: Seg, b: Seg, corner: Vec, name: str, line: int) -> Vec:
    """Where the offsets of two blocks meet at an inside corner: of their (extended) intersections the one
    nearest the programmed corner."""
    found = _intersections(a, b)
    if not found:
        raise ProgramError(f"{name}: the nose cannot follow the inside corner at line {line} (its offset blocks "
                           "do not meet)")
    return min(found, key=lambda p: math.hypot(p[0] - corner[0], p[1] - corner[1]))


def _intersections(a: Seg, b: Seg) -> list[Vec]:
    if a.kind == "line" and b.kind == "line":
        return _line_line(a, b)
    if a.kind == "line":
        return _line_circle(a, b)
    if b.kind == "line":
        return _line_circle(b, a)
    return _circle_circle(a, b)


def _line_line(a: Seg, b: Seg) -> list[Vec]:
    d1 = (a.z1 - a.z0, a.x1 - a.x0)
    d2 = (b.z1 - b.z0, b.x1 - b.x0)
    den = d1[0] * d2[1] - d1[1] * d2[0]
    if abs(den) <= EPS * EPS:
        return []
    wz, wx = b.z0 - a.z0, b.x0 - a.x0
    s = (wz * d2[1] - wx * d2[0]) / den
    return [(a.z0 + s * d1[0], a.x0 + s * d1[1])]


def _line_circle(line: Seg, arc: Seg) -> list[Vec]:
    assert arc.cx is not None and arc.cz is not None
    r = arc_radius(arc)
    dz, dx = line.z1 - line.z0, line.x1 - line.x0
    fz, fx = line.z0 - arc.cz, line.x0 - arc.cx
    qa = dz * dz + dx * dx
    qb = 2.0 * (fz * dz + fx * dx)
    qc = fz * fz + fx * fx - r * r
    disc = qb * qb - 4.0 * qa * qc
    if qa <= EPS or disc < 0.0:
        return []
    root = math.sqrt(disc)
    return [(line.z0 + t * dz, line.x0 + t * dx) for t in ((-qb - root) / (2 * qa), (-qb + root) / (2 * qa))]


def _circle_circle(a: Seg, b: Seg) -> list[Vec]:
    assert a.cx is not None and a.cz is not None and b.cx is not None and b.cz is not None
    r1, r2 = arc_radius(a), arc_radius(b)
    dz, dx = b.cz - a.cz, b.cx - a.cx
    d = math.hypot(dz, dx)
    if d <= EPS or d > r1 + r2 or d < abs(r1 - r2):
        return []
    along = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(max(0.0, r1 * r1 - along * along))
    mz, mx = a.cz + along * dz / d, a.cx + along * dx / d
    return [(mz - h * dx / d, mx + h * dz / d), (mz + h * dx / d, mx - h * dz / d)]


def _trimmed(seg: Seg, point: Vec, at_end: bool, name: str) -> Seg:
    """The segment with one end moved to ``point`` (on its line or circle); refused when that would reverse
    it (the block is shorter than the inside corner takes)."""
    z, x = point
    new = replace(seg, x1=x, z1=z) if at_end else replace(seg, x0=x, z0=z)
    if seg.kind == "line":
        ahead = (new.z1 - new.z0) * (seg.z1 - seg.z0) + (new.x1 - new.x0) * (seg.x1 - seg.x0)
        if ahead <= 0.0:
            raise ProgramError(f"{name}: the profile block at line {seg.line} is shorter than the tool nose needs at "
                               "its inside corner")
        return new
    if arc_sweep(new) > arc_sweep(seg) + 1e-9:
        raise ProgramError(f"{name}: the profile arc at line {seg.line} is shorter than the tool nose needs at its "
                           "inside corner")
    return new
