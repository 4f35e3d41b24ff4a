"""ISG (Beckhoff TwinCAT CNC) codes: one table, read by the block syntax and inverted by the writer.

Rows are ``(spelling, modal group, kind, argument)`` (``postproc.rs274.codes``); the group labels
follow the family's (01 motion, 06 units...). The codes whose number means something else on a Fanuc
control are where the table matters (DIALECTS.md 1.3, 3.3):

* ``G70``/``G71`` are inch/mm (Fanuc ``G20``/``G21``); ISG's ``G20``-``G23`` mirror the path.
* ``G98``/``G99`` set the software limit switches, ``G74`` homes, ``G92`` presets the position,
  ``G80``-``G89`` call the machine builder's subroutine files: each is kept verbatim (``native_g``),
  so it round-trips in ISG and is refused by every other dialect, by name and meaning.
* ``G162`` (arc centre relative to the start, the default) is the only arc-centre mode the IR has: it
  adds nothing. ``G161`` (absolute centres) is kept verbatim.
* ``G61``/``G260``/``G261`` (polynomial blending) round the path's corners: kept verbatim, never
  simulated as sharp corners. So Fanuc's ``G61`` (exact stop mode) is never written ``G61`` here.
* Exact stop [V: TF5200 programming manual "Exact stop (G60/G360/G359)", 206301707]: ``G60`` for one
  block (Fanuc ``G09``), ``G360`` selects it (Fanuc ``G61``), ``G359`` deselects it (Fanuc ``G64``).
* ``G53`` deselects the zero offsets (modal), not Fanuc's one-block move in machine coordinates: kept
  verbatim. A move in machine coordinates is ``#SUPPRESS OFFSETS`` (``writer``).
* ``G331``/``G332`` tap in and out spindle-synchronised (``taps``) [V: TF5200 "Tapping (G331/G332)"].
* ``M19`` orients the spindle to the machine's angle (the set-up's ``orientAngle``) [?: a DIN M code
  whose ISG meaning we did not read].
* ``G68 R.. X.. Y..``/``G69`` rotate the programmed contour in the plane [V: TF5200 programming manual, "Rotate
  the coordinate system in the plane (G68/G69)", CNC build V3.1.3079.33 on]: read as the neutral frame change
  under the ``isg`` rules (``postproc.frames``), in G17, G18 (centre Z, X) and G19 (centre Y, Z). ``#ROTATION
  ON/OFF`` is read as the same rotation where its centre offsets are 0 (``rotation``); with others it is kept
  verbatim (its ``CENTER1``/``CENTER2`` are "the offset of the main axis relative to the centre", whose sign is
  not settled [?]).
* ``M17``/``M29`` (subroutine end) are read by the reader (``reader.RETURN_CODES``), not here.
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable

ROWS = (
    ("G00", "01", "motion", "rapid"),
    ("G01", "01", "motion", "linear"),
    ("G02", "01", "motion", "cw"),
    ("G03", "01", "motion", "ccw"),
    ("G04", "00", "dwell", None),
    ("G17", "02", "plane", "XY"),
    ("G18", "02", "plane", "ZX"),
    ("G19", "02", "plane", "YZ"),
    ("G40", "07", "cutter", "off"),
    ("G41", "07", "cutter", "left"),
    ("G42", "07", "cutter", "right"),
    ("G54", "14", "offset", 1),
    ("G68", "16", "frame", "rotate"),
    ("G69", "16", "frame", "rotate_off"),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G60", "00", "path_once", "exact_stop"),
    ("G70", "06", "units", "inch"),
    ("G71", "06", "units", "mm"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
    ("G162", "16", "arc_centre", "relative"),
    ("G331", "01", "motion", "tap_in"),
    ("G332", "01", "motion", "tap_out"),
    ("G359", "15", "path", "cutting"),
    ("G360", "15", "path", "exact_stop"),
    ("M00", "", "program", "stop"),
    ("M01", "", "program", "optional_stop"),
    ("M02", "", "program", "end"),
    ("M03", "", "spindle", "cw"),
    ("M04", "", "spindle", "ccw"),
    ("M05", "", "spindle", "stop"),
    ("M06", "", "tool_change", None),
    ("M07", "", "coolant", "mist"),
    ("M08", "", "coolant", "flood"),
    ("M09", "", "coolant", "off"),
    ("M19", "", "orient", None),
    ("M30", "", "program", "end_rewind"),
)
"""Codes whose meaning the IR models (``arc_centre`` has no section: G162 is the IR's only mode)."""

IMPLICIT_CALL = "implicit subroutine call: runs the file the machine builder configured"

CODES = CodeTable(
    ROWS,
    native_g={
        "10": "feed behaviour under radius compensation", "11": "feed behaviour under radius compensation",
        "12": "corner deceleration off", "13": "corner deceleration on",
        "20": "end of mirroring", "21": "mirroring", "22": "mirroring", "23": "mirroring",
        "33": "thread cutting", "51": "diameter programming on", "52": "diameter programming off",
        "53": "zero offset deselection", "61": "polynomial blending for one block",
        "63": "tapping", "74": "programmable homing", "92": "coordinate preset",
        "93": "feed as time", "96": "constant cutting speed", "97": "spindle speed in rpm",
        "98": "set the negative software limit switch", "99": "set the positive software limit switch",
        "161": "arc centre in absolute coordinates", "260": "polynomial blending off",
        # radius compensation's modes (cutter_rules.py: their constructions are in figures only [?])
        "25": "linear transitions at outside corners under radius compensation",
        "26": "circular transitions at outside corners under radius compensation",
        "138": "direct selection of radius compensation", "139": "indirect selection of radius compensation",
        "236": "direct selection of radius compensation on the path",
        "237": "perpendicular selection of radius compensation",
        "238": "selection of radius compensation at an inside corner",
        "239": "selection of radius compensation without a block", "5": "tangential selection of radius compensation",
        "261": "polynomial blending on",
        **{str(n): IMPLICIT_CALL for n in range(80, 90)},
    },
)
"""ISG's code table. ``native_g``: codes kept verbatim (they round-trip to ISG, are refused anywhere
else and are never simulated)."""
