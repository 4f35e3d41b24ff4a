"""How the RS274 family's controllers judge and run an I/J/K arc whose end lies off its circle
(``postproc.geometry.arc_end``): the rules the Fanuc-family and RS274/NGC-family dialects declare as ``ARC_END``."""

from __future__ import annotations

from typing import Final

from ..geometry.arc_end import SPIRAL, ArcEndRule

FANUC_ARC_END: Final = ArcEndRule(metric=0.01, inch=0.001, runs=SPIRAL)
"""Fanuc: parameter 3410 (tolerance of arc radius) limits the difference of the start and end radii; past
it alarm PS0020 (over tolerance of radius) [K: Fanuc 0i-MF parameter manual, No. 3410]. Its unit is the
input unit, so one setting is 0.01 mm in a metric program and 0.001 in in an inch program [K: same]; the
value itself is the machine builder's (10 at IS-B taken here) [?]. Within it the tool moves along a spiral
whose radius changes evenly from the start to the end radius [K: Fanuc operator's manual, circular
interpolation]. GSK and Haas controls are taken to follow it [?]."""

RS274NGC_ARC_END: Final = ArcEndRule(metric=2 * 0.01 * 2 ** 0.5, inch=2 * 0.001 * 2 ** 0.5, relative=0.001,
                                     ceiling=100.0, runs=SPIRAL)
"""LinuxCNC's interpreter [V: src/emc/rs274ngc/interp_arc.cc ``arc_data_ijk`` and interp_internal.hh,
LinuxCNC master 2026-08]: refused when the radii differ by more than 100 times
``CENTER_ARC_RADIUS_TOLERANCE`` (2 * 0.001 * sqrt 2 in, 2 * 0.01 * sqrt 2 mm by default, lowered only
by the INI), or by more than that and more than ``SPIRAL_RELATIVE_TOLERANCE`` (0.001) of the larger
radius. The arc keeps its programmed centre and ends at its programmed end point (``ARC_FEED``); the
trajectory planner runs it as a spiral [V: the same file; tp spiral arcs, LinuxCNC PR "TP circular
motion improvements"]."""
