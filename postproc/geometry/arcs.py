"""Arc geometry shared by the toolpath simulator, the backplot and verify (no dependency on either)."""

from __future__ import annotations

import math
from typing import Iterator

from ..errors import ProgramError

PLACES = 6
"""Decimals of every number in a toolpath (1 nm): enough for any controller, stable across float noise."""
ARC_TOLERANCE_MM = 0.01
"""Largest difference between the start and end radius of an I/J/K arc (Fanuc parameter 3410's role)."""
PLANE_INDEX = {"XY": (0, 1, 2), "ZX": (2, 0, 1), "YZ": (1, 2, 0)}
"""Per plane, indices into an (x, y, z) point of the first and second plane axis and of the normal."""
CENTRE_KEYS = {"X": "cx", "Y": "cy", "Z": "cz"}
MAX_ARC_POINTS = 4096
"""Most points ``arc_points`` yields for one arc (under 0.1 degree apart on a full circle)."""


def centre_from_radius(s: tuple[float, float], e: tuple[float, float], r: float,
                       clockwise: bool) -> tuple[float, float]:
    """Centre of an R-form arc in plane coordinates. Negative R is the long way (over 180 degrees)."""
    dx, dy = e[0] - s[0], e[1] - s[1]
    chord = math.hypot(dx, dy)
    if chord < 10.0 ** -PLACES:
        raise ProgramError("a full circle cannot be programmed with R (use I/J/K)")
    half = chord / 2.0
    radius = abs(r)
    if radius < half:
        if half - radius > ARC_TOLERANCE_MM:
            raise ProgramError(f"arc radius {radius:.4f} mm is too small for a chord of {chord:.4f} mm")
        radius = half
    h = math.sqrt(max(radius - half, 0.0)) * math.sqrt(radius + half)  # no overflow near the float range
    # Left normal of the chord: a counter-clockwise arc of up to 180 degrees has its centre on the left.
    nx, ny = -dy / chord, dx / chord
    side = 1.0 if clockwise == (r < 0) else -1.0
    return s[0] + dx / 2.0 + side * h * nx, s[1] + dy / 2.0 + side * h * ny


def arc_sweep(s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
              clockwise: bool) -> float:
    """Angle swept from s to e about c, in (0, 2*pi]; coincident end points make a full circle."""
    a0 = math.atan2(s[1] - c[1], s[0] - c[0])
    a1 = math.atan2(e[1] - c[1], e[0] - c[0])
    sweep = (a0 - a1) if clockwise else (a1 - a0)
    sweep %= 2.0 * math.pi
    if sweep < 1e-9:
        sweep = 2.0 * math.pi
    return sweep


def arc_points(start: tuple[float, float, float], end: tuple[float, float, float],
               centre: tuple[float, float, float], plane: str, clockwise: bool,
               chord_error: float = 0.01, max_step: float = math.radians(5.0)) -> Iterator[tuple[float, float, float]]:
    """Points along an arc (helix) after ``start`` up to ``end``, within ``chord_error`` of the curve
    (at most ``MAX_ARC_POINTS``: an arc of a huge radius is drawn coarser, never with millions of points)."""
    i, j, k = PLANE_INDEX[plane]
    s, e, c = (start[i], start[j]), (end[i], end[j]), (centre[i], centre[j])
    sweep = arc_sweep(s, e, c, clockwise)
    r0 = math.hypot(s[0] - c[0], s[1] - c[1])
    r1 = math.hypot(e[0] - c[0], e[1] - c[1])
    rmax = max(r0, r1)
    step = max_step
    if rmax > chord_error:
        step = min(step, 2.0 * math.acos(1.0 - chord_error / rmax))
    n = min(MAX_ARC_POINTS, math.ceil(sweep / step)) if step > 0 else MAX_ARC_POINTS  # huge radii: step 0
    n = max(1, n)
    a0 = math.atan2(s[1] - c[1], s[0] - c[0])
    sign = -1.0 if clockwise else 1.0
    for q in range(1, n):
        t = q / n
        a = a0 + sign * sweep * t
        r = r0 + (r1 - r0) * t
        p = [0.0, 0.0, 0.0]
        p[i] = c[0] + r * math.cos(a)
        p[j] = c[1] + r * math.sin(a)
        p[k] = start[k] + (end[k] - start[k]) * t
        yield p[0], p[1], p[2]
    yield end
