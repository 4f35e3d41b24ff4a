"""The compensation geometry a controller's rules need: arcs about outside corners (``cutter_radius``)
or straight corners (``extended_corners``), one state per run."""

from __future__ import annotations

from typing import Callable

from .cutter_radius import CutterRadius, Item
from .extended_corners import ExtendedCorners
from .rules import CutterRules


def cutter_for(rules: CutterRules, release: Callable[[Item], None]) -> CutterRadius:
    """A compensation state under ``rules``; ``release`` writes what it lets go of."""
    if rules.outside_corner == "extend":
        return ExtendedCorners(rules, release)
    return CutterRadius(rules, release)
