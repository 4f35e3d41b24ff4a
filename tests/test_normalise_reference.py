"""verify's lean normalising and pairing (``postproc.simulate.runs``: a straight move merged into its run
without a ``Move`` of its own, the run's extent along its line kept, the first three axes in locals, ``hypot``
called only where a sum of squares cannot decide) held to the code it replaced (``tests/support/
reference_normalise.py``, commit 2ecc27b's, unchanged) on random paths made to land on the decisions it
makes: moves that continue a line, turn back, stop short, leave it by about the merge distance, go nowhere, on
two to five axes, with controlled points and arcs between. The same runs, to the bit; and a comparison's
deviation, count and place as measured pair by pair (the largest, the first of equals)."""

from __future__ import annotations

import math
from itertools import zip_longest
from typing import Any

import pytest
from hypothesis import given, settings, strategies as st

from postproc.simulate.compare import compare, normalise
from postproc.simulate.normal_move import Move
from tests.support.reference_normalise import normalise as reference_normalise

EPS = 0.0005
"""Half verify's default tolerance: the merge distance ``compare`` gives ``normalise``."""
AXES = {2: "xz", 3: "xyz", 4: "xyza", 5: "xyzab"}


def _fields(item: Any) -> Any:
    if isinstance(item, Move):
        return (item.kind, item.start, item.end, item.f, item.first_line, item.last_line, item.direction, item.centre,
                item.plane, item.radius, item.sweep, item.length)
    return item


@st.composite
def _path(draw: Any) -> tuple[dict[str, float], list[dict[str, Any]]]:
    """A start and a toolpath (no header) of straight moves that mostly follow the line of the one before:
    further along it, back along it, short of its end, off it by a multiple of the merge distance near 1,
    nowhere at all, or anywhere; a feed or kind that changes now and then, arcs and machine events between,
    and controlled points beside some programmed ones."""
    keys = AXES[draw(st.sampled_from(sorted(AXES)))]
    start = {k.upper(): float(draw(st.integers(-20, 20))) for k in keys}
    pos = [start[k.upper()] for k in keys]
    direction = [1.0] + [0.0] * (len(keys) - 1)
    events: list[dict[str, Any]] = []
    feed = 100
    for line in range(1, draw(st.integers(1, 14)) + 1):
        what = draw(st.sampled_from(["on", "on", "on", "back", "short", "off", "still", "any", "arc", "event"]))
        if what == "event":
            events.append({"line": line, "event": "coolant", "on": draw(st.booleans())})
            continue
        if what == "arc" and "y" in keys:  # a half circle about a centre one unit left of here (XY)
            ev: dict[str, Any] = {"line": line, "move": "ccw", "f": feed}
            x, y = pos[0], pos[1]
            ev.update({k: v for k, v in zip(keys, pos)})
            ev.update(x=x - 2.0, cx=x - 1.0, cy=y, plane="XY")
            pos[0] = x - 2.0
            events.append(ev)
            continue
        if what == "any" or what == "arc":
            direction = [float(draw(st.integers(-3, 3))) for _ in keys]
            if not any(direction):
                direction[0] = 1.0
            norm = math.hypot(*direction)
            direction = [d / norm for d in direction]
        step = {"on": draw(st.sampled_from([0.5, 1.0, 3.25, 1e-7])), "back": -1.0, "short": 0.0, "off": 1.0,
                "still": 0.0, "any": 2.0, "arc": 2.0}[what]
        if what == "short":
            step = -draw(st.sampled_from([0.25, 1e-9]))
        target = [p + step * d for p, d in zip(pos, direction)]
        if what == "off":  # across the line, about the merge distance from it
            across = 1 if len(keys) > 1 else 0
            target[across] += EPS * draw(st.sampled_from([0.5, 0.999999, 1.0, 1.000001, 1.5, 3.0]))
        if draw(st.integers(0, 9)) == 0:
            feed = draw(st.sampled_from([100, 200]))
        ev = {"line": line, "move": draw(st.sampled_from(["feed", "feed", "feed", "rapid"]))}
        ev.update({k: v for k, v in zip(keys, target)})
        if ev["move"] != "rapid":
            ev["f"] = feed
        if draw(st.integers(0, 4)) == 0:  # a controlled point: a tool length on the last axis
            ev["controlled"] = {k: v for k, v in zip(keys, target)}
            ev["controlled"][keys[-1]] = target[-1] + draw(st.sampled_from([0.0, 120.0]))
        if what != "still":
            pos = target
        events.append(ev)
    return start, events


@settings(max_examples=400, deadline=None)
@given(path=_path())
def test_normalise_is_the_reference(path: tuple[dict[str, float], list[dict[str, Any]]]) -> None:
    start, events = path
    ours = [_fields(i) for i in normalise(iter(events), start, EPS)]
    assert ours == [_fields(i) for i in reference_normalise(iter(events), start, EPS)]


def test_the_paths_reach_the_decisions() -> None:
    """The strategy's paths do merge, and do stop merging by the distance from the line (not a test that
    cannot fail: on a line's worth of moves, the runs the reference makes)."""
    start = {"X": 0.0, "Y": 0.0, "Z": 0.0}
    on = [{"line": n, "move": "feed", "x": float(n), "y": 0.0, "z": 0.0, "f": 100} for n in (1, 2, 3)]
    off = [{"line": 4, "move": "feed", "x": 4.0, "y": EPS * 1.5, "z": 0.0, "f": 100}]
    back = [{"line": 5, "move": "feed", "x": 4.5, "y": EPS * 1.5, "z": 0.0, "f": 100},
            {"line": 6, "move": "feed", "x": 4.25, "y": EPS * 1.5, "z": 0.0, "f": 100}]
    runs = [(m.first_line, m.last_line) for m in normalise(iter(on + off + back), start, EPS)]
    assert runs == [(1, 3), (4, 5), (6, 6)]
    assert runs == [(m.first_line, m.last_line) for m in reference_normalise(iter(on + off + back), start, EPS)]


@settings(max_examples=300, deadline=None)
@given(path=_path(), moved=st.lists(st.sampled_from([0.0, 0.0, 2e-4, 5e-4, 1e-3, 0.25]), min_size=1, max_size=14))
def test_deviation_is_the_largest_pair_apart(path: tuple[dict[str, float], list[dict[str, Any]]],
                                            moved: list[float]) -> None:
    """A path against a copy with its ends moved (ties among the distances on purpose): the report's count,
    largest deviation and its place are those of the pairs of runs measured one by one, the first of the
    largest where several are equal."""
    start, events = path
    events = [ev for ev in events if ev.get("move") in ("feed", "rapid") and "controlled" not in ev]
    copy = []
    for n, ev in enumerate(events):
        ev = dict(ev)
        ev["x"] = ev["x"] + moved[n % len(moved)]
        copy.append(ev)
    head = {"toolpath": 1, "units": "mm", "dialect": "fanuc"}
    report = compare([head, *events], [head, *copy], start_in=start, start_out=start, tolerance=0.001)
    pairs = list(zip_longest(reference_normalise(iter(events), start, EPS), reference_normalise(iter(copy), start,
                                                                                                     EPS)))
    if report.mismatch is not None:  # the moved copy merged differently: pairs no longer line up
        assert any(a is None or b is None or a.kind != b.kind or a.f != b.f for a, b in pairs)
        return
    best: tuple[float, tuple[int, int]] | None = None
    for a, b in pairs:
        dev = math.hypot(*[v - b.end[k] for k, v in a.end.items() if k in b.end])
        if best is None or dev > best[0]:
            best = (dev, (a.last_line, b.last_line))
    assert report.moves == len(pairs)
    assert (report.max_deviation, report.where) == (best if best is not None else (0.0, None))


def _zigzag(moved: dict[int, float]) -> list[str]:
    """A Fanuc program of 60 feeds that each turn (no two merge), the Y of the feeds on the lines in
    ``moved`` (program line -> mm) moved."""
    text = ["%", "O0001", "G21 G90 G17", "G00 X0. Y0. Z5.", "G01 Z-1. F500."]
    for n in range(60):
        line = len(text) + 1
        y = (n % 2) * 3.0 + moved.get(line, 0.0)
        text.append(f"X{n + 1}. Y{y:.4f}")
    text += ["M30", "%"]
    return [t + "\n" for t in text]


def _verify(a: list[str], b: list[str]) -> Any:
    from postproc.simulate.verify import verify_lines
    return verify_lines(a, b, file_in="in.nc", file_out="out.nc", source="fanuc", target="fanuc", tolerance=0.001)


def test_one_move_moved_deep_in_a_program_fails_there() -> None:
    """Past many pairs that agree (where the deviation is no longer measured: ``_beyond``), one point moved
    just beyond the tolerance fails at its lines; just within, it passes; of two equal deviations the first
    is reported."""
    same = _zigzag({})
    report = _verify(same, _zigzag({40: 0.0011}))
    assert not report.ok and report.mismatch is None and report.where == (40, 40)
    assert report.max_deviation == pytest.approx(0.0011)
    assert report.moves == 62  # the plunge, 60 feeds, the rapid before them
    within = _verify(same, _zigzag({40: 0.0009}))
    assert within.ok and within.where == (40, 40)
    twice = _verify(same, _zigzag({30: 0.002, 50: 0.002}))
    assert not twice.ok and twice.where == (30, 30)
    assert _verify(same, same).ok and _verify(same, same).where == (4, 4)


# -- points read by key, wherever the key stands (``runs.key_index``) ------------------------------------------

def _shuffled(ev: dict[str, Any], order: list[int]) -> dict[str, Any]:
    """An event with its axis keys (and its controlled point's) in another order: the other keys stay first."""
    axes = [k for k in ev if len(k) == 1]
    moved = [axes[i % len(axes)] for i in order if i < len(axes)]
    moved += [k for k in axes if k not in moved]
    out = {k: v for k, v in ev.items() if k not in axes}
    out.update({k: ev[k] for k in dict.fromkeys(moved)})
    if "controlled" in ev:
        ctrl = ev["controlled"]
        out["controlled"] = {k: ctrl[k] for k in reversed(list(ctrl))}
    return out


@settings(max_examples=300, deadline=None)
@given(path=_path(), order=st.permutations(range(5)), every=st.integers(1, 3))
def test_normalise_reads_keys_in_any_order_as_the_reference(path: tuple[dict[str, float], list[dict[str, Any]]],
                                                            order: list[int], every: int) -> None:
    """A point whose keys stand in another order than the point before's (the start's, a move's) is read by key:
    ``normalise`` looks for a key where it stood in the other point first, then anywhere. Every ``every``-th event
    shuffled, the runs are the reference's of the same events (the reference reads dictionaries by key)."""
    start, events = path
    events = [_shuffled(ev, order) if n % every == 0 and "move" in ev and "cx" not in ev else ev
              for n, ev in enumerate(events)]
    ours = [_fields(i) for i in normalise(iter(events), start, EPS)]
    assert ours == [_fields(i) for i in reference_normalise(iter(events), start, EPS)]


@settings(max_examples=200, deadline=None)
@given(path=_path(), order=st.permutations(range(5)), moved=st.sampled_from([0.0, 2e-4, 0.25]))
def test_compare_pairs_axes_by_key_in_any_order(path: tuple[dict[str, float], list[dict[str, Any]]],
                                                order: list[int], moved: float) -> None:
    """OUT's events with their keys in another order than IN's: the comparison pairs the axes by key (the largest
    deviation, its place, the count and where the structure first differs as with the keys in IN's order; a
    message names a point's axes in its own order)."""
    start, events = path
    events = [ev for ev in events if ev.get("move") in ("feed", "rapid") and "controlled" not in ev]
    copy = [dict(ev, x=ev["x"] + moved) for ev in events]
    head = {"toolpath": 1, "units": "mm", "dialect": "fanuc"}
    same_order = compare([head, *events], [head, *copy], start_in=start, start_out=start, tolerance=0.001)
    other_order = compare([head, *events], [head, *[_shuffled(ev, order) for ev in copy]], start_in=start,
                          start_out=start, tolerance=0.001)
    assert (other_order.moves, other_order.max_deviation, other_order.where, other_order.mismatch_at) == \
        (same_order.moves, same_order.max_deviation, same_order.where, same_order.mismatch_at)
    assert (other_order.mismatch is None) == (same_order.mismatch is None)


def test_a_normaliser_ends_and_stays_ended() -> None:
    """After its last run, a pull gives None again (the comparison pulls the shorter side past its end)."""
    from postproc.simulate.runs import Normaliser
    start = {"X": 0.0, "Y": 0.0}
    events = [{"line": 1, "move": "feed", "x": 1.0, "y": 0.0, "f": 100}, {"line": 2, "event": "coolant", "on": True}]
    ins = Normaliser(iter(events), start, EPS)
    first, second = ins.pull(), ins.pull()
    assert isinstance(first, Move) and (first.first_line, first.end) == (1, {"x": 1.0, "y": 0.0})
    assert second == events[1]
    assert [ins.pull(), ins.pull()] == [None, None]
