"""Affine maps of the X, Y, Z space (``w = m p + t``): how a frame carries a programmed point to the work
coordinates, as pure functions of floats.

Rotation, scaling and mirroring are linear about a centre; offsets are translations. A frame is their
composition, so a move, an arc centre offset (a vector: ``linear``) and a canned cycle's points are all
carried by one map. An arc stays an arc only where the map keeps its plane and is conformal there
(``arc_factor``).
"""

from __future__ import annotations

import math
from typing import Final, Sequence

XYZ: Final = ("X", "Y", "Z")
INDEX: Final = {"X": 0, "Y": 1, "Z": 2}
EXACT: Final = 1e-12
"""Below this a matrix entry is zero: an axis the map does not mix into another."""

Matrix = tuple[float, float, float, float, float, float, float, float, float]
Vector = tuple[float, float, float]


class Affine:
    """``w = m p + t`` on X, Y, Z (``m`` row-major)."""

    __slots__ = ("m", "t")

    def __init__(self, m: Matrix = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0),
                 t: Vector = (0.0, 0.0, 0.0)) -> None:
        self.m = m
        self.t = t

    def then(self, after: "Affine") -> "Affine":
        """``after`` applied to this map's result."""
        a, b = after.m, self.m
        m = tuple(sum(a[3 * i + k] * b[3 * k + j] for k in range(3)) for i in range(3) for j in range(3))
        t = tuple(sum(a[3 * i + k] * self.t[k] for k in range(3)) + after.t[i] for i in range(3))
        return Affine(m, t)  # type: ignore[arg-type]

    def point(self, p: Sequence[float]) -> Vector:
        m, t = self.m, self.t
        return (m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + t[0],
                m[3] * p[0] + m[4] * p[1] + m[5] * p[2] + t[1],
                m[6] * p[0] + m[7] * p[1] + m[8] * p[2] + t[2])

    def linear(self, v: Sequence[float]) -> Vector:
        m = self.m
        return (m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
                m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
                m[6] * v[0] + m[7] * v[1] + m[8] * v[2])

    def mixes(self, row: int, column: int) -> bool:
        """Whether output axis ``row`` depends on input axis ``column``."""
        return abs(self.m[3 * row + column]) > EXACT

    def is_identity(self) -> bool:
        return self.m == IDENTITY.m and self.t == IDENTITY.t

    def arc_factor(self, plane: Sequence[str]) -> tuple[float, bool] | None:
        """For an arc in ``plane`` (first, second, normal axis): (the factor its radius is multiplied by,
        whether its direction turns over), or None when the map takes the arc out of its plane or
        scales its two axes unequally (an ellipse)."""
        i, j, n = (INDEX[a] for a in plane)
        m = self.m
        for row, column in ((i, n), (j, n), (n, i), (n, j)):
            if abs(m[3 * row + column]) > EXACT:
                return None
        a, b, c, d = m[3 * i + i], m[3 * i + j], m[3 * j + i], m[3 * j + j]
        det = a * d - b * c
        s1, s2 = math.hypot(a, c), math.hypot(b, d)
        if abs(s1 - s2) > 1e-9 * max(s1, s2, 1.0) or abs(a * b + c * d) > 1e-9 * max(s1 * s2, 1.0) or det == 0.0:
            return None
        return s1, det < 0


IDENTITY: Final = Affine()


def translation(offset: Sequence[float]) -> Affine:
    return Affine(IDENTITY.m, (offset[0], offset[1], offset[2]))


def about(centre: Sequence[float], m: Matrix) -> Affine:
    """The linear map ``m`` about ``centre`` (a rotation or a scaling that leaves the centre in place)."""
    inner = Affine(m, (0.0, 0.0, 0.0))
    moved = inner.point((-centre[0], -centre[1], -centre[2]))
    return Affine(m, (moved[0] + centre[0], moved[1] + centre[1], moved[2] + centre[2]))


def rotation(plane: Sequence[str], degrees: float) -> Matrix:
    """Counter-clockwise by ``degrees`` in ``plane`` (from its first axis toward its second)."""
    i, j = INDEX[plane[0]], INDEX[plane[1]]
    rad = math.radians(degrees)
    c, s = _exact_cos_sin(rad, degrees)
    m = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
    m[3 * i + i], m[3 * i + j], m[3 * j + i], m[3 * j + j] = c, -s, s, c
    return tuple(m)  # type: ignore[return-value]


def diagonal(factors: Sequence[float]) -> Matrix:
    return (factors[0], 0.0, 0.0, 0.0, factors[1], 0.0, 0.0, 0.0, factors[2])


def _exact_cos_sin(rad: float, degrees: float) -> tuple[float, float]:
    """cos and sin, exact at whole quarter turns (a 90 degree rotation must not leave 6e-17 behind)."""
    quarter = degrees / 90.0
    if quarter.is_integer():
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
    return math.cos(rad), math.sin(rad)
