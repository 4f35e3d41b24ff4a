"""Where a hole pattern's points are and how the tool travels between them: pure functions of a
``HolePattern`` (its ``start`` holds point 1), so the reader, the lowering and the tests share one
computation.

Coordinates are plane coordinates (a, b) = (first, second plane axis) of the pattern's plane: the
same code serves XY, ZX and YZ. Angles turn counter-clockwise from a to b.
"""

from __future__ import annotations

import math

from postproc.records import record
from postproc.ir.state import PLANE_AXES

from .section import HolePattern

Point = tuple[float, float]


@record(frozen=True, slots=True)
class Hop:
    """The tool's way to a machined point from the machined point before it (point 1 for the first)."""

    number: int
    """The point's number in the pattern (point 1 is the first point)."""
    point: Point
    mode: str
    """'rapid', 'linear', 'cw' or 'ccw' (the pattern's ``move``)."""
    centre: Point | None
    """The circle's centre for an arc move, else None."""


def first_point(p: HolePattern) -> Point:
    """Point 1: where the tool stood in the plane when the pattern started."""
    first, second, _ = PLANE_AXES[p.plane]
    try:
        return p.start[first], p.start[second]
    except KeyError as missing:
        raise ValueError(f"the pattern's first point has no {missing.args[0]} coordinate") from None


def centre(p: HolePattern) -> Point:
    """The centre of a circle or arc (point 1 plus the centre offset)."""
    first, second, _ = PLANE_AXES[p.plane]
    a, b = first_point(p)
    return a + p.center.get(first, 0.0), b + p.center.get(second, 0.0)


def pattern_points(p: HolePattern) -> list[Point]:
    """Every point of the pattern, skipped ones included, in the order of their numbers."""
    a0, b0 = first_point(p)
    if p.kind in ("circle", "arc"):
        ca, cb = centre(p)
        radius = math.hypot(a0 - ca, b0 - cb)
        theta = math.degrees(math.atan2(b0 - cb, a0 - ca))
        points = [(a0, b0)]
        for i in range(1, p.count):
            points.append(_at((ca, cb), _direction(theta + i * p.step), radius))
        return points
    u = _direction(p.angle)
    if p.kind == "line":
        return [_at((a0, b0), u, i * p.step) for i in range(p.count)]
    v = _direction(p.angle + p.angle2)
    n1, n2 = p.count, p.count2 or 0
    step2 = p.step2 or 0.0
    if p.kind == "grid":
        points = []
        for j in range(n2):
            row = _at((a0, b0), v, j * step2)
            columns = range(n1) if j % 2 == 0 else range(n1 - 1, -1, -1)
            points.extend(_at(row, u, i * p.step) for i in columns)
        return points
    # parallelogram: along the first side, up the second, back along the third, down the fourth
    side1, side2 = (n1 - 1) * p.step, (n2 - 1) * step2
    corner2 = _at((a0, b0), u, side1)
    corner3 = _at(corner2, v, side2)
    corner4 = _at((a0, b0), v, side2)
    points = [_at((a0, b0), u, i * p.step) for i in range(n1)]
    points += [_at(corner2, v, j * step2) for j in range(1, n2)]
    points += [_at(corner3, u, -i * p.step) for i in range(1, n1)]
    points += [_at(corner4, v, -j * step2) for j in range(1, n2 - 1)]
    return points


def pattern_hops(p: HolePattern) -> list[Hop]:
    """The machined points after point 1, each with the move that reaches it: the tool goes from one
    machined point straight to the next (a skipped point is not visited), or along the circle."""
    arc = p.move in ("cw", "ccw")
    c = centre(p) if arc else None
    skip = frozenset(p.skip)
    return [Hop(n, point, p.move, c) for n, point in enumerate(pattern_points(p), start=1)
            if n > 1 and n not in skip]


def _direction(degrees: float) -> Point:
    """The unit vector at ``degrees``; exact on the axes (cos 90 is 0, not 6e-17)."""
    quarter, rest = divmod(degrees, 90.0)
    if rest == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
    t = math.radians(degrees)
    return math.cos(t), math.sin(t)


def _at(origin: Point, unit: Point, distance: float) -> Point:
    return origin[0] + distance * unit[0], origin[1] + distance * unit[1]
