"""grblHAL's G73 and G83 as its motion control runs them, for reading grblHAL (its own programs simulate and
round-trip with the cycle native; towards any other controller the cycle is expanded with these moves).

From ``motion_control.c`` ``mc_canned_drill`` and ``gcode.c`` (github.com/grblHAL/core, stored commit f80fc34) [V]:

* Q is the peck depth (> 0; in the block's units), each peck going Q further from R: R - Q, R - 2Q, ... and
  the bottom last; at each peck's depth the tool dwells 0.25 s (``canned.dwell = 0.25f``), for G73 and G83
  alike, whatever P says.
* G83 then rapids out to the retract level (R under G99, the level the block started at under G98) and feeds
  from there to the next depth: no rapid back down near the last bottom, as Fanuc and LinuxCNC do.
* G73 rapids up by the G73 retract distance (setting ``$73``, default 0.1 mm: ``DEFAULT_G73_RETRACT``; the
  cycle's clearance, ``Grblhal.PECK_CLEARANCE_MM``) and feeds from there to the next depth; after the bottom's dwell it rapids out to the retract level.

Positioning, R and the repeats are those of G81 (``cycles``), which the reading rules hold to the cases where
RS274/NGC's resolve step positions as grblHAL does.
"""

from __future__ import annotations

from typing import Final

from postproc.cycles.expansion import EPS, ToolPath, level
from postproc.cycles.peck_drilling import PeckDrillingExpansion, peck_depth
from postproc.cycles.section import CannedCycle

PECK_DWELL: Final = 0.25
"""Seconds grblHAL dwells at every peck's depth (``gcode.c``)."""


class GrblhalPeckExpansion(PeckDrillingExpansion):
    """G73/G83 per grblHAL's ``mc_canned_drill`` (module docstring)."""

    XNAME = "GrblhalPeckSyntax"
    __slots__ = ()

    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        self.position(path, cycle, a, b)
        r, bottom = level(cycle, "r"), level(cycle, "bottom")
        q = peck_depth(cycle)
        out = self.return_level(cycle)
        k = 1
        while True:
            depth = r - k * q
            if depth < bottom + EPS:
                depth = bottom
            path.cut(depth, cycle.feed)
            path.dwell(PECK_DWELL)
            if depth == bottom:
                break
            path.rapid(level=depth + (cycle.clearance or 0.0) if cycle.kind == "peck_chip" else out)
            k += 1
        path.rapid(level=out)
