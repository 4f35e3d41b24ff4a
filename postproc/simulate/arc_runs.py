"""verify's arcs as runs (``postproc.simulate.runs``): an arc's event or record read as a ``Move`` (its controlled end
and centre where it has them), and consecutive arcs merged into one run where they cut one circle
(``merge_arc``). Compiled with the normalising (``pyproject.toml [tool.postproc] compiled``)."""

from __future__ import annotations

import math
from typing import Any, Final

from ..geometry.arcs import CENTRE_KEYS, PLANE_INDEX, arc_sweep
from .events import Event
from .move_record import MoveRecord
from .normal_move import Move
from .points import Keys, _event_point, _hypot, _plane_point, _real, _record_point, point_value

# -- an arc read -----------------------------------------------------------------------------------

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


# -- arcs merged -----------------------------------------------------------------------------------

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
