"""The cutter radius compensation rules of the RS274 family's controllers, as data (``CutterRules``): Fanuc's
cutter compensation C and tool nose radius compensation (start-up types A and B), GSK's and Haas's (which
follow Fanuc's), LinuxCNC's interpreter and the NIST RS274/NGC interpreter (Mach3's). Each dialect names its
rules (``Dialect.CUTTER_RULES``, ``Dialect.cutter_rules``); the neutral geometry reads only the values.

Tags as in DIALECTS.md: [V] verified against the controller or its interpreter, [K] from its manual,
[?] assumed.
"""

from __future__ import annotations

import dataclasses

from ..compensation.rules import CutterRules


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

# Cutter compensation C of the Fanuc family, as the operator's manuals describe it: B-62764EN (Series
# 16/18-C MC) section 15.5 and 15.6 "Details of cutter compensation C" (15.6.2 start-up, 15.6.3 offset
# mode, 15.6.4 cancel, 15.6.5 interference check), the same chapters in B-64484EN / B-63944EN (30i).
# [V] B-62764EN 15.5 (text read here): the start-up move is G00 or G01, "circular interpolation (G02,
#     G03) cannot be used"; compensation runs in the G17/G18/G19 plane; a negative value swaps G41/G42.
# [V] B-63782EN/B-63784EN (15i) 14.3 text: an arc in the cancel block is alarm PS034.
# [V] B-62764EN 15.6.1 (text read here): a corner is "inner" when the angle between the two moves on the
#     workpiece side is 180 degrees or more, else "outer"; an intersection is where the two programmed
#     paths meet once each is shifted by the radius.
# [K] 15.6.3 figures: inner corner at the intersection of the offset paths (line or arc); outer corner of
#     90 degrees or more at the intersection; an acute outer corner extends both paths by the radius and
#     joins them with a straight move (no arc, for either start-up type); no solution is alarm PS033,
#     a compensated move turned against its programmed direction is the interference alarm PS041.
# [K] 15.6.2 figures: start-up type A (parameter SUP, No. 5003#0 = 0, the default) ends the start-up move
#     with a vector square to the next move at its start; type B ends it as an outer corner of offset mode
#     (intersection, or the radius extensions when acute).
# [K] 15.6.4 figures, type A: the last compensated move ends with a vector square to it at its end; the
#     cancel move goes from there to its programmed end.
# [K] 15.6.1/15.6.3: the control reads two blocks ahead: one block without motion in the offset plane
#     between two moves is looked past; two or more make the corner from the previous move alone, which
#     is not modelled (refused). [V] the mechanism, B-63324EN/03 (15i-MA) 14.4.3 text (read in the stored
#     pages, cncmanuals.com): the intersection needs two moving blocks among the N read ahead, so it is
#     made while the blocks without motion are at most N - 2, otherwise overcutting or undercutting;
#     there N is parameter 6009 [?: the 16/18 and 0i value of N, kept at the [K] above].
# Checked in this session (issue 26, tooltab): the stored pages hold the text of B-62764EN 15.5/15.6.1,
#     B-63324EN 14.3/14.4.3 and B-63944EN-2 (30i) 6.x, but the corner and start-up constructions are in
#     the figures, which carry no text there: the [K] tags on the figure rules below stay [K].
# [?] not read in this session: the type B figures for an inner start-up corner and for the cancel move
#     (refused by name), the less-than-1-degree outer start-up case (simulated as any acute corner).
# Searched again (issue 26, tool26), text found in the stored pages:
# [V] that outer corners get no arc: B-62754EN (16/18-C MC) "Corner offset circular interpolation (G39)",
#     http://www.cncmanuals.com/fanuc/fanuc-series-16-18-160-180-model-c-machining-center-operators-manual.html/298:
#     an arc of the tool radius round a corner is made by G39, programmed in offset mode, which creates the
#     new vector and moves along the arc from the old vector to it; so without G39 a corner has none. How
#     the outer corner is made instead (the intersection, or the radius extensions when acute) is in the
#     figures only: ``outside_corner="extend"`` stays [K].
# [V] start-up and cancel ends, Haas mill operator's manual (a Fanuc-compatible control), "Entry and Exit
#     from Cutter Compensation", https://staging-diy.haascnc.com/entry-and-exit-cutter-compensation-0: the
#     block that turns compensation on starts at the programmed point and ends offset to the left or right;
#     the block that turns it off starts offset and ends at the programmed point (the cancel move modelled
#     below). Which way the start-up's end vector points (square to the next move: type A) is not in that
#     text: ``entry`` stays [K].
# [V] a changed radius in offset mode: B-63324EN/03 (15i-MA) 14.3, "Change of the cutter compensation value",
#     http://www.cncmanuals.com/fanuc/fanuc-series-15i-150i-ma-programming-operators-manual.html/402: the
#     vector at the end point of the block is calculated with the new value. Not modelled: a G41/G42 while
#     compensation is on is refused (``CutterRadius.start``), so no path is guessed.
# Nothing found contradicts a rule below.
FANUC_A = CutterRules(
    name="Fanuc cutter compensation C",
    register_absent="modal",  # [K] the D register stays in force until another is programmed
    entry="perpendicular",  # [K] 15.6.2 type A
    outside_corner="extend",  # [K] 15.6.3
    corner_tolerance=1e-6,
    arc_after_cancel=False,  # [V] alarm PS034
    planes=("XY", "ZX", "YZ"),  # [V] 15.5: the plane G17/G18/G19 selects
    inside_corner="meet",  # [K] 15.6.3: the intersection
    look_ahead=1,  # [K] two blocks read ahead
)
"""Fanuc cutter compensation C, start-up type A (parameter SUP = 0, the factory setting)."""
FANUC_B = dataclasses.replace(FANUC_A, name="Fanuc cutter compensation C (start-up type B)",
                              entry="corner")  # [K] 15.6.2 type B
"""Fanuc cutter compensation C, start-up type B (parameter SUP = 1): type A's rules but the start-up's end."""


# Tool nose radius compensation of Fanuc T (and GSK, which follows Fanuc T's rules), as data: the same
# offset vector rules as cutter compensation C, in the ZX plane, the radius and the imaginary tool nose
# direction read from the offset the T code selected. The [K] tags below are the manuals as known; their
# text was not re-read in this session (the search corpora hold none of it): the hand-derived tests
# (tests/test_fanuc_nose.py) check the geometry these rules make, not the rules themselves.
# [K] B-64304EN (0i-D operator's manual, common to M and T) describes "tool radius / tool nose radius
#     compensation" in one chapter: start-up types A and B by parameter SUP, offset mode corners and the
#     cancel are one set of figures for both; the lathe adds the imaginary tool nose (a direction 0-9 in
#     the offset's T column, 0 and 9 the nose centre) and the radius in the offset's R column.
# [K] Haas lathe operator's manual, "Approach and Departure Moves For TNC": the approach move is not
#     compensated at its start and fully compensated at its end; the departure starts "at a right angle to
#     the last programmed block" (the type A cancel).
# [K] Fanuc T: G41/G42 name no register, the offset number of the T code is the register (T0102: 2).
# [K] Fanuc T multiple repetitive cycles (0i-D, "Stock removal in turning (G71)", its notes on tool nose
#     radius compensation): G41/G42 is programmed before G70-G73 and G40 outside the finishing shape's
#     blocks ns..nf (G40/G41/G42 inside them is an alarm); G70 then runs the shape compensated, with the
#     temporary cancel below on the move to its start point and on its return (``compensation.cycle_entry``).
# [K] Fanuc T 0i-D/0i-F operator's manual (B-64304EN, B-64604EN), the same notes: G71/G72 (and G73) under
#     the mode rough to the finishing shape with tool nose radius compensation applied to it (the finishing
#     allowance added to that shape); "the offset is temporarily canceled during movement to the start
#     point", "start-up is performed at the first block" (ns), the offset "is temporarily canceled at return
#     to the cycle start point after the termination of the cycle", and "start-up is performed again
#     according to the next move command"; a G40/G41/G42 in the G70-G73 blocks themselves is alarm PS0325.
#     As known, not re-read in this session (the search corpora hold none of the text): ``roughing_cycles``
#     takes G71 and G72 type I only. [?] how a type II cycle (pockets) roughs to the offset shape and G73's
#     passes under the mode: refused by name (``postproc.rs274.lathe_cycles``, ``cycles.lathe_lowering``).
# [?] GSK980TDc: the user manual's "tool nose radius compensation" chapter (C type, start-up, offset mode,
#     cancel; T column 0-9) is assumed to follow Fanuc's type A figures: not read in this session.
FANUC_T = CutterRules(
    name="Fanuc T tool nose radius compensation",
    register_absent="offset",  # [K] the T code's offset number
    entry="perpendicular",  # [K] start-up type A (SUP = 0, the default)
    outside_corner="extend",  # [K] the common chapter's offset mode figures
    corner_tolerance=1e-6,
    arc_after_cancel=False,  # [K] the cancel block is G00 or G01 (an arc: alarm PS034)
    planes=("XY", "ZX", "YZ"),  # [K] the plane G17/G18/G19 selects (a lathe's G18)
    inside_corner="meet",
    look_ahead=1,  # [K] two blocks read ahead
    profile_cycles=frozenset(("turn_finish",)),  # [K] G41/G42 before G70, G40 after it, none in ns..nf
    roughing_cycles=frozenset(("turn_rough", "face_rough")),  # [K] G71/G72 rough to the offset shape (above)
)
"""Fanuc T tool nose radius compensation, start-up type A (parameter SUP = 0)."""
GSK_T = dataclasses.replace(FANUC_T, roughing_cycles=frozenset())
"""GSK 980TDc: Fanuc T's rules ([?] above), without its roughing under compensation: what G71/G72 do with
G41/G42 on is not in our sources [?] (a third-party summary of a Chinese lathe control's rules, blog.csdn.net
mybirdsky 2078236, says nose compensation does not act in G71-G73 at all): refused by name."""
FANUC_T_B = dataclasses.replace(FANUC_T, name="Fanuc T tool nose radius compensation (start-up type B)",
                                entry="corner")  # [K] start-up type B (SUP = 1)
"""Fanuc T tool nose radius compensation, start-up type B (parameter SUP = 1)."""


# Cutter compensation of a Haas mill (a Fanuc-compatible control), as its operator's manual describes it.
# [V] Haas mill operator's manual, "Entry and Exit from Cutter Compensation" (stored page,
#     https://staging-diy.haascnc.com/entry-and-exit-cutter-compensation-0): G41/G42 need a nonzero D; the block
#     that turns compensation on starts at the programmed point and ends offset, the block with G40 starts
#     offset and ends at the programmed point; a G41/G42/G40 in a block without an X-Y move takes effect at
#     the next X or Y move.
# [K] Haas mill operator's manual, Settings (not in the stored pages, not re-read in this session): Setting 43
#     "Cutter Comp Type", A or B, chooses how the first compensated stroke begins and how the tool leaves the
#     part, with figures of Fanuc's start-up types A and B (the set-up's ``cutterStartup``); Setting 58
#     "Cutter Compensation", FANUC or YASNAC: under FANUC the control joins outside angles of at most 270
#     degrees with a sharp corner (the offset paths meet: ``outside_corner="extend"``, as Fanuc's) and
#     alarms where the path would overcut; over 270 degrees (an acute corner) with "an extra linear motion",
#     whose ends the text does not give (refused: ``acute_corner_known``); under YASNAC a circular motion
#     joins every outside angle (not modelled). [?] factory settings: 43 = A, 58 = FANUC (the rules below).
# [?] not found for Haas: an arc as the start-up or the cancel move, more than one block without an X-Y move
#     between two compensated moves (Fanuc's two blocks read ahead kept): refused as not simulated.
HAAS_A = CutterRules(
    name="Haas cutter compensation (setting 58 FANUC, setting 43 A)",
    register_absent="modal",  # [V] the page above: G41/G42 need a nonzero D ([?] modal, as Fanuc's)
    entry="perpendicular",  # [K] setting 43 A: Fanuc's type A
    outside_corner="extend",  # [K] setting 58 FANUC: a sharp corner
    corner_tolerance=1e-6,
    arc_after_cancel=False,
    planes=("XY",),  # [?] the manual's compensation is the X-Y plane's (the page above speaks of X-Y moves only)
    inside_corner="meet",
    exit_arc_known=False,
    look_ahead=1,
    startup_arc_known=False,
    acute_corner_known=False,
)
"""A Haas mill with settings 43 = A and 58 = FANUC."""
HAAS_B = CutterRules(
    name="Haas cutter compensation (setting 58 FANUC, setting 43 B)",
    register_absent="modal",
    entry="corner",  # [K] setting 43 B: Fanuc's type B
    outside_corner="extend",
    corner_tolerance=1e-6,
    arc_after_cancel=False,
    planes=("XY",),
    inside_corner="meet",
    exit_arc_known=False,
    look_ahead=1,
    startup_arc_known=False,
    acute_corner_known=False,
)
"""A Haas mill with settings 43 = B and 58 = FANUC."""


# Tool nose compensation of a Haas lathe, as its operator's manual describes it (Classic Control lathe
# operator's manual, the stored pages of https://staging-diy.haascnc.com, read in this session):
# [V] "Tool Nose Compensation Geometry": "Two FANUC compensation types are supported, Type A and Type B. The
#     default compensation is Type A"; its figures (approach, mode to mode, departure for line-line,
#     line-arc, arc-line) are Fanuc's figures: every rule of ``FANUC_T`` (start-up, corners, cancel) holds
#     [K: the figures themselves carry no text there]. Which setting chooses type B is not in those pages
#     [?: setting 43 "Cutter Comp Type", as on the Haas mill]: the set-up's ``cutterStartup``.
# [V] "Approach and Departure Moves For TNC": the approach (the first X or Z motion in the block with G41 or
#     G42) must be G00 or G01, not compensated at its start, fully compensated at its end; the departure (a
#     block with G40) must be G00 or G01, starts fully compensated "at a right angle to the last programmed
#     block" (type A's cancel) and ends uncompensated.
# [V] same page: I and K in the G40 block give a vector that decides the compensated end of the block before
#     it (to keep a departure from overcutting): Haas's own, not Fanuc T's; not modelled, refused where it
#     stands (``dialects/fanuc/lathe_block_syntax.py``).
# [V] "Tool Nose Compensation Geometry" again, its "Tool Radius And Angle Chart (1/32 RADIUS)": per taper angle, the X (diameter) and Z amounts a
#     1/32 in nose's compensation moves a taper by; the simulation reproduces its rows to its last digit
#     (tests/test_haas_nose.py ``HAAS_CHART``): the mode-to-mode offset geometry, tip 3.
# [V] "Tool Nose Compensation Concept": G41 shifts the tool to the left of the programmed path, G42 to the
#     right, G40 cancels; OD turning toward the chuck takes G42.
# [V] "Imaginary Tool Tip and Direction": the tip code 0-9 sits next to the radius on the geometry offsets
#     page; directions as ``nose.TIPS`` (which cites it). The T code's offset number selects the offset
#     (``T0101``) [K: the manual's TNC examples], as on Fanuc T: ``register_absent="offset"``.
HAAS_T = dataclasses.replace(FANUC_T, name="Haas lathe tool nose compensation (type A)", roughing_cycles=frozenset())
"""A Haas lathe, type A (the default): Fanuc T's rules, one algorithm (``extended_corners``)."""
HAAS_T_B = dataclasses.replace(FANUC_T_B, name="Haas lathe tool nose compensation (type B)",
                               roughing_cycles=frozenset())
"""A Haas lathe with type B chosen: Fanuc T's type B rules."""
