"""A normalised move of a toolpath (``verify`` compares two streams of them; ``chords`` reads them too).
Compiled with the comparison (``pyproject.toml [tool.postproc] compiled``): every move of both programs
is one.

A move holds its points as fields: the axis keys (one tuple a simulation, shared by its moves) and a list of
floats in their order, for the start, the end and a straight run's direction. ``normalise`` and the comparison
read them by index (``postproc.simulate.runs``: a key is looked for where it stood in the other point first);
as dictionaries keyed by axis letter each move cost a dictionary or two to build and a look-up an axis to read,
about 8k instructions a move a side (callgrind, ``benchmarks/callgrind.sh fanuc verify:linuxcnc 0``). The
readers that are not hot (``chords``, the arcs' path comparison, messages, tests) take the points as the
dictionaries they were (``start``, ``end``, ``direction``: made when read, set from one)."""

from __future__ import annotations

import math
from typing import Final

from mypy_extensions import mypyc_attr

FEED_TOLERANCE: Final = 1e-4
"""Relative: feeds agree when within 0.01 % (a converted inch feed written with fewer places)."""

NO_KEYS: Final[tuple[str, ...]] = ()
NO_VALUES: Final[list[float]] = []
"""A point of no axes (never changed in place: a point's list is replaced, not edited)."""


@mypyc_attr(allow_interpreted_subclasses=True)
@mypyc_attr(acyclic=True)
class Move:
    """A normalised move: possibly several merged moves of one file. A plain class, not a dataclass:
    compiled, a dataclass's ``__init__`` is the one ``dataclasses`` writes, run as Python (about 4,000
    instructions a move of each program; this one is native). ``start`` and ``end`` given as dictionaries
    (a reader that is not hot: ``chords``, tests) fill the fields; ``normalise`` passes None and sets the
    fields itself. Acyclic (its fields are numbers, strings and their tuples and lists): compiled, not tracked
    by the cyclic collector, as ``MoveRecord``."""

    def __init__(self, kind: str, start: dict[str, float] | None, end: dict[str, float] | None, f: float | None,
                 first_line: int, last_line: int, direction: dict[str, float] | None = None,
                 centre: tuple[float, float] | None = None, plane: str | None = None, radius: float = 0.0,
                 sweep: float = 0.0, length: float = 0.0) -> None:
        self.kind = kind
        self.start_keys = NO_KEYS
        self.start_values = NO_VALUES
        """The start: its axis keys, and their values in that order."""
        self.end_keys = NO_KEYS
        self.end_values = NO_VALUES
        """The end, as the start."""
        self.unit_keys = NO_KEYS
        self.unit: list[float] | None = None
        """Unit vector of a straight run, in the order of ``unit_keys`` (its first move's end keys); None for arcs."""
        if start is not None:
            self.start = start
        if end is not None:
            self.end = end
        if direction is not None:
            self.direction = direction
        self.f = f
        self.first_line = first_line
        self.last_line = last_line
        self.centre = centre
        self.plane = plane
        self.radius = radius
        self.sweep = sweep
        self.length = length
        """A straight move's length (an arc's is not needed: a full circle is not zero-length)."""
        self.along = math.nan
        """How far along ``direction`` a straight run's end lies from its start (the length of its first move,
        then of its furthest): a move that continues the run must end further along (``runs._extends``).
        Kept rather than measured again at every move (nan: not known, measured from the points)."""

    @property
    def start(self) -> dict[str, float]:
        """The start as a dictionary (axis key -> mm)."""
        return as_dict(self.start_keys, self.start_values)

    @start.setter
    def start(self, point: dict[str, float]) -> None:
        self.start_keys, self.start_values = tuple(point), list(point.values())

    @property
    def end(self) -> dict[str, float]:
        """The end as a dictionary (axis key -> mm)."""
        return as_dict(self.end_keys, self.end_values)

    @end.setter
    def end(self, point: dict[str, float]) -> None:
        self.end_keys, self.end_values = tuple(point), list(point.values())

    @property
    def direction(self) -> dict[str, float] | None:
        """A straight run's unit vector as a dictionary (None for arcs)."""
        unit = self.unit
        return None if unit is None else as_dict(self.unit_keys, unit)

    @direction.setter
    def direction(self, vector: dict[str, float] | None) -> None:
        if vector is None:
            self.unit_keys, self.unit = NO_KEYS, None
        else:
            self.unit_keys, self.unit = tuple(vector), list(vector.values())

    def __repr__(self) -> str:
        return (f"Move({self.kind!r}, {self.start!r}, {self.end!r}, f={self.f!r}, lines {self.first_line}-"
                f"{self.last_line}, centre={self.centre!r}, sweep={self.sweep!r})")


def as_dict(keys: tuple[str, ...], values: list[float]) -> dict[str, float]:
    """A point's keys and values as a dictionary."""
    point: dict[str, float] = {}
    for i in range(len(keys)):
        point[keys[i]] = values[i]
    return point


def same_feed(a: float | None, b: float | None) -> bool:
    """Two feeds agree (both absent, or within ``FEED_TOLERANCE`` of each other)."""
    if a is None or b is None:
        return a is b
    x: float = a  # (each unboxed once: compiled, every use of ``a`` unboxed it again)
    y: float = b
    return abs(x - y) <= max(1e-9, FEED_TOLERANCE * max(abs(x), abs(y)))
