"""SINUMERIK 840D sl / 828D milling codes: one table, read by the block syntax and inverted by the writer.

Rows are ``(spelling, modal group, kind, argument)`` (``postproc.rs274.codes``), group labels the
family's (01 motion, 06 units, 15 path control...). Sources: SINUMERIK 840D sl Fundamentals / Job
planning (list of G functions) [K], the ONE NC programming manual 12/2019 p.309/p.315 [K], the Autodesk
``siemens-840d.cps`` post (``G4 F`` seconds, ``G710``/``G700``, ``G64``, ``G60``) [K]. Where a number
means something else on a Fanuc control, the table is what tells them apart (issue 28, item 5):

* ``G70``/``G71`` are inch/mm for the geometry only (feeds stay in the basic system's unit) and
  ``G700``/``G710`` inch/mm for feeds too (``block_syntax`` refuses an F that G70/G71 would leave in
  another unit); the writer writes ``G700``/``G710``, whose meaning is the neutral one.
* ``G58``/``G59`` are axial programmable offsets, not work systems 5 and 6: kept verbatim. The settable
  work offsets are ``G54``-``G57`` (1-4) and ``G505``-``G599`` (5-99). ``G500`` (deselect, or the base
  frame G500 holds) is kept verbatim [?].
* ``G4`` takes its time in ``F`` (seconds) or ``S`` (spindle revolutions, not modelled), never a feed.
* ``G33`` is thread cutting: kept verbatim. ``G331``/``G332`` are the rigid tap's strokes, in and out
  (``postproc.isg_family.taps``, which says the facts), after ``SPOS=`` (an oriented stop: ``reader``).
* ``G53``/``G153`` suppress the frames for one block (not Fanuc's move in machine coordinates; whether the
  tool offsets stay is machine data ``$MN_G53_TOOLCORR`` [V: 802D sl/840D ISO Milling 04.07, 3.1.1]): the
  block syntax reads them, with ``SUPA``, where that cannot matter (``frame_suppression``), else keeps them
  verbatim (a reference return is written as ``G75``: ``fixed_point``). ``G641``/``G642`` (corner rounding:
  the path is not sharp) and ``G9``'s companions ``G601``-``G603`` are kept verbatim.
* ``M17`` ends a subprogram: the reader reads it as a return.
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable

ROWS = (
    ("G0", "01", "motion", "rapid"),
    ("G1", "01", "motion", "linear"),
    ("G2", "01", "motion", "cw"),
    ("G3", "01", "motion", "ccw"),
    ("G331", "01", "motion", "tap_in"),
    ("G332", "01", "motion", "tap_out"),
    ("G4", "00", "dwell", None),
    ("G9", "00", "path_once", "exact_stop"),
    ("G17", "02", "plane", "XY"),
    ("G18", "02", "plane", "ZX"),
    ("G19", "02", "plane", "YZ"),
    ("G40", "07", "cutter", "off"),
    ("G41", "07", "cutter", "left"),
    ("G42", "07", "cutter", "right"),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    *((f"G{500 + n}", "14", "offset", n) for n in range(5, 100)),
    ("G60", "15", "path", "exact_stop"),
    ("G64", "15", "path", "cutting"),
    ("G710", "06", "units", "mm"),
    ("G700", "06", "units", "inch"),
    ("G71", "06", "units", "mm"),
    ("G70", "06", "units", "inch"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
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
"""Codes whose meaning the IR models; the first row of a meaning is how the writer spells it (G710/G700
before G71/G70, which ``block_syntax`` reads with its feed check). Coolant M7/M8/M9 are the machine
builder's [?: the Autodesk post writes M8/M9]."""

GEOMETRY_UNITS = frozenset({"70", "71"})
"""G70/G71: inch/mm for lengths only (F keeps the basic system's unit)."""

CODES = CodeTable(
    ROWS,
    native_g={
        "5": "high-speed grinding", "25": "working area limitation", "26": "working area limitation",
        "33": "thread cutting",
        "58": "axial programmable offset", "59": "axial programmable offset",
        "500": "settable zero offset deselection", "93": "inverse-time feed", "96": "constant cutting speed",
        "97": "constant cutting speed off", "110": "polar pole", "111": "polar pole", "112": "polar pole",
        "140": "smooth approach and retract", "147": "smooth approach", "148": "smooth retract",
        "601": "exact stop window", "602": "exact stop window", "603": "exact stop window",
        "641": "corner rounding by distance", "642": "corner rounding by tolerance",
        "643": "corner rounding", "644": "corner rounding", "645": "corner rounding",
        "450": "corner behaviour under radius compensation", "451": "corner behaviour under radius compensation",
        "291": "ISO dialect mode", "290": "SINUMERIK mode",
    },
    native_m={19: "spindle positioning"},
)
"""The 840D table. ``native_g``/``native_m``: kept verbatim (round trip to SINUMERIK only, refused
anywhere else and never simulated)."""
