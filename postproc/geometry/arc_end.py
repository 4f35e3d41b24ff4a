"""How far a controller lets an I/J/K arc's end point lie off the circle through its start, and which
path it then runs: one rule per controller (``Dialect.ARC_END``), in the program's units, because a
program written to three decimals in inches carries ten times the rounding of one in millimetres.

The reading pipeline (``postproc.syntaxes.modal_state``) and the simulator (``postproc.simulate.moves``)
judge every arc by the *reading* dialect's rule through ``postproc.block_rules.arc_centre``, so an arc its
own controller accepts is read, simulated as that controller runs it, and an arc it refuses is a located
error. A translation's output is read back under the target's rule (``verify``), so an arc the target
would refuse is found there.

The facts behind each rule are in the dialect (or family base) that declares it, tagged with their source.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Final

from .arc_paths import ArcPath, deviation
from .arcs import arc_sweep
from ..records import record
from ..ir.state import MM_PER_INCH

SPIRAL: Final = "spiral"
"""The controller keeps the programmed centre and lets the radius change evenly from the start radius to
the end radius over the sweep (a spiral ending at the programmed end point)."""
START_RADIUS: Final = "start_radius"
"""The controller moves the centre onto the perpendicular bisector of the chord, at the start radius from
the start point, on the programmed centre's side: a true circle through both end points."""
NEAREST_CENTRE: Final = "nearest_centre"
"""The controller moves the centre to the nearest point of the chord's perpendicular bisector (the least move
that puts both end points on one circle, its radius about the mean of the two) and runs that circle. Well
conditioned where ``START_RADIUS`` is not: near half a turn the move stays about half the difference of radii."""
RUNS: Final = (SPIRAL, START_RADIUS, NEAREST_CENTRE)


@record(frozen=True)  # every run makes it (dialect.py): a record's methods are not compiled at start
class ArcEndRule:
    """What a controller accepts of an arc whose end radius differs from its start radius by ``d``, with
    ``r`` the larger radius (``of_start``: the start radius), in the program's units:

    * ``d <= metric`` (``inch`` in an inch program) is always accepted;
    * beyond it, with ``relative`` > 0, ``d <= relative * r`` is accepted, but never past ``ceiling``
      times the absolute limit (0: no ceiling);
    * anything else is refused.

    With ``of_centre_shift`` the same limits bound how far the controller moves the centre (``shift``) instead
    of the difference of radii, and ``relative`` is a share of the corrected radius.

    ``runs`` says which path an accepted arc takes (one of ``RUNS``)."""

    metric: float
    """The absolute limit in a millimetre program (mm)."""
    inch: float
    """The absolute limit in an inch program (inches)."""
    relative: float = 0.0
    """The share of the radius accepted beyond the absolute limit (0: none)."""
    ceiling: float = 0.0
    """With ``relative``: no difference above this multiple of the absolute limit is accepted (0: none)."""
    of_start: bool = False
    """``relative`` is a share of the start radius (else of the larger of the two radii)."""
    runs: str = SPIRAL
    """The path an accepted arc takes (see ``RUNS``)."""
    of_centre_shift: bool = False
    """The limits bound the centre's move onto the bisector (``NEAREST_CENTRE`` only), not the radii's difference."""

    def __post_init__(self) -> None:
        if self.runs not in RUNS:
            raise ValueError(f"unknown arc path {self.runs!r} (one of {', '.join(RUNS)})")
        if self.of_centre_shift and self.runs != NEAREST_CENTRE:
            raise ValueError("a limit on the centre's move needs the nearest-centre path")

    def describe(self) -> dict[str, object]:
        """The rule as plain data (the capability table, ``postproc dialects``)."""
        return {"mm": self.metric, "inch": self.inch, "relative": self.relative, "ceiling": self.ceiling,
                "of_start": self.of_start, "runs": self.runs, "of_centre_shift": self.of_centre_shift}

    def with_machine(self, limit: float | None, share: float | None) -> "ArcEndRule":
        """This rule with a machine's own parameters where its set-up gives them (a controller whose limits
        are machine parameters: ``Dialect.arc_end_rule``): ``limit`` the absolute limit in mm, whatever the
        program's units (the inch limit follows from it), ``share`` the relative one; None keeps this rule's."""
        if limit is None and share is None:
            return self
        metric = self.metric if limit is None else limit
        return replace(self, metric=metric, inch=metric / MM_PER_INCH,
                       relative=self.relative if share is None else share)

    def covers(self, other: "ArcEndRule") -> bool:
        """Whether every arc ``other`` accepts, in either units, this rule accepts too (sufficient, not
        necessary: a False only costs a closer look at each arc, ``postproc.lowering.arcs.settle_arc_ends``).
        Never where the two run an accepted arc on different paths, or judge different distances."""
        if self.runs != other.runs or self.of_centre_shift != other.of_centre_shift:
            return False
        if self.metric < other.metric or self.inch < other.inch:
            return False
        if other.relative <= 0.0:
            return True
        if self.relative < other.relative or self.of_start and not other.of_start:
            return False
        if self.ceiling <= 0.0:
            return True
        return other.ceiling > 0.0 and min(self.ceiling * self.metric - other.ceiling * other.metric,
                                           self.ceiling * self.inch - other.ceiling * other.inch) >= 0.0

    def limit(self, r_start: float, r_end: float, inch: bool, chord: float = 0.0) -> float:
        """The largest difference of radii (with ``of_centre_shift``: move of the centre) accepted for an arc of
        these radii and this chord (program units)."""
        absolute = self.inch if inch else self.metric
        if self.relative <= 0.0:
            return absolute
        if self.of_centre_shift:
            shift = self.shift(r_start, r_end, chord)
            radius = math.sqrt(max((r_start * r_start + r_end * r_end) / 2.0 - shift * shift, 0.0))
        else:
            radius = r_start if self.of_start else max(r_start, r_end)
        share = self.relative * radius
        if self.ceiling > 0.0:
            share = min(share, self.ceiling * absolute)
        return max(absolute, share)

    def judged(self, r_start: float, r_end: float, chord: float = 0.0) -> float:
        """What the limits bound for an arc of these radii and this chord: the difference of radii, or (with
        ``of_centre_shift``) the centre's move."""
        return self.shift(r_start, r_end, chord) if self.of_centre_shift else abs(r_start - r_end)

    @staticmethod
    def shift(r_start: float, r_end: float, chord: float) -> float:
        """How far the centre moves to the nearest point of the chord's perpendicular bisector: the programmed
        centre's distance from it along the chord, (r_start^2 - r_end^2) / (2 chord) (a full circle: none)."""
        if chord <= 0.0:
            return 0.0 if r_start == r_end else math.inf
        return abs(r_start * r_start - r_end * r_end) / (2.0 * chord)

    def centre_move(self, r_start: float, r_end: float, chord: float) -> float:
        """How far the controller moves the centre of an accepted arc (program units): none for ``SPIRAL``;
        with the programmed centre at ``shift`` along the chord and h along the bisector from the chord's middle
        (r_start^2 + r_end^2 = 2 h^2 + chord^2 / 2 + 2 shift^2), ``shift`` for ``NEAREST_CENTRE`` and the distance
        to the point at sqrt(r_start^2 - chord^2 / 4) along the bisector for ``START_RADIUS``."""
        if self.runs == SPIRAL:
            return 0.0
        along = self.shift(r_start, r_end, chord)
        if self.runs == NEAREST_CENTRE or not math.isfinite(along):
            return along
        quarter = chord * chord / 4.0
        h = math.sqrt(max((r_start * r_start + r_end * r_end) / 2.0 - quarter - along * along, 0.0))
        return math.hypot(along, math.sqrt(max(r_start * r_start - quarter, 0.0)) - h)

    def spiral_gap(self, s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
                   clockwise: bool, floor: float = -1.0) -> float:
        """How far the circle this rule runs (about the centre it moves to) lies from a spiral controller's path for
        the same arc, the spiral from ``s`` to ``e`` about ``c`` whose radius changes evenly with the angle: the
        largest distance between the two paths, as ``verify`` measures it (``postproc.geometry.arc_paths.deviation``,
        with its ``floor``); 0 for a ``SPIRAL`` rule."""
        if self.runs == SPIRAL:
            return 0.0
        moved = self.centre(s, e, c)
        turn = _turn(s, e, c, clockwise)
        if floor >= 0.0:  # most arcs: the closed-form bound decides (``circle_gap_bounds``), no search
            bounds = circle_gap_bounds(s, e, c, moved, turn)
            if bounds is not None and bounds[1] <= floor:
                return bounds[1]
        spiral = ArcPath(s, e, c, turn, [], [])
        return deviation(spiral, ArcPath(s, e, moved, _turn(s, e, moved, clockwise), [], []), floor)

    def allows(self, r_start: float, r_end: float, inch: bool, chord: float = 0.0) -> bool:
        """Whether the controller runs an arc with these start and end radii and this chord (program units;
        the chord matters only ``of_centre_shift``)."""
        return self.judged(r_start, r_end, chord) <= self.limit(r_start, r_end, inch, chord) * (1.0 + 1e-9)

    def centre(self, s: tuple[float, float], e: tuple[float, float],
               c: tuple[float, float]) -> tuple[float, float]:
        """The centre the controller turns about for an accepted arc from ``s`` to ``e`` programmed about ``c``."""
        if self.runs == SPIRAL:
            return c
        r0 = math.hypot(s[0] - c[0], s[1] - c[1])
        dx, dy = e[0] - s[0], e[1] - s[1]
        chord = math.hypot(dx, dy)
        if chord == 0.0:
            return c  # a full circle: its end is its start, on the circle
        mid = (s[0] + dx / 2.0, s[1] + dy / 2.0)
        nx, ny = -dy / chord, dx / chord  # the bisector's direction
        if self.runs == NEAREST_CENTRE:
            along = (c[0] - mid[0]) * nx + (c[1] - mid[1]) * ny
            return mid[0] + along * nx, mid[1] + along * ny
        side = 1.0 if (c[0] - mid[0]) * nx + (c[1] - mid[1]) * ny >= 0.0 else -1.0
        h = math.sqrt(max(r0 * r0 - chord * chord / 4.0, 0.0))
        return mid[0] + side * h * nx, mid[1] + side * h * ny


def circle_gap_bounds(s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
                      m: tuple[float, float], turn: float) -> tuple[float, float] | None:
    """Bounds (low, high) of how far the circle from ``s`` to ``e`` about ``m`` (a moved centre: ``m`` on the
    chord's bisector) lies from the spiral from ``s`` to ``e`` about ``c`` turning ``turn`` (radians, negative
    clockwise, as ``_turn``): the distance ``spiral_gap`` computes, in a few trigonometric calls where the search
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
    r0 = math.hypot(sx, sy)
    r1 = math.hypot(ex, ey)
    rho_min = r0 if r0 < r1 else r1
    dx, dy = c[0] - m[0], c[1] - m[1]
    d = math.hypot(dx, dy)
    span = turn if turn > 0.0 else -turn
    if not (0.0 < span < _TWO_PI and 0.0 < rho_min and d <= 0.5 * rho_min):
        return None
    k = (r1 - r0) / span
    if rho_min * (rho_min - d) <= (k if k > 0.0 else -k) * d:
        return None
    w = math.pi * d / (rho_min - d) + 1e-6  # at least 2 asin(d / (rho_min - d)) (asin(y) <= pi y / 2 on [0, 1])
    if not w < span < _TWO_PI - w:
        return None
    radius = math.hypot(s[0] - m[0], s[1] - m[1])
    wobble = math.hypot(e[0] - m[0], e[1] - m[1]) - radius
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
        base = math.asin(lean)
        rise = d * math.sqrt(1.0 - lean * lean)
        offset = math.atan2(sx * dy - sy * dx, sx * dx + sy * dy)  # delta's angle less the start's (about c)
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


def _turn(s: tuple[float, float], e: tuple[float, float], c: tuple[float, float], clockwise: bool) -> float:
    """How far an arc from ``s`` to ``e`` about ``c`` turns (radians, negative clockwise; end on start: a turn)."""
    sweep = arc_sweep(s, e, c, clockwise)
    return -sweep if clockwise else sweep

UNKNOWN_START_TARGET: Final = "unknown_start_target"
"""``ctx.run_data`` key of a translation to another dialect: the target's name. The reading pipeline's arc check
then refuses an arc whose absolute end word in its plane meets a start unknown on that axis: whether the target
accepts its radius depends on where the machine happens to stand (``postproc.syntaxes.modal_state``)."""

TARGET_ARC_END: Final = "target_arc_end"
"""``ctx.run_data`` key of a translation whose target's rule does not cover the source's
(``ArcEndRule.covers``): (the target's name, its rule). The reading pipeline's arc check then refuses an arc
the source's controller runs as a spiral but the target's would refuse (``postproc.syntaxes.modal_state``)."""

NEUTRAL_ARC_END: Final = ArcEndRule(metric=0.01, inch=0.01 / MM_PER_INCH)
"""The rule of a dialect that declares none: 0.01 mm in any units, the path a spiral (the project's
rule before the controllers' own were modelled: ``postproc.geometry.arcs.ARC_TOLERANCE_MM``)."""
