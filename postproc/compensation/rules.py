"""A controller's cutter radius compensation rules, as data: the reading dialect names its value
(``Dialect.CUTTER_COMPENSATION``), the geometry (``cutter_radius``) reads it. A dialect without rules
leaves compensation unsimulated (``verify`` then compares the setting, as before).

Tags as in DIALECTS.md: [V] verified against the controller or its interpreter, [K] from its manual,
[?] assumed.
"""

from __future__ import annotations

from ..records import record


@record(frozen=True)  # made at every start (the LinuxCNC plugin's): a dataclass's generated methods cost ~0.4 ms
class CutterRules:
    """How one controller family starts, runs and ends cutter radius compensation."""

    name: str
    """Who follows these rules (for messages and documentation)."""
    register_absent: str
    """Where the radius comes from when the block names no register: ``"tool"``, the register of the tool
    in the spindle; ``"modal"``, the register named last."""
    entry: str
    """The first move after compensation starts: ``"tangent"``, the tool ends beside the move's end point,
    perpendicular to the line from the start point (an arc: beside its end, on its radius);
    ``"touching"``, the tool ends beside the end point, perpendicular to the line from the end point that
    touches the tool's circle about the start point (an entry arc is not modelled: refused)."""
    outside_corner: str
    """``"arc"``: the tool rolls around an outside corner on an arc about the programmed corner (a rapid
    cuts the arc short with a straight traverse to the arc's end, or goes straight to the move's
    compensated end: ``rapid_corner``)."""
    corner_tolerance: float
    """Radians within which two directions count as one (no corner)."""
    arc_after_cancel: bool
    """Whether the move after a cancel (the exit move) may be an arc."""
    planes: tuple[str, ...] = ("XY",)
    """The planes compensation runs in (``state.PLANE_AXES`` names); another is a program error."""
    inside_corner: str = "meet"
    """``"meet"``: the two compensated moves are cut short where they meet (the first waits for the second);
    ``"error"``: an inside (concave) corner is a program error."""
    rapid_corner: str = "to_arc_end"
    """A rapid around an outside corner: ``"to_arc_end"``, a traverse to where the corner's arc would end,
    then the move; ``"direct"``, one traverse to the move's compensated end."""
    exit_arc_known: bool = True
    """Whether the rules for an arc right after a cancel are known (``arc_after_cancel`` says which); when
    not, such an arc is refused as not simulated."""


ARC_CORNERS = CutterRules(
    name="LinuxCNC",
    register_absent="tool",  # [V] rs274: G41 without D takes the tool in the spindle (tool table index 0)
    entry="tangent",  # [V] convert_straight_comp1 / convert_arc_comp1 (interp_convert.cc)
    outside_corner="arc",  # [V] convert_straight_comp2 / convert_arc_comp2 insert an arc about the corner
    corner_tolerance=0.05,  # [V] TOLERANCE_CONCAVE_CORNER (interp_internal.hh)
    arc_after_cancel=False,  # [V] "The move just after exiting cutter compensation mode must be straight"
    planes=("XY", "ZX"),  # [V] convert_cutter_compensation_on: NCE_RADIUS_COMP_ONLY_IN_XY_OR_XZ
)
"""LinuxCNC's interpreter (``interp_convert.cc``, ``interp_queue.cc``): the oracle of the differential test
``tests/test_cutter_compensation_rs274.py``."""

NIST_V3 = CutterRules(
    name="the NIST RS274/NGC interpreter (version 3)",
    # [K] the NIST code as EMC2 imported it (LinuxCNC commit 6f27a9e96b, 2005, interp_convert.cc):
    # convert_cutter_compensation_on takes D, else current_slot (the tool in the spindle)
    register_absent="tool",
    # [K] convert_straight_comp1: alpha = atan2(c - p) -/+ acos(r / d) (left/right); the EMC handbook's "the
    # first move": a line from the end point touching a circle of the tool's radius about the start
    entry="touching",
    outside_corner="arc",  # [K] convert_straight_comp2 / convert_arc_comp2: ARC_FEED about the programmed corner
    corner_tolerance=0.01,  # [K] TOLERANCE_CONCAVE_CORNER, "(0.01 radian)" in that interp_convert.cc
    arc_after_cancel=False,  # [?] not modelled: refused (exit_arc_known)
    planes=("XY",),  # [K] NCE_CANNOT_TURN_CUTTER_RADIUS_COMP_ON_OUT_OF_XY_PLANE
    inside_corner="error",  # [K] NCE_CONCAVE_CORNER_WITH_CUTTER_RADIUS_COMP (no look-ahead)
    rapid_corner="direct",  # [K] convert_straight_comp2: G0 is one STRAIGHT_TRAVERSE to the compensated end
    exit_arc_known=False,
)
"""The NIST RS274/NGC version 3 interpreter's rules, before LinuxCNC's 2009 look-ahead (entry move and
concave corners): Mach3's, whose interpreter follows that one [?: Mach3's manual follows the NIST report;
its source is closed]."""
