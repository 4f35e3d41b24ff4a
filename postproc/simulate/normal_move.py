"""A normalised move of a toolpath (``verify`` compares two streams of them; ``chords`` reads them too).
Compiled with the comparison (``pyproject.toml [tool.postproc] compiled``): every move of both programs
is one."""

from __future__ import annotations

import math
from typing import Final

from mypy_extensions import mypyc_attr

FEED_TOLERANCE: Final = 1e-4
"""Relative: feeds agree when within 0.01 % (a converted inch feed written with fewer places)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Move:
    """A normalised move: possibly several merged moves of one file. A plain class, not a dataclass:
    compiled, a dataclass's ``__init__`` is the one ``dataclasses`` writes, run as Python (about 4,000
    instructions a move of each program; this one is native)."""

    def __init__(self, kind: str, start: dict[str, float], end: dict[str, float], f: float | None,
                 first_line: int, last_line: int, direction: dict[str, float] | None = None,
                 centre: tuple[float, float] | None = None, plane: str | None = None, radius: float = 0.0,
                 sweep: float = 0.0, length: float = 0.0) -> None:
        self.kind = kind
        self.start = start
        self.end = end
        self.f = f
        self.first_line = first_line
        self.last_line = last_line
        self.direction = direction
        """Unit vector of a straight run (None for arcs)."""
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

    def __repr__(self) -> str:
        return (f"Move({self.kind!r}, {self.start!r}, {self.end!r}, f={self.f!r}, lines {self.first_line}-"
                f"{self.last_line}, centre={self.centre!r}, sweep={self.sweep!r})")


def same_feed(a: float | None, b: float | None) -> bool:
    """Two feeds agree (both absent, or within ``FEED_TOLERANCE`` of each other)."""
    if a is None or b is None:
        return a is b
    return abs(a - b) <= max(1e-9, FEED_TOLERANCE * max(abs(a), abs(b)))
