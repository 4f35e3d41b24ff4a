"""Mach3/Mach4 mill codes: one table, read by the reader and inverted by the writer.

Rows are ``(spelling, modal group, kind, argument)`` (``postproc.rs274.codes.CodeTable``). Mach3's
interpreter descends from the NIST RS274/NGC interpreter, so the words, modal groups and order of
execution are RS274/NGC's; codes are written without leading zeros (``G0``, ``M3``), and read with or
without them. Canned cycles are read as G73 and G81-G89 with the RS274/NGC words (R, Q, P seconds, L
repeats). Not in the table, so refused by name when read and never written: M19 (an oriented spindle
stop is a machine builder's macro on Mach3, not a standard code), G44, G95, G90.1 and the lathe codes.
G91.1 (incremental I/J/K: offsets from the arc's start) is read as the mode the IR's arcs already have, so it
leaves no section and is never written; Fusion 360's Mach3 post writes it in its first block
(``G90 G94 G91.1 G40 G49 G17``). [K] Mach3 Mill manual, G-code table: "G91.1 Incremental IJ mode", "G90.1
Absolute IJ mode"; Mach3's initial IJ mode is a configuration setting (General Config, "IJ Mode"), which
this plugin takes as incremental, the mode every arc it reads is given [?]. G90.1 stays unknown: a located
error, never an arc read with the wrong centre.
Sources: the Mach3 Mill "Using Mach3Mill" manual (chapter 10, G- and M-code tables) and the NIST
RS274/NGC interpreter version 3 report the manual follows.
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable
from postproc.rs274.cycle_words import rs274_cycle_words

ROWS = (
    ("G0", "01", "motion", "rapid"),
    ("G1", "01", "motion", "linear"),
    ("G2", "01", "motion", "cw"),
    ("G3", "01", "motion", "ccw"),
    ("G4", "00", "dwell", None),
    ("G17", "02", "plane", "XY"),
    ("G18", "02", "plane", "ZX"),
    ("G19", "02", "plane", "YZ"),
    ("G20", "06", "units", "inch"),
    ("G21", "06", "units", "mm"),
    ("G28", "00", "home", "home"),
    ("G30", "00", "home", "home2"),
    ("G40", "07", "cutter", "off"),
    ("G41", "07", "cutter", "left"),
    ("G42", "07", "cutter", "right"),
    ("G43", "08", "length", "positive"),
    ("G49", "08", "length", "cancel"),
    ("G53", "00", "machine", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G61", "15", "path", "exact_stop"),
    ("G64", "15", "path", "cutting"),
    ("G73", "09", "cycle", "peck_chip"),
    ("G80", "09", "cycle_cancel", None),
    ("G81", "09", "cycle", "drill"),
    ("G82", "09", "cycle", "drill_dwell"),
    ("G83", "09", "cycle", "peck_deep"),
    ("G85", "09", "cycle", "bore_feed"),
    ("G86", "09", "cycle", "bore_stop"),
    ("G89", "09", "cycle", "bore_dwell_feed"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G91.1", "13", "arc_centres", "incremental"),
    ("G94", "05", "feed_mode", "per_min"),
    ("G98", "10", "return", "initial"),
    ("G99", "10", "return", "r"),
    ("M0", "", "program", "stop"),
    ("M1", "", "program", "optional_stop"),
    ("M2", "", "program", "end"),
    ("M3", "", "spindle", "cw"),
    ("M4", "", "spindle", "ccw"),
    ("M5", "", "spindle", "stop"),
    ("M6", "", "tool_change", None),
    ("M7", "", "coolant", "mist"),
    ("M8", "", "coolant", "flood"),
    ("M9", "", "coolant", "off"),
    ("M30", "", "program", "end_rewind"),
)
"""The codes this dialect reads and writes; the writer spells a meaning as its first row."""

USER_M = range(100, 1000)
"""User macros: an M code Mach3 has no built-in meaning for runs the macro file of that name (``M120.m1s``) in the
profile's macros folder, which the machine's integrator writes (an indexer, a clamp) [K: Mach3 Mill manual, macros;
warp9td's M-code FAQ: "M-Code ... allows you to run a Macro"]; read and written verbatim, like LinuxCNC's
M100-M199. The span: the numbers user macros take beyond the built-in codes, M100-M999 [?: Mach3 runs a macro for
an unused number below 100 too; those stay refused, a machine builder's meaning this plugin does not know]."""

M_GROUPS: dict[int, str] = {
    **dict.fromkeys((0, 1, 2, 30), "4"), 6: "6", **dict.fromkeys((3, 4, 5), "7"), **dict.fromkeys((7, 8, 9), "8"),
    **dict.fromkeys(USER_M, "10"),
}
"""RS274/NGC M-code modal groups: two codes of one group in a block are an error."""

NATIVE_G: dict[str, str] = {"10": "coordinate system data (G10 L2)"}
"""G10 is read only in its ``L2`` form (``Mach3BlockSyntax.DATA_TABLES``): a work offset set from the program. [K]
"Using Mach3Mill" (Beta 7.57), chapter 10, "Coordinate system data - G10": ``G10 L2 P~ X~ Y~ Z~ A~ B~ C~`` sets the
origin of fixture P to the given coordinates, in terms of the absolute (machine) coordinate system, axis words
optional (the NIST RS274/NGC version 3 rule, section 3.5.5, which the manual copies) [?: not run on a Mach3
here]. Another L is kept verbatim (this dialect only)."""

CODES = CodeTable(ROWS, native_g=NATIVE_G, user_m=USER_M)

CYCLE_WORDS = rs274_cycle_words(CODES, ("L",))
"""The hole-cycle words this table gives (the dialect's ``CYCLE_WORDS``, imported with the table where a run
first reads them: registering the dialect imports neither)."""
