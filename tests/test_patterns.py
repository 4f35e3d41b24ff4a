"""Hole patterns (``postproc.patterns``): the points and moves of every kind, derived by hand here (the
trigonometry is written out, never taken from the code under test), the section's own checks, and the
properties of a full circle."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.patterns import HolePattern, pattern_hops, pattern_points

R3 = 3 ** 0.5
"""sqrt(3): 2 sin 60 and 2 cos 30."""
H2 = 2 ** 0.5 / 2
"""sin 45 = cos 45."""


def close(points, expected):
    assert len(points) == len(expected), points
    for (a, b), (ea, eb) in zip(points, expected):
        assert a == pytest.approx(ea, abs=1e-9) and b == pytest.approx(eb, abs=1e-9), (points, expected)


def test_line_at_30_degrees():
    # from (10, 5), 10 apart at 30 deg: + (10 cos 30, 10 sin 30) = + (5 sqrt3, 5) per step
    p = HolePattern("line", 3, 10.0, angle=30.0, start={"X": 10.0, "Y": 5.0, "Z": 50.0})
    close(pattern_points(p), [(10, 5), (10 + 5 * R3, 10), (10 + 10 * R3, 15)])


def test_parallelogram_perimeter_is_numbered_along_side_1_up_side_2_back_and_down():
    # sides 20 (3 points 10 apart along X) and 10 (3 points 5 apart along Y): 2 * (3 + 3) - 4 = 8 points
    p = HolePattern("parallelogram", 3, 10.0, count2=3, step2=5.0, start={"X": 0.0, "Y": 0.0})
    close(pattern_points(p), [(0, 0), (10, 0), (20, 0), (20, 5), (20, 10), (10, 10), (0, 10), (0, 5)])


def test_parallelogram_with_sides_at_60_degrees():
    # the second side is 10 long at 60 deg: + (10 cos 60, 10 sin 60) = + (5, 5 sqrt3)
    p = HolePattern("parallelogram", 2, 10.0, count2=2, step2=10.0, angle2=60.0, start={"X": 0.0, "Y": 0.0})
    close(pattern_points(p), [(0, 0), (10, 0), (15, 5 * R3), (5, 5 * R3)])


def test_grid_zig_zags_row_by_row():
    p = HolePattern("grid", 3, 10.0, count2=2, step2=5.0, start={"X": 0.0, "Y": 0.0})
    close(pattern_points(p), [(0, 0), (10, 0), (20, 0), (20, 5), (10, 5), (0, 5)])


def test_rotated_grid():
    # first side at 90 deg (along +Y), second side 90 deg further (along -X)
    p = HolePattern("grid", 2, 4.0, angle=90.0, count2=2, step2=3.0, start={"X": 1.0, "Y": 1.0})
    close(pattern_points(p), [(1, 1), (1, 5), (-2, 5), (-2, 1)])


def test_full_circle_counter_clockwise_and_clockwise():
    # start (20, 0), centre 20 to the left: (0, 0), radius 20, start angle 0
    ccw = HolePattern("circle", 4, 90.0, center={"X": -20.0, "Y": 0.0}, start={"X": 20.0, "Y": 0.0})
    close(pattern_points(ccw), [(20, 0), (0, 20), (-20, 0), (0, -20)])
    cw = HolePattern("circle", 4, -90.0, center={"X": -20.0, "Y": 0.0}, start={"X": 20.0, "Y": 0.0})
    close(pattern_points(cw), [(20, 0), (0, -20), (-20, 0), (0, 20)])


def test_six_holes_on_a_circle_off_the_origin():
    # centre (100, 50) + radius 20 at 0, 60, ..., 300 deg: (20 cos a, 20 sin a) = (10, 10 sqrt3) at 60
    p = HolePattern("circle", 6, 60.0, center={"X": -20.0, "Y": 0.0}, start={"X": 120.0, "Y": 50.0})
    close(pattern_points(p), [(120, 50), (110, 50 + 10 * R3), (90, 50 + 10 * R3), (80, 50),
                              (90, 50 - 10 * R3), (110, 50 - 10 * R3)])


def test_circle_from_a_start_that_is_not_on_an_axis_of_the_centre():
    # start (0, 10), centre (-10, 0) (X-10 Y-10): radius 10 sqrt2, start angle 45 deg; 90 deg steps
    p = HolePattern("circle", 4, 90.0, center={"X": -10.0, "Y": -10.0}, start={"X": 0.0, "Y": 10.0})
    close(pattern_points(p), [(0, 10), (-20, 10), (-20, -10), (0, -10)])


def test_arc_of_90_degrees_in_45_degree_steps():
    # start (10, 0), centre (0, 0): points at 0, 45, 90 deg
    p = HolePattern("arc", 3, 45.0, center={"X": -10.0}, start={"X": 10.0, "Y": 0.0})
    close(pattern_points(p), [(10, 0), (10 * H2, 10 * H2), (0, 10)])


def test_hops_skip_points_and_go_straight_to_the_next_machined_one():
    p = HolePattern("circle", 6, 60.0, center={"X": -20.0, "Y": 0.0}, skip=(3, 5), start={"X": 20.0, "Y": 0.0})
    hops = pattern_hops(p)
    assert [h.number for h in hops] == [2, 4, 6]
    close([h.point for h in hops], [(10, 10 * R3), (-20, 0), (10, -10 * R3)])
    assert {h.mode for h in hops} == {"rapid"} and {h.centre for h in hops} == {None}


def test_arc_hops_carry_the_centre():
    p = HolePattern("circle", 4, 90.0, center={"X": -20.0, "Y": 0.0}, skip=(3,), move="ccw", feed=300.0,
                    start={"X": 20.0, "Y": 0.0})
    hops = pattern_hops(p)
    assert [(h.number, h.mode, h.centre) for h in hops] == [(2, "ccw", (0.0, 0.0)), (4, "ccw", (0.0, 0.0))]


def test_zx_plane_uses_z_and_x_as_plane_axes():
    p = HolePattern("line", 2, 5.0, plane="ZX", angle=90.0, start={"Z": 1.0, "X": 2.0, "Y": 0.0})
    close(pattern_points(p), [(1, 2), (1, 7)])


@pytest.mark.parametrize("kwargs, message", [
    (dict(kind="spiral", count=2, step=1.0), "unknown hole pattern kind 'spiral'"),
    (dict(kind="line", count=2, step=1.0, move="zigzag"), "unknown move between points 'zigzag'"),
    (dict(kind="line", count=0, step=1.0), "a hole pattern has at least one point"),
    (dict(kind="grid", count=2, step=1.0), "a grid needs count2 and step2"),
    (dict(kind="grid", count=1, step=1.0, count2=2, step2=1.0), "each side of a grid has at least two points"),
    (dict(kind="line", count=2, step=1.0, count2=2, step2=1.0), "a line has no second side"),
    (dict(kind="circle", count=4, step=0.0, center={"X": 1.0}), "the angular step of a circle cannot be 0"),
    (dict(kind="circle", count=4, step=90.0), "the centre of a circle cannot be its first point"),
    (dict(kind="circle", count=4, step=90.0, center={"Z": 1.0}), "the centre of a circle lies in the XY plane"),
    (dict(kind="line", count=2, step=1.0, move="cw", feed=1.0), "a line has no circle to move along"),
    (dict(kind="circle", count=4, step=90.0, center={"X": 1.0}, move="cw", feed=1.0),
     "a cw move between points turns against the step 90.0"),
    (dict(kind="circle", count=4, step=90.0, center={"X": 1.0}, move="linear"),
     "a linear move between points needs a positive feed"),
    (dict(kind="line", count=3, step=1.0, skip=(1,)), "point 1 is machined by the cycle's own block"),
    (dict(kind="line", count=3, step=1.0, skip=(4,)), "the line has 3 points: point 4 cannot be skipped"),
    (dict(kind="line", count=3, step=1.0, plane="AB"), "unknown plane 'AB'"),
])
def test_the_section_refuses_what_makes_no_pattern(kwargs, message):
    with pytest.raises(ValueError, match="^" + message.replace("(", r"\(").replace(")", r"\)")):
        HolePattern(**kwargs)


@settings(max_examples=200, deadline=None)
@given(count=st.integers(2, 72), clockwise=st.booleans(),
       dx=st.floats(-500, 500).filter(lambda v: abs(v) > 0.01), dy=st.floats(-500, 500),
       x0=st.floats(-1000, 1000), y0=st.floats(-1000, 1000))
def test_circle_points_lie_on_the_circle_equally_spaced_from_the_start(count, clockwise, dx, dy, x0, y0):
    step = (-360.0 if clockwise else 360.0) / count
    p = HolePattern("circle", count, step, center={"X": dx, "Y": dy}, start={"X": x0, "Y": y0})
    points = pattern_points(p)
    cx, cy = x0 + dx, y0 + dy
    radius = math.hypot(dx, dy)
    assert points[0] == (x0, y0)
    assert len(points) == count
    chord = 2 * radius * math.sin(math.pi / count)  # the distance between neighbours, closing the circle
    for i, (a, b) in enumerate(points):
        assert math.hypot(a - cx, b - cy) == pytest.approx(radius, abs=1e-9 * (1 + radius))
        na, nb = points[(i + 1) % count]
        assert math.hypot(na - a, nb - b) == pytest.approx(chord, abs=1e-8 * (1 + radius))
        # the turn from one point to the next has the step's direction
        cross = (a - cx) * (nb - cy) - (b - cy) * (na - cx)
        if count > 2:
            assert (cross < 0) == clockwise
