"""LinuxCNC (RS274/NGC, milling) codes: one table, read by the reader and inverted by the writer.

Rows are ``(spelling, modal group, kind, argument)`` (see ``postproc.rs274.codes``); LinuxCNC writes
codes without leading zeros (``G0``, ``M3``). The rows were copied from the Fanuc milling table and
changed where the same number means something else or does not exist: no G9 or G44, G76 is threading
and G87/G88 follow the NIST RS274/NGC words and motion (kept verbatim, see ``NATIVE_G``); G59.1-G59.3,
G61.1 and G93 are added; on a lathe set-up G33 (spindle-synchronised motion, K the distance per revolution),
G96 S D/G97 (constant surface speed with its clamp) and G7/G8 read into lathe sections (``lathe``), and G76 (the
threading cycle) into its moves (``threading``), as are G70-G72.2 (the lathe cycles, ``lathe_cycles``); on a mill they stay verbatim (``NATIVE_G``); G33.1 (rigid tapping) reads into ``RigidTap`` and G90.1/G91.1 (the arc centre
mode, kind ``arc_centres``, which no section carries) into offsets from the arc's start (``block_syntax``). G61 (exact path) and G61.1 (exact stop) both read as exact stop (a
reading kept from before the IR told them apart: the same programmed points; G61.1 is not written, so every
output that has G61 keeps it); G61 is written for both, and for the exact path (grbl's one mode) [V:
``g-code.adoc`` "G61 Exact Path mode", "G61.1 Exact Stop mode"]. Sources: LinuxCNC ``docs/src/gcode/g-code.adoc`` and
``m-code.adoc``, and DIALECTS.md §2.1 "LinuxCNC / RS274-NGC baseline". G52 and G92-G92.3 are frame
codes (``postproc.frames``, rs274 rules).
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable
from postproc.rs274.cycle_words import rs274_cycle_words

ROWS = (
    ("G0", "01", "motion", "rapid"),
    ("G1", "01", "motion", "linear"),
    ("G2", "01", "motion", "cw"),
    ("G3", "01", "motion", "ccw"),
    ("G33", "01", "motion", "thread"),
    ("G33.1", "01", "motion", "rigid_tap"),
    ("G76", "01", "motion", "ngc_thread_cycle"),
    ("G70", "01", "motion", "ngc_g70"),
    ("G71", "01", "motion", "ngc_g71"),
    ("G71.1", "01", "motion", "ngc_g71.1"),
    ("G71.2", "01", "motion", "ngc_g71.2"),
    ("G72", "01", "motion", "ngc_g72"),
    ("G72.1", "01", "motion", "ngc_g72.1"),
    ("G72.2", "01", "motion", "ngc_g72.2"),
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
    ("G43.1", "08", "length", "dynamic"),
    ("G49", "08", "length", "cancel"),
    ("G52", "00", "frame", "local"),
    ("G53", "00", "machine", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G59.1", "14", "offset", 7),
    ("G59.2", "14", "offset", 8),
    ("G59.3", "14", "offset", 9),
    ("G61", "15", "path", "exact_stop"),
    ("G61.1", "15", "path", "exact_stop"),
    ("G64", "15", "path", "cutting"),
    ("G73", "09", "cycle", "peck_chip"),
    ("G74", "09", "cycle", "tap_left"),
    ("G80", "09", "cycle_cancel", None),
    ("G81", "09", "cycle", "drill"),
    ("G82", "09", "cycle", "drill_dwell"),
    ("G83", "09", "cycle", "peck_deep"),
    ("G84", "09", "cycle", "tap"),
    ("G85", "09", "cycle", "bore_feed"),
    ("G86", "09", "cycle", "bore_stop"),
    ("G89", "09", "cycle", "bore_dwell_feed"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G90.1", "13", "arc_centres", "absolute"),
    ("G91.1", "13", "arc_centres", "incremental"),
    ("G92", "00", "frame", "origin"),
    ("G92.1", "00", "frame", "origin_clear"),
    ("G92.2", "00", "frame", "origin_suspend"),
    ("G92.3", "00", "frame", "origin_restore"),
    ("G93", "05", "feed_mode", "inverse_time"),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
    ("G96", "96", "spindle_mode", "css"),
    ("G97", "96", "spindle_mode", "rpm"),
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
    ("M19", "", "orient", None),
    ("M30", "", "program", "end_rewind"),
)
"""Codes whose meaning the IR models (M19 takes its angle from R on LinuxCNC)."""

NATIVE_G: dict[str, str] = {
    "5": "cubic spline", "5.1": "quadratic spline", "5.2": "NURBS block", "5.3": "NURBS block end",
    "7": "lathe diameter mode", "8": "lathe radius mode", "10": "set offsets (G10 L)",
    "17.1": "UV plane", "18.1": "WU plane", "19.1": "VW plane", "28.1": "store G28 position",
    "30.1": "store G30 position", "33": "spindle-synchronised motion",
    "38.2": "probe toward, error on failure", "38.3": "probe toward", "38.4": "probe away, error on failure",
    "38.5": "probe away", "41.1": "dynamic cutter compensation left",
    "42.1": "dynamic cutter compensation right",
    "43.2": "additional tool length offset", "70": "lathe finishing cycle", "71": "lathe roughing cycle",
    "71.1": "lathe roughing cycle", "71.2": "lathe roughing cycle", "72": "lathe facing cycle",
    "72.1": "lathe facing cycle", "72.2": "lathe facing cycle", "76": "threading cycle",
    "87": "RS274/NGC back boring (I/J shift, K top)", "88": "RS274/NGC manual boring",
    "96": "constant surface speed", "97": "spindle speed in rpm",
}
"""LinuxCNC codes kept verbatim: they round-trip to LinuxCNC and are unsupported anywhere else."""

REFUSED_G: dict[str, str] = {}
"""Codes that would change how later blocks read: refused rather than kept verbatim."""

NATIVE_M: dict[int, str] = {
    48: "feed and speed overrides on", 49: "feed and speed overrides off", 50: "feed override control",
    51: "spindle speed override control", 52: "adaptive feed control", 53: "feed stop control",
    60: "pallet change pause", 61: "set current tool", 62: "digital output on, synchronised",
    63: "digital output off, synchronised", 64: "digital output on", 65: "digital output off",
    66: "wait on input", 67: "analog output, synchronised", 68: "analog output",
    70: "save modal state", 71: "invalidate saved modal state", 72: "restore modal state",
    73: "save and autorestore modal state",
}

REFUSED_M: dict[int, str] = {
    98: "a computed M98 (M#..): write M98 P.. alone on its line",
    99: "a computed M99 (M#..): write M99 alone on its line",
}

USER_M = range(100, 200)
"""M100-M199 run user programs; kept verbatim."""

M_GROUPS: dict[int, str] = {
    **dict.fromkeys((0, 1, 2, 30, 60), "4"), **dict.fromkeys((6, 61), "6"),
    **dict.fromkeys((3, 4, 5, 19, 70, 71, 72, 73), "7"), **dict.fromkeys((7, 8, 9), "8"),
    **dict.fromkeys(range(48, 54), "9"), **dict.fromkeys(range(62, 69), "5"), **dict.fromkeys(USER_M, "10"),
}
"""LinuxCNC's M-code modal groups (``m-code.adoc``; each checked with rs274: ``M5 M19``, ``M7 M8``, ``M70 M3``,
``M62 P1 M64 P2`` and ``M0 M60`` are refused, ``M3 M8 M0`` and ``M48 M3`` run)."""

CODES = CodeTable(ROWS, native_g=NATIVE_G, native_m=NATIVE_M, refused_g=REFUSED_G, refused_m=REFUSED_M,
                  user_m=USER_M, aliases={("path", "exact_path"): "G61"})
"""LinuxCNC's code table."""

CYCLE_WORDS = rs274_cycle_words(CODES, ("L",))
"""The hole-cycle words this table gives (the dialect's ``CYCLE_WORDS``, imported with the table where a run
first reads them: registering the dialect imports neither)."""
