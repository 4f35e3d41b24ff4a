"""Modal state of a controller while a program streams through a pipeline.

Neutral: it knows 'rapid' and 'initial level', never 'G00' or 'G98'. Positions are in program units
(converted when the units change) and None while unknown, so a step that needs an absolute position it
does not have can fail loudly instead of guessing.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

MM_PER_INCH = 25.4

PLANE_AXES = {"XY": ("X", "Y", "Z"), "ZX": ("Z", "X", "Y"), "YZ": ("Y", "Z", "X")}
"""Per plane: first and second plane axis, then the axis normal to the plane (the drilling axis)."""


@dataclass(slots=True)
class CycleState:
    """The active canned cycle and its modal data (Fanuc: Z, R, Q, P, F stay in force)."""

    kind: str
    words: dict[str, float | int] = field(default_factory=dict)
    initial: float | None = None
    """Initial level on the drilling axis when the cycle was first commanded."""


@dataclass(slots=True)
class ModalState:
    motion: str | None = None
    plane: str = "XY"
    units: str = "mm"
    distance: str = "absolute"
    feed_mode: str = "per_min"
    feed: float | None = None
    spindle_rpm: float | None = None
    spindle: str = "stop"
    return_level: str = "initial"
    work_offset: int = 1
    tool: int | None = None
    cycle: CycleState | None = None
    position: dict[str, float | None] = field(default_factory=lambda: {"X": None, "Y": None, "Z": None})
    extra: dict[str, Any] = field(default_factory=dict)
    """Room for dialect- or syntax-specific modal data (keyed by the syntax's XML name)."""

    def set_units(self, system: str) -> None:
        """Switch units, converting the tracked position (a controller keeps the physical position)."""
        if system == self.units:
            return
        factor = MM_PER_INCH if system == "mm" else 1.0 / MM_PER_INCH
        for axis, value in self.position.items():
            if value is not None and axis in "XYZUVW":
                self.position[axis] = value * factor
        self.units = system
