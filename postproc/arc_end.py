"""How far a controller lets an I/J/K arc's end point lie off the circle through its start, and which
path it then runs: one rule per controller (``Dialect.ARC_END``), in the program's units, because a
program written to three decimals in inches carries ten times the rounding of one in millimetres.

The reading pipeline (``postproc.syntaxes.modal_state``) and the simulator (``postproc.simulate.moves``)
judge every arc by the *reading* dialect's rule through ``postproc.block_rules.arc_centre``, so an arc its
own controller accepts is read, simulated as that controller runs it, and an arc it refuses is a located
error. A translation's output is read back under the target's rule (``verify``), so an arc the target
would refuse is found there.

The facts behind each rule are in the dialect (or family base) that declares it, tagged with their source.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Final

from .state import MM_PER_INCH

SPIRAL: Final = "spiral"
"""The controller keeps the programmed centre and lets the radius change evenly from the start radius to
the end radius over the sweep (a spiral ending at the programmed end point)."""
START_RADIUS: Final = "start_radius"
"""The controller moves the centre onto the perpendicular bisector of the chord, at the start radius from
the start point, on the programmed centre's side: a true circle through both end points."""
RUNS: Final = (SPIRAL, START_RADIUS)


@dataclass(frozen=True)
class ArcEndRule:
    """What a controller accepts of an arc whose end radius differs from its start radius by ``d``, with
    ``r`` the larger radius (``of_start``: the start radius), in the program's units:

    * ``d <= metric`` (``inch`` in an inch program) is always accepted;
    * beyond it, with ``relative`` > 0, ``d <= relative * r`` is accepted, but never past ``ceiling``
      times the absolute limit (0: no ceiling);
    * anything else is refused.

    ``runs`` says which path an accepted arc takes (``SPIRAL`` or ``START_RADIUS``)."""

    metric: float
    """The absolute limit in a millimetre program (mm)."""
    inch: float
    """The absolute limit in an inch program (inches)."""
    relative: float = 0.0
    """The share of the radius accepted beyond the absolute limit (0: none)."""
    ceiling: float = 0.0
    """With ``relative``: no difference above this multiple of the absolute limit is accepted (0: none)."""
    of_start: bool = False
    """``relative`` is a share of the start radius (else of the larger of the two radii)."""
    runs: str = SPIRAL
    """The path an accepted arc takes (see ``RUNS``)."""

    def __post_init__(self) -> None:
        if self.runs not in RUNS:
            raise ValueError(f"unknown arc path {self.runs!r} (one of {', '.join(RUNS)})")

    def describe(self) -> dict[str, object]:
        """The rule as plain data (the capability table, ``postproc dialects``)."""
        return {"mm": self.metric, "inch": self.inch, "relative": self.relative, "ceiling": self.ceiling,
                "of_start": self.of_start, "runs": self.runs}

    def covers(self, other: "ArcEndRule") -> bool:
        """Whether every arc ``other`` accepts, in either units, this rule accepts too (sufficient, not
        necessary: a False only costs a closer look at each arc, ``postproc.lowering.arcs.settle_arc_ends``)."""
        if self.metric < other.metric or self.inch < other.inch:
            return False
        if other.relative <= 0.0:
            return True
        if self.relative < other.relative or self.of_start and not other.of_start:
            return False
        if self.ceiling <= 0.0:
            return True
        return other.ceiling > 0.0 and min(self.ceiling * self.metric - other.ceiling * other.metric,
                                           self.ceiling * self.inch - other.ceiling * other.inch) >= 0.0

    def limit(self, r_start: float, r_end: float, inch: bool) -> float:
        """The largest difference of radii accepted for an arc of these radii (program units)."""
        absolute = self.inch if inch else self.metric
        if self.relative <= 0.0:
            return absolute
        radius = r_start if self.of_start else max(r_start, r_end)
        share = self.relative * radius
        if self.ceiling > 0.0:
            share = min(share, self.ceiling * absolute)
        return max(absolute, share)

    def allows(self, r_start: float, r_end: float, inch: bool) -> bool:
        """Whether the controller runs an arc with these start and end radii (program units)."""
        return abs(r_start - r_end) <= self.limit(r_start, r_end, inch) * (1.0 + 1e-9)

    def centre(self, s: tuple[float, float], e: tuple[float, float],
               c: tuple[float, float]) -> tuple[float, float]:
        """The centre the controller turns about for an accepted arc from ``s`` to ``e`` programmed about ``c``."""
        if self.runs == SPIRAL:
            return c
        r0 = math.hypot(s[0] - c[0], s[1] - c[1])
        dx, dy = e[0] - s[0], e[1] - s[1]
        chord = math.hypot(dx, dy)
        if chord == 0.0:
            return c  # a full circle: its end is its start, on the circle
        mid = (s[0] + dx / 2.0, s[1] + dy / 2.0)
        nx, ny = -dy / chord, dx / chord  # the bisector's direction
        side = 1.0 if (c[0] - mid[0]) * nx + (c[1] - mid[1]) * ny >= 0.0 else -1.0
        h = math.sqrt(max(r0 * r0 - chord * chord / 4.0, 0.0))
        return mid[0] + side * h * nx, mid[1] + side * h * ny


TARGET_ARC_END: Final = "target_arc_end"
"""``ctx.run_data`` key of a translation whose target's rule does not cover the source's
(``ArcEndRule.covers``): (the target's name, its rule). The reading pipeline's arc check then refuses an arc
the source's controller runs as a spiral but the target's would refuse (``postproc.syntaxes.modal_state``)."""

NEUTRAL_ARC_END: Final = ArcEndRule(metric=0.01, inch=0.01 / MM_PER_INCH)
"""The rule of a dialect that declares none: 0.01 mm in any units, the path a spiral (the project's
rule before the controllers' own were modelled: ``postproc.geometry.ARC_TOLERANCE_MM``)."""
