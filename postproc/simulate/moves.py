"""A normalised move of a toolpath (``verify`` compares two streams of them; ``chords`` reads them too)."""

from __future__ import annotations

from dataclasses import dataclass

FEED_TOLERANCE = 1e-4
"""Relative: feeds agree when within 0.01 % (a converted inch feed written with fewer places)."""


@dataclass(slots=True)
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


def same_feed(a: float | None, b: float | None) -> bool:
    """Feeds agree within ``FEED_TOLERANCE`` (relative); a rapid's None only with None."""
    if a is None or b is None:
        return a is b
    return abs(a - b) <= max(1e-9, FEED_TOLERANCE * max(abs(a), abs(b)))
