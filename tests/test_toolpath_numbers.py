"""How a toolpath writes its numbers and its lines: ``toolpath.num`` against its definition on any float
(and on the near-ties its integer path hands to ``round``), and the JSON lines encoders of a run
(``export.event_encoder``, ``event_text.event_text`` and ``write_lines``) against ``json.JSONEncoder(allow_nan=False).encode``,
the definition of the format, on any event and on the events a simulation makes."""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterator

import pytest
from hypothesis import given, settings, strategies as st

from postproc.errors import ProgramError
from postproc.commands.export import event_encoder
from postproc.simulate.event_text import EventValueError, event_text, float_text, write_lines
from postproc.simulate.move_record import MoveRecord
from postproc.simulate.events import all_as_written
from postproc.simulate.toolpath import num


@settings(max_examples=500, deadline=None)
@given(value=st.floats(allow_nan=True, allow_infinity=True))
def test_num_rounds_to_six_places_integral_as_int_and_refuses_what_is_not_finite(value: float) -> None:
    if not math.isfinite(value):
        with pytest.raises(ProgramError, match="nan|beyond the range of a float"):
            num(value)
        return
    r = round(value, 6)
    written = num(value)
    if r.is_integer():
        assert type(written) is int and written == int(r)  # -0.0 and 0.0 as 0
    else:
        assert type(written) is float and written == r


FLOATS = st.one_of(st.floats(allow_nan=False, allow_infinity=False), st.sampled_from([0.0, -0.0, 1.5, -2.25]))
SCALARS = st.one_of(st.integers(-10**20, 10**20), FLOATS, st.booleans(), st.none(), st.text(max_size=8))
VALUES = st.one_of(SCALARS, st.lists(SCALARS, max_size=3), st.dictionaries(st.text(max_size=3), SCALARS, max_size=4))
EVENTS = st.dictionaries(st.one_of(st.text(max_size=6), st.integers(0, 9)), VALUES, max_size=8)
ENCODER = event_encoder()


def _as_text(written: list[str]) -> Callable[[bytes], None]:
    """``write_lines``' ``write`` that keeps each chunk (ASCII bytes) as its text."""
    return lambda chunk: written.append(chunk.decode("ascii"))


@settings(max_examples=500, deadline=None)
@given(event=EVENTS)
def test_the_encoder_writes_what_json_writes(event: dict[str, object]) -> None:
    assert ENCODER(event) == json.JSONEncoder(allow_nan=False).encode(event)


@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan])
def test_the_encoder_refuses_what_is_not_finite(bad: float) -> None:
    with pytest.raises(ValueError):
        ENCODER({"line": 3, "move": "feed", "x": bad})
    with pytest.raises(ValueError):
        ENCODER({"line": 3, "move": "feed", "controlled": {"x": bad}})


def _by_round(value: float) -> float | int:
    r = round(value, 6)
    return 0 if r == 0 else int(r) if r.is_integer() else r


def _near_ties() -> st.SearchStrategy[float]:
    """Values within a few ulps of a half millionth (where ``value * 1e6`` may round across the half),
    of a whole millionth, and decimals as a CAM program writes them."""
    units = st.integers(-10**14, 10**14)
    half = units.map(lambda k: (k + 0.5) / 1e6)
    whole = units.map(lambda k: k / 1e6)
    stepped = st.tuples(st.one_of(half, whole), st.integers(-4, 4)).map(
        lambda t: _step(t[0], t[1]))
    decimal = st.tuples(st.integers(-10**9, 10**9), st.integers(0, 9)).map(lambda t: float(f"{t[0]}e-{t[1]}"))
    return st.one_of(stepped, decimal)


def _step(value: float, ulps: int) -> float:
    for _ in range(abs(ulps)):
        value = math.nextafter(value, math.inf if ulps > 0 else -math.inf)
    return value


@settings(max_examples=2000, deadline=None)
@given(value=st.one_of(_near_ties(), st.floats(allow_nan=False, allow_infinity=False, min_value=-1e9, max_value=1e9)))
def test_num_is_round_on_near_ties_too(value: float) -> None:
    written, expected = num(value), _by_round(value)
    assert type(written) is type(expected) and written == expected


@pytest.mark.parametrize("value", [0.5e-6, -0.5e-6, 1.5e-6, 2.5e-6, 1.2345675, -1.2345675, 0.0000125, 99999999.9999995,
                                   1e14 / 1e6 - 0.5e-6, -0.0, 5e-324, 1e300, 0.1 + 0.2])
def test_num_is_round_at_chosen_ties(value: float) -> None:
    written, expected = num(value), _by_round(value)
    assert type(written) is type(expected) and written == expected


def _written_as_is(value: float) -> bool:
    """``num(value)`` is a float equal to ``value`` (by ``round``: ``_by_round``), for a value num accepts."""
    if not math.isfinite(value):
        return False
    expected = _by_round(value)
    return type(expected) is float and expected == value


@settings(max_examples=3000, deadline=None)
@given(value=st.one_of(_near_ties(), _near_ties().map(num).map(float), st.floats(allow_nan=True, allow_infinity=True),
                       st.sampled_from([0.0, -0.0, 1.0, -3.0, 0.3008, -41.6654, 1e-6, -1e-6, 5e-7, 1e8 + 0.5])))
def test_as_written_is_num_leaving_a_float_as_it_is(value: float) -> None:
    """``all_as_written`` of one value is "num gives a float equal to the value": never for an integral value (an int in the JSON
    line), a near tie num rounds away, nan or an infinity; below 1e8 (the range of ``num``'s integer arithmetic)
    exactly that, beyond it never (such a value takes the general path, which calls ``num``)."""
    if all_as_written([value]):
        assert _written_as_is(value)
    elif abs(value) < 1e8:
        assert not _written_as_is(value)


@settings(max_examples=300, deadline=None)
@given(values=st.lists(st.one_of(_near_ties(), _near_ties().map(num).map(float), st.integers(-5, 5).map(float)),
                       max_size=6))
def test_all_as_written_is_every_value_as_written(values: list[float]) -> None:
    """Below 1e8 exactly each value as written; a list holding a value beyond it is never (as for one value:
    ``test_as_written_is_num_leaving_a_float_as_it_is``; hypothesis found ``[100000000.000001]``)."""
    if all(abs(v) < 1e8 for v in values):
        assert all_as_written(values) is all(_written_as_is(v) for v in values)
    else:
        assert not all_as_written(values)


@pytest.mark.parametrize("text", ["0.3008", "-3.956", "-41.6654", "12.5", "0.000001", "99999999.999999"])
def test_a_cam_programs_decimals_are_as_written(text: str) -> None:
    """The values the shortcut is for: a word's decimal of at most six places, not integral (hand-checked: each is
    the float ``round(value, 6)`` gives back)."""
    assert all_as_written([float(text)]) and not all_as_written([float(text.split(".")[0] + ".0")])


@settings(max_examples=2000, deadline=None)
@given(value=st.one_of(_near_ties().map(num), st.floats(allow_nan=False, allow_infinity=False)))
def test_float_text_is_repr(value: float) -> None:
    if isinstance(value, float):
        assert float_text(value) == repr(value)


@pytest.mark.parametrize("value", [1500.0, -7.0, 1e-4, -1e-4, 0.0001234, 999.999999, -999.999999, 1000.000001, 1000.5,
                                   -1000.0, 0.5, 0.001, 0.000001 + 12, 12.000100, 99999999.999999, -99999999.0,
                                   123.456, 123.4567, 1e8, 1e16, 9.999e-5, 2.5e-7])
def test_float_text_is_repr_where_its_digits_change(value: float) -> None:
    """``float_text``'s digits (whole parts of one to eight digits, written three at a time from the right; the
    decimals, trailing zeros dropped) at their edges, and integral floats (``repr`` adds ".0")."""
    assert float_text(value) == repr(value)
    assert float_text(num(value) * 1.0) == repr(num(value) * 1.0)


WHOLES = [0, 1, 9, 10, 11, 99, 100, 101, 999, 1000, 1001, 1010, 9999, 10_000, 99_999, 100_000, 100_100, 999_999,
          1_000_000, 1_002_003, 12_345_678, 99_999_999, 10**14, 10**15 - 1, 10**15, 10**18, 10**30]


@pytest.mark.parametrize("whole", WHOLES)
def test_whole_numbers_are_written_as_str_writes_them(whole: int) -> None:
    """An int's digits (a line number, an integral coordinate or feed), written by ``event_text`` three at a time
    from the right below 10**15 and by ``str`` above, at each count of digits and with zeros inside, both signs: a
    record's and an event's text are json's."""
    for value in (whole, -whole):
        record = MoveRecord(whole, "feed", ("x", "y"), [value, value + 0.25], value, None, [value, whole / 1e6])
        assert event_text(record, ENCODER) == _json(record.event())
        event = {"line": whole, "x": value, "controlled": {"x": value}}
        assert event_text(event, ENCODER) == _json(event)


def _json(event: dict[object, object]) -> str:
    return json.JSONEncoder(allow_nan=False).encode(event)


@settings(max_examples=500, deadline=None)
@given(event=EVENTS)
def test_event_text_writes_what_json_writes(event: dict[object, object]) -> None:
    assert event_text(event, ENCODER) == _json(event)


AXES = st.one_of(_near_ties().map(num), st.integers(-10**6, 10**6))
MOVES = st.fixed_dictionaries(
    {"line": st.integers(1, 10**7), "move": st.sampled_from(["rapid", "feed", "cw", "ccw", "tap"]),
     "x": AXES, "y": AXES, "z": AXES},
    optional={"cx": AXES, "cy": AXES, "plane": st.sampled_from(["XY", "ZX", "YZ"]), "f": AXES,
              "feed_mode": st.sampled_from(["per_rev", "inverse_time"]),
              "controlled": st.fixed_dictionaries({"x": AXES, "y": AXES, "z": AXES})})


@settings(max_examples=1000, deadline=None)
@given(event=MOVES)
def test_event_text_writes_moves_as_json_does(event: dict[object, object]) -> None:
    assert event_text(event, ENCODER) == _json(event)


@settings(max_examples=300, deadline=None)
@given(event=MOVES, shared=st.lists(st.sampled_from("xyz"), max_size=3))
def test_event_text_writes_a_controlled_point_sharing_the_programmed_floats_as_json_does(
        event: dict[str, object], shared: list[str]) -> None:
    """The controlled point holds the very float objects of the programmed one on some axes (as the simulator
    makes it: ``Moves._offset_line``), which ``event_text`` spells again for it."""
    controlled = {k: event[k] for k in "xyz"}
    for k in "xyz":
        if k not in shared and isinstance(event[k], float):
            controlled[k] = float(event[k]) + 0.5  # type: ignore[arg-type]
    event["controlled"] = controlled
    assert event_text(event, ENCODER) == _json(event)


@pytest.mark.parametrize("bad", [math.inf, -math.inf, math.nan])
def test_event_text_refuses_what_is_not_finite(bad: float) -> None:
    with pytest.raises(ValueError):
        event_text({"line": 3, "move": "feed", "x": bad}, ENCODER)
    with pytest.raises(ValueError):
        event_text({"line": 3, "move": "feed", "controlled": {"x": bad}}, ENCODER)


@settings(max_examples=30, deadline=None)
@given(events=st.lists(st.one_of(MOVES, EVENTS), min_size=0, max_size=40), copies=st.integers(1, 20))
def test_write_lines_writes_each_event_as_json_does_a_chunk_at_a_time(events: list[dict[object, object]],
                                                                      copies: int) -> None:
    """``write_lines`` (``toolpath --format jsonl``) writes a chunk of lines at a time: the text is still json's
    line by line, over as many chunks as the events fill (up to 800 events: three chunks and a part)."""
    stream = events * copies
    written: list[str] = []
    write_lines(iter(stream), _as_text(written), ENCODER)
    assert "".join(written) == "".join(_json(ev) + "\n" for ev in stream)
    assert all(chunk.count("\n") <= 256 for chunk in written)


def test_write_lines_writes_the_lines_before_an_error() -> None:
    """An error of the events' stream (a program error raised at its end) or of a value json refuses: every
    line before it is written first, as line by line."""
    def failing() -> Iterator[dict[str, object]]:
        for i in range(300):
            yield {"line": i, "move": "feed", "x": i / 8}
        raise ValueError("the program had errors")

    written: list[str] = []
    with pytest.raises(ValueError, match="the program had errors"):
        write_lines(failing(), _as_text(written), ENCODER)
    assert "".join(written).splitlines() == [_json({"line": i, "move": "feed", "x": i / 8}) for i in range(300)]
    written.clear()
    events = [{"line": i, "move": "feed", "x": float(i)} for i in range(270)] + [{"line": 270, "x": math.inf}]
    with pytest.raises(EventValueError) as err:
        write_lines(iter(events + [{"line": 271}]), _as_text(written), ENCODER)
    assert err.value.event["line"] == 270
    assert "".join(written) == "".join(_json(ev) + "\n" for ev in events[:270])


KEYS = st.sampled_from(["line", "move", "x", "y", "f", "controlled", "event", "on"])
RUN_VALUES = st.one_of(st.sampled_from([1500, 7, "feed", "rapid", True, None, 0.5]), st.integers(-10**9, 10**9),
                       st.fixed_dictionaries({"x": st.sampled_from([1500, "feed", 2.25])}))


@settings(max_examples=300, deadline=None)
@given(shapes=st.lists(st.lists(st.tuples(KEYS, RUN_VALUES), max_size=6), min_size=1, max_size=4),
       order=st.lists(st.integers(0, 3), min_size=1, max_size=30))
def test_write_lines_writes_runs_of_events_of_few_shapes_as_json_does(
        shapes: list[list[tuple[str, object]]], order: list[int]) -> None:
    """A toolpath's events come in runs of one shape, whose key texts (and int and str values) ``event_text``
    keeps by place: the same key and value objects at a place, or others there, an int where a str was, a
    key moving to another place, nested or not, are written as json writes them."""
    stream = [dict(shapes[i % len(shapes)]) for i in order]
    written: list[str] = []
    write_lines(iter(stream), _as_text(written), ENCODER)
    assert "".join(written) == "".join(_json(ev) + "\n" for ev in stream)


@settings(max_examples=500, deadline=None)
@given(tenths=st.lists(st.integers(-10**12, 10**12), min_size=1, max_size=40))
def test_numbers_of_at_most_four_decimals_are_written_as_repr(tenths: list[int]) -> None:
    """A number of at most four decimals (a CAM program's coordinates) takes its point and decimals from a table
    filled as they are met (``event_text._SHORT``): each is written as ``repr`` writes it, met once or again, as
    an event's value, a record's point and the controlled point sharing its float objects."""
    values = [n / 1e4 for n in tenths]
    for value in values + values:
        assert float_text(value) == repr(value)
    keys = ("x", "y", "z")
    for i in range(0, len(values) - 2, 3):
        point: list[float | int] = list(values[i:i + 3])
        controlled: list[float | int] = [point[0], point[1], values[i + 2] + 120.0]
        record = MoveRecord(i + 1, "feed", keys, point, 1500, None, controlled)
        assert event_text(record, ENCODER) == _json(record.event())


@pytest.mark.parametrize("feeds", [[1500, 1500, 2500.5, float("2500.5"), 1500], [0.25, 0.25, 7, 7, int("7")]])
def test_a_record_run_writes_each_feed_and_kind_it_holds(feeds: list[float | int]) -> None:
    """The writer keeps the text of the kind and the feed met last (by identity: the simulator writes one feed object
    while the feed stays): records that change either, or hold an equal feed as another object, are written as json
    writes their events."""
    kinds = ["feed", "rapid", "tap", "feed"]
    records = [MoveRecord(n, kinds[n % len(kinds)], ("x", "z"), [n / 8, -n], None if kinds[n % len(kinds)] == "rapid"
                          else f, None, None if n % 2 else [n / 8, 100 - n]) for n, f in enumerate(feeds * 3)]
    written: list[str] = []
    write_lines(iter(records), _as_text(written), ENCODER)
    assert "".join(written) == "".join(_json(r.event()) + "\n" for r in records)


RECORD_NUMBERS = st.one_of(_near_ties().map(num), st.integers(-10**6, 10**6),
                           st.integers(-10**6, 10**6).map(lambda n: num(n / 1e4)))
RECORD_KEYS = st.sampled_from([("x", "y", "z"), ("x", "z"), ("x", "y", "z", "a"), ()])
FEEDS = [1500, 250.5, 1500.0, 0.1234]
"""Feed objects the records share, as the simulator's moves share the feed in force."""


@st.composite
def _records(draw: st.DrawFn) -> MoveRecord:
    """A move's record as the simulator makes one: its keys among a few tuples (one a simulation), a line number
    small or large, a kind, a feed (the same object again, often), a feed mode, a controlled point, an arc's
    centre."""
    keys = draw(RECORD_KEYS)
    point = [draw(RECORD_NUMBERS) for _ in keys]
    kind = draw(st.sampled_from(["rapid", "feed", "cw", "ccw", "tap"]))
    arc = kind in ("cw", "ccw")
    centre_keys = ("cx", "cy", "cz") if arc else ()
    controlled = draw(st.one_of(st.none(), st.just([draw(RECORD_NUMBERS) if draw(st.booleans()) else v
                                                    for v in point])))
    return MoveRecord(draw(st.one_of(st.integers(0, 2000), st.integers(0, 10**7))), kind, keys, point,
                      draw(st.one_of(st.none(), st.sampled_from(FEEDS), RECORD_NUMBERS)),
                      draw(st.sampled_from([None, None, "per_rev", "inverse_time"])), controlled, centre_keys,
                      [draw(RECORD_NUMBERS) for _ in centre_keys] if arc else None,
                      draw(st.sampled_from(["XY", "ZX"])) if arc else None,
                      [draw(RECORD_NUMBERS) for _ in centre_keys] if arc and controlled is not None else None)


@settings(max_examples=500, deadline=None)
@given(records=st.lists(_records(), min_size=1, max_size=30))
def test_write_lines_writes_records_as_json_writes_their_events(records: list[MoveRecord]) -> None:
    """``write_lines`` writes a record by field, its line number's digits joined with its kind, its feed with the
    controlled point's first key, its last short fraction with its closing (``event_text._KeyTexts``,
    ``_CLOSING``): each line is json's text of the record's ``event()``, the record alone (``event_text``)
    too."""
    written: list[str] = []
    write_lines(iter(records), _as_text(written), ENCODER)
    assert "".join(written) == "".join(_json(r.event()) + "\n" for r in records)
    for r in records:
        assert event_text(r, ENCODER) == _json(r.event())


RECORD_NUMBERS = st.one_of(st.integers(-10**6, 10**6).map(lambda n: n / 1e4), st.integers(-500, 500),
                           st.floats(-1e9, 1e9, allow_nan=False))


@settings(max_examples=500, deadline=None)
@given(keys=st.sampled_from([("x", "y", "z"), ("x", "z"), ("x", "y", "z", "a"), ("x",), ()]),
       data=st.data(), twins=st.lists(st.booleans(), min_size=4, max_size=4),
       f=st.one_of(st.none(), st.just(1500), st.just(250.5)), mode=st.sampled_from([None, None, "per_rev"]),
       arc=st.booleans(), controlled=st.booleans())
def test_a_record_writes_what_json_writes_of_its_event(keys: tuple[str, ...], data: st.DataObject,
                                                       twins: list[bool], f: float | int | None, mode: str | None,
                                                       arc: bool, controlled: bool) -> None:
    """``_record_into`` on random records: straight moves and arcs, with or without a feed, a feed mode and a
    controlled point whose values are the programmed point's own objects on some axes (spelt from the units the
    programmed ones had) or other numbers: the text json writes of the record's ``event()``."""
    point: list[float | int] = [data.draw(RECORD_NUMBERS) for _ in keys]
    ctrl: list[float | int] | None = None
    if controlled:
        ctrl = [v if twin else data.draw(RECORD_NUMBERS) for v, twin in zip(point, twins)]
    centre_keys: tuple[str, ...] = ("cx", "cy", "cz") if arc else ()
    centre = [data.draw(RECORD_NUMBERS) for _ in centre_keys] if arc else None
    ccentre = [data.draw(RECORD_NUMBERS) for _ in centre_keys] if arc and ctrl is not None else None
    record = MoveRecord(9, "cw" if arc else "feed", keys, point, f, mode, ctrl, centre_keys, centre,
                        "XY" if arc else None, ccentre)
    assert event_text(record, ENCODER) == _json(record.event())
    written: list[str] = []
    write_lines(iter([record, record]), _as_text(written), ENCODER)
    assert "".join(written) == (_json(record.event()) + "\n") * 2
