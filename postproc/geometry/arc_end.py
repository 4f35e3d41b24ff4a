"""How far a controller lets an I/J/K arc's end point lie off the circle through its start, and which
path it then runs: one rule per controller (``Dialect.ARC_END``), in the program's units, because a
program written to three decimals in inches carries ten times the rounding of one in millimetres.

The reading pipeline (``postproc.syntaxes.modal_state``) and the simulator (``postproc.simulate.moves``)
judge every arc by the *reading* dialect's rule through ``postproc.block_rules.arc_centre``, so an arc its
own controller accepts is read, simulated as that controller runs it, and an arc it refuses is a located
error. A translation's output is read back under the target's rule (``verify``), so an arc the target
would refuse is found there.

The facts behind each rule are in the dialect (or family base) that declares it, tagged with their source.
The rule's arithmetic is ``arc_end_math`` (compiled: every arc an ISG or Fagor translation reads is judged by it).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Final

from .arc_end_math import centre_shift, circle_spiral_gap, rule_allows, rule_centre, rule_judged, rule_limit
from ..records import record
from ..ir.state import MM_PER_INCH

SPIRAL: Final = "spiral"
"""The controller keeps the programmed centre and lets the radius change evenly from the start radius to
the end radius over the sweep (a spiral ending at the programmed end point)."""
START_RADIUS: Final = "start_radius"
"""The controller moves the centre onto the perpendicular bisector of the chord, at the start radius from
the start point, on the programmed centre's side: a true circle through both end points."""
NEAREST_CENTRE: Final = "nearest_centre"
"""The controller moves the centre to the nearest point of the chord's perpendicular bisector (the least move
that puts both end points on one circle, its radius about the mean of the two) and runs that circle. Well
conditioned where ``START_RADIUS`` is not: near half a turn the move stays about half the difference of radii."""
RUNS: Final = (SPIRAL, START_RADIUS, NEAREST_CENTRE)
assert (SPIRAL, NEAREST_CENTRE) == ("spiral", "nearest_centre")  # as ``arc_end_math.rule_centre`` spells them


@record(frozen=True)  # every run makes it (dialect.py): a record's methods are not compiled at start
class ArcEndRule:
    """What a controller accepts of an arc whose end radius differs from its start radius by ``d``, with
    ``r`` the larger radius (``of_start``: the start radius), in the program's units:

    * ``d <= metric`` (``inch`` in an inch program) is always accepted;
    * beyond it, with ``relative`` > 0, ``d <= relative * r`` is accepted, but never past ``ceiling``
      times the absolute limit (0: no ceiling);
    * anything else is refused.

    With ``of_centre_shift`` the same limits bound how far the controller moves the centre (``shift``) instead
    of the difference of radii, and ``relative`` is a share of the corrected radius.

    ``runs`` says which path an accepted arc takes (one of ``RUNS``)."""

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
    of_centre_shift: bool = False
    """The limits bound the centre's move onto the bisector (``NEAREST_CENTRE`` only), not the radii's difference."""

    def __post_init__(self) -> None:
        if self.runs not in RUNS:
            raise ValueError(f"unknown arc path {self.runs!r} (one of {', '.join(RUNS)})")
        if self.of_centre_shift and self.runs != NEAREST_CENTRE:
            raise ValueError("a limit on the centre's move needs the nearest-centre path")

    def settles_for(self, r_arc_float_slack: float) -> bool:
        """Whether a translation from this rule's controller to a target with ``r_arc_float_slack``
        (``Dialect.R_ARC_FLOAT_SLACK``) has arcs to settle (``postproc.lowering.arcs.settle_arc_ends``): the
        source's controller moves the centre, or the target refuses an R arc over 2R by any rounding. Asked
        before that module is imported: a translation with none to settle does not load it."""
        return self.runs != SPIRAL or r_arc_float_slack != 0.0

    def describe(self) -> dict[str, object]:
        """The rule as plain data (the capability table, ``postproc dialects``)."""
        return {"mm": self.metric, "inch": self.inch, "relative": self.relative, "ceiling": self.ceiling,
                "of_start": self.of_start, "runs": self.runs, "of_centre_shift": self.of_centre_shift}

    def with_machine(self, limit: float | None, share: float | None) -> "ArcEndRule":
        """This rule with a machine's own parameters where its set-up gives them (a controller whose limits
        are machine parameters: ``Dialect.arc_end_rule``): ``limit`` the absolute limit in mm, whatever the
        program's units (the inch limit follows from it), ``share`` the relative one; None keeps this rule's."""
        if limit is None and share is None:
            return self
        metric = self.metric if limit is None else limit
        return replace(self, metric=metric, inch=metric / MM_PER_INCH,
                       relative=self.relative if share is None else share)

    def covers(self, other: "ArcEndRule") -> bool:
        """Whether every arc ``other`` accepts, in either units, this rule accepts too (sufficient, not
        necessary: a False only costs a closer look at each arc, ``postproc.lowering.arcs.settle_arc_ends``).
        Never where the two run an accepted arc on different paths, or judge different distances."""
        if self.runs != other.runs or self.of_centre_shift != other.of_centre_shift:
            return False
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

    def limit(self, r_start: float, r_end: float, inch: bool, chord: float = 0.0) -> float:
        """The largest difference of radii (with ``of_centre_shift``: move of the centre) accepted for an arc of
        these radii and this chord (program units; ``arc_end_math.rule_limit``)."""
        return rule_limit(self, r_start, r_end, inch, chord)

    def judged(self, r_start: float, r_end: float, chord: float = 0.0) -> float:
        """What the limits bound for an arc of these radii and this chord: the difference of radii, or (with
        ``of_centre_shift``) the centre's move (``arc_end_math.rule_judged``)."""
        return rule_judged(self, r_start, r_end, chord)

    @staticmethod
    def shift(r_start: float, r_end: float, chord: float) -> float:
        """How far the centre moves to the nearest point of the chord's perpendicular bisector: the programmed
        centre's distance from it along the chord, (r_start^2 - r_end^2) / (2 chord) (a full circle: none;
        ``arc_end_math.centre_shift``)."""
        return centre_shift(r_start, r_end, chord)

    def centre_move(self, r_start: float, r_end: float, chord: float) -> float:
        """How far the controller moves the centre of an accepted arc (program units): none for ``SPIRAL``;
        with the programmed centre at ``shift`` along the chord and h along the bisector from the chord's middle
        (r_start^2 + r_end^2 = 2 h^2 + chord^2 / 2 + 2 shift^2), ``shift`` for ``NEAREST_CENTRE`` and the distance
        to the point at sqrt(r_start^2 - chord^2 / 4) along the bisector for ``START_RADIUS``."""
        if self.runs == SPIRAL:
            return 0.0
        along = self.shift(r_start, r_end, chord)
        if self.runs == NEAREST_CENTRE or not math.isfinite(along):
            return along
        quarter = chord * chord / 4.0
        h = math.sqrt(max((r_start * r_start + r_end * r_end) / 2.0 - quarter - along * along, 0.0))
        return math.hypot(along, math.sqrt(max(r_start * r_start - quarter, 0.0)) - h)

    def spiral_gap(self, s: tuple[float, float], e: tuple[float, float], c: tuple[float, float],
                   clockwise: bool, floor: float = -1.0) -> float:
        """How far the circle this rule runs (about the centre it moves to) lies from a spiral controller's path for
        the same arc, the spiral from ``s`` to ``e`` about ``c`` whose radius changes evenly with the angle: the
        largest distance between the two paths, as ``verify`` measures it (``postproc.geometry.arc_paths.deviation``,
        with its ``floor``); 0 for a ``SPIRAL`` rule (``arc_end_math.circle_spiral_gap``)."""
        if self.runs == SPIRAL:
            return 0.0
        return circle_spiral_gap(self.runs == NEAREST_CENTRE, s, e, c, clockwise, floor)

    def allows(self, r_start: float, r_end: float, inch: bool, chord: float = 0.0) -> bool:
        """Whether the controller runs an arc with these start and end radii and this chord (program units;
        the chord matters only ``of_centre_shift``; ``arc_end_math.rule_allows``)."""
        return rule_allows(self, r_start, r_end, inch, chord)

    def centre(self, s: tuple[float, float], e: tuple[float, float],
               c: tuple[float, float]) -> tuple[float, float]:
        """The centre the controller turns about for an accepted arc from ``s`` to ``e`` programmed about ``c``
        (``arc_end_math.rule_centre``)."""
        return rule_centre(self, s, e, c)


UNKNOWN_START_TARGET: Final = "unknown_start_target"
"""``ctx.run_data`` key of a translation to another dialect: the target's name. The reading pipeline's arc check
then refuses an arc whose absolute end word in its plane meets a start unknown on that axis: whether the target
accepts its radius depends on where the machine happens to stand (``postproc.syntaxes.modal_state``)."""

TARGET_ARC_END: Final = "target_arc_end"
"""``ctx.run_data`` key of a translation whose target's rule does not cover the source's
(``ArcEndRule.covers``): (the target's name, its rule). The reading pipeline's arc check then refuses an arc
the source's controller runs as a spiral but the target's would refuse (``postproc.syntaxes.modal_state``)."""

NEUTRAL_ARC_END: Final = ArcEndRule(metric=0.01, inch=0.01 / MM_PER_INCH)
"""The rule of a dialect that declares none: 0.01 mm in any units, the path a spiral (the project's
rule before the controllers' own were modelled: ``postproc.geometry.arcs.ARC_TOLERANCE_MM``)."""
