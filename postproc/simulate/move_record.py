"""A move of a toolpath (straight or arc) as one compiled record: the simulator fills it by field, the JSON lines
writer (``postproc.simulate.event_text``) and verify's normalising (``postproc.simulate.runs``) read it by field.

A CAM program is almost all moves; as a dictionary each was built key by key (two dictionaries under a tool
length: the event and its controlled point), then taken apart key by key again by the writer and by ``normalise``
(a type test, a look-up and a boxed number each item). The record holds the same event: its line, kind, the axis
keys, the programmed point as written, for an arc its centre and plane, the feed and feed mode where the event has
them, and the controlled point (with an arc's controlled centre) where it differs. ``event()`` is that event as
the dictionary the toolpath format defines (docs/toolpath-format.md), its keys in the order the JSON line writes
them; every consumer that is not one of the two readers above takes that dictionary (``as_events``), so a record
never leaves the toolpath's own streams.

The simulator makes a record for a move (``Moves.line_move``, ``Moves._offset_line``, ``Moves.arc_move``,
``Moves._offset_arc``) only where its run asks for them (``Moves.records``: ``toolpath_stream``); otherwise it emits
``event()`` of the same record, so both forms come from one computation. The lists a record holds are never
changed after it is made (the simulator makes new lists where a point changes: ``Moves.reframe``)."""

from __future__ import annotations

from typing import Any, Iterable, Iterator, Union

from mypy_extensions import mypyc_attr

Event = dict[str, Any]


@mypyc_attr(allow_interpreted_subclasses=True)
@mypyc_attr(acyclic=True)
class MoveRecord:
    """One move event (``"move"``: rapid, feed, tap; cw, ccw with ``centre`` and ``plane``), by field. Acyclic (no
    field can lead back to it: numbers, strings, their tuples and lists): compiled, not tracked by the cyclic
    collector, its making and freeing ~100 instructions less a move (callgrind, branch tpmove)."""

    def __init__(self, line: int, kind: str, keys: tuple[str, ...], point: list[float | int],
                 f: float | int | None, feed_mode: str | None, controlled: list[float | int] | None,
                 centre_keys: tuple[str, ...] = (), centre: list[float | int] | None = None, plane: str | None = None,
                 ccentre: list[float | int] | None = None) -> None:
        self.line = line
        self.kind = kind
        """The event's ``move``."""
        self.keys = keys
        """The axis keys, in the machine's order (``"x"``, ``"y"``, ``"z"``...): one tuple a run, shared."""
        self.point = point
        """The programmed point as written (``num``'s values: an int where integral), one value a key."""
        self.f = f
        """``f`` (None: the event has none, a rapid)."""
        self.feed_mode = feed_mode
        """``feed_mode`` where the event states one (it differs from the header's)."""
        self.controlled = controlled
        """The controlled point as written, one value a key, where it differs from the programmed one (else None;
        an arc's where its point or its centre differs)."""
        self.centre_keys = centre_keys
        """An arc's centre keys (``"cx"``, ``"cy"``, ``"cz"``: the machine's X, Y and Z): one tuple a run, shared."""
        self.centre = centre
        """An arc's centre as written, one value a centre key (None: a straight move)."""
        self.plane = plane
        """An arc's ``plane``."""
        self.ccentre = ccentre
        """An arc's controlled centre as written, one value a centre key, where ``controlled`` is not None."""

    def event(self) -> Event:
        """The event as its dictionary: ``line``, ``move``, the axes, an arc's centre and ``plane``, ``f``,
        ``feed_mode``, ``controlled``."""
        keys, point = self.keys, self.point
        ev: Event = {"line": self.line, "move": self.kind}
        for i in range(len(keys)):
            ev[keys[i]] = point[i]
        centre = self.centre
        centre_keys = self.centre_keys
        if centre is not None:
            for i in range(len(centre_keys)):
                ev[centre_keys[i]] = centre[i]
            ev["plane"] = self.plane
        if self.f is not None:
            ev["f"] = self.f
        if self.feed_mode is not None:
            ev["feed_mode"] = self.feed_mode
        controlled = self.controlled
        if controlled is not None:
            ctrl: Event = {}
            for i in range(len(keys)):
                ctrl[keys[i]] = controlled[i]
            ccentre = self.ccentre
            if ccentre is not None:
                for i in range(len(centre_keys)):
                    ctrl[centre_keys[i]] = ccentre[i]
            ev["controlled"] = ctrl
        return ev

    def __repr__(self) -> str:
        return f"MoveRecord({self.event()!r})"


Emitted = Union[Event, MoveRecord]
"""What the simulator emits: an event's dictionary, or a straight move's record."""


def as_event(item: Emitted) -> Event:
    """An event of a toolpath stream as its dictionary (a record's ``event()``, any other as it is)."""
    return item.event() if isinstance(item, MoveRecord) else item


def as_events(items: Iterable[Emitted]) -> Iterator[Event]:
    """A toolpath stream with each record as its dictionary: for the consumers that read events by key."""
    for item in items:
        yield item.event() if isinstance(item, MoveRecord) else item


def move_kind(item: Emitted) -> str | None:
    """An emitted event's ``move`` (None: it is no move)."""
    if isinstance(item, MoveRecord):
        return item.kind
    kind: str | None = item.get("move")
    return kind
