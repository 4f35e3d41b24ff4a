"""The arithmetic of a controller's arc-end rule (``postproc.geometry.arc_end.ArcEndRule``): what it accepts
(``rule_allows``, ``rule_limit``, ``rule_judged``, ``centre_shift``), the centre it moves to (``moved_centre``) and how
far the circle it runs about that centre lies from a spiral controller's path (``circle_spiral_gap``, first by the
closed-form ``circle_gap_bounds``), apart from the record so that it is compiled (``pyproject.toml``).

Every arc an ISG or Fagor translation reads from Fanuc is judged by the target's rule (the modal step's
``_target_accepts``). Interpreted, the record's methods cost ~58k instructions an arc (eight Python frames of float
arithmetic), ~1.5k a block of the benchmark's CAM program (issue 30); the record's methods now call these functions,
and the modal step calls them directly. One computation in either build: only where it runs changed.
"""

from __future__ import annotations

import math
from math import asin, atan2, hypot  # (no primitive in mypyc: a global's look-up, not the module's attribute)
from typing import TYPE_CHECKING, Final

from .arc_paths import ArcPath, deviation
from .arcs import arc_sweep

if TYPE_CHECKING:
    from .arc_end_fields import ArcEndLimits  # (only a type: nothing to import at run time)


def centre_shift(r_start: float, r_end: float, chord: float) -> float:
    """How far the centre moves to the nearest point of the chord's perpendicular bisector: the programmed
    centre's distance from it along the chord, (r_start^2 - r_end^2) / (2 chord) (a full circle: none)."""
    if chord <= 0.0:
        return 0.0 if r_start == r_end else math.inf
    return abs(r_start * r_start - r_end * r_end) / (2.0 * chord)


def rule_limit(rule: ArcEndLimits, r_start: float, r_end: float, inch: bool, chord: float = 0.0) -> float:
    """``ArcEndRule.limit``: the largest difference of radii (with ``of_centre_shift``: move of the centre) ``rule``
    accepts for an arc of these radii and this chord (program units)."""
    absolute = rule.inch if inch else rule.metric
    relative = rule.relative
    if relative <= 0.0:
        return absolute
    if rule.of_centre_shift:
        shift = centre_shift(r_start, r_end, chord)
        radius = math.sqrt(max((r_start * r_start + r_end * r_end) / 2.0 - shift * shift, 0.0))
    else:
        radius = r_start if rule.of_start else max(r_start, r_end)
    share = relative * radius
    ceiling = rule.ceiling
    if ceiling > 0.0:
        share = min(share, ceiling * absolute)
    return max(absolute, share)


def rule_judged(rule: ArcEndLimits, r_start: float, r_end: float, chord: float = 0.0) -> float:
    """``ArcEndRule.judged``: what ``rule``'s limits bound for an arc of these radii and this chord: the difference
    of radii, or (with ``of_centre_shift``) the centre's move."""
    return centre_shift(r_start, r_end, chord) if rule.of_centre_shift else abs(r_start - r_end)


def rule_allows(rule: ArcEndLimits, r_start: float, r_end: float, inch: bool, chord: float = 0.0) -> bool:
    """``ArcEndRule.allows``: whether the controller runs an arc with these start and end radii and this chord
    (program units; the chord matters only ``of_centre_shift``)."""
    return rule_judged(rule, r_start, r_end, chord) <= rule_limit(rule, r_start, r_end, inch, chord) * (1.0 + 1e-9)


def rule_centre(rule: ArcEndLimits, s: tuple[float, float], e: tuple[float, float],
                c: tuple[float, float]) -> tuple[float, float]:
    """``ArcEndRule.centre``: the centre the controller turns about for an accepted arc from ``s`` to ``e`` programmed
    about ``c`` (its own for a spiral, ``arc_end.SPIRAL``; else ``moved_centre``)."""
    runs = rule.runs
    if runs == "spiral":
        return c
    return moved_centre(runs == "nearest_centre", s, e, c)


def moved_centre(nearest: bool, s: tuple[float, float], e: tuple[float, float],
                 c: tuple[float, float]) -> tuple[float, float]:
    """The centre a centre-moving controller turns about for an accepted arc from ``s`` to ``e`` programmed about
    ``c``: the nearest point of the chord's perpendicular bisector (``nearest``: ``arc_end.NEAREST_CENTRE``), else the
    point there at the start radius on the programmed centre's side (``arc_end.START_RADIUS``)."""
    r0 = hypot(s[0] - c[0], s[1] - c[1])
    dx, dy = e[0] - s[0], e[1] - s[1]
    chord = hypot(dx, dy)
    if chord == 0.0:
        return c  # a full circle: its end is its start, on the circle
    mid = (s[0] + dx / 2.0, s[1] + dy / 2.0)
    nx, ny = -dy / chord, dx / chord  # the bisector's direction
    if nearest:
        along = (c[0] - mid[0]) * nx + (c[1] - mid[1]) * ny
        return mid[0] + along * nx, mid[1] + along * ny
    side = 1.0 if (c[0] - mid[0]) * nx + (c[1] - mid[1]) * ny >= 0.0 else -1.0
    h = math.sqrt(max(r0 * r0 - chord * chord / 4.0, 0.0))
    return mid[0] + side * h * nx, mid[1] + side * h * ny


def turn(s: tuple[float, float], e: tuple[float, float], c: tuple[float, float], clockwise: bool) -> float:
    """How far an arc from ``s`` to ``e`` about ``c`` turns (radians, negative clockwise; end on start: a turn)."""
    sweep = arc_sweep(s, e, c, clockwise)
    return -sweep if clockwise else sweep


def circle_spiral_gap(nearest: bool, s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
                      clockwise: bool, floor: float = -1.0) -> float:
    """``ArcEndRule.spiral_gap`` for a centre-moving rule (``nearest`` as ``moved_centre``): how far the circle it
    runs lies from a spiral controller's path for the same arc, the spiral from ``s`` to ``e`` about ``c`` whose
    radius changes evenly with the angle: the largest distance between the two paths, as ``verify`` measures it
    (``postproc.geometry.arc_paths.deviation``, with its ``floor``)."""
    moved = moved_centre(nearest, s, e, c)
    turned = turn(s, e, c, clockwise)
    if floor >= 0.0:  # most arcs: the closed-form bound decides (``circle_gap_bounds``), no search
        bounds = circle_gap_bounds(s, e, c, moved, turned)
        if bounds is not None and bounds[1] <= floor:
            return bounds[1]
    spiral = ArcPath(s, e, c, turned, [], [])
    return deviation(spiral, ArcPath(s, e, moved, turn(s, e, moved, clockwise), [], []), floor)


def circle_gap_bounds(s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
                      m: tuple[float, float], turn: float) -> tuple[float, float] | None:
    """Bounds (low, high) of how far the circle from ``s`` to ``e`` about ``m`` (a moved centre: ``m`` on the
    chord's bisector) lies from the spiral from ``s`` to ``e`` about ``c`` turning ``turn`` (radians, negative
    clockwise, as ``turn``): the distance ``circle_spiral_gap`` computes, in a few trigonometric calls where the search
    of ``postproc.geometry.arc_paths.deviation`` takes hundreds. None where the proof below does not hold (tiny radii, a
    centre moved far, a sweep near none or a whole turn): the caller then computes the distance.

    Proof. Let r0, r1 be the spiral's radii, rho(tau) = r0 + k tau (k = (r1 - r0) / T, T = |turn|, tau in [0, T])
    its radius at the angle tau turned, u(tau) the unit vector there, delta = c - m, d = |delta|, and
    q(tau) = delta + rho u the spiral's point seen from ``m``; R the circle's radius |s - m| (|e - m| differs
    from it by rounding only: ``wobble`` below).

    1. The ray from ``m`` matches the two paths. q x q' = rho^2 + rho (delta . u) + k (delta x u)
       >= rho (rho - d) - |k| d, positive by the first condition below: the angle of q about ``m`` grows
       strictly in the turn's direction. It differs from the angle about ``c`` by the angle the segment
       c-m subtends at the point, at most w = asin(d / (rho - d)), so q turns about ``m`` by T within 2 w
       in all; with 2 w < T < 2 pi - 2 w (the second condition) that is strictly between 0 and a whole
       turn, and q runs from s - m to e - m: it sweeps exactly the circle's arc (``arc_sweep`` about ``m``).
       Each point of either path then has a partner on its ray from ``m``, at distance | |q| - R |; and
       no point of the circle lies nearer a spiral point than | |q| - R |. So the Hausdorff distance
       ``deviation`` computes is exactly G = max over tau of | |q(tau)| - R | (its end points coincide, and
       neither path runs on past the other's end, so its other terms are 0).
    2. With a = delta . u (|a| <= d): |q| - (rho + a) = (d^2 - a^2) / (|q| + rho + a), in [0, eps] with
       eps = d^2 / (2 (rho_min - d)). So |q| - R = P(tau) + e(tau), 0 <= e <= eps, for the model
       P(tau) = rho(tau) + d cos(angle(tau) - angle of delta) - R: linear plus a sinusoid, whose extremes over
       [0, T] lie at its ends or where its derivative k - sign d sin(angle - angle of delta) vanishes (closed
       form, as ``postproc.geometry.arc_paths._Matching._model_extremes``).
    3. Hence max(max P, -min P - eps) <= G <= max(max P + eps, -min P); ``wobble`` (|e - m| - R: the circle
       ``deviation`` draws is a spiral of that rounding) and the rounding of P (``_ROUNDING`` of the radii)
       widen both sides.

    Conditions: d <= rho_min / 2 (``deviation``'s own matching, not its sampled search), rho_min (rho_min - d)
    > |k| d, and 2 w + 1e-6 < T < 2 pi - 2 w - 1e-6 (``arc_sweep`` reads a sweep under 1e-9 as a whole turn; 2 w
    taken as pi d / (rho_min - d), which is at least it).

    Written with conditionals, not ``min``/``max``, and with the ends' directions taken from the end points, not
    trigonometry: every arc an ISG or Fagor translation reads comes here (a builtin call is ~500 instructions)."""
    sx, sy = s[0] - c[0], s[1] - c[1]
    ex, ey = e[0] - c[0], e[1] - c[1]
    r0 = hypot(sx, sy)
    r1 = hypot(ex, ey)
    rho_min = r0 if r0 < r1 else r1
    dx, dy = c[0] - m[0], c[1] - m[1]
    d = hypot(dx, dy)
    span = turn if turn > 0.0 else -turn
    if not (0.0 < span < _TWO_PI and 0.0 < rho_min and d <= 0.5 * rho_min):
        return None
    k = (r1 - r0) / span
    if rho_min * (rho_min - d) <= (k if k > 0.0 else -k) * d:
        return None
    w = math.pi * d / (rho_min - d) + 1e-6  # at least 2 asin(d / (rho_min - d)) (asin(y) <= pi y / 2 on [0, 1])
    if not w < span < _TWO_PI - w:
        return None
    radius = hypot(s[0] - m[0], s[1] - m[1])
    wobble = hypot(e[0] - m[0], e[1] - m[1]) - radius
    if wobble < 0.0:
        wobble = -wobble
    # P at the ends (d cos(angle - angle of delta) = delta . u, u the end's direction from c), and where its
    # derivative vanishes: sin(x) = sign k / d with x the angle less delta's, at tau = sign (x + delta's angle
    # less the start's) modulo a turn; P there is r0 + k tau + d cos(x).
    high = low = r0 + (dx * sx + dy * sy) / r0 - radius
    p = r1 + (dx * ex + dy * ey) / r1 - radius
    if p > high:
        high = p
    if p < low:
        low = p
    if 0.0 < d and (k if k > 0.0 else -k) <= d:
        sign = 1.0 if turn > 0.0 else -1.0
        lean = sign * k / d
        base = asin(lean)
        rise = d * math.sqrt(1.0 - lean * lean)
        offset = atan2(sx * dy - sy * dx, sx * dx + sy * dy)  # delta's angle less the start's (about c)
        t = (sign * (base + offset)) % _TWO_PI
        if t <= span:
            p = r0 + k * t + rise - radius
            if p > high:
                high = p
            if p < low:
                low = p
        t = (sign * (math.pi - base + offset)) % _TWO_PI
        if t <= span:
            p = r0 + k * t - rise - radius
            if p > high:
                high = p
            if p < low:
                low = p
    eps = d * d / (2.0 * (rho_min - d))
    slack = wobble + _ROUNDING * (r0 + r1 + radius + d + 1.0)
    upper = high + eps if high + eps > -low else -low
    lower = high if high > -low - eps else -low - eps
    return (lower - slack if lower > slack else 0.0), upper + slack


_TWO_PI: Final = 2.0 * math.pi
_ROUNDING: Final = 1e-12
"""The rounding ``circle_gap_bounds`` allows each side, as a share of the radii it adds (a few ulps of each term,
generously: 1e-9 mm on a 1000 mm arc, against ``SPIRAL_AS_CIRCLE_MM``'s 0.0005 mm)."""
