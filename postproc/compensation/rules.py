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
    perpendicular to the line from the start point (an arc: beside its end, on its radius)."""
    outside_corner: str
    """``"arc"``: the tool rolls around an outside corner on an arc about the programmed corner (a rapid
    cuts the arc short with a straight traverse to the arc's end)."""
    corner_tolerance: float
    """Radians within which two directions count as one (no corner)."""
    arc_after_cancel: bool
    """Whether the move after a cancel (the exit move) may be an arc."""
    planes: tuple[str, ...] = ("XY",)
    """The planes compensation runs in (``state.PLANE_AXES`` names); another is a program error."""


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
