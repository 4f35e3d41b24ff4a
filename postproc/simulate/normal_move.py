"""A normalised move of a toolpath (``verify`` compares two streams of them; ``chords`` reads them too).
Compiled with the comparison (``pyproject.toml [tool.postproc] compiled``): every move of both programs
is one."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final

from mypy_extensions import mypyc_attr

FEED_TOLERANCE: Final = 1e-4
"""Relative: feeds agree when within 0.01 % (a converted inch feed written with fewer places)."""


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass
class Move:
    """A normalised move: possibly several merged moves of one file."""

    kind: str
    start: dict[str, float]
    end: dict[str, float]
    f: float | None
    first_line: int
    last_line: int
    direction: dict[str, float] | None = None
    """Unit vector of a straight run (None for arcs)."""
    centre: tuple[float, float] | None = None
    plane: str | None = None
    radius: float = 0.0
    sweep: float = 0.0
    length: float = 0.0
    """A straight move's length (an arc's is not needed: a full circle is not zero-length)."""


def same_feed(a: float | None, b: float | None) -> bool:
    """Two feeds agree (both absent, or within ``FEED_TOLERANCE`` of each other)."""
    if a is None or b is None:
        return a is b
    return abs(a - b) <= max(1e-9, FEED_TOLERANCE * max(abs(a), abs(b)))
