"""CycleWords: which address letter carries which role in a dialect's hole cycles, and how it names them.

The cycle geometry (``postproc.cycles``) is neutral: it knows "the hole bottom" and "the reference
level", never ``Z`` or ``R``. A dialect describes its words once: on the RS274 family the bottom is the
axis normal to the plane and ``R`` the reference level; on Fagor ``Z`` is the reference plane and ``I``
the depth. The reading dialect gives its description to the run's ``Context`` (``Dialect.CYCLE_WORDS``),
and messages name a cycle in that dialect's spelling.
"""

from __future__ import annotations

from dataclasses import field
from typing import Mapping

from .records import record


@record(frozen=True, slots=True)
class CycleWords:
    """The letters of a dialect's hole-cycle words, by role."""

    names: Mapping[str, str]
    """Neutral cycle kind -> how the dialect spells it ("drill" -> "G81"), for messages and columns."""
    return_to_r: str
    """How the dialect spells the return to the reference level (for messages), e.g. "G99"."""
    level: str
    """The reference (R) level, e.g. "R"."""
    peck: str
    """The peck depth of a peck-drilling cycle, e.g. "Q"."""
    shift: str
    """The shift of a fine- or back-boring cycle, e.g. "Q"."""
    dwell: str
    """The dwell at the hole bottom, e.g. "P"."""
    spindle: Mapping[str, str] = field(default_factory=dict)
    """Spindle direction ("cw", "ccw") -> how the dialect spells it, for messages (e.g. "M3")."""
    bottom: Mapping[str, str] = field(default_factory=dict)
    """Plane ("XY", "ZX", "YZ") -> the letter of the hole bottom; a plane not listed takes the axis
    normal to it (Z in XY)."""
    repeat: tuple[str, ...] | None = None
    """The repeat-count letters in order of preference, or None to take them from the set-up's
    ``Input repeatAddress`` (K, L or K+L)."""
    max_repeat: int | None = None
    """The largest repeat count the controller accepts (Fanuc K: 9999), None when it sets no limit of
    its own (the set-up's ``<Limits movesPerBlock>`` still bounds the expansion)."""
    dwell_unit: float | None = None
    """Seconds per unit of the dwell word (Fagor K: 1 or 0.01, from the set-up); None: the cycle
    semantics decide (Fanuc milliseconds, RS274 seconds)."""
    undwelled: Mapping[str, str] = field(default_factory=dict)
    """A dwelling cycle kind -> the kind it is when no dwell is in force, for a dialect whose one code
    drills with or without a dwell (Fagor ``G81``: ``K`` absent or 0 is a plain drill, Fanuc's ``G81``,
    not a ``G82`` with no dwell time)."""

    def bottom_letter(self, plane: str, normal: str) -> str:
        """The hole bottom's letter in ``plane``, whose normal axis is ``normal``."""
        return self.bottom.get(plane, normal)

    def repeat_letters(self, repeat_address: str) -> tuple[str, ...]:
        """The letters that count repeats, in order of preference."""
        return self.repeat if self.repeat is not None else tuple(repeat_address.split("+"))

    def same_letters(self, other: "CycleWords") -> bool:
        """Both dialects write a cycle's words with the same letters and units (a cycle read in one is
        written in the other as programmed)."""
        return (self.level, self.peck, self.shift, self.dwell, dict(self.bottom), self.repeat, self.dwell_unit) == (
            other.level, other.peck, other.shift, other.dwell, dict(other.bottom), other.repeat, other.dwell_unit)

    def name(self, kind: str) -> str:
        """How the dialect names a cycle kind (the kind itself when it has no code for it)."""
        return self.names.get(kind, kind)
