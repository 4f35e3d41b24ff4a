"""``points.Steps``: the one loop that collects per-axis differences for verify's normalising (a move's steps) and its
comparison (a pair's distance), the first three as fields and any further one in a list, as ``beyond`` and ``_norm``
take them. Held to the plain list of the same differences on random lists, reused as its owners reuse it (cleared
between two points), and the distance of a pair of moves of more than three axes (``compare._differ``) to
``math.dist`` of the axes both have."""

from __future__ import annotations

import math

from hypothesis import given, settings, strategies as st

from postproc.simulate.compare import Report, _differ
from postproc.simulate.normal_move import Move
from postproc.simulate.points import Steps, _norm, beyond

_FINITE = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(lists=st.lists(st.lists(_FINITE, max_size=7), min_size=1, max_size=4))
def test_steps_are_the_differences_in_order(lists: list[list[float]]) -> None:
    steps = Steps()  # one object, cleared between the points (as the normaliser and the report keep theirs)
    for values in lists:
        steps.clear()
        for v in values:
            steps.add(v)
        padded = values + [0.0] * 3
        assert (steps.d0, steps.d1, steps.d2, steps.n) == (padded[0], padded[1], padded[2], len(values))
        assert steps.more == (values[3:] or None)
        assert _norm(steps.d0, steps.d1, steps.d2, steps.n, steps.more) == math.hypot(*values)
        assert beyond(steps.d0, steps.d1, steps.d2, steps.n, steps.more, 1.0) == (math.hypot(*values) > 1.0)


@settings(max_examples=200, deadline=None)
@given(a=st.lists(_FINITE, min_size=5, max_size=5), b=st.lists(_FINITE, min_size=5, max_size=5),
       drop=st.integers(min_value=0, max_value=5))
def test_a_pairs_distance_is_over_the_axes_both_have(a: list[float], b: list[float], drop: int) -> None:
    keys = ("x", "y", "z", "a", "b")
    end_a = dict(zip(keys, a))
    end_b = {k: v for i, (k, v) in enumerate(zip(keys, b)) if i != drop}  # (drop 5: every axis)
    report = Report(0.001)
    first = Move("feed", {}, end_a, 100.0, 1, 1)
    second = Move("feed", {}, end_b, 100.0, 1, 1)
    assert _differ(first, second, report) is None
    both = [k for k in keys if k in end_b]
    assert report.max_deviation == math.dist([end_a[k] for k in both], [end_b[k] for k in both])
    assert report.where == (1, 1)
