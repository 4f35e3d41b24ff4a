"""Where a hole cycle block leaves the tool, told to the lowering steps that follow the programmed point
(``postproc.lowering.point_after``: the cutter compensation resolver, the tool length timing, the arc settling).

The cycle engine's own steps are lowering steps, so it stands above ``postproc.lowering``; lowering asks it
through ``follow_hole_cycles``, which this module fills when the cycle package loads (no ``CannedCycle`` exists
before that: the cycle engine makes them).
"""

from __future__ import annotations

from typing import Final

from postproc.errors import PostprocError
from postproc.ir import Section
from postproc.ir.state import PLANE_AXES
from postproc.lowering.point_after import follow_hole_cycles

from .expansion import CycleExpansion
from .resolve import EXPANSIONS
from .section import CannedCycle

_BY_KIND: Final[dict[str, CycleExpansion]] = {kind: expansion() for expansion in EXPANSIONS for kind in expansion.KINDS}
"""Hole cycle kind -> the family expansion that knows where it ends. A family's own expansion (grblHAL's pecks,
``postproc_grblhal.pecking``) moves differently in the hole and ends as the built-in one: over its last hole at
the return level (``CycleExpansion.ENDS_OVER_THE_SPOT``)."""


def hole_cycle_end(section: Section) -> dict[str, float] | None:
    """Where a hole cycle block leaves the tool, absolute, program units: the plane's axes and the drilling
    axis (a block of no hole, K0, where it stood: the axes known before it; a cycle at the spot, with no hole
    position, the drilling axis alone); None where not known (a kind no family expands, a level the record
    lacks: the reader refused those already)."""
    if not isinstance(section, CannedCycle):
        return None
    expansion = _BY_KIND.get(section.kind)
    if expansion is None:
        return None
    first, second, normal = PLANE_AXES[section.plane]
    try:
        if first not in section.position or second not in section.position:
            # a cycle a lowering step made at the spot where the tool stands (a rigid tap become a tap cycle,
            # ``cycles.rigid_tap_lowering``): the plane's axes stay, the drilling axis ends at the return level
            return {normal: expansion.return_level(section)}
        return expansion.end(section)
    except PostprocError:
        return None


follow_hole_cycles(hole_cycle_end)
