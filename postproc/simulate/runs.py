"""verify's normalising of a toolpath as it streams: moves merged into runs (consecutive straight moves of one
kind and feed that continue one line, arcs on one circle), machine events as they are. Compiled with the
comparison (``pyproject.toml [tool.postproc] compiled``): it reads every move event of both programs, so a
straight move that continues its run is merged without a ``Move`` of its own, its point is read by field (a
``MoveRecord``'s list, kept as it is where its values are floats), a point is a tuple of axis keys and a list of
floats in their order (``postproc.simulate.normal_move``), and the arithmetic keeps the first three axes in
unboxed locals (``tests/test_normalise_reference.py`` holds it to the code it replaced). ``Normaliser`` is pulled
a move at a time (``pull``), not a generator: compiled, a generator keeps every local in an object of its own,
read and written at each resume."""

from __future__ import annotations

import math
from typing import Any, Final, Iterable, Iterator, TypeVar

from mypy_extensions import mypyc_attr

from ..geometry.arcs import CENTRE_KEYS, PLANE_INDEX, arc_sweep
from .events import Event
from .move_record import MoveRecord
from .normal_move import Move, same_feed as _same_feed

_hypot: Final = math.hypot
"""Compiled, ``math.hypot`` is an attribute look-up on the module each call; a Final is a C static."""

_AXIS_KEYS: Final = frozenset("xyzabcuvw")
_AXIS_BITS: Final = 0x3f00007  # bit n: chr(ord("a") + n) is in _AXIS_KEYS (a, b, c, u, v, w, x, y, z)
assert _AXIS_BITS == sum(1 << (ord(k) - 97) for k in _AXIS_KEYS)

Keys = tuple[str, ...]


def _is_axis(k: str) -> bool:
    """``k in _AXIS_KEYS`` by the letter's bit: compiled, ``ord`` and a shift are a few instructions where a
    frozenset look-up is a call through Python's set (~125 instructions, four an event in ``_event_point``)."""
    if len(k) != 1:
        return False
    n = ord(k) - 97
    return 0 <= n < 26 and (_AXIS_BITS >> n) & 1 == 1


# -- points: axis keys and their values ------------------------------------------------------------

def key_index(keys: Keys, k: str, hint: int) -> int:
    """Where ``k`` stands in ``keys`` (-1: not there), looked for at ``hint`` first: the points of one simulation
    share their keys, so a key stands where it stood in the other point."""
    if hint < len(keys) and keys[hint] == k:
        return hint
    for i in range(len(keys)):
        if keys[i] == k:
            return i
    return -1


def point_value(keys: Keys, values: list[float], k: str, hint: int) -> float:
    """The value of ``k`` in a point (0.0 where it has none: an axis a point lacks counts from 0)."""
    i = key_index(keys, k, hint)
    return values[i] if i >= 0 else 0.0


def _floats(values: list[float | int]) -> list[float]:
    """A record's values as floats: the list itself where every value is one (a record's lists are never
    changed: ``postproc.simulate.move_record``), else a copy with each int converted."""
    for v in values:
        if not isinstance(v, float):
            return [_real(x) for x in values]
    return values


def _record_point(record: MoveRecord, all_axes: bool) -> tuple[Keys, list[float]]:
    """The end point of a straight move's record: its controlled point where it has one, read by field. Its keys are
    the machine's axes, each in both points. ``all_axes``: every key is an axis key (``_all_axes`` of the record's
    keys, one tuple a simulation: tested once, not a key a move)."""
    controlled = record.controlled
    values = record.point if controlled is None else controlled
    if all_axes:
        return record.keys, _floats(values)
    keys: list[str] = []
    floats: list[float] = []
    record_keys = record.keys
    for i in range(len(record_keys)):
        k = record_keys[i]
        if _is_axis(k):
            keys.append(k)
            floats.append(_real(values[i]))
    return tuple(keys), floats


def _event_point(ev: Event, controlled: Event | None) -> tuple[Keys, list[float]]:
    """The end point of a move event, in its order (the machine's axes): its controlled point where it has
    one, as ``compare._controlled`` gives it (the controlled axes replace the programmed ones in place, any other
    follows). A number is converted as its type: compiled, ``float(v)`` of a value of unknown type is a call
    of the builtin through Python (~250 instructions)."""
    keys: list[str] = []
    values: list[float] = []
    matched = 0
    for k, v in ev.items():
        if _is_axis(k):
            c = None if controlled is None else controlled.get(k)
            if c is None:
                x = _real(v)
            else:
                x = _real(c)
                matched += 1
            keys.append(k)
            values.append(x)
    if controlled is not None and matched != len(controlled):  # an arc's centre, or an axis the programmed
        for k, c in controlled.items():                        # point does not name
            if _is_axis(k) and k not in keys:
                keys.append(k)
                values.append(_real(c))
    return tuple(keys), values


def _all_axes(keys: Keys) -> bool:
    """Every key of a record's keys is an axis key."""
    for k in keys:
        if not _is_axis(k):
            return False
    return True


def _real(v: Any) -> float:
    """``float(v)`` of a toolpath's number, an int or a float mostly."""
    if isinstance(v, float):
        return v
    if isinstance(v, int):
        return float(v)
    return float(v)


def _plane_point(keys: Keys, values: list[float], plane: str) -> tuple[float, float]:
    i, j, _ = PLANE_INDEX[plane]
    return point_value(keys, values, "xyz"[i], i), point_value(keys, values, "xyz"[j], j)


def norm(values: list[float]) -> float:
    """``math.hypot(*values)`` (it scales: no overflow near the float range). Compiled, a call of a fixed number
    of arguments is a vector call, where ``*`` of a list builds a tuple and calls through Python (~450
    instructions more)."""
    n = len(values)
    if n == 3:
        return _hypot(values[0], values[1], values[2])
    if n == 2:
        return _hypot(values[0], values[1])
    return _hypot(*values)


def _norm(a: float, b: float, c: float, n: int, rest: list[float] | None) -> float:
    """``norm`` of ``n`` components held as ``beyond``'s are (``a``, ``b``, ``c`` the first three, ``rest`` those
    after the third)."""
    if rest is not None:
        return _hypot(a, b, c, *rest)
    if n == 3:
        return _hypot(a, b, c)
    if n == 2:
        return _hypot(a, b)
    if n == 1:
        return _hypot(a)
    return 0.0


def beyond(a: float, b: float, c: float, n: int, rest: list[float] | None, limit: float) -> bool:
    """``math.hypot(*components) > limit`` of ``n`` components (``a``, ``b``, ``c`` the first three, 0.0 where
    there are fewer; ``rest`` those after the third), exactly: the plain sum of squares decides where it lies
    more than a millionth of ``limit``'s square from it (it is within a few ulps of the true square: the
    answer cannot differ there), ``hypot`` only in between or where the sum overflows, underflows or is not a
    number (compiled, ``hypot`` is a call through Python, ~850 instructions, where the squares are a few)."""
    q = a * a + b * b + c * c
    if rest is not None:
        for v in rest:
            q += v * v
    square = limit * limit
    if q > square * 1.000001 and q < _INF:
        return True
    if q < square * 0.999999 and q > 0.0:
        return False
    if rest is None and a == 0.0 and b == 0.0 and c == 0.0:  # two points that agree exactly (a translation that
        return 0.0 > limit                                   # writes the source's numbers): no call of hypot
    if rest is not None:
        return _hypot(a, b, c, *rest) > limit
    if n == 3:
        return _hypot(a, b, c) > limit
    if n == 2:
        return _hypot(a, b) > limit
    return (_hypot(a) if n == 1 else 0.0) > limit


_INF: Final = math.inf


# -- moves -----------------------------------------------------------------------------------------

def _arc(ev: Event, start_keys: Keys, start: list[float]) -> Move:
    """An arc event as a ``Move`` from ``start``: its end and centre the controlled ones where it has them
    (``compare._controlled``, read in place), its plane, radius and sweep."""
    controlled: Event | None = ev.get("controlled")
    f = ev.get("f")
    keys, end = _event_point(ev, controlled)
    plane = ev.get("plane", "XY")
    i, j, _ = PLANE_INDEX[plane]
    ci, cj = CENTRE_KEYS["XYZ"[i]], CENTRE_KEYS["XYZ"[j]]
    s = _plane_point(start_keys, start, plane)
    ui: Any = ev.get(ci, s[0])
    uj: Any = ev.get(cj, s[1])
    if controlled is not None:
        ui, uj = controlled.get(ci, ui), controlled.get(cj, uj)
    return _arc_move(ev["move"], None if f is None else _real(f), ev["line"], start_keys, start, keys, end, plane,
                     s, (float(ui), float(uj)))


def _arc_record(record: MoveRecord, all_axes: bool, start_keys: Keys, start: list[float]) -> Move:
    """``_arc`` of an arc's record, read by field rather than as its event (``MoveRecord.event``, a dictionary of
    a dozen keys built and taken apart again: ~8k instructions an arc a side): the same ``Move``, to the bit
    (``tests/test_verify_arc_records.py`` holds the two to each other). The centre is the controlled one where
    the record has it (``ccentre``), else the programmed one, as the event's ``controlled`` gives it."""
    keys, end = _record_point(record, all_axes)
    plane = record.plane if record.plane is not None else "XY"
    i, j, _ = PLANE_INDEX[plane]
    s = _plane_point(start_keys, start, plane)
    centre_keys = record.centre_keys
    centre = record.ccentre if record.controlled is not None and record.ccentre is not None else record.centre
    ui = _centre_value(centre_keys, centre, CENTRE_KEYS["XYZ"[i]], s[0])
    uj = _centre_value(centre_keys, centre, CENTRE_KEYS["XYZ"[j]], s[1])
    f = record.f
    return _arc_move(record.kind, None if f is None else _real(f), record.line, start_keys, start, keys, end, plane,
                     s, (ui, uj))


def _centre_value(keys: Keys, values: list[float | int] | None, k: str, default: float) -> float:
    """A centre coordinate of a record (``default``, the start's, where it has none: as ``_arc`` reads an event)."""
    if values is not None:
        for n in range(len(keys)):
            if keys[n] == k:
                return _real(values[n])
    return default


def _arc_move(kind: str, f: float | None, line: int, start_keys: Keys, start: list[float], keys: Keys,
              end: list[float], plane: str, s: tuple[float, float], c: tuple[float, float]) -> Move:
    """An arc as a ``Move`` (``_arc``, ``_arc_record``): from ``start`` (``s`` its point in the plane) to ``end``
    about ``c``; its radius and sweep."""
    m = Move(kind, None, None, f, line, line)
    m.start_keys, m.start_values, m.end_keys, m.end_values = start_keys, start, keys, end
    e = _plane_point(keys, end, plane)
    m.plane, m.centre = plane, c
    m.radius = _hypot(s[0] - c[0], s[1] - c[1])
    m.sweep = arc_sweep(s, e, c, kind == "cw")
    return m


NO_STEPS: Final[list[float]] = []
"""No steps after the third axis (``_straight``'s list where there are none; never changed)."""


def _straight(kind: str, start_keys: Keys, start: list[float], keys: Keys, end: list[float], f: float | None,
              line: int, d0: float, d1: float, d2: float, more: list[float] | None, length: float) -> Move:
    """A straight move of ``length`` (the norm of its steps ``d0``, ``d1``, ``d2`` and ``more``, axis by axis in the
    order of ``keys``) as a ``Move``: its direction, and how far along it its end lies (``Move.along``, which a
    continuing move must pass: ``_extends``)."""
    m = Move(kind, None, None, f, line, line)
    m.start_keys, m.start_values, m.end_keys, m.end_values = start_keys, start, keys, end
    m.length = length
    if length > 0:
        n = len(keys)
        unit: list[float] = []  # (appended: compiled, ``[0.0] * n`` is a list repeated through Python, ~200 more)
        rest: list[float] = more if more is not None else NO_STEPS
        along = 0.0
        for i in range(n):
            # a float local, each step unboxed: compiled, the conditional of a list's item was an object and
            # its division, product and sum three generic calls (~300 instructions an axis)
            step: float = d0 if i == 0 else d1 if i == 1 else d2 if i == 2 else rest[i - 3]
            uk = step / length
            unit.append(uk)
            along += step * uk
        m.unit_keys, m.unit = keys, unit
        m.along = along
    return m


def _merge(run: Move, m: Move, eps: float) -> bool:
    """Extend ``run`` by ``m`` when they are one line or one circle (same kind and feed)."""
    if m.kind != run.kind or not _same_feed(run.f, m.f):
        return False
    if run.unit is not None and m.unit is not None:
        return _extends(run, m.end_keys, m.end_values, m.last_line, eps)
    return merge_arc(run, m, eps)


def merge_arc(run: Move, m: Move, eps: float) -> bool:
    """Extend the arc run ``run`` by the arc ``m`` (same kind and feed: the caller checked) when they are one
    circle: their centres and start radii within ``eps``, or else the path of the one that sweeps less within
    ``eps`` of the other's circle (``_off_circle``; a run that sweeps less takes ``m``'s centre); and the axes
    outside the plane moving at one rate per angle (``_one_helix``). Why the path too: a controller that moves a
    tiny arc's centre onto its chord's bisector (ISG, Fagor: ``postproc.geometry.arc_end``) cuts the other's circle within
    a micron with a centre a micron or more away, so by centres alone one side of a comparison merged a helix the
    other split and verify said the structure differs (issue 26: a CamBam helical bore, the 0.012 mm arc where
    each turn meets the next, towards ISG and Fagor; ``tests/test_verify_arc_runs.py``)."""
    if run.centre is None or m.centre is None or run.plane != m.plane:
        return False
    recentre = False
    if _hypot(run.centre[0] - m.centre[0], run.centre[1] - m.centre[1]) > eps or abs(run.radius - m.radius) > eps:
        if m.sweep <= run.sweep:
            if _off_circle(m, run.centre, run.radius) > eps:
                return False
        elif _off_circle(run, m.centre, m.radius) > eps:
            return False
        else:
            recentre = True
    if not _one_helix(run, m, eps):
        return False
    if recentre:
        _recentre(run, m.centre)
    run.end_keys, run.end_values, run.last_line = m.end_keys, m.end_values, m.last_line
    run.sweep += m.sweep
    return True


_TWO_PI: Final = 2.0 * math.pi


def _off_circle(a: Move, c: tuple[float, float], r: float) -> float:
    """How far the arc ``a``'s path (from its start about its centre through its sweep, the radius changing evenly
    with the angle from the start radius to the end radius, as the simulator draws it) strays from the circle
    about ``c`` of radius ``r``, in the plane: the largest at its ends and where it points along the line of the
    two centres (the distance from ``c`` is extreme there, up to the radius's slope: a move within ``eps`` of a
    circle changes its radius by far less than its centre is off)."""
    plane = a.plane or "XY"
    ac = a.centre
    assert ac is not None
    s, e = _plane_point(a.start_keys, a.start_values, plane), _plane_point(a.end_keys, a.end_values, plane)
    worst = max(abs(_hypot(s[0] - c[0], s[1] - c[1]) - r), abs(_hypot(e[0] - c[0], e[1] - c[1]) - r))
    dx, dy = ac[0] - c[0], ac[1] - c[1]
    if (dx == 0.0 and dy == 0.0) or a.sweep <= 0.0:
        return worst
    r0, r1 = a.radius, _hypot(e[0] - ac[0], e[1] - ac[1])
    a0 = math.atan2(s[1] - ac[1], s[0] - ac[0])
    sign = -1.0 if a.kind == "cw" else 1.0
    phi = math.atan2(dy, dx)
    for base in (phi, phi + math.pi):
        t = ((base - a0) * sign) % _TWO_PI  # the angle from the start, the way the arc turns
        while t < a.sweep:
            rho = r0 + (r1 - r0) * t / a.sweep
            theta = a0 + sign * t
            worst = max(worst, abs(_hypot(ac[0] + rho * math.cos(theta) - c[0],
                                          ac[1] + rho * math.sin(theta) - c[1]) - r))
            t += _TWO_PI
    return worst


def _recentre(run: Move, c: tuple[float, float]) -> None:
    """The run about the centre ``c`` of the arc that continues it: its start radius and its sweep measured about
    ``c`` (the whole turns it made kept)."""
    plane = run.plane or "XY"
    s, e = _plane_point(run.start_keys, run.start_values, plane), _plane_point(run.end_keys, run.end_values, plane)
    base = arc_sweep(s, e, c, run.kind == "cw")
    run.sweep = base + round((run.sweep - base) / _TWO_PI) * _TWO_PI
    run.centre = c
    run.radius = _hypot(s[0] - c[0], s[1] - c[1])


def _extends(run: Move, keys: Keys, end: list[float], line: int, eps: float) -> bool:
    """Extend the straight run ``run`` to ``end`` (a straight move of its kind and feed, ending on ``line``) when
    that lies on its line (within ``eps``) and further along it than the run's end (``Move.along``). The first
    three axes are held in locals (compiled, unboxed floats: a list boxes each), any further one in a list."""
    u, ukeys = run.unit, run.unit_keys
    s, skeys = run.start_values, run.start_keys
    assert u is not None
    n = 0
    r0 = r1 = r2 = u0 = u1 = u2 = 0.0
    more: list[float] | None = None  # (the end from the run's start, the direction) of each axis after the third
    along = 0.0
    same = len(keys) == len(ukeys)  # the run's own axes (those of every move of a simulation)
    shared = keys is skeys and keys is ukeys  # one tuple a simulation: each key at its own index, not looked for
    for i in range(len(keys)):
        r: float
        uk: float
        if shared:
            r = end[i] - s[i]
            uk = u[i]
        else:
            k = keys[i]
            r = end[i] - point_value(skeys, s, k, i)
            j = key_index(ukeys, k, i)
            if j < 0:
                uk = 0.0
                same = False
            else:
                uk = u[j]
        along += r * uk
        if n == 0:
            r0, u0 = r, uk
        elif n == 1:
            r1, u1 = r, uk
        elif n == 2:
            r2, u2 = r, uk
        else:
            if more is None:
                more = []
            more.append(r)
            more.append(uk)
        n += 1
    if along <= _along(run):
        return False
    off: list[float] | None = None  # the end from the line, on the axes after the third
    if more is not None:
        off = [more[i] - along * more[i + 1] for i in range(0, len(more), 2)]
    if beyond(r0 - along * u0, r1 - along * u1, r2 - along * u2, n, off, eps):
        return False
    run.end_keys, run.end_values, run.last_line = keys, end, line
    run.along = along if same else math.nan  # (nan: measured again, over the run's axes, when needed)
    return True


def _along(run: Move) -> float:
    """How far along its direction the straight run's end lies: ``Move.along``, or measured over the
    direction's axes where the run was extended by a move of other axes."""
    if run.along == run.along:
        return run.along
    u, ukeys = run.unit, run.unit_keys
    assert u is not None
    along = 0.0
    for i in range(len(ukeys)):
        k = ukeys[i]
        along += (point_value(run.end_keys, run.end_values, k, i) - point_value(run.start_keys, run.start_values, k, i)) * u[i]
    return along


def _one_helix(run: Move, m: Move, eps: float) -> bool:
    """True when the axes outside the plane move in ``m`` at the rate per angle they moved in ``run`` (none:
    a flat arc; the same: one helix, as an arc split into pieces), so the arcs may be joined."""
    i, j, _ = PLANE_INDEX[m.plane or "XY"]
    a1, a2 = "xyz"[i], "xyz"[j]
    keys, end = m.end_keys, m.end_values
    for n in range(len(keys)):
        k = keys[n]
        if k != a1 and k != a2:
            rate = (point_value(run.end_keys, run.end_values, k, n) - point_value(run.start_keys, run.start_values, k, n)) \
                / run.sweep
            if abs(end[n] - point_value(m.start_keys, m.start_values, k, n) - rate * m.sweep) > eps:
                return False
    return True


# -- the stream ------------------------------------------------------------------------------------

_Item = TypeVar("_Item")


def pull_item(events: Iterator[_Item]) -> _Item | None:
    """``next(events, None)`` (None: the stream ended), stepped natively: compiled, ``next`` is the builtin looked up
    by name and called through Python (~400 instructions an event), where a ``for`` loop's step calls the
    iterator's own slot (``postproc.lowering.lower.run_blocks`` says the same of its blocks). A stream never holds
    None."""
    for item in events:
        return item
    return None


@mypyc_attr(allow_interpreted_subclasses=True)
class Normaliser:
    """A toolpath's moves merged into runs, machine events as they are, pulled one at a time (``pull``; an
    iterator too); the header is skipped. A move ends at its controlled point where it has one
    (``compare._controlled``, read in place). ``codes``: the events of a machine-specific code (they carry
    ``code``) go there instead: another family has no such code, so they are listed, not compared
    (``compare_machine_codes``)."""

    def __init__(self, events: Iterator[Event | MoveRecord], start: dict[str, float], eps: float,
                 codes: list[Event] | None = None) -> None:
        self.events = events
        self.eps = eps
        self.codes = codes
        self.pos_keys: Keys = tuple(k.lower() for k in start)
        """Where the tool stands (the last move's end): its keys and values."""
        self.pos_values: list[float] = [float(v) for v in start.values()]
        self.run: Move | None = None
        """The run being merged (given when a move or an event does not continue it)."""
        self.pending: Event | None = None
        """A machine event met after the run, given at the next pull."""
        self.seen_keys: Keys | None = None
        """The records' keys met last (one tuple a simulation), and whether they are all axis keys."""
        self.all_axes = False
        self.pos3 = False
        """``pos_values`` held unboxed too (``p0``, ``p1``, ``p2``): a point of three axes whose keys tuple is the
        next move's (one tuple a simulation), whose steps are then taken without reading the start's list."""
        self.p0 = self.p1 = self.p2 = 0.0
        self.run3 = False
        """The run is a straight one of three axes in one keys tuple (its start's, its direction's): its start and
        direction held unboxed (``s0``.., ``u0``..), so a move that may continue it is tested without reading them
        from their lists (``_extends``, in ``pull``). False for an arc or any other run."""
        self.s0 = self.s1 = self.s2 = 0.0
        self.u0 = self.u1 = self.u2 = 0.0

    def __iter__(self) -> Normaliser:
        return self

    def __next__(self) -> Move | Event:
        item = self.pull()
        if item is None:
            raise StopIteration
        return item

    def pull(self) -> Move | Event | None:
        """The next run or machine event; None at the end (and after it)."""
        pending = self.pending
        if pending is not None:
            self.pending = None
            return pending
        events = self.events
        eps = self.eps
        while True:
            item = pull_item(events)
            if item is None:
                run = self.run
                self.run = None
                return run
            if isinstance(item, MoveRecord):  # a move, read by field
                kind = item.kind
                record_keys = item.keys
                if record_keys is not self.seen_keys:
                    self.seen_keys, self.all_axes = record_keys, _all_axes(record_keys)
                if item.centre is not None and (kind == "cw" or kind == "ccw"):  # an arc
                    m = _arc_record(item, self.all_axes, self.pos_keys, self.pos_values)
                    self.pos_keys, self.pos_values, self.pos3 = m.end_keys, m.end_values, False
                    run = self.run
                    if run is not None and _merge(run, m, eps):
                        continue
                    self.run, self.run3 = m, False
                    if run is not None:
                        return run
                    continue
                keys, end = _record_point(item, self.all_axes)
                raw_f: Any = item.f
                line = item.line
                ev: Event | None = None
            else:
                ev = item
                if "toolpath" in ev:
                    continue
                codes = self.codes
                if codes is not None and "code" in ev:
                    codes.append(ev)
                    continue
                if "move" not in ev:
                    run = self.run
                    if run is not None:
                        self.run = None
                        self.pending = ev
                        return run
                    return ev
                kind = ev["move"]
                if kind == "cw" or kind == "ccw":
                    m = _arc(ev, self.pos_keys, self.pos_values)
                    self.pos_keys, self.pos_values, self.pos3 = m.end_keys, m.end_values, False
                    run = self.run
                    if run is not None and _merge(run, m, eps):
                        continue
                    self.run, self.run3 = m, False
                    if run is not None:
                        return run
                    continue
                keys, end = _event_point(ev, ev.get("controlled"))
                raw_f = None
                line = 0
            # a straight move: merged into the run without a ``Move`` of its own where it continues it
            start_keys, start = self.pos_keys, self.pos_values
            n = len(keys)
            d0 = d1 = d2 = 0.0
            e0 = e1 = e2 = 0.0  # a point of three axes: its end, unboxed
            s0 = s1 = s2 = 0.0  # and its start, where it shares the end's keys tuple
            more: list[float] | None = None  # the steps after the third axis
            shared = keys is start_keys  # (one tuple a simulation: each key at its own index, not looked for)
            three = shared and n == 3
            if three:
                e0 = end[0]
                e1 = end[1]
                e2 = end[2]
                if self.pos3:
                    s0 = self.p0
                    s1 = self.p1
                    s2 = self.p2
                else:
                    s0 = start[0]
                    s1 = start[1]
                    s2 = start[2]
                d0 = e0 - s0
                d1 = e1 - s1
                d2 = e2 - s2
            else:
                for i in range(n):
                    d = end[i] - (start[i] if shared else point_value(start_keys, start, keys[i], i))
                    if i == 0:
                        d0 = d
                    elif i == 1:
                        d1 = d
                    elif i == 2:
                        d2 = d
                    else:
                        if more is None:
                            more = []
                        more.append(d)
            square = d0 * d0 + d1 * d1 + d2 * d2
            if more is not None:
                for d in more:
                    square += d * d
            length = -1.0  # (not measured yet: a plain sum of squares above 0 and finite says it is above 0)
            if not (0.0 < square < _INF):
                length = _norm(d0, d1, d2, n, more)
                if length == 0.0:
                    self._place(keys, end, three, e0, e1, e2)
                    continue
            self._place(keys, end, three, e0, e1, e2)
            if ev is not None:  # (read where the move is not dropped, as before the records)
                raw_f = ev.get("f")
                line = ev["line"]
            f = None if raw_f is None else _real(raw_f)
            run = self.run
            if run is not None and run.unit is not None and (length < 0.0 or length > 0.0) and kind == run.kind \
                    and _same_feed(run.f, f):
                if three and self.run3 and keys is run.start_keys:
                    # ``_extends`` of a run of the same three axes, its start and direction unboxed: the same
                    # arithmetic in the same order (``tests/test_runs_shared_keys.py`` holds it to the events')
                    u0 = self.u0
                    u1 = self.u1
                    u2 = self.u2
                    r0 = e0 - self.s0
                    r1 = e1 - self.s1
                    r2 = e2 - self.s2
                    along = 0.0
                    along += r0 * u0
                    along += r1 * u1
                    along += r2 * u2
                    if not (along <= _along(run)) and not beyond(r0 - along * u0, r1 - along * u1, r2 - along * u2, 3,
                                                                 None, eps):
                        run.end_keys, run.end_values, run.last_line = keys, end, line
                        run.along = along
                        continue
                elif _extends(run, keys, end, line, eps):
                    continue
            if length < 0.0:
                length = _norm(d0, d1, d2, n, more)
            new = _straight(kind, start_keys, start, keys, end, f, line, d0, d1, d2, more, length)
            self.run = new
            self.run3 = three and new.unit is not None
            if self.run3:  # (as ``_straight`` divides them)
                self.s0 = s0
                self.s1 = s1
                self.s2 = s2
                self.u0 = d0 / length
                self.u1 = d1 / length
                self.u2 = d2 / length
            if run is not None:
                return run

    def _place(self, keys: Keys, end: list[float], three: bool, e0: float, e1: float, e2: float) -> None:
        """The tool stands at ``end`` (``pos_keys``, ``pos_values``); a point of three axes in the records' keys
        tuple (``three``: ``e0``.. its values) is held unboxed too (``pos3``)."""
        self.pos_keys, self.pos_values = keys, end
        self.pos3 = three
        if three:
            self.p0 = e0
            self.p1 = e1
            self.p2 = e2


def normalise(events: Iterable[Event | MoveRecord], start: dict[str, float], eps: float,
              codes: list[Event] | None = None) -> Iterator[Move | Event]:
    """Moves merged into runs, machine events as they are (``Normaliser``, as an iterator)."""
    return Normaliser(iter(events), start, eps, codes)
