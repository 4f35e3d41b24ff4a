"""verify's normalising of a toolpath as it was before it was made lean (commit 2ecc27b's
``postproc.simulate.compare``, now ``postproc.simulate.runs``: ``normalise`` and the helpers it used, unchanged but for the merging of arcs, which is the code's own
``merge_arc`` since issue 26 added a path test to it), the reference that
``tests/test_normalise_reference.py`` holds today's ``normalise`` to on random paths: the same runs, to the
bit. Every straight move here is a ``Move`` of its own, with its direction as a dictionary, and a run's
extent along its line is measured again at every move."""

from __future__ import annotations

import math
from typing import Any, Iterable, Iterator

from postproc.geometry.arcs import CENTRE_KEYS, PLANE_INDEX, arc_sweep
from postproc.simulate.events import Event
from postproc.simulate.normal_move import Move, same_feed as _same_feed
from postproc.simulate.runs import merge_arc

_hypot = math.hypot


_AXIS_KEYS = frozenset("xyzabcuvw")


def _axes(ev: Event, controlled: Event | None) -> dict[str, float]:
    """The end point of a move event, in its order (the machine's axes): its controlled point where it has
    one, as ``_controlled`` gives it (the controlled axes replace the programmed ones in place, any other
    follows). A number is converted as its type: compiled, ``float(v)`` of a value of unknown type is a call
    of the builtin through Python (~250 instructions)."""
    end: dict[str, float] = {}
    if controlled is None:
        for k, v in ev.items():
            if len(k) == 1 and k in _AXIS_KEYS:  # (the length first: "line", "move"... need no set look-up)
                end[k] = _real(v)
        return end
    matched = 0
    for k, v in ev.items():
        if len(k) == 1 and k in _AXIS_KEYS:
            c = controlled.get(k)
            if c is None:
                end[k] = _real(v)
            else:
                end[k] = _real(c)
                matched += 1
    if matched != len(controlled):  # an arc's centre, or an axis the programmed point does not name
        for k, c in controlled.items():
            if k in _AXIS_KEYS and k not in end:
                end[k] = _real(c)
    return end


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


def _move(ev: Event, start: dict[str, float]) -> Move:
    """A move event as a ``Move`` from ``start``, its controlled point the end (``_controlled``, read in place:
    copying each event that has one was a dictionary a move)."""
    controlled: Event | None = ev.get("controlled")
    end = _axes(ev, controlled)
    kind = ev["move"]
    f = ev.get("f")
    line = ev["line"]
    m = Move(kind, start, end, None if f is None else _real(f), line, line)
    if kind == "cw" or kind == "ccw":
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
    steps: list[float] = []  # a list, not a dict's values: compiled, ``*`` of a list is its own tuple (~600 less)
    for k, v in end.items():
        steps.append(v - start.get(k, 0.0))
    length = m.length = _hypot(*steps)  # _dist(end, start), its differences kept
    if length > 0:
        direction: dict[str, float] = {}
        i = 0
        for k in end:
            direction[k] = steps[i] / length
            i += 1
        m.direction = direction
    return m


def _merge(run: Move, m: Move, eps: float) -> bool:
    """Extend ``run`` by ``m`` when they are one line or one circle (same kind and feed)."""
    if m.kind != run.kind or not _same_feed(run.f, m.f):
        return False
    if run.direction is not None and m.direction is not None:
        u, s, run_end, end = run.direction, run.start, run.end, m.end
        along_old = 0.0
        for k, uk in u.items():
            along_old += (run_end[k] - s.get(k, 0.0)) * uk
        rel: list[float] = []  # m's end from the run's start, and the direction, axis by axis
        along = 0.0
        for k, v in end.items():
            r = v - s.get(k, 0.0)
            uk = u.get(k, 0.0)
            rel.append(r)
            rel.append(uk)
            along += r * uk
        off = _hypot(*[rel[i] - along * rel[i + 1] for i in range(0, len(rel), 2)])  # distance from the line
        if off > eps or along <= along_old:
            return False
        run.end, run.last_line = m.end, m.last_line
        return True
    # arcs: the code's own rule (issue 26 added the path test there; this reference holds the straight runs)
    return merge_arc(run, m, eps)


def normalise(events: Iterable[Event], start: dict[str, float], eps: float,
              codes: list[Event] | None = None) -> Iterator[Move | Event]:
    """Moves merged into runs, machine events as they are; the header is skipped. A move ends at its
    controlled point where it has one (``_controlled``, read in place). ``codes``: the events of a
    machine-specific code (they carry ``code``) go there instead: another family has no such code, so they
    are listed, not compared (``compare_machine_codes``)."""
    pos = {k.lower(): v for k, v in start.items()}
    run: Move | None = None
    for ev in events:
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
        m = _move(ev, pos)
        pos = m.end
        if m.centre is None and m.length == 0.0:
            continue
        if run is not None and _merge(run, m, eps):
            continue
        if run is not None:
            yield run
        run = m
    if run is not None:
        yield run
