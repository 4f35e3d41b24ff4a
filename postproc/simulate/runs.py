"""verify's normalising of a toolpath as it streams: moves merged into runs (consecutive straight moves of one
kind and feed that continue one line, arcs on one circle), machine events as they are. Compiled with the
comparison (``pyproject.toml [tool.postproc] compiled``): it reads every move event of both programs, so a
straight move that continues its run is merged without a ``Move`` of its own, its point is read by field (a
``MoveRecord``'s list, kept as it is where its values are floats), a point is a tuple of axis keys and a list of
floats in their order (``postproc.simulate.normal_move``), and the arithmetic keeps the first three axes in
unboxed locals (``tests/test_normalise_reference.py`` holds it to the code it replaced). ``Normaliser`` is pulled
a move at a time (``pull``), not a generator: compiled, a generator keeps every local in an object of its own,
read and written at each resume. A point's reading and distances are ``postproc.simulate.points``; arcs, read and
merged, ``postproc.simulate.arc_runs``."""

from __future__ import annotations

import math
from typing import Any, Final, Iterable, Iterator, TypeVar

from mypy_extensions import mypyc_attr

from .arc_runs import _arc, _arc_record, merge_arc as merge_arc
from .events import Event
from .move_record import MoveRecord
from .normal_move import Move, same_feed as _same_feed
from .points import (_AXIS_KEYS as _AXIS_KEYS, _INF, Keys, Steps, _all_axes, _event_point, _is_axis as _is_axis, _norm,
                     _real, _record_point, beyond as beyond, key_index as key_index, norm as norm,
                     point_value as point_value)

# -- moves -----------------------------------------------------------------------------------------

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
        along = 0.0
        if n == 3:  # (the loop below for three axes: a list made of three, not grown from empty, ~250 instructions)
            u0 = d0 / length
            u1 = d1 / length
            u2 = d2 / length
            along += d0 * u0
            along += d1 * u1
            along += d2 * u2
            m.unit_keys, m.unit = keys, [u0, u1, u2]
            m.along = along
            return m
        unit: list[float] = []  # (appended: compiled, ``[0.0] * n`` is a list repeated through Python, ~200 more)
        rest: list[float] = more if more is not None else NO_STEPS
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
class Pulled:
    """A toolpath stream that gives its next event by a method (``pull``: None at the end), so a compiled reader of
    it (``Normaliser``, verify's ``FeedModes`` of its ``PerMinute``) steps it by a native call: stepped as an
    iterator (``pull_item``), each layer cost ~120 instructions an event a side, its ``__iter__`` and ``__next__``
    called through their slots (callgrind, ``benchmarks/callgrind.sh fanuc verify:linuxcnc 0``, branch tpmove). It
    is an iterator too, for any other reader."""

    def pull(self) -> Event | MoveRecord | None:
        raise NotImplementedError

    def __iter__(self) -> Pulled:
        return self

    def __next__(self) -> Event | MoveRecord:
        item = self.pull()
        if item is None:
            raise StopIteration
        return item


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
        self.source: Pulled | None = events if isinstance(events, Pulled) else None
        """``events`` where it is ``Pulled``: stepped by its ``pull``, not as an iterator."""
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
        self.steps = Steps()
        """Where a move's steps are collected (``points.Steps``) but for a point of three axes in the run's keys."""

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
        source = self.source
        eps = self.eps
        while True:
            item = source.pull() if source is not None else pull_item(events)
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
                    run = self._arc_run(_arc_record(item, self.all_axes, self.pos_keys, self.pos_values), eps)
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
                    run = self._arc_run(_arc(ev, self.pos_keys, self.pos_values), eps)
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
                steps = self.steps
                steps.clear()
                for i in range(n):
                    steps.add(end[i] - (start[i] if shared else point_value(start_keys, start, keys[i], i)))
                d0, d1, d2, more = steps.d0, steps.d1, steps.d2, steps.more
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

    def _arc_run(self, m: Move, eps: float) -> Move | None:
        """An arc read (from a record or an event, ``pull``): the tool goes to its end; it joins the run where it
        continues it (None), else it starts a run of its own and the run it ends is given (None where there was
        none)."""
        self.pos_keys, self.pos_values, self.pos3 = m.end_keys, m.end_values, False
        run = self.run
        if run is not None and _merge(run, m, eps):
            return None
        self.run, self.run3 = m, False
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
