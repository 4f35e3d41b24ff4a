"""The closed-form bounds of how far a centre-moving controller's circle lies from a spiral controller's path
(``postproc.geometry.arc_end_math.circle_gap_bounds``), which let the ISG/Fagor arc check skip the search of
``postproc.geometry.arc_paths.deviation``: held to that full computation on random arcs (hypothesis), and to a gap
derived by hand."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.geometry.arc_end import NEAREST_CENTRE, START_RADIUS, ArcEndRule
from postproc.geometry.arc_end_math import circle_gap_bounds
from postproc.geometry.arcs import arc_sweep

_RULES = {runs: ArcEndRule(metric=1.0, inch=1.0, runs=runs) for runs in (NEAREST_CENTRE, START_RADIUS)}


def _arc(r0: float, change: float, a0: float, sweep: float, cx: float, cy: float,
         clockwise: bool) -> tuple[tuple[float, float], tuple[float, float], tuple[float, float]]:
    turned = -sweep if clockwise else sweep
    s = (cx + r0 * math.cos(a0), cy + r0 * math.sin(a0))
    r1 = r0 + change
    e = (cx + r1 * math.cos(a0 + turned), cy + r1 * math.sin(a0 + turned))
    return s, e, (cx, cy)


def _turn(s: tuple[float, float], e: tuple[float, float], c: tuple[float, float], clockwise: bool) -> float:
    """The spiral's turn as ``spiral_gap`` passes it (radians, negative clockwise)."""
    sweep = arc_sweep(s, e, c, clockwise)
    return -sweep if clockwise else sweep


def _full(rule: ArcEndRule, s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
          clockwise: bool) -> float:
    return rule.spiral_gap(s, e, c, clockwise)  # no floor: the search, never the bound


_ARCS = st.tuples(
    st.floats(-1.0, 3.0),  # log10 of the start radius
    st.one_of(st.floats(-2e-3, 2e-3), st.floats(-0.2, 0.2)),  # the end radius' change, as a CAM arc's or far
    st.floats(0.0, 2 * math.pi),
    st.one_of(st.floats(1e-4, 0.5), st.floats(0.0, 2 * math.pi)),  # the sweep
    st.floats(-500.0, 500.0), st.floats(-500.0, 500.0), st.booleans(), st.sampled_from(sorted(_RULES)))


@settings(max_examples=300, deadline=None)
@given(_ARCS)
def test_the_bounds_hold_the_full_computation_between_them(arc: tuple[float, float, float, float, float, float,
                                                                      bool, str]) -> None:
    """Where the bounds apply, the search's distance lies between them (to the search's own precision,
    ``deviation``'s golden-section refinement: (r + d) 1.25e-13 mm, and its Newton steps); and a check with a
    floor decides as the search does (the bound returned only where it is at most the floor)."""
    log_r, change, a0, sweep, cx, cy, clockwise, runs = arc
    r0 = 10.0 ** log_r
    change *= r0 if abs(change) > 2e-3 else 1.0  # the far ones as a share of the radius
    s, e, c = _arc(r0, change, a0, sweep, cx, cy, clockwise)
    rule = _RULES[runs]
    moved = rule.centre(s, e, c)
    bounds = circle_gap_bounds(s, e, c, moved, _turn(s, e, c, clockwise))
    if bounds is None:
        return
    low, high = bounds
    full = _full(rule, s, e, c, clockwise)
    precision = 1e-11 * (r0 + 1.0)
    assert low <= high
    assert low - precision <= full <= high + precision, (low, full, high)
    for floor in (0.0005, full * 0.999, full * 1.001):
        decided = rule.spiral_gap(s, e, c, clockwise, floor)
        if full <= floor - precision:
            assert decided <= floor
        elif full > floor + precision:
            assert decided > floor


def test_the_bounds_are_close_on_cam_arcs_and_decide_them() -> None:
    """On a CAM program's arcs (a radius of 1 to 100 mm, its end off by rounding to 4 decimals, a sweep of
    a degree to most of a turn) the bounds apply and lie within 1e-6 mm of each other: the check decides them
    without the search (near a whole turn the centre moves far: those are known refused, the search then giving
    the message its value)."""
    import random
    rnd = random.Random(30)
    for _ in range(500):
        r0 = rnd.uniform(1.0, 100.0)
        clockwise = rnd.random() < 0.5
        s, e, c = _arc(r0, rnd.uniform(-1e-4, 1e-4), rnd.uniform(0, 2 * math.pi), rnd.uniform(0.02, 6.0),
                       rnd.uniform(-100, 100), rnd.uniform(-100, 100), clockwise)
        rule = _RULES[NEAREST_CENTRE]
        bounds = circle_gap_bounds(s, e, c, rule.centre(s, e, c), _turn(s, e, c, clockwise))
        assert bounds is not None
        assert bounds[1] - bounds[0] < 1e-6
        assert bounds[1] <= 0.0005 or bounds[0] > 0.0005  # decided either way


@pytest.mark.parametrize("runs", sorted(_RULES))
def test_the_bounds_hold_a_gap_derived_by_hand(runs: str) -> None:
    """(10, 0) to (-10.008, 0) clockwise about the origin (tests/test_arc_end.py): the nearest-centre circle
    leaves the spiral by 0.004 (2 t - 1 + cos(pi t)) to first order, largest where sin(pi t) = 2 / pi
    (0.0008420 mm); the start-radius rule keeps the radius 10 about (-0.008, 0.4000...) on the bisector x = -0.004,
    whose gap the search gives. Both bounds bracket the value, and the nearest-centre one within the model's
    second-order term (d^2 / r = 1.6e-6 mm)."""
    s, e, c = (10.0, 0.0), (-10.008, 0.0), (0.0, 0.0)
    rule = _RULES[runs]
    bounds = circle_gap_bounds(s, e, c, rule.centre(s, e, c), _turn(s, e, c, True))
    assert bounds is not None
    low, high = bounds
    if runs == NEAREST_CENTRE:
        t = math.asin(2 / math.pi) / math.pi
        gap = 0.004 * (2 * t - 1 + math.cos(math.pi * t))
        assert low - 2e-6 <= gap <= high + 2e-6
        assert high - low < 2e-6
    full = _full(rule, s, e, c, True)
    assert low - 1e-12 <= full <= high + 1e-12


def test_the_bounds_step_aside_where_their_proof_does_not_hold() -> None:
    """A sweep near none or a whole turn (the paths' turns about the two centres may differ by a turn), or a
    centre moved by more than half the radius: None, the caller searches."""
    rule = _RULES[NEAREST_CENTRE]
    for sweep in (1e-9, 2 * math.pi - 1e-9):
        s, e, c = _arc(10.0, 1e-3, 0.3, sweep, 0.0, 0.0, False)
        assert circle_gap_bounds(s, e, c, rule.centre(s, e, c), _turn(s, e, c, False)) is None
    s, e, c = _arc(10.0, 8.0, 0.3, 0.5, 0.0, 0.0, False)
    assert circle_gap_bounds(s, e, c, rule.centre(s, e, c), _turn(s, e, c, False)) is None
