"""verify's normalising of a toolpath as it streams: moves merged into runs (consecutive straight moves of one
kind and feed that continue one line, arcs on one circle), machine events as they are. Compiled with the
comparison (``pyproject.toml [tool.postproc] compiled``): it reads every move event of both programs, so a
straight move that continues its run is merged without a ``Move`` of its own, and the arithmetic keeps the
first three axes in unboxed locals (``tests/test_normalise_reference.py`` holds it to the code it replaced)."""

from __future__ import annotations

import math
from typing import Any, Final, Iterable, Iterator

from ..geometry import CENTRE_KEYS, PLANE_INDEX, arc_sweep
from .events import Event
from .move_record import MoveRecord
from .normal_move import Move, same_feed as _same_feed

_hypot: Final = math.hypot
"""Compiled, ``math.hypot`` is an attribute look-up on the module each call; a Final is a C static."""

_AXIS_KEYS: Final = frozenset("xyzabcuvw")
_AXIS_BITS: Final = 0x3f00007  # bit n: chr(ord("a") + n) is in _AXIS_KEYS (a, b, c, u, v, w, x, y, z)
assert _AXIS_BITS == sum(1 << (ord(k) - 97) for k in _AXIS_KEYS)


def _is_axis(k: str) -> bool:
    """``k in _AXIS_KEYS`` by the letter's bit: compiled, ``ord`` and a shift are a few instructions where a
    frozenset look-up is a call through Python's set (~125 instructions, four an event in ``_axes``)."""
    if len(k) != 1:
        return False
    n = ord(k) - 97
    return 0 <= n < 26 and (_AXIS_BITS >> n) & 1 == 1


def _axes(ev: Event, controlled: Event | None, start: dict[str, float] | None = None,
          steps: list[float] | None = None) -> dict[str, float]:
    """The end point of a move event, in its order (the machine's axes): its controlled point where it has
    one, as ``compare._controlled`` gives it (the controlled axes replace the programmed ones in place, any other
    follows). A number is converted as its type: compiled, ``float(v)`` of a value of unknown type is a call
    of the builtin through Python (~250 instructions). ``steps``: receives ``end - start`` axis by axis in the
    same pass (a straight move's; an axis ``start`` lacks counts from 0)."""
    end: dict[str, float] = {}
    matched = 0
    for k, v in ev.items():
        if _is_axis(k):
            c = None if controlled is None else controlled.get(k)
            if c is None:
                x = _real(v)
            else:
                x = _real(c)
                matched += 1
            end[k] = x
            if steps is not None:
                steps.append(x - (0.0 if start is None else start.get(k, 0.0)))
    if controlled is not None and matched != len(controlled):  # an arc's centre, or an axis the programmed
        for k, c in controlled.items():                        # point does not name
            if _is_axis(k) and k not in end:
                x = _real(c)
                end[k] = x
                if steps is not None:
                    steps.append(x - (0.0 if start is None else start.get(k, 0.0)))
    return end


def _record_end(record: MoveRecord, start: dict[str, float], steps: list[float], all_axes: bool) -> dict[str, float]:
    """``_axes`` of a record's event (its controlled point where it has one), read by field: its keys are the
    machine's axes, each in both points; ``steps`` receives ``end - start`` axis by axis. ``all_axes``: every key
    is an axis key (``_all_axes`` of the record's keys, one tuple a simulation: tested once, not a key a move)."""
    end: dict[str, float] = {}
    keys = record.keys
    controlled = record.controlled
    values = record.point if controlled is None else controlled
    for i in range(len(keys)):
        k = keys[i]
        if all_axes or _is_axis(k):
            v = values[i]
            x = v if isinstance(v, float) else _real(v)
            end[k] = x
            steps.append(x - start.get(k, 0.0))
    return end


def _all_axes(keys: tuple[str, ...]) -> bool:
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


def _plane_point(p: dict[str, float], plane: str) -> tuple[float, float]:
    i, j, _ = PLANE_INDEX[plane]
    return p.get("xyz"[i], 0.0), p.get("xyz"[j], 0.0)


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
    if rest is not None:
        return _hypot(a, b, c, *rest) > limit
    if n == 3:
        return _hypot(a, b, c) > limit
    if n == 2:
        return _hypot(a, b) > limit
    return (_hypot(a) if n == 1 else 0.0) > limit


_INF: Final = math.inf


def _move(ev: Event, start: dict[str, float]) -> Move:
    """A move event as a ``Move`` from ``start``, its controlled point the end (``compare._controlled``, read in place:
    copying each event that has one was a dictionary a move)."""
    controlled: Event | None = ev.get("controlled")
    kind = ev["move"]
    f = ev.get("f")
    line = ev["line"]
    if kind == "cw" or kind == "ccw":
        return _arc(ev, kind, start, _axes(ev, controlled), None if f is None else _real(f), line, controlled)
    steps: list[float] = []
    end = _axes(ev, controlled, start, steps)
    return _straight(kind, start, end, None if f is None else _real(f), line, steps, norm(steps))


def _straight(kind: str, start: dict[str, float], end: dict[str, float], f: float | None, line: int, steps: list[float],
              length: float) -> Move:
    """A straight move of ``length`` (``norm(steps)``) as a ``Move``: its direction, and how far along it its end
    lies (``Move.along``, which a continuing move must pass: ``_extends``)."""
    m = Move(kind, start, end, f, line, line)
    m.length = length
    if length > 0:
        direction: dict[str, float] = {}
        along = 0.0
        i = 0
        for k in end:
            step = steps[i]
            uk = step / length
            direction[k] = uk
            along += step * uk
            i += 1
        m.direction = direction
        m.along = along
    return m


def _arc(ev: Event, kind: str, start: dict[str, float], end: dict[str, float], f: float | None, line: int,
         controlled: Event | None) -> Move:
    """An arc event as a ``Move``: its plane, centre (the controlled one where it has one), radius and sweep."""
    m = Move(kind, start, end, f, line, line)
    plane = ev.get("plane", "XY")
    i, j, _ = PLANE_INDEX[plane]
    ci, cj = CENTRE_KEYS["XYZ"[i]], CENTRE_KEYS["XYZ"[j]]
    s, e = _plane_point(start, plane), _plane_point(end, plane)
    ui: Any = ev.get(ci, s[0])
    uj: Any = ev.get(cj, s[1])
    if controlled is not None:
        ui, uj = controlled.get(ci, ui), controlled.get(cj, uj)
    c = (float(ui), float(uj))
    m.plane, m.centre = plane, c
    m.radius = _hypot(s[0] - c[0], s[1] - c[1])
    m.sweep = arc_sweep(s, e, c, kind == "cw")
    return m


def _merge(run: Move, m: Move, eps: float) -> bool:
    """Extend ``run`` by ``m`` when they are one line or one circle (same kind and feed)."""
    if m.kind != run.kind or not _same_feed(run.f, m.f):
        return False
    if run.direction is not None and m.direction is not None:
        return _extends(run, m.end, m.last_line, eps)
    return merge_arc(run, m, eps)


def merge_arc(run: Move, m: Move, eps: float) -> bool:
    """Extend the arc run ``run`` by the arc ``m`` (same kind and feed: the caller checked) when they are one
    circle: their centres and start radii within ``eps``, or else the path of the one that sweeps less within
    ``eps`` of the other's circle (``_off_circle``; a run that sweeps less takes ``m``'s centre); and the axes
    outside the plane moving at one rate per angle (``_one_helix``). Why the path too: a controller that moves a
    tiny arc's centre onto its chord's bisector (ISG, Fagor: ``postproc.arc_end``) cuts the other's circle within
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
    run.end, run.last_line = m.end, m.last_line
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
    s, e = _plane_point(a.start, plane), _plane_point(a.end, plane)
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
    s, e = _plane_point(run.start, plane), _plane_point(run.end, plane)
    base = arc_sweep(s, e, c, run.kind == "cw")
    run.sweep = base + round((run.sweep - base) / _TWO_PI) * _TWO_PI
    run.centre = c
    run.radius = _hypot(s[0] - c[0], s[1] - c[1])


def _extends(run: Move, end: dict[str, float], line: int, eps: float) -> bool:
    """Extend the straight run ``run`` to ``end`` (a straight move of its kind and feed, ending on ``line``) when
    that lies on its line (within ``eps``) and further along it than the run's end (``Move.along``). The first
    three axes are held in locals (compiled, unboxed floats: a list boxes each), any further one in a list."""
    u, s = run.direction, run.start
    assert u is not None
    n = 0
    r0 = r1 = r2 = u0 = u1 = u2 = 0.0
    more: list[float] | None = None  # (the end from the run's start, the direction) of each axis after the third
    along = 0.0
    same = len(end) == len(u)  # the run's own axes (those of every move of a simulation)
    for k, v in end.items():
        r = v - s.get(k, 0.0)
        uk = u.get(k)
        if uk is None:
            uk = 0.0
            same = False
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
    run.end, run.last_line = end, line
    run.along = along if same else math.nan  # (nan: measured again, over the run's axes, when needed)
    return True


def _along(run: Move) -> float:
    """How far along its direction the straight run's end lies: ``Move.along``, or measured over the
    direction's axes where the run was extended by a move of other axes."""
    if run.along == run.along:
        return run.along
    u, s, run_end = run.direction, run.start, run.end
    assert u is not None
    along = 0.0
    for k, uk in u.items():
        along += (run_end[k] - s.get(k, 0.0)) * uk
    return along


def _one_helix(run: Move, m: Move, eps: float) -> bool:
    """True when the axes outside the plane move in ``m`` at the rate per angle they moved in ``run`` (none:
    a flat arc; the same: one helix, as an arc split into pieces), so the arcs may be joined."""
    i, j, _ = PLANE_INDEX[m.plane or "XY"]
    plane_keys = {"xyz"[i], "xyz"[j]}
    for k in m.end:
        if k not in plane_keys:
            rate = (run.end[k] - run.start.get(k, 0.0)) / run.sweep
            if abs(m.end[k] - m.start.get(k, 0.0) - rate * m.sweep) > eps:
                return False
    return True


def normalise(events: Iterable[Event | MoveRecord], start: dict[str, float], eps: float,
              codes: list[Event] | None = None) -> Iterator[Move | Event]:
    """Moves merged into runs, machine events as they are; the header is skipped. A move ends at its
    controlled point where it has one (``compare._controlled``, read in place). ``codes``: the events of a
    machine-specific code (they carry ``code``) go there instead: another family has no such code, so they
    are listed, not compared (``compare_machine_codes``)."""
    pos = {k.lower(): v for k, v in start.items()}
    run: Move | None = None
    seen_keys: tuple[str, ...] | None = None  # the records' keys met last (one tuple a simulation) and whether
    all_axes = False                           # they are all axis keys
    for item in events:
        steps: list[float] = []
        if isinstance(item, MoveRecord) and item.centre is None:  # a straight move, read by field
            kind = item.kind
            keys = item.keys
            if keys is not seen_keys:
                seen_keys, all_axes = keys, _all_axes(keys)
            end = _record_end(item, pos, steps, all_axes)
            raw_f: Any = item.f
            line = item.line
        else:
            ev = item.event() if isinstance(item, MoveRecord) else item  # (an arc's record: read as its event)
            if "toolpath" in ev:
                continue
            if codes is not None and "code" in ev:
                codes.append(ev)
                continue
            if "move" not in ev:
                if run is not None:
                    yield run
                    run = None
                yield ev
                continue
            kind = ev["move"]
            if kind == "cw" or kind == "ccw":
                m = _move(ev, pos)
                pos = m.end
                if run is not None and _merge(run, m, eps):
                    continue
                if run is not None:
                    yield run
                run = m
                continue
            end = _axes(ev, ev.get("controlled"), pos, steps)
            raw_f = None
            line = 0
        # a straight move: merged into the run without a ``Move`` of its own where it continues it
        square = 0.0
        for step in steps:
            square += step * step
        length = -1.0  # (not measured yet: a plain sum of squares above 0 and finite says it is above 0)
        if not (0.0 < square < _INF):
            length = norm(steps)
            if length == 0.0:
                pos = end
                continue
        before, pos = pos, end
        if not isinstance(item, MoveRecord):  # (read where the move is not dropped, as before the records)
            raw_f = item.get("f")
            line = item["line"]
        f = None if raw_f is None else _real(raw_f)
        if run is not None and run.direction is not None and (length < 0.0 or length > 0.0) and kind == run.kind \
                and _same_feed(run.f, f) and _extends(run, end, line, eps):
            continue
        if run is not None:
            yield run
        run = _straight(kind, before, end, f, line, steps, norm(steps) if length < 0.0 else length)
    if run is not None:
        yield run

