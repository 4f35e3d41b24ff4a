"""verify's normalising reads a simulation's straight moves as records (``MoveRecord``) whose points share one keys
tuple, by index, without looking each key up (``postproc.simulate.runs``: ``Normaliser.pull``, ``_extends``), and
pulls its events with ``pull_item``, not the builtin ``next``. Held here to the general path, the same moves as
their event dictionaries (every key looked up: ``tests/test_normalise_reference.py`` holds that path to the code
it replaced), on the random paths of that test: the same runs, to the bit. ``beyond`` of a pair of equal points
(answered without ``hypot``) is held to ``hypot`` itself."""

from __future__ import annotations

import math
from typing import Any

from hypothesis import given, settings, strategies as st

from postproc.simulate.compare import normalise
from postproc.simulate.move_record import MoveRecord
from postproc.simulate.runs import beyond, pull_item
from tests.test_normalise_reference import EPS, _fields, _path


def _as_records(start: dict[str, float], events: list[dict[str, Any]]) -> list[Any]:
    """Each straight move of ``events`` as the record a simulation makes of it: one keys tuple for all, the points
    as lists in its order; arcs and machine events as they are."""
    keys = tuple(k.lower() for k in start)
    out: list[Any] = []
    for ev in events:
        if ev.get("move") in ("feed", "rapid"):
            controlled = ev.get("controlled")
            out.append(MoveRecord(ev["line"], ev["move"], keys, [ev[k] for k in keys], ev.get("f"), None,
                                  None if controlled is None else [controlled[k] for k in keys]))
        else:
            out.append(ev)
    return out


@settings(max_examples=400, deadline=None)
@given(path=_path())
def test_records_normalise_as_their_events(path: tuple[dict[str, float], list[dict[str, Any]]]) -> None:
    start, events = path
    records = _as_records(start, events)
    assert sum(isinstance(r, MoveRecord) for r in records) == sum(ev.get("move") in ("feed", "rapid") for ev in events)
    ours = [_fields(i) for i in normalise(iter(records), start, EPS)]
    assert ours == [_fields(i) for i in normalise(iter(events), start, EPS)]


def test_pull_item_steps_an_iterator_to_its_end() -> None:
    items = iter([{"line": 1}, {"line": 2}])
    assert pull_item(items) == {"line": 1}
    assert pull_item(items) == {"line": 2}
    assert pull_item(items) is None
    assert pull_item(items) is None
    assert pull_item(iter([])) is None


@given(n=st.integers(0, 3), limit=st.sampled_from([0.0, 5e-324, 1e-9, 0.0005, 1.0]),
       tiny=st.sampled_from([0.0, 5e-324, 1e-200, -1e-200, 1e-160]))
def test_beyond_of_equal_points_is_hypot(n: int, limit: float, tiny: float) -> None:
    """Components all zero (two points that agree exactly) or so small their squares underflow: ``beyond`` is
    ``hypot(components) > limit`` either way."""
    parts = [tiny if i == 0 else 0.0 for i in range(n)]
    a, b, c = (parts + [0.0, 0.0, 0.0])[:3]
    assert beyond(a, b, c, n, None, limit) == (math.hypot(*parts) > limit)
