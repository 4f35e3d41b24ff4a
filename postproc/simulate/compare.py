"""verify's comparison of two toolpaths as they stream: each normalised (moves merged into runs,
``postproc.simulate.runs``), then compared pair by pair (``verify``'s docstring says how). Compiled with the
simulator (``pyproject.toml [tool.postproc] compiled``): verify runs this for every event of both programs."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import chain
from typing import Any, Final, Iterable, Iterator

from mypy_extensions import mypyc_attr

from ..lowering.inverse_time import per_minute
from .arc_moves import arc_deviation
from .chords import pair_with_chords
from .events import MOVES_THE_TOOL, Event
from .move_record import MoveRecord
from .normal_move import FEED_TOLERANCE as FEED_TOLERANCE, Move, same_feed as _same_feed  # (public names here too)
from .points import Steps, beyond, key_index, norm, point_value
from .runs import Normaliser, Pulled, normalise as normalise, pull_item

Point = tuple[float, float, float]

_hypot: Final = math.hypot
"""Compiled, ``math.hypot`` is an attribute look-up on the module each call; a Final is a C static."""
OMIT: Final = "omit"
"""A ``<ForeignCodes>`` code left out (``postproc.setup.foreign_codes.OMIT``)."""
_HALF_TURN: Final = math.pi
EVENT_TOLERANCE: Final = 1e-6
"""Numbers in machine events (dwell seconds, angles) compare within this."""
@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass
class Report:
    """The outcome of a comparison; ``ok`` only when within tolerance and structurally the same."""

    tolerance: float
    moves: int = 0
    max_deviation: float = 0.0
    where: tuple[int, int] | None = None
    """Source lines (IN, OUT) of the largest deviation."""
    where_at: tuple[Point, Point] | None = None
    """End points (IN, OUT) of the moves with the largest deviation: X, Y, Z in mm, true geometry (a
    lathe's x as a radius), as a backplot draws them."""
    mismatch: str | None = None
    mismatch_at: tuple[int | None, int | None] = (None, None)
    notes: list[str] = field(default_factory=list)
    ignored: list[str] = field(default_factory=list)
    """What the comparison left out (machine-specific codes, settings the simulation does not apply),
    one line each."""
    left_out_moves: bool = False
    """A setting that moves the tool (cutter compensation, tool length or work offset, path control)
    differs between the programs: the paths compared are not the paths cut."""
    allow_ignored: bool = False
    """``--allow-ignored``: such a difference does not fail the comparison."""
    lost: list[str] = field(default_factory=list)
    """Tool data in force in IN that OUT lacks, one line each (``postproc.simulate.lost_tool_data``): what
    explains a comparison that fails."""
    chord_tolerance: float | None = None
    """``--arcs lines:TOL``: OUT may cut an arc of IN into chords within TOL mm of it (``postproc.simulate.chords``)."""
    chord_deviation: float = 0.0
    chord_where: tuple[int, int] | None = None
    """Source lines (IN, OUT) of the chord furthest from its arc."""
    steps: Steps = field(default_factory=Steps, repr=False, compare=False)
    keys_in: tuple[str, ...] = field(default=(), repr=False, compare=False)
    keys_out: tuple[str, ...] = field(default=(), repr=False, compare=False)
    same_keys: bool = field(default=True, repr=False, compare=False)
    """The end keys of the pair compared last (one tuple a simulation) and whether they are alike: a pair with the
    same two tuples takes each axis at its own index, not looked for (``_differ``)."""
    """Where ``_differ`` collects a pair's distances (one for the comparison: no object a pair)."""

    @property
    def ok(self) -> bool:
        return (self.mismatch is None and self.max_deviation <= self.tolerance
                and (self.allow_ignored or not self.left_out_moves)
                and self.chord_deviation <= (self.chord_tolerance or 0.0) + self.tolerance)

    def summary(self) -> str:
        where = f"IN:{self.where[0]} / OUT:{self.where[1]}" if self.where else "IN:- / OUT:-"
        if self.mismatch is not None:
            verdict = "structure differs"
        elif self.max_deviation > self.tolerance:
            verdict = f"exceeds tolerance {self.tolerance:g} mm"
        elif self.chord_deviation > (self.chord_tolerance or 0.0) + self.tolerance:
            verdict = f"a chord lies beyond the chord tolerance {self.chord_tolerance:g} mm of its arc"
        elif self.left_out_moves and not self.allow_ignored:
            verdict = "settings that move the tool differ (listed below; --allow-ignored accepts them)"
        elif self.left_out_moves:
            verdict = "ok, with settings that move the tool left out (--allow-ignored)"
        else:
            verdict = "ok"
        text = f"max deviation {self.max_deviation:.4f} mm over {self.moves} moves ({where}): {verdict}"
        if self.chord_tolerance is not None:
            at = f"IN:{self.chord_where[0]} / OUT:{self.chord_where[1]}" if self.chord_where else "IN:- / OUT:-"
            text += f"\nchords at most {self.chord_deviation:.4f} mm from their arcs ({at}; --arcs lines:{self.chord_tolerance:g})"
        if self.mismatch is not None:
            a, b = self.mismatch_at
            text += (f"\nfirst difference at IN:{'-' if a is None else a} / OUT:{'-' if b is None else b}: "
                     f"{self.mismatch}")
        for line in self.lost:
            text += f"\nlost: {line}"
        if self.ignored:
            text += "\nnot compared:\n" + "\n".join(f"  {line}" for line in self.ignored)
        return text


# -- distances -------------------------------------------------------------------------------------

def _dist(a: dict[str, float], b: dict[str, float]) -> float:
    """Euclidean distance over ``a``'s axes (``math.hypot`` scales: no overflow near the float range; it is
    ``math.dist``'s norm of the same differences, without the two lists of coordinates)."""
    return _hypot(*[a[k] - b.get(k, 0.0) for k in a])


# -- comparing -------------------------------------------------------------------------------------

def describe(item: Move | Event) -> str:
    """A short human description of a move or event, for mismatch messages."""
    if isinstance(item, Move):
        where = " ".join(f"{k.upper()}{v:.4f}".rstrip("0").rstrip(".") for k, v in item.end.items())
        feed = "" if item.f is None else f" F{item.f:g}"
        name = {"rapid": "rapid", "feed": "feed", "cw": "cw arc", "ccw": "ccw arc"}.get(item.kind, item.kind)
        return f"a {name} to {where}{feed}"
    kind = item.get("event")
    if kind == "dwell":
        return f"a dwell of {item.get('seconds')} s"
    if kind == "spindle":
        return f"spindle {item.get('dir')}"
    if kind == "orient":
        return f"a spindle orientation to {item.get('angle')} deg"
    if kind == "tool":
        number = item.get("number")
        return "a tool change with no tool selected" if number is None else f"tool change to T{number}"
    if kind == "coolant":
        return f"coolant {'on' if item.get('on') else 'off'}"
    if kind == "stop":
        return "an optional stop" if item.get("optional") else "a program stop"
    if kind == "end":
        return "the program end"
    if kind == FEED_MODE_EVENT:
        mode = item.get("mode")
        return f"feed {'per revolution' if mode == 'per_rev' else 'per minute' if mode == 'per_min' else mode} from here"
    return f"event {kind}"


def _line(item: Move | Event | None) -> int | None:
    if item is None:
        return None
    return item.first_line if isinstance(item, Move) else item.get("line")


def _same_event(a: Event, b: Event) -> bool:
    keys = (set(a) | set(b)) - {"line"}
    for k in keys:
        x, y = a.get(k), b.get(k)
        if isinstance(x, (int, float)) and isinstance(y, (int, float)) and not isinstance(x, bool):
            if abs(x - y) > EVENT_TOLERANCE:
                return False
        elif x != y:
            return False
    return True


def compare(events_in: Iterable[Event | MoveRecord], events_out: Iterable[Event | MoveRecord], *, start_in: dict[str, float],
            start_out: dict[str, float], tolerance: float, chord_tolerance: float | None = None,
            mapped: dict[str, str] | None = None) -> Report:
    """Walk two toolpaths (each with its header first) and report their largest deviation.
    ``chord_tolerance``: OUT may cut IN's arcs into chords within it (``postproc.simulate.chords``).
    ``mapped``: IN's machine-specific code -> what the target set-up's ``<ForeignCodes>`` makes of it
    (``compare_machine_codes``)."""
    report = Report(tolerance, chord_tolerance=chord_tolerance)
    # feeds compared per minute: an inverse-time program and its translation for a target without G93
    # the paths compared are the controlled ones (``_controlled``): ``normalise`` reads a move's controlled
    # point in place, ``per_minute_from_first`` and ``_as_radius`` take it where they change the event
    it_in: Iterator[Event | MoveRecord] = FeedModes(per_minute_from_first(iter(events_in), start_in))
    it_out: Iterator[Event | MoveRecord] = FeedModes(per_minute_from_first(iter(events_out), start_out))
    head_in, head_out = _event(next(it_in, {})), _event(next(it_out, {}))  # (a header is a dictionary)
    modes = (head_in.get("x_mode"), head_out.get("x_mode"))
    if modes[0] != modes[1] or (chord_tolerance is not None and "diameter" in modes):
        # a diameter program and its radius translation: compare both as radii (true geometry); chords
        # are checked against their arc in true geometry too (a diameter stretches the arc into an ellipse)
        it_in, it_out = _as_radius(it_in, head_in), _as_radius(it_out, head_out)
        head_in = {k: v for k, v in head_in.items() if k != "x_mode"}
        head_out = {k: v for k, v in head_out.items() if k != "x_mode"}
    for key in ("units", "x_mode", "feed_mode"):
        if head_in.get(key) != head_out.get(key):
            report.mismatch = f"the toolpath headers differ in {key}: {head_in.get(key)} vs {head_out.get(key)}"
            report.mismatch_at = (1, 1)
    eps = tolerance / 2.0
    codes_in: list[Event] = []
    codes_out: list[Event] = []
    ins, outs = Normaliser(it_in, start_in, eps, codes_in), Normaliser(it_out, start_out, eps, codes_out)
    if chord_tolerance is None:  # pulled pair by pair: ``zip_longest`` of the two, without a tuple a pair
        while True:
            a, b = ins.pull(), outs.pull()
            if a is None and b is None:
                break
            if report.mismatch is None:  # else drain both streams: a program error still has to surface
                _pair(a, b, report)
    else:
        for a, b in pair_with_chords(ins, outs, report):
            if report.mismatch is None:
                _pair(a, b, report)
    compare_machine_codes(report, codes_in, codes_out, mapped)
    if head_in.get("x_mode") == "diameter" and report.where_at is not None:  # both diameters: as radii
        report.where_at = tuple((x / 2.0, y, z) for x, y, z in report.where_at)  # type: ignore[assignment]
    return report


def per_minute_from_first(events: Iterator[Event | MoveRecord], start: dict[str, float]) -> Iterator[Event | MoveRecord]:
    """``per_minute(events, start)``, which converts the path from its first inverse-time feed on: until then
    the events pass as they are (``per_minute`` follows every move's end point, a dict of three floats a
    move, to know where an inverse-time move starts), and from there ``per_minute`` continues from the
    last move's end, where it would stand. A header in inverse time: ``per_minute`` from the start. What
    ``per_minute`` converts is the controlled path (``_controlled``); the events before pass with their
    controlled points as they are (``normalise`` reads them). ``tests/test_verify.py`` holds this to
    ``per_minute(_controlled(events))`` on random paths. An iterator object, not a generator (``PerMinute``)."""
    return PerMinute(events, start)


@mypyc_attr(allow_interpreted_subclasses=True)
class PerMinute(Pulled):
    """``per_minute_from_first``'s iterator: compiled, a generator keeps its locals in an object of its own, read
    and written at every resume; this keeps three fields. ``FeedModes`` pulls it (``Pulled``)."""

    def __init__(self, events: Iterator[Event | MoveRecord], start: dict[str, float]) -> None:
        self.events = events
        self.start = start
        self.head: Event | None = None
        """The header, until the first inverse-time feed (None before the first event, and after the switch)."""
        self.rest: Iterator[Event] | None = None
        """``per_minute``'s stream, from the first inverse-time feed on."""
        self.last: Event | MoveRecord | None = None
        """The last move passed as it is."""

    def pull(self) -> Event | MoveRecord | None:
        rest = self.rest
        if rest is not None:
            return pull_item(rest)
        head = self.head
        if head is None:
            first_item = pull_item(self.events)
            if first_item is None:
                return None
            head = _event(first_item)
            if head.get("feed_mode") == "inverse_time":
                self.rest = per_minute(_controlled(chain((head,), self.events)), self.start)
                return pull_item(self.rest)
            self.head = head
            return head
        ev = pull_item(self.events)  # (stepped natively: compiled, ``next`` is a builtin called through Python)
        if ev is None:
            return None
        mode = _feed_mode(ev)
        if mode is not None and mode == "inverse_time":  # (most moves state none: no string comparison)
            last = self.last
            converted: Iterator[Event] = per_minute(_controlled(chain((head, ev), self.events)),
                                                    self.start if last is None else _resolved(last))
            next(converted)  # the header, already given
            self.rest = converted
            first: Event = next(converted)
            return first
        if isinstance(ev, MoveRecord) or "move" in ev:  # (a record is a move: ``postproc.simulate.move_record``)
            self.last = ev
        return ev


FEED_MODE_EVENT: Final = "feed mode"
"""The event ``FeedModes`` puts before a feed move whose feed mode is not the one before it."""


@mypyc_attr(allow_interpreted_subclasses=True)
class FeedModes(Pulled):
    """A toolpath with a ``feed mode`` event before each feed move whose feed mode (per minute, per revolution) is
    not the previous feed move's, so that the comparison sees a mode change as it sees a spindle or coolant
    event: a move states its mode only where it is not the header's, and a normalised ``Move`` keeps its F but
    not its mode. Without it a translation that lost a change of feed mode in mid-program (a Fanuc T ``G98`` before
    ``F100.``) compared equal: F100 per revolution where the source feeds 100 mm/min (issue 29 audit). The header
    passes first (its mode is compared as a header field); rapids state no mode and change none. After
    ``per_minute_from_first``: inverse-time feeds are per minute by then. An iterator object: one more step an
    event, no generator frame (``PerMinute``), pulled by ``Normaliser`` (``Pulled``)."""

    def __init__(self, events: Iterator[Event | MoveRecord]) -> None:
        self.events = events
        self.source: Pulled | None = events if isinstance(events, Pulled) else None
        """``events`` where it is ``Pulled`` (``PerMinute``): stepped by its ``pull``."""
        self.started = False
        """The header has passed."""
        self.header = "per_min"
        """The header's feed mode (per minute where it states none): a feed move that states none is in it."""
        self.stated: str | None = None
        """The mode the last feed move stated (None: the header's, which a move does not state)."""
        self.pending: Event | MoveRecord | None = None
        """The feed move after the event just given."""

    def pull(self) -> Event | MoveRecord | None:
        pending = self.pending
        if pending is not None:
            self.pending = None
            return pending
        source = self.source
        item = source.pull() if source is not None else pull_item(self.events)
        if item is None:
            return None
        if not self.started:
            self.started = True
            head = _event(item)
            self.header = str(head.get("feed_mode") or "per_min")
            return item
        mode = _feed_mode(item)
        stated = self.stated
        if mode is not stated and mode != stated:  # (most moves state none, as the one before: no event, no look at
            # F; identity first: compiled, ``!=`` of None and None was Python's rich comparison, ~90 instructions)
            if isinstance(item, MoveRecord):
                line: Any = item.line
                feeds = item.f is not None
            else:
                line = item.get("line")
                feeds = "move" in item and item.get("f") is not None
            if feeds:
                self.stated = mode
                self.pending = item
                return {"line": line, "event": FEED_MODE_EVENT, "mode": self.header if mode is None else mode}
        return item


def _event(item: Event | MoveRecord) -> Event:
    """An event as its dictionary (``MoveRecord.event``)."""
    return item.event() if isinstance(item, MoveRecord) else item


def _feed_mode(item: Event | MoveRecord) -> Any:
    """An event's ``feed_mode`` (None: it states none), a record's by field."""
    return item.feed_mode if isinstance(item, MoveRecord) else item.get("feed_mode")


def _controlled(events: Iterator[Event | MoveRecord]) -> Iterator[Event]:
    """The path the machine runs: a move's controlled point (tool length, cutter radius) in place of its
    programmed one, so a program that offsets the tool and one that writes the offset path compare equal."""
    for ev in events:
        yield _resolved(ev)


def _resolved(item: Event | MoveRecord) -> Event:
    """An event with its controlled point in place of its programmed one (``_controlled``)."""
    ev = _event(item)
    controlled = ev.get("controlled")
    if controlled is None:
        return ev
    moved = dict(ev)  # the keys in their order: the controlled axes replace the programmed ones
    del moved["controlled"]
    moved.update(controlled)
    return moved


def compare_machine_codes(report: Report, codes_in: list[Event], codes_out: list[Event],
                          mapped: dict[str, str] | None = None) -> None:
    """List each machine-specific code of either program: how often each side has it, from which line. A code
    of IN the target set-up maps (``mapped``: code -> the target's code, or ``omit``) is compared instead: the
    codes it became must be OUT's in the same order (else the structure differs), and an omitted one is listed
    as omitted by the set-up, never taken as equal."""
    mapped = mapped or {}
    expected = [(ev["line"], mapped[ev["code"]]) for ev in codes_in if mapped.get(ev["code"], OMIT) != OMIT]
    targets = {to for to in mapped.values() if to != OMIT}
    found = [(ev["line"], str(ev["code"])) for ev in codes_out if ev["code"] in targets]
    if expected or found:
        if [to for _, to in expected] != [code for _, code in found]:
            at = next((n for n in range(min(len(expected), len(found))) if expected[n][1] != found[n][1]),
                      min(len(expected), len(found)))
            report.mismatch = report.mismatch or (
                f"the machine codes the set-up's <ForeignCodes> maps differ: IN's become "
                f"{_sequence([to for _, to in expected])}, OUT has {_sequence([code for _, code in found])}")
            if report.mismatch_at == (None, None):
                report.mismatch_at = (expected[at][0] if at < len(expected) else None,
                                      found[at][0] if at < len(found) else None)
    seen: dict[str, tuple[str, list[int], list[int]]] = {}
    for side, events in ((1, codes_in), (2, codes_out)):
        for ev in events:
            if side == 2 and ev["code"] in targets:
                continue
            name, lines_in, lines_out = seen.setdefault(ev["code"], (ev.get("name", ""), [], []))
            (lines_in if side == 1 else lines_out).append(ev["line"])
    for code, (name, lines_in, lines_out) in seen.items():
        what = f"{code} ({name})" if name else code
        to = mapped.get(code)
        if to == OMIT:
            report.ignored.append(f"{what}, a machine-specific code omitted by the set-up (<ForeignCodes>): "
                                  f"{_count(lines_in, 'IN')}, {_count(lines_out, 'OUT')}")
        elif to is not None:
            report.notes.append(f"{what} became {to} by the set-up (<ForeignCodes>): compared, "
                                f"{_count(lines_in, 'IN')}")
        else:
            report.ignored.append(f"{what}, a machine-specific code: {_count(lines_in, 'IN')}, "
                                  f"{_count(lines_out, 'OUT')}")


def _sequence(codes: list[str]) -> str:
    return " ".join(codes[:6]) + (" ..." if len(codes) > 6 else "") if codes else "none"


def _count(lines: list[int], side: str) -> str:
    if not lines:
        return f"{side} none"
    return f"{side} {len(lines)}x from line {lines[0]}"


def compare_settings(report: Report, settings_in: list[tuple[int, str, str]],
                     settings_out: list[tuple[int, str, str]]) -> None:
    """Compare the changes of the settings the simulation does not apply, setting by setting: the same
    sequence on both sides is a note when the setting moves the tool; a different one is listed, and
    fails the comparison when the setting moves the tool (unless ``--allow-ignored``)."""
    kinds = list(dict.fromkeys(kind for _, kind, _ in settings_in + settings_out))
    for kind in kinds:
        a = [(line, value) for line, k, value in settings_in if k == kind]
        b = [(line, value) for line, k, value in settings_out if k == kind]
        if [v for _, v in a] == [v for _, v in b]:
            if kind in MOVES_THE_TOOL:  # the paths compared are the programmed ones, not those cut
                report.ignored.append(f"{kind}: not simulated, the same on both sides ({_values(a)})")
            continue
        report.ignored.append(f"{kind} differs: IN {_values(a) or 'never set'}; OUT {_values(b) or 'never set'}")
        if kind in MOVES_THE_TOOL:
            report.left_out_moves = True


def _values(changes: list[tuple[int, str]], most: int = 4) -> str:
    text = ", ".join(f"{value} (line {line})" for line, value in changes[:most])
    return text + (f", ... {len(changes) - most} more" if len(changes) > most else "")
def _as_radius(events: Iterator[Event | MoveRecord], head: Event) -> Iterator[Event | MoveRecord]:
    """The events of a toolpath whose x is a diameter (``x_mode``), with x and cx as radii (of the controlled
    point: ``_controlled``)."""
    if head.get("x_mode") != "diameter":
        yield from events
        return
    for ev in events:
        ev = _resolved(ev)
        if "x" in ev or "cx" in ev:
            ev = dict(ev)
            for key in ("x", "cx"):
                if key in ev:
                    ev[key] = ev[key] / 2.0
        yield ev


def _pair(a: Move | Event | None, b: Move | Event | None, report: Report) -> None:
    """Compare a pair (``_differ``); the first structural difference is the report's mismatch."""
    problem = _differ(a, b, report)
    if problem is not None:
        report.mismatch = problem
        report.mismatch_at = (_line(a), _line(b))


def _differ(a: Move | Event | None, b: Move | Event | None, report: Report) -> str | None:
    """Record the deviation of a pair; return a description when they differ in structure."""
    if a is None:
        if _is_end(b):
            return None  # IN ends by running out there, OUT says so (M2: LinuxCNC refuses a file without one)
        return f"IN has no more moves or events, OUT has {describe(b)}"  # type: ignore[arg-type]
    if b is None:  # an end OUT lacks is a difference: M2/M30 stop the spindle and coolant, running out does not
        return f"OUT has no more moves or events, IN has {describe(a)}"
    if not isinstance(a, Move) or not isinstance(b, Move):
        if isinstance(a, Move) or isinstance(b, Move) or not _same_event(a, b):
            return f"IN has {describe(a)}, OUT {describe(b)}"
        return None
    if a.kind != b.kind or a.plane is not b.plane and a.plane != b.plane:  # (identity first: two straight moves' None)
        return f"IN has {describe(a)}, OUT {describe(b)}"
    if not _same_feed(a.f, b.f):
        return f"IN feeds at F{a.f:g}, OUT at F{b.f:g} ({describe(a)})"
    a_keys, a_end, b_keys, b_end = a.end_keys, a.end_values, b.end_keys, b.end_values
    steps = report.steps  # the axes both have (math.dist's norm)
    steps.clear()
    if a_keys is report.keys_in and b_keys is report.keys_out:
        same = report.same_keys
    else:
        same = a_keys == b_keys
        report.keys_in, report.keys_out, report.same_keys = a_keys, b_keys, same
    for i in range(len(a_keys)):
        j = i if same else key_index(b_keys, a_keys[i], i)
        if j >= 0:
            steps.add(a_end[i] - b_end[j])
    d0, d1, d2, n, more = steps.d0, steps.d1, steps.d2, steps.n, steps.more
    report.moves += 1
    if report.where is not None and (a.centre is None or b.centre is None) \
            and not beyond(d0, d1, d2, n, more, report.max_deviation):
        return None  # no further apart than the pair furthest apart so far (measured only where it is)
    apart = [d0, d1, d2][:n] if more is None else [d0, d1, d2, *more]
    dev = norm(apart)
    if a.centre is not None and b.centre is not None and (a.centre != b.centre or abs(a.sweep - b.sweep) >= _HALF_TURN):
        # two controllers' paths for the arc (each centre where its own rule puts it): the largest distance
        # between them (``postproc.geometry.arc_paths``), decided by a bound where it cannot exceed the largest so far;
        # about one centre, turning within half a turn of each other, the paths lie apart at most as far as
        # their ends (radii and angles change evenly; the start's distance is the pair before's end's)
        dev = max(dev, arc_deviation(a, b, report.max_deviation if report.where is not None else -1.0))
    if report.where is None or dev > report.max_deviation:
        report.max_deviation = dev
        report.where = (a.last_line, b.last_line)
        report.where_at = (_xyz(a_keys, a_end), _xyz(b_keys, b_end))
    return None


def _is_end(item: Move | Event | None) -> bool:
    """The program end event (M2/M30)."""
    return not isinstance(item, Move) and item is not None and item.get("event") == "end"


def _xyz(keys: tuple[str, ...], values: list[float]) -> Point:
    return point_value(keys, values, "x", 0), point_value(keys, values, "y", 1), point_value(keys, values, "z", 2)


def compare_after_end(report: Report, lines_in: list[int], lines_out: list[int]) -> None:
    """Live blocks after the program end run on a controller that is streamed to: the translation having
    them where the source has none is a structural mismatch (reported when nothing before differed).
    The reverse is the safe translation of dead code (written as comments), not a mismatch. Only their
    presence is compared: an expanded cycle there is one block in one file and several in the other."""
    if report.mismatch is not None or not lines_out or lines_in:
        return
    report.mismatch = (f"OUT has live blocks after the program end (from line {lines_out[0]}), IN has none "
                       "(a controller that is streamed to would run them)")
    report.mismatch_at = (None, lines_out[0])
