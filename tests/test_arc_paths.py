"""The largest distance between two arc paths (``postproc.geometry.arc_paths``), which ``verify`` compares arcs by: against
distances known by construction (a radius changed, a path moved or turned about its centre), against an
independent brute-force search (points of one path densely sampled, their distance from the other a minimum
over its densely sampled points), and through ``verify`` itself (an arc against its chords)."""

from __future__ import annotations

import io
import math
from typing import Any

import pytest
from hypothesis import given, settings, strategies as st

from postproc.geometry.arc_paths import ArcPath, deviation
from postproc.simulate.compare import compare

_RADIUS = st.floats(0.5, 500.0)
_ANGLE = st.floats(-math.pi, math.pi)
_SWEEP = st.floats(0.05, 2 * math.pi - 0.05)


def _arc(centre: tuple[float, float], r0: float, r1: float, a0: float, turn: float,
         z: tuple[float, float] = (0.0, 0.0)) -> ArcPath:
    start = (centre[0] + r0 * math.cos(a0), centre[1] + r0 * math.sin(a0))
    end = (centre[0] + r1 * math.cos(a0 + turn), centre[1] + r1 * math.sin(a0 + turn))
    return ArcPath(start, end, centre, turn, [z[0]], [z[1]])


@settings(max_examples=200, deadline=None)
@given(_RADIUS, _ANGLE, _SWEEP, st.booleans(), st.floats(-0.01, 0.01), st.floats(-0.01, 0.01))
def test_a_radius_changed_evenly_is_apart_by_the_larger_change(r: float, a0: float, sweep: float, cw: bool,
                                                               d0: float, d1: float) -> None:
    """About one centre, a spiral from r + d0 to r + d1 and the circle of radius r, over the same angles: at each
    angle the spiral lies r + d0 + (d1 - d0) t out, so the largest distance is max(|d0|, |d1|) (by hand)."""
    turn = -sweep if cw else sweep
    circle = _arc((3.0, -2.0), r, r, a0, turn)
    spiral = _arc((3.0, -2.0), r + d0, r + d1, a0, turn)
    assert deviation(spiral, circle) == pytest.approx(max(abs(d0), abs(d1)), abs=1e-9)
    assert deviation(circle, spiral) == pytest.approx(max(abs(d0), abs(d1)), abs=1e-9)


@settings(max_examples=200, deadline=None)
@given(_RADIUS, _ANGLE, _SWEEP, st.booleans(), st.floats(-0.01, 0.01), st.floats(-0.01, 0.01),
       st.floats(-0.01, 0.01))
def test_a_path_moved_is_apart_by_the_move(r: float, a0: float, sweep: float, cw: bool, dx: float, dy: float,
                                          dz: float) -> None:
    """A path moved by (dx, dy, dz) (a helix, each point the same vector away): every point of one lies that far
    from its copy, the ends among them; no point of a circle lies further from the moved circle than that."""
    turn = -sweep if cw else sweep
    path = _arc((0.0, 0.0), r, r, a0, turn, (0.0, 5.0))
    moved = ArcPath((path.start[0] + dx, path.start[1] + dy), (path.end[0] + dx, path.end[1] + dy), (dx, dy), turn,
                    [dz], [5.0 + dz])
    assert deviation(moved, path) == pytest.approx(math.sqrt(dx * dx + dy * dy + dz * dz), abs=1e-9)


@settings(max_examples=200, deadline=None)
@given(_RADIUS, _ANGLE, _SWEEP, st.booleans(), st.floats(-0.001, 0.001))
def test_a_path_turned_about_its_centre_is_apart_by_its_ends(r: float, a0: float, sweep: float, cw: bool,
                                                           phi: float) -> None:
    """One circle, the path turned by phi about its centre: the parts on the circle lie on each other, so the
    distance is the ends' (and the starts'), the chord 2 r sin(|phi| / 2) (by hand)."""
    turn = -sweep if cw else sweep
    assert deviation(_arc((1.0, 1.0), r, r, a0 + phi, turn), _arc((1.0, 1.0), r, r, a0, turn)) == \
        pytest.approx(2 * r * math.sin(abs(phi) / 2), abs=1e-9)


def _brute(a: ArcPath, b: ArcPath, n: int = 300) -> float:
    """The Hausdorff distance of the two paths by brute force: each path sampled at n + 1 points, each point's
    distance from the other the least over that one's points, refined about the nearest (independent of
    ``postproc.geometry.arc_paths``: no ray, no model)."""
    def point(p: ArcPath, t: float) -> tuple[float, float, float]:
        x, y, off = p.at(t)
        return x, y, off[0]

    ts = [i / n for i in range(n + 1)]
    samples = {id(a): [point(a, t) for t in ts], id(b): [point(b, t) for t in ts]}
    """Each path's n + 1 points, computed once: every query samples the same ones (the same numbers as computing
    them per query, at a fraction of the cost)."""

    def nearest(q: tuple[float, float, float], p: ArcPath) -> float:
        ds = [math.dist(q, s) for s in samples[id(p)]]
        i = min(range(n + 1), key=ds.__getitem__)
        lo, hi = ts[max(0, i - 1)], ts[min(n, i + 1)]
        for _ in range(60):  # ternary search of the convex neighbourhood
            m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
            if math.dist(q, point(p, m1)) < math.dist(q, point(p, m2)):
                hi = m2
            else:
                lo = m1
        return min(ds[i], math.dist(q, point(p, (lo + hi) / 2)))

    def directed(p: ArcPath, o: ArcPath) -> float:
        ts = [i / 100 for i in range(101)]
        ds = [nearest(point(p, t), o) for t in ts]
        i = max(range(101), key=ds.__getitem__)
        lo, hi, best = ts[max(0, i - 1)], ts[min(100, i + 1)], ds[i]
        for _ in range(40):
            m1, m2 = lo + (hi - lo) / 3, hi - (hi - lo) / 3
            f1, f2 = nearest(point(p, m1), o), nearest(point(p, m2), o)
            best = max(best, f1, f2)
            if f1 > f2:
                hi = m2
            else:
                lo = m1
        return best

    return max(directed(a, b), directed(b, a))


@settings(max_examples=12, deadline=None)
@given(st.floats(0.5, 50.0), _ANGLE, _SWEEP, st.booleans(), st.floats(-0.005, 0.005), st.floats(-0.005, 0.005),
       st.floats(-0.005, 0.005), st.floats(-0.005, 0.005))
def test_a_moved_centre_against_brute_force(r: float, a0: float, sweep: float, cw: bool, dr: float, cx: float,
                                            cy: float, end_r: float) -> None:
    """Arcs as two controllers cut one programmed arc: a spiral about the programmed centre, and a circle through
    the same ends about a centre moved onto the chord's bisector (ISG's G165, Fagor's G265), or any other centre
    near it: ``deviation`` and the brute-force Hausdorff distance agree within 1e-6 mm."""
    turn = -sweep if cw else sweep
    spiral = _arc((0.0, 0.0), r, r + dr, a0, turn)
    s, e = spiral.start, spiral.end
    chord = math.dist(s, e)
    mid = ((s[0] + e[0]) / 2, (s[1] + e[1]) / 2)
    nx, ny = -(e[1] - s[1]) / chord, (e[0] - s[0]) / chord
    along = -mid[0] * nx - mid[1] * ny
    moved = (mid[0] + along * nx, mid[1] + along * ny)
    for centre, end in ((moved, e), ((cx, cy), (e[0] * (1 + end_r / r), e[1] * (1 + end_r / r)))):
        a0c, a1c = math.atan2(s[1] - centre[1], s[0] - centre[0]), math.atan2(end[1] - centre[1], end[0] - centre[0])
        other_turn = (a1c - a0c) % (2 * math.pi) if not cw else -((a0c - a1c) % (2 * math.pi))
        if abs(other_turn - turn) > 0.5:
            continue  # the end moved across the start: another arc altogether
        other = ArcPath(s, end, centre, other_turn, [0.0], [0.0])
        expected = max(_brute(spiral, other), math.dist(e, end))
        assert deviation(spiral, other) == pytest.approx(expected, abs=1e-6)
        assert deviation(other, spiral) == pytest.approx(expected, abs=1e-6)


def test_a_bound_below_the_floor_decides_without_the_search() -> None:
    """``floor``: a pair whose distance is below it gets a value of at most ``floor``; above it, the distance."""
    spiral = _arc((0.0, 0.0), 10.0, 10.0003, 0.3, 2.0)
    s, e = spiral.start, spiral.end
    circle = ArcPath(s, e, (0.0002, -0.0001), 2.0, [0.0], [0.0])
    exact = deviation(spiral, circle)
    assert deviation(spiral, circle, floor=0.01) <= 0.01
    assert deviation(spiral, circle, floor=exact / 2) == pytest.approx(exact, abs=1e-12)


def test_a_circle_cut_once_more_is_no_match() -> None:
    """About one centre, a quarter turn and a turn and a quarter end at the same points: every point of the longer
    lies on the shorter's circle, but it cuts the whole circle once more; its far side lies 2 r from the ends."""
    quarter = _arc((0.0, 0.0), 5.0, 5.0, 0.0, math.pi / 2)
    longer = _arc((0.0, 0.0), 5.0, 5.0, 0.0, math.pi / 2 + 2 * math.pi)
    assert deviation(longer, quarter) == pytest.approx(10.0, abs=1e-9)
    assert deviation(quarter, longer) == pytest.approx(10.0, abs=1e-9)


# -- through verify: an arc against its chords -----------------------------------------------------------------

def _chords_report(r: float, a0: float, sweep: float, n: int) -> Any:
    head = {"toolpath": 1, "units": "mm"}
    start = {"X": r * math.cos(a0), "Y": r * math.sin(a0), "Z": 0.0}
    end = (r * math.cos(a0 + sweep), r * math.sin(a0 + sweep))
    arc = [head, {"line": 1, "move": "ccw", "x": end[0], "y": end[1], "z": 0.0, "cx": 0.0, "cy": 0.0, "plane": "XY",
                  "f": 100}]
    chords: list[dict[str, Any]] = [dict(head)]
    for q in range(1, n + 1):
        a = a0 + sweep * q / n
        chords.append({"line": q, "move": "feed", "x": r * math.cos(a), "y": r * math.sin(a), "z": 0.0, "f": 100})
    # (a tolerance of 1e-9 mm: verify merges straight moves within half its tolerance of one line)
    return compare(iter(arc), iter(chords), start_in=start, start_out=dict(start), tolerance=1e-9,
                   chord_tolerance=1.0)


@settings(max_examples=100, deadline=None)
@given(st.floats(1.0, 200.0), _ANGLE, _SWEEP, st.integers(3, 60))
def test_an_arc_against_its_inscribed_chords_is_apart_by_their_sagitta(r: float, a0: float, sweep: float,
                                                                       n: int) -> None:
    """n equal chords inscribed in an arc: each lies r (1 - cos(sweep / 2n)) inside it at its middle (by hand),
    and that is how far verify finds the chords from the arc."""
    report = _chords_report(r, a0, sweep, n)
    sagitta = r * (1 - math.cos(sweep / (2 * n)))
    assert report.mismatch is None, report.mismatch
    assert report.chord_deviation == pytest.approx(sagitta, abs=1e-6)
