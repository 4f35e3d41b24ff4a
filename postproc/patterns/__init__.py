"""Hole patterns: the active canned cycle repeated at computed points (Fagor's multiple machining).

``HolePattern`` is the neutral record (kind, geometry, skipped points, the moves between points),
``pattern_points``/``pattern_hops`` compute the points and moves, ``resolve_hole_pattern`` gives a
pattern block its motion, and ``expand_hole_patterns`` (lowering) keeps a pattern native where the
target runs it (``Dialect.HOLE_PATTERNS``) or writes the cycle point by point.
"""

from __future__ import annotations

from postproc.xmlio import XFactory

from .geometry import Hop, pattern_hops, pattern_points
from .lowering import expand_hole_patterns
from .resolve import resolve_hole_pattern
from .section import KINDS, HolePattern

__all__ = ["HolePattern", "Hop", "KINDS", "expand_hole_patterns", "pattern_hops", "pattern_points", "register",
           "resolve_hole_pattern"]


def register(factory: XFactory | None = None) -> None:
    """Register the package's XML classes with ``factory`` (the default one if None); idempotent."""
    HolePattern.reg(factory)
