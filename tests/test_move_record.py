"""The move record (``postproc.simulate.move_record``) held to the dictionary events it stands for: its
event as the toolpath format spells it (a hand-written line), its JSON line as json writes its event (any
record), verify's normalising and comparison of records as of their events (random paths), and a simulation's
stream of records as the dictionaries the same simulation makes without them (example and CAM programs)."""

from __future__ import annotations

import io
import json
import math
import sys
from pathlib import Path
from typing import Any, Callable

import pytest
from hypothesis import given, settings, strategies as st

from postproc.commands.export import event_encoder
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import load_setup
from postproc.simulate.compare import compare, normalise
from postproc.simulate.event_text import EventValueError, event_text, write_lines
from postproc.simulate.move_record import MoveRecord, as_events
from postproc.simulate.normal_move import Move
from postproc.simulate.toolpath import toolpath_events, toolpath_stream
from tests.test_normalise_reference import EPS, _path

ROOT = Path(__file__).parent.parent
ENCODER = event_encoder()


def _as_text(written: list[str]) -> Callable[[bytes], None]:
    """``write_lines``' ``write`` that keeps each chunk (ASCII bytes) as its text."""
    return lambda chunk: written.append(chunk.decode("ascii"))


def _json(event: Any) -> str:
    return json.JSONEncoder(allow_nan=False).encode(event)


def test_a_record_is_the_event_the_format_defines() -> None:
    """docs/toolpath-format.md: a move's keys in this order, ``controlled`` last; no ``f`` for a rapid."""
    record = MoveRecord(7, "feed", ("x", "y", "z"), [1, 2.5, -3], 1500, None, [1, 2.5, 117])
    assert record.event() == {"line": 7, "move": "feed", "x": 1, "y": 2.5, "z": -3, "f": 1500,
                              "controlled": {"x": 1, "y": 2.5, "z": 117}}
    assert event_text(record, ENCODER) == ('{"line": 7, "move": "feed", "x": 1, "y": 2.5, "z": -3, "f": 1500, '
                                           '"controlled": {"x": 1, "y": 2.5, "z": 117}}')
    rapid = MoveRecord(3, "rapid", ("x", "z"), [0.000125, -12], None, None, None)
    assert event_text(rapid, ENCODER) == '{"line": 3, "move": "rapid", "x": 0.000125, "z": -12}'
    arc = MoveRecord(4, "cw", ("x", "y", "z"), [10, 0, -2.5], 800, None, [10, 0, 97.5], ("cx", "cy", "cz"),
                     [5, 0, -2.5], "XY", [5, 0, 97.5])
    assert list(arc.event()) == ["line", "move", "x", "y", "z", "cx", "cy", "cz", "plane", "f", "controlled"]
    assert event_text(arc, ENCODER) == ('{"line": 4, "move": "cw", "x": 10, "y": 0, "z": -2.5, "cx": 5, "cy": 0, '
                                        '"cz": -2.5, "plane": "XY", "f": 800, "controlled": {"x": 10, "y": 0, '
                                        '"z": 97.5, "cx": 5, "cy": 0, "cz": 97.5}}')
    tap = MoveRecord(9, "tap", ("x", "y", "z"), [0, 0, -10.5], 1.25, "per_rev", None)
    assert list(tap.event()) == ["line", "move", "x", "y", "z", "f", "feed_mode"]
    assert event_text(tap, ENCODER) == ('{"line": 9, "move": "tap", "x": 0, "y": 0, "z": -10.5, "f": 1.25, '
                                        '"feed_mode": "per_rev"}')


NUMBERS = st.one_of(st.integers(-10**6, 10**6), st.floats(allow_nan=False, allow_infinity=False),
                    st.integers(-10**9, 10**9).map(lambda n: n / 1e6), st.sampled_from([0.0, -0.0, 1e-4, 9e-5, 1e8]))
KEYS = st.sampled_from([("x", "y", "z"), ("x", "z"), ("x", "y", "z", "a"), ("x", "y", "z", "a", "b", "c"), ("x",)])


@st.composite
def _records(draw: Any) -> MoveRecord:
    keys = draw(KEYS)
    point = [draw(NUMBERS) for _ in keys]
    controlled = [draw(NUMBERS) for _ in keys] if draw(st.booleans()) else None
    kind = draw(st.sampled_from(["rapid", "feed", "tap", "cw", "ccw"]))
    f = None if kind == "rapid" else draw(NUMBERS)
    mode = None if kind == "rapid" else draw(st.sampled_from([None, "per_rev", "inverse_time", "per_min"]))
    if kind in ("cw", "ccw"):  # an arc: its centre keys are the machine's X, Y, Z, its centre beside its point
        centre_keys = tuple("c" + k for k in keys if k in "xyz")
        centre = [draw(NUMBERS) for _ in centre_keys]
        ccentre = None if controlled is None else [draw(NUMBERS) for _ in centre_keys]
        return MoveRecord(draw(st.integers(1, 10**7)), kind, keys, point, f, mode, controlled, centre_keys, centre,
                          draw(st.sampled_from(["XY", "ZX", "YZ"])), ccentre)
    return MoveRecord(draw(st.integers(1, 10**7)), kind, keys, point, f, mode, controlled)


@settings(max_examples=500, deadline=None)
@given(record=_records())
def test_a_record_is_written_as_json_writes_its_event(record: MoveRecord) -> None:
    assert event_text(record, ENCODER) == _json(record.event())


@settings(max_examples=200, deadline=None)
@given(stream=st.lists(st.one_of(_records(), st.fixed_dictionaries({"line": st.integers(1, 99), "event": st.just("dwell"),
                                                                    "seconds": NUMBERS})), max_size=600))
def test_write_lines_writes_records_among_events_as_json_writes_them(stream: list[Any]) -> None:
    """Runs of records with other events between them, over more than one chunk."""
    written: list[str] = []
    write_lines(iter(stream), _as_text(written), ENCODER)
    assert "".join(written) == "".join(_json(ev) + "\n" for ev in as_events(stream))


@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan])
def test_a_record_that_is_not_finite_fails_with_its_event(bad: float) -> None:
    before = MoveRecord(1, "rapid", ("x",), [1], None, None, None)
    record = MoveRecord(2, "feed", ("x", "z"), [1, 2], 100, None, [1, bad])
    written: list[str] = []
    with pytest.raises(EventValueError) as failure:
        write_lines(iter([before, record]), _as_text(written), ENCODER)
    assert "".join(written) == '{"line": 1, "move": "rapid", "x": 1}\n'
    assert failure.value.event == record.event() or math.isnan(bad)
    assert failure.value.event["line"] == 2


def _as_record(ev: dict[str, Any]) -> dict[str, Any] | MoveRecord:
    """A straight move event as its record, where it has the record's shape (its keys in the record's order)."""
    if ev.get("move") not in ("rapid", "feed", "tap"):
        return ev
    keys = tuple(k for k in ev if k not in ("line", "move", "f", "feed_mode", "controlled"))
    if list(ev) != ["line", "move", *keys, *[k for k in ("f", "feed_mode", "controlled") if k in ev]]:
        return ev
    controlled = ev.get("controlled")
    if controlled is not None and tuple(controlled) != keys:
        return ev
    return MoveRecord(ev["line"], ev["move"], keys, [ev[k] for k in keys], ev.get("f"), ev.get("feed_mode"),
                      None if controlled is None else [controlled[k] for k in keys])


def _fields(item: Any) -> Any:
    if isinstance(item, Move):
        return (item.kind, item.start, item.end, item.f, item.first_line, item.last_line, item.direction, item.centre,
                item.plane, item.radius, item.sweep, item.length)
    return item


@settings(max_examples=300, deadline=None)
@given(path=_path())
def test_normalise_reads_a_record_as_its_event(path: tuple[dict[str, float], list[dict[str, Any]]]) -> None:
    start, events = path
    records = [_as_record(ev) for ev in events]
    assert records == events or any(isinstance(r, MoveRecord) for r in records)
    ours = [_fields(i) for i in normalise(iter(records), start, EPS)]
    assert ours == [_fields(i) for i in normalise(iter(events), start, EPS)]


@settings(max_examples=200, deadline=None)
@given(path=_path(), inverse=st.integers(0, 6), moved=st.sampled_from([0.0, 2e-4, 0.25]))
def test_a_comparison_of_records_is_the_comparison_of_their_events(
        path: tuple[dict[str, float], list[dict[str, Any]]], inverse: int, moved: float) -> None:
    """Inverse-time feeds from one move on (``per_minute_from_first`` converts the rest from the move before) and a
    copy moved in x: the report is the same with records as with dictionaries."""
    start, events = path
    events = [dict(ev) for ev in events]
    if inverse < len(events) and "f" in events[inverse]:
        for ev in events[inverse:]:
            if "f" in ev:
                ev["feed_mode"] = "inverse_time"
    copy = [dict(ev, x=ev["x"] + moved) if "x" in ev and ev.get("move") in ("feed", "rapid") else ev for ev in events]
    head = {"toolpath": 1, "units": "mm", "dialect": "fanuc"}

    def report(a: list[Any], b: list[Any]) -> tuple[Any, ...]:
        r = compare([head, *a], [head, *b], start_in=start, start_out=start, tolerance=0.001)
        return r.moves, r.max_deviation, r.where, r.where_at, r.mismatch, r.mismatch_at

    assert report([_as_record(ev) for ev in events], [_as_record(ev) for ev in copy]) == report(events, copy)


def _cam_program(blocks: int) -> str:
    """A CAM program of benchmarks/generate.py (under a tool length: every move has its controlled point)."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import generate
    finally:
        sys.path.pop(0)
    out = io.StringIO()
    generate.write(blocks, out)
    return out.getvalue()


PROGRAMS = [
    ("fanuc", "examples/fanuc/o1003_pocket_and_edge.nc", "examples/setups/fanuc_0i_mf_vmc.xml"),
    ("fanuc", "examples/fanuc/o1002_bracket_inch.nc", "examples/setups/fanuc_0i_mf_vmc.xml"),
    ("fanuc", "examples/fanuc-lathe/o2001_stepped_shaft.nc", "examples/setups/fanuc_0i_tf.xml"),
    ("fanuc", "examples/fanuc-lathe/o2003_thread.nc", "examples/setups/fanuc_0i_tf.xml"),
    ("linuxcnc", "examples/linuxcnc/cover_profile.ngc", "examples/setups/linuxcnc_mill.xml"),
    ("linuxcnc", "examples/linuxcnc/plate_drill_peck.ngc", "examples/setups/linuxcnc_mill.xml"),
    ("siemens", "examples/siemens/tapping.mpf", "examples/setups/siemens_840d_mill.xml"),
    ("fanuc", "cam", "benchmarks/machine.xml"),
]


@pytest.mark.parametrize("dialect,program,setup", PROGRAMS)
def test_a_simulation_streams_the_records_of_its_events(dialect: str, program: str, setup: str) -> None:
    """The same program simulated with records (``toolpath_stream``) and without (``toolpath_events``): the same
    events, the straight moves among them as records; and its JSON lines as json writes the events."""
    machine = load_setup(ROOT / setup)
    text = _cam_program(600) if program == "cam" else (ROOT / program).read_text()
    plain = list(toolpath_events(io.StringIO(text), file=program, dialect=dialect, setup=machine))
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    streamed = list(toolpath_stream(io.StringIO(text), file=program, dialect=dialect, setup=machine,
                                    diagnostics=diagnostics))
    assert not diagnostics.errors
    assert any(isinstance(ev, MoveRecord) for ev in streamed)
    assert not any(isinstance(ev, MoveRecord) for ev in plain)
    assert list(as_events(streamed)) == plain
    written: list[str] = []
    write_lines(iter(streamed), _as_text(written), ENCODER)
    assert "".join(written) == "".join(_json(ev) + "\n" for ev in plain)
