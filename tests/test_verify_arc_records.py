"""verify's normalising reads an arc's record by field (``postproc.simulate.arc_runs._arc_record``), no longer as the
dictionary ``MoveRecord.event`` builds: the runs it makes of a stream of records are those it makes of the same
stream as dictionaries (the path ``tests/test_normalise_reference.py`` holds to the reference), to the bit: arcs
and straight moves mixed, on two to five axes, in every plane, with controlled points and centres (a tool length,
a cutter radius), integral values as ints (as ``num`` writes them), arcs that continue one circle."""

from __future__ import annotations

import math
from typing import Any

from hypothesis import given, settings, strategies as st

from postproc.simulate.move_record import MoveRecord
from postproc.simulate.normal_move import Move
from postproc.simulate.runs import normalise

EPS = 0.0005
"""Half verify's default tolerance: the merge distance ``compare`` gives ``normalise``."""
MACHINES = [(("x", "z"), ("cx", "cz"), ["ZX"]), (("x", "y", "z"), ("cx", "cy", "cz"), ["XY", "ZX", "YZ"]),
            (("x", "y", "z", "a"), ("cx", "cy", "cz"), ["XY", "YZ"]),
            (("x", "y", "z", "a", "b"), ("cx", "cy", "cz"), ["XY"])]
"""Axis keys, centre keys and the planes of a simulation's records (one tuple each, shared as the simulator's)."""
PLANE_AXES = {"XY": (0, 1), "ZX": (2, 0), "YZ": (1, 2)}


def _fields(item: Any) -> Any:
    if isinstance(item, Move):
        return (item.kind, item.start, item.end, item.f, item.first_line, item.last_line, item.direction, item.centre,
                item.plane, item.radius, item.sweep, item.length)
    return item


def _number(x: float) -> float | int:
    """As ``num`` writes a value: an int where integral."""
    return int(x) if x == int(x) else x


@st.composite
def _records(draw: Any) -> tuple[dict[str, float], list[MoveRecord]]:
    """A start and a stream of straight moves and arcs as records, arcs that often go on about the centre of the
    one before (a circle split into pieces), controlled points beside some."""
    keys, centre_keys, planes = draw(st.sampled_from(MACHINES))
    start = {k.upper(): float(draw(st.integers(-5, 5))) for k in keys}
    pos = [start[k.upper()] for k in keys]
    records: list[MoveRecord] = []
    centre: dict[str, float] = {}
    plane = draw(st.sampled_from(planes))
    for line in range(1, draw(st.integers(1, 12)) + 1):
        kind = draw(st.sampled_from(["feed", "rapid", "cw", "ccw", "cw", "ccw"]))
        f: float | int | None = None if kind == "rapid" else _number(draw(st.sampled_from([100.0, 250.5])))
        shift = draw(st.sampled_from([0.0, 0.0, 120.0, 0.25]))  # a tool length, or a cutter radius's offset
        if kind in ("cw", "ccw"):
            if draw(st.integers(0, 3)) == 0:
                plane = draw(st.sampled_from(planes))
            i, j = PLANE_AXES[plane]
            if i >= len(pos) or j >= len(pos) or "xyz"[i] not in keys or "xyz"[j] not in keys:
                continue
            i, j = keys.index("xyz"[i]), keys.index("xyz"[j])
            if not centre or draw(st.integers(0, 2)) == 0:  # a new circle about a centre near here
                centre = {centre_keys[n]: float(draw(st.integers(-3, 3))) for n in range(len(centre_keys))}
            ci, cj = "c" + keys[i], "c" + keys[j]
            r = math.hypot(pos[i] - centre.get(ci, pos[i]), pos[j] - centre.get(cj, pos[j])) or 1.0
            angle = draw(st.sampled_from([0.3, 1.0, 2.5, -1.2]))
            target = list(pos)
            target[i] = round(centre.get(ci, pos[i]) + r * math.cos(angle), 4)
            target[j] = round(centre.get(cj, pos[j]) + r * math.sin(angle), 4)
            for n in range(len(keys)):
                if n not in (i, j) and draw(st.integers(0, 3)) == 0:  # a helix, or a move of another axis
                    target[n] += draw(st.sampled_from([-0.5, 1.0]))
            written = [_number(centre[k]) for k in centre_keys]
            controlled = [_number(v + (shift if n == len(keys) - 1 else 0.0)) for n, v in enumerate(target)]
            ccentre = [_number(v + (shift if shift == 0.25 else 0.0)) for v in centre.values()]
            apart = shift != 0.0
            records.append(MoveRecord(line, kind, keys, [_number(v) for v in target], f, None,
                                       controlled if apart else None, centre_keys, written, plane,
                                       ccentre if apart else None))
        else:
            step = [float(draw(st.integers(-2, 2))) for _ in keys]
            target = [p + s for p, s in zip(pos, step)]
            controlled = [_number(v + (shift if n == len(keys) - 1 else 0.0)) for n, v in enumerate(target)]
            records.append(MoveRecord(line, kind, keys, [_number(v) for v in target], f, None,
                                      controlled if shift != 0.0 else None))
        pos = target
    return start, records


@settings(max_examples=400, deadline=None)
@given(path=_records())
def test_an_arc_record_is_read_as_its_event(path: tuple[dict[str, float], list[MoveRecord]]) -> None:
    start, records = path
    by_field = [_fields(m) for m in normalise(iter(records), start, EPS)]
    assert by_field == [_fields(m) for m in normalise(iter([r.event() for r in records]), start, EPS)]


def test_an_arc_record_ends_and_turns_about_its_controlled_centre() -> None:
    """Not a test that cannot fail: one arc's record under a cutter radius (its controlled end and centre beside
    the programmed ones), by hand: a quarter circle of radius 2 about (1, 0) from (3, 0) to (1, 2),
    counter-clockwise, where the programmed arc is about (0, 0). And the same record without a controlled point
    turns about the programmed centre."""
    keys, centre_keys = ("x", "y", "z"), ("cx", "cy", "cz")
    start = {"X": 3.0, "Y": 0.0, "Z": 0.0}
    record = MoveRecord(7, "ccw", keys, [0, 2, 0], 300, None, [1, 2, 0], centre_keys, [0, 0, 0], "XY", [1, 0, 0])
    (m,) = normalise(iter([record]), start, EPS)
    assert isinstance(m, Move)
    assert (m.kind, m.end, m.centre, m.plane, m.f, m.first_line) == ("ccw", {"x": 1.0, "y": 2.0, "z": 0.0}, (1.0, 0.0),
                                                                     "XY", 300.0, 7)
    assert m.radius == 2.0 and math.isclose(m.sweep, math.pi / 2)
    programmed = MoveRecord(7, "ccw", keys, [0, 3, 0], 300, None, None, centre_keys, [0, 0, 0], "XY")
    (p,) = normalise(iter([programmed]), start, EPS)
    assert isinstance(p, Move)
    assert p.centre == (0.0, 0.0) and p.radius == 3.0 and math.isclose(p.sweep, math.pi / 2)
