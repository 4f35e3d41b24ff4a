"""Arc arithmetic for ``--arcs`` (``postproc.lowering.arcs``): chord points within a tolerance, the
R form of an arc and whether a controller would place its centre back where it was.

Pure functions on plane coordinates (the two axes of the arc's plane) plus the other axes that move
with the arc (a helix's linear axis, a rotary axis), each interpolated in proportion to the angle, as
RS274 controllers run a helix ([V] LinuxCNC ``interp_convert.cc`` ``convert_arc``: the axes outside
the plane move linearly with the arc; [V] grbl ``motion_control.c`` ``mc_arc``: ``linear_per_segment``).
Units are those of the caller (the program's); tolerances are passed in the same units.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterator, Mapping

from mypy_extensions import mypyc_attr

from ..geometry.arcs import arc_sweep, centre_from_radius

MAX_CHORDS = 100_000
"""Most chords one arc becomes: beyond it the tolerance is refused (a 10 m circle at 1 um needs 7,000)."""
HALF_TURN = math.pi
R_PIECE = 2.0 * math.pi / 3.0
"""Largest sweep of a piece an arc is split into for the R form (120 degrees): there the centre lies half
a radius off the chord, and a written R moves it at most twice the rounding of R."""


Point = tuple[float, float]


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(frozen=True)
class Arc:
    """One arc in the plane: start, end and centre (plane coordinates), direction, and the other axes'
    start and end values (``along``: axis letter -> (start, end)) that move in proportion to the angle."""

    start: Point
    end: Point
    centre: Point
    clockwise: bool
    along: Mapping[str, tuple[float, float]]

    @property
    def sweep(self) -> float:
        """Angle swept, in (0, 2*pi]; coincident end points are a full circle."""
        return arc_sweep(self.start, self.end, self.centre, self.clockwise)

    @property
    def radii(self) -> tuple[float, float]:
        """Radius at the start and at the end (they differ within the reader's arc tolerance)."""
        c = self.centre
        return (math.hypot(self.start[0] - c[0], self.start[1] - c[1]),
                math.hypot(self.end[0] - c[0], self.end[1] - c[1]))

    def at(self, t: float) -> tuple[Point, dict[str, float]]:
        """The point at fraction ``t`` of the sweep (radius interpolated between the start's and the
        end's, as the simulator draws it) and the other axes there."""
        c = self.centre
        r0, r1 = self.radii
        a0 = math.atan2(self.start[1] - c[1], self.start[0] - c[0])
        a = a0 + (-1.0 if self.clockwise else 1.0) * self.sweep * t
        r = r0 + (r1 - r0) * t
        others = {axis: s + (e - s) * t for axis, (s, e) in self.along.items()}
        return (c[0] + r * math.cos(a), c[1] + r * math.sin(a)), others


def chord_count(arc: Arc, tolerance: float) -> int:
    """Fewest equal-angle chords that stay within ``tolerance`` of the arc: a chord over angle ``a`` of
    a circle of radius r lies at most r * (1 - cos(a / 2)) inside it (at its middle). Raises
    ``ValueError`` when that takes more than ``MAX_CHORDS``."""
    r = max(arc.radii)
    sweep = arc.sweep
    if tolerance >= r:
        step = HALF_TURN  # any chord of up to half a turn lies within r of its arc
    else:
        step = 2.0 * math.acos(1.0 - tolerance / r)
    if step <= 0.0:
        raise ValueError(f"a chord tolerance of {tolerance:g} is too fine for a radius of {r:g}")
    n = max(1, math.ceil(sweep / step - 1e-12))
    if n > MAX_CHORDS:
        raise ValueError(f"{n} chords would be needed (most {MAX_CHORDS}): the tolerance {tolerance:g} is too "
                         f"fine for a radius of {r:g}")
    return n


def chord_points(arc: Arc, tolerance: float, quantum: float) -> Iterator[tuple[Point, dict[str, float]]]:
    """The end points of the chords after the start, the last one the arc's own end (exactly). The points
    between are rounded to ``quantum`` (a power of ten): a program written incrementally then sums its
    written steps to the exact end, with no drift."""
    n = chord_count(arc, tolerance)
    for k in range(1, n):
        (p, q), others = arc.at(k / n)
        yield (_quantize(p, quantum), _quantize(q, quantum)), {a: _quantize(v, quantum) for a, v in others.items()}
    yield arc.end, {axis: e for axis, (_, e) in arc.along.items()}


def _quantize(value: float, quantum: float) -> float:
    places = max(0, round(-math.log10(quantum)))
    return round(value, places)


def signed_radius(arc: Arc) -> float:
    """The R word of an arc: its start radius, negative over half a turn (the RS274 convention). [V] LinuxCNC:
    its interpreter rs274 runs the negative R this writes as the long arc (tests/test_arcs_rs274.py); [K] grbl
    ``gcode.c`` (and the ports derived from it): a negative R puts the centre on the far side of the chord,
    "an arc of more than 180 degrees"; [K] Fanuc operator's manuals, circular interpolation: an arc over 180
    degrees is programmed with a negative R; [K] Beckhoff ISG: "with negative radius value the largest
    possible circle" (infosys, Radius programming)."""
    r = arc.radii[0]
    return -r if arc.sweep > HALF_TURN else r


def r_centre_error(arc: Arc, slack: float) -> float:
    """How far from the arc's centre a controller puts the centre it computes from the R form (the
    start, the end and ``signed_radius``) when each written number may be off by ``slack``: the worst of
    R written ``slack`` larger or smaller. Infinite for a full circle (R cannot give one)."""
    if arc.sweep >= 2.0 * math.pi - 1e-12:
        return math.inf
    r = signed_radius(arc)
    worst = 0.0
    for dr in (-slack, 0.0, slack):
        trial = math.copysign(abs(r) + dr, r)
        try:
            c = centre_from_radius(arc.start, arc.end, trial, arc.clockwise)
        except Exception:  # a radius too short for the chord: the R form cannot be written safely
            return math.inf
        worst = max(worst, math.hypot(c[0] - arc.centre[0], c[1] - arc.centre[1]))
    return worst


def split(arc: Arc, pieces: int, quantum: float) -> list[Arc]:
    """The arc as ``pieces`` arcs of equal sweep about the same centre; the points between lie on it,
    rounded to ``quantum``, the last piece ends at the arc's own end."""
    points = [(arc.start, {axis: s for axis, (s, _) in arc.along.items()})]
    for k in range(1, pieces):
        (p, q), others = arc.at(k / pieces)
        points.append(((_quantize(p, quantum), _quantize(q, quantum)),
                       {a: _quantize(v, quantum) for a, v in others.items()}))
    points.append((arc.end, {axis: e for axis, (_, e) in arc.along.items()}))
    return [Arc(points[k][0], points[k + 1][0], arc.centre, arc.clockwise,
                {axis: (points[k][1][axis], points[k + 1][1][axis]) for axis in arc.along})
            for k in range(pieces)]


def r_pieces(arc: Arc) -> int:
    """How many pieces the R form needs: one, unless the arc is a full circle or within reach of half a
    turn, where R places the centre badly; then enough pieces of at most ``R_PIECE``."""
    return max(2, math.ceil(arc.sweep / R_PIECE - 1e-12))
