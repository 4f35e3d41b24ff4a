"""How far apart two controllers cut an arc: the largest distance between two arc paths, computed, not
sampled to a bound (``verify`` compares arcs by it; ``postproc.geometry.arc_end`` judges a centre correction by it).

An arc path (``ArcPath``) is what the simulator draws (``postproc.geometry.arcs.arc_points``) once a controller's
rule has placed the centre (``postproc.geometry.arc_end``): from the start about the centre, the radius changing evenly
with the angle from the start radius to the end radius (a circle where they are equal, a spiral otherwise),
every axis outside the plane moving evenly with the angle (a helix). Two controllers' paths for one programmed
arc differ where their rules differ: one keeps the programmed centre and runs a spiral, another moves the centre
onto the chord's bisector and runs a circle; the centres then lie apart (a 4-decimal CAM arc: 0.0007 mm) where
the paths stay within a micron of each other.

``deviation(a, b)`` is the largest of the start points' distance, the end points' distance and the Hausdorff
distance of the two paths (the largest distance of a point of either from the other), computed, not sampled to
a bound; except that a path running half a turn or more beyond the other's end is measured from that end (its far
side: ``_Matching.beyond``), where the Hausdorff distance would not see a circle cut once more over the other's.

How: first a bound. The points of ``a`` and ``b`` on one ray from ``b``'s centre match the two paths over the
angles both cover (every point of either has a partner), so the largest distance between partners bounds the
Hausdorff distance from above; for a flat circle ``b`` it is that distance (the nearest point of a circle lies
on the ray through its centre). With d the centres' offset, the partners' radial distance is d cos(angle -
angle of d) plus a linear function of the angle (the two radii), within d^2/r: the closed form of that model's
extremes (the overlap's ends, where its derivative is zero) plus the margin is the bound. A pair whose bound is
below what the caller already has (``floor``: verify's largest deviation so far, or the centre correction's
limit) is decided there, as are two flat paths about one centre (no margin; for a spiral within its pitch's
cosine): most arcs of a program. Otherwise the
Hausdorff distance itself: each point's distance from the other path is the foot of its perpendicular (Newton's
method on the squared distance from the ray's partner, which converges in a step or two on paths this close,
within the path or at its nearest end), taken at every eighth of half a turn of each path and at the model's
extremes, each local largest value refined by golden-section search to 1e-6 rad (its curvature is at most about
r + d: the value found is within (r + d) 1.25e-13 mm of the largest).

Paths whose centres lie more than half the smaller radius apart, or that turn opposite ways, are no longer close
enough for the ray matching: ``deviation`` then gives their Hausdorff distance from ``GROSS_SAMPLES`` points of
each, the distance of each from the other path exact, refined about the largest (``_sampled``): such a pair
lies far apart, and the value says how far, to the precision of that search.
"""

from __future__ import annotations

import math
from typing import Callable, Final, Mapping

from .arcs import PLANE_INDEX

_TWO_PI: Final = 2.0 * math.pi
_STEP: Final = math.pi / 8.0
"""Largest spacing (rad) of the samples of a point's distance from the other path before refinement (about a
sinusoid plus a linear term, within d^2/r: at most two extremes a turn, each bracketed by samples this close)."""
_REFINED: Final = 1e-6
"""Width of the bracket (rad) golden-section search narrows each largest value to: the distance's curvature is at
most about r + d, so the value found is within (r + d) 1.25e-13 mm of the largest."""
_GOLD: Final = (math.sqrt(5.0) - 1.0) / 2.0
GROSS_SAMPLES: Final = 256
"""Points a path is sampled at where the paths are too far apart for the ray matching (``_sampled``)."""


def _wrap(angle: float) -> float:
    """``angle`` in (-pi, pi]."""
    angle = math.fmod(angle, _TWO_PI)
    if angle > math.pi:
        angle -= _TWO_PI
    elif angle <= -math.pi:
        angle += _TWO_PI
    return angle


class ArcPath:
    """One controller's path for an arc, in mm: plane coordinates of its start, end and centre, how far it turns
    (radians, positive counter-clockwise, may exceed a turn: a helix of several; made to end at the end's angle),
    and the axes outside the plane at its start and end (one list each, in the same order for both paths
    compared)."""

    def __init__(self, start: tuple[float, float], end: tuple[float, float], centre: tuple[float, float],
                 turn: float, off_start: list[float], off_end: list[float]) -> None:
        self.start = start
        self.end = end
        self.centre = centre
        self.turn = turn
        self.off_start = off_start
        self.off_end = off_end
        self.r0 = math.hypot(start[0] - centre[0], start[1] - centre[1])
        self.r1 = math.hypot(end[0] - centre[0], end[1] - centre[1])
        self.a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
        # the turn made to end at the end's angle (a run of arcs merged about one centre within a tolerance turns
        # by the sum of its pieces' turns, each about its own centre)
        self.turn = turn + _wrap(math.atan2(end[1] - centre[1], end[0] - centre[0]) - (self.a0 + turn))

    def at(self, t: float) -> tuple[float, float, list[float]]:
        """The point at the fraction ``t`` of the turn: plane coordinates, then the axes outside the plane."""
        a = self.a0 + self.turn * t
        r = self.r0 + (self.r1 - self.r0) * t
        return (self.centre[0] + r * math.cos(a), self.centre[1] + r * math.sin(a),
                [s + (e - s) * t for s, e in zip(self.off_start, self.off_end)])


def arc_path(start: Mapping[str, float], end: Mapping[str, float], centre: tuple[float, float], plane: str,
             sweep: float, clockwise: bool, off_keys: list[str]) -> ArcPath:
    """An ``ArcPath`` from points given axis by axis (a toolpath's; an axis absent counts as 0), its centre in
    plane coordinates, its sweep (radians, positive) and direction; ``off_keys``: the axes outside the plane
    compared (the same list for both paths)."""
    i, j, _ = PLANE_INDEX[plane]
    pi, pj = "xyz"[i], "xyz"[j]
    return ArcPath((start.get(pi, 0.0), start.get(pj, 0.0)), (end.get(pi, 0.0), end.get(pj, 0.0)), centre,
                   -sweep if clockwise else sweep, [start.get(k, 0.0) for k in off_keys],
                   [end.get(k, 0.0) for k in off_keys])


def _points_apart(p: tuple[float, float], q: tuple[float, float], off_p: list[float], off_q: list[float]) -> float:
    square = (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2
    for u, v in zip(off_p, off_q):
        square += (u - v) ** 2
    return math.sqrt(square)


def deviation(a: ArcPath, b: ArcPath, floor: float = -1.0) -> float:
    """The largest distance between the paths ``a`` and ``b`` (the module's docstring says which distance and
    how). ``floor``: a caller that only needs the distance where it exceeds ``floor`` gets some value of at most
    ``floor`` where the distance is at most that (a bound, decided without the search)."""
    ends = max(_points_apart(a.start, b.start, a.off_start, b.off_start),
               _points_apart(a.end, b.end, a.off_end, b.off_end))
    dx, dy = a.centre[0] - b.centre[0], a.centre[1] - b.centre[1]
    apart = math.hypot(dx, dy)
    smallest = min(a.r0, a.r1, b.r0, b.r1)
    if (a.turn > 0.0) != (b.turn > 0.0) or a.turn == 0.0 or b.turn == 0.0 or not apart <= 0.5 * smallest:
        return max(ends, _sampled(a, b, floor))
    m = _Matching(a, b, dx, dy, apart)
    if m.hi < m.lo:  # no angle both cover: each runs beyond the other's end
        return max(ends, _sampled(a, b, floor))
    ends = max(ends, m.beyond())
    bound, exact = m.bound(smallest)
    if exact or max(ends, bound) <= floor:
        return max(ends, bound)
    return max(ends, m.largest())


class _Matching:
    """The points of ``a`` and ``b`` on the rays from ``b``'s centre, as functions of the angle ``t`` turned from
    ``b``'s start (``t`` in [lo, hi], the angles both cover)."""

    def __init__(self, a: ArcPath, b: ArcPath, dx: float, dy: float, apart: float) -> None:
        self.a, self.b = a, b
        self.dx, self.dy, self.apart = dx, dy, apart
        self.sign = 1.0 if b.turn > 0.0 else -1.0
        self.span_b = abs(b.turn)
        self.span_a = abs(a.turn)
        cb = b.centre
        start_angle = math.atan2(a.start[1] - cb[1], a.start[0] - cb[0])
        self.t_start = self.sign * _wrap(start_angle - b.a0)  # where a starts, in b's angles
        end_angle = math.atan2(a.end[1] - cb[1], a.end[0] - cb[0])
        self.t_end = self.t_start + self.span_a + self.sign * _wrap(end_angle - (start_angle + a.turn))
        self.lo = max(0.0, self.t_start)
        self.hi = min(self.span_b, self.t_end)
        self.k_a = (a.r1 - a.r0) / self.span_a  # radius per radian
        self.k_b = (b.r1 - b.r0) / self.span_b

    def beyond(self) -> float:
        """How far the part of one path past the other's end (in angle) gets from that end: at its own end where it
        runs on less than half a turn (the distance from a point near a circle grows with the angle up to half a
        turn, so that is the end points' distance, already counted: 0 here); else at most the far side of its
        circle, the end's distance from its centre plus its larger radius (a path that turns once more than the
        other is no match for it, though every point of it lies near the other's circle)."""
        a, b = self.a, self.b
        if self.t_end - self.span_b >= math.pi:  # a runs on past b's end
            return _far_side(a, b)
        if self.span_b - self.t_end >= math.pi:
            return _far_side(b, a)
        return 0.0

    def bound(self, smallest: float) -> tuple[float, bool]:
        """An upper bound of the matched distance over [lo, hi] from the closed form of its model, and whether it
        is the largest matched distance itself (within 1e-12 mm: centres that coincide, flat arcs)."""
        a, b = self.a, self.b
        d = self.apart
        # off the model: the circle's chord through the ray (at most d^2/r) and the angle about a's centre
        # against the angle about b's (at most 2 asin(d / (r - d)) between the two starts' and two points')
        shift = 2.0 * math.asin(min(1.0, d / (smallest - d)))
        margin = d * d / smallest + abs(self.k_a) * shift
        worst = 0.0
        for t in self._model_extremes():
            worst = max(worst, abs(self._model(t)))
        off = 0.0
        if a.off_start:
            for k in range(len(a.off_start)):
                rate_a = (a.off_end[k] - a.off_start[k]) / self.span_a
                at_lo = abs(self._off_a(k, self.lo - self.t_start) - self._off_b(k, self.lo))
                at_hi = abs(self._off_a(k, self.hi - self.t_start) - self._off_b(k, self.hi))
                off += (max(at_lo, at_hi) + abs(rate_a) * shift) ** 2
        exact = margin <= 1e-12 and off == 0.0
        return math.sqrt((worst + margin) ** 2 + off), exact

    def _off_a(self, k: int, turned: float) -> float:
        return self.a.off_start[k] + (self.a.off_end[k] - self.a.off_start[k]) * turned / self.span_a

    def _off_b(self, k: int, t: float) -> float:
        return self.b.off_start[k] + (self.b.off_end[k] - self.b.off_start[k]) * t / self.span_b

    def _model(self, t: float) -> float:
        """The radial gap's model: d cos(angle - angle of d) + a's radius (its angle taken as b's) - b's radius."""
        a, b = self.a, self.b
        angle = b.a0 + self.sign * t
        along = self.dx * math.cos(angle) + self.dy * math.sin(angle)
        return along + a.r0 + self.k_a * (t - self.t_start) - b.r0 - self.k_b * t

    def _model_extremes(self) -> list[float]:
        """[lo, hi] and the model's critical points inside: -sign d sin(x) + (k_a - k_b) = 0 with x the ray's
        angle less the angle of d."""
        found = [self.lo, self.hi]
        d = self.apart
        slope = self.k_a - self.k_b
        if d <= 0.0 or abs(slope) > d:
            return found
        phase = math.atan2(self.dy, self.dx)
        base = math.asin(self.sign * slope / d)
        for x in (base, math.pi - base):
            # t = sign (x + phase - b.a0) + 2 pi m, every m that lands in [lo, hi]
            t0 = self.sign * (x + phase - self.b.a0)
            m = math.ceil((self.lo - t0) / _TWO_PI)
            t = t0 + m * _TWO_PI
            while t <= self.hi:
                found.append(t)
                t += _TWO_PI
        return found

    def largest(self) -> float:
        """The Hausdorff distance of the two paths: the largest distance of a point of either from the other
        (``_from``), each sampled at most ``_STEP`` apart (and at the model's extremes), each local largest value
        refined by golden-section search."""
        return max(self._largest_from(self.a, self.b, self.t_start, self.span_a, self.span_b),
                   self._largest_from(self.b, self.a, -self.t_start, self.span_b, self.span_a))

    def _largest_from(self, p: ArcPath, o: ArcPath, start: float, span: float, other_span: float) -> float:
        """The largest distance of a point of ``p`` from ``o``; ``start``: where ``p`` starts in ``o``'s angles."""
        n = max(2, math.ceil(span / _STEP))
        ts = [q / n for q in range(n + 1)]
        extra = [(t - start) / span for t in self._model_extremes()] if p is self.a else \
            [t / span for t in self._model_extremes()]
        ts = sorted(set(ts + [t for t in extra if 0.0 < t < 1.0]))

        def f(t: float) -> float:
            return _from(p.at(t), o, (start + t * span) / other_span)

        values = [f(t) for t in ts]
        best = max(values)
        for q in range(1, len(ts) - 1):
            if values[q] >= values[q - 1] and values[q] >= values[q + 1]:
                best = max(best, _golden(f, ts[q - 1], ts[q + 1], _REFINED / span))
        return best



def _golden(f: Callable[[float], float], lo: float, hi: float, width: float) -> float:
    """The largest value of ``f`` in [lo, hi] about a single local largest value inside, to a bracket ``width``."""
    x1 = hi - _GOLD * (hi - lo)
    x2 = lo + _GOLD * (hi - lo)
    f1, f2 = f(x1), f(x2)
    best = max(f1, f2)
    while hi - lo > width:
        if f1 >= f2:
            hi, x2, f2 = x2, x1, f1
            x1 = hi - _GOLD * (hi - lo)
            f1 = f(x1)
            best = max(best, f1)
        else:
            lo, x1, f1 = x1, x2, f2
            x2 = lo + _GOLD * (hi - lo)
            f2 = f(x2)
            best = max(best, f2)
    return best


def _from(point: tuple[float, float, list[float]], o: ArcPath, guess: float) -> float:
    """The distance of ``point`` from the path ``o``: the foot of the perpendicular found by Newton's method on
    the squared distance from ``guess`` (a fraction of ``o``'s turn, first moved to the point's angle about
    ``o``'s centre), kept within the path (its nearest end otherwise)."""
    x, y, off = point
    c = o.centre
    turn = o.turn
    s = guess + _wrap(math.atan2(y - c[1], x - c[0]) - (o.a0 + turn * guess)) / turn
    s = min(1.0, max(0.0, s))
    dr = o.r1 - o.r0
    deltas = [e - b for b, e in zip(o.off_start, o.off_end)]
    for _ in range(8):
        a = o.a0 + turn * s
        ca, sa = math.cos(a), math.sin(a)
        rho = o.r0 + dr * s
        px, py = c[0] + rho * ca - x, c[1] + rho * sa - y  # the path's point less the point
        vx, vy = dr * ca - rho * turn * sa, dr * sa + rho * turn * ca  # its derivative
        ax, ay = -2.0 * dr * turn * sa - rho * turn * turn * ca, 2.0 * dr * turn * ca - rho * turn * turn * sa
        g = px * vx + py * vy
        h = vx * vx + vy * vy + px * ax + py * ay
        for k in range(len(deltas)):
            w = o.off_start[k] + deltas[k] * s - off[k]
            g += w * deltas[k]
            h += deltas[k] * deltas[k]
        if h <= 0.0:
            break
        step = g / h
        s_new = min(1.0, max(0.0, s - step))
        if s_new == s:
            break
        s = s_new
        if abs(step) * math.sqrt(vx * vx + vy * vy) < 1e-13:
            break
    ex, ey, eoff = o.at(s)
    return _points_apart((x, y), (ex, ey), off, eoff)


def _sampled(a: ArcPath, b: ArcPath, floor: float) -> float:
    """The Hausdorff distance of two paths too far apart for the ray matching (or turning opposite ways): each
    path sampled at ``GROSS_SAMPLES`` points, each point's distance from the other path taken exactly (its
    circle's nearest point, or an end), the largest refined by golden-section search about the largest sample;
    and where one turns a whole turn more, the far side of its circle from the other's end (``_Matching.beyond``).
    First a bound: no point of a path lies further from a point of the other than their distance plus a radius."""
    bound = max(_far_side(a, b), _far_side(b, a))
    if bound <= floor:
        return bound
    found = max(_directed(a, b), _directed(b, a))
    if abs(abs(a.turn) - abs(b.turn)) >= _TWO_PI - 1e-9:
        found = max(found, bound)
    return found


def _far_side(a: ArcPath, b: ArcPath) -> float:
    """How far a point of ``a`` lies from ``b``'s end at most: the end's distance from ``a``'s centre plus ``a``'s
    larger radius in the plane, the larger difference of ``a``'s axes outside it (at its start or end)."""
    plane = math.hypot(b.end[0] - a.centre[0], b.end[1] - a.centre[1]) + max(a.r0, a.r1)
    square = plane * plane
    for k in range(len(b.off_end)):
        square += max(abs(a.off_start[k] - b.off_end[k]), abs(a.off_end[k] - b.off_end[k])) ** 2
    return math.sqrt(square)


def _directed(a: ArcPath, b: ArcPath) -> float:
    """The largest distance of a point of ``a`` from the path ``b``."""
    n = GROSS_SAMPLES
    values = [_to_path(a.at(q / n), b) for q in range(n + 1)]
    q = max(range(n + 1), key=values.__getitem__)
    lo, hi = max(0, q - 1) / n, min(n, q + 1) / n
    best = values[q]
    while hi - lo > _REFINED / max(abs(a.turn), 1e-9):
        x1, x2 = hi - _GOLD * (hi - lo), lo + _GOLD * (hi - lo)
        f1, f2 = _to_path(a.at(x1), b), _to_path(a.at(x2), b)
        best = max(best, f1, f2)
        if f1 >= f2:
            hi = x2
        else:
            lo = x1
    return best


def _to_path(point: tuple[float, float, list[float]], b: ArcPath) -> float:
    """The distance of ``point`` from the path ``b``: its ends, and where the point's angle about ``b``'s centre
    lies within ``b``'s turn, the point of ``b`` at that angle (the nearest of a circle; of a spiral, within its
    pitch)."""
    x, y, off = point
    best = min(_points_apart((x, y), b.start, off, b.off_start), _points_apart((x, y), b.end, off, b.off_end))
    span = abs(b.turn)
    turned = ((math.atan2(y - b.centre[1], x - b.centre[0]) - b.a0) * (1.0 if b.turn > 0.0 else -1.0)) % _TWO_PI
    while turned <= span:
        bx, by, boff = b.at(turned / span)
        best = min(best, _points_apart((x, y), (bx, by), off, boff))
        turned += _TWO_PI
    return best
