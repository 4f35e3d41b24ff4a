"""Fanuc milling (0i-MF / 30i-M) codes: one table, read by the reader and inverted by the writer.

Rows are ``(spelling, modal group, kind, argument)`` (see ``postproc.rs274.codes``); Fanuc writes the
spelling with its leading zero (``G00``, ``M03``) and reads ``G0``/``G00``/``G000`` alike. Modal groups
follow the Fanuc manuals (01 motion, 09 canned cycles, 11 scaling, 16 rotation, 22 mirror image, ...).
The frame codes (G52, G92, G68/G69, G51/G50, G51.1/G50.1)
and G16/G15 (polar coordinates, modal group 17) are read into ``FrameChange`` (``postproc.frames``).
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable
from postproc.rs274.cycle_words import rs274_cycle_words

ROWS = (
    ("G00", "01", "motion", "rapid"),
    ("G01", "01", "motion", "linear"),
    ("G02", "01", "motion", "cw"),
    ("G03", "01", "motion", "ccw"),
    ("G04", "00", "dwell", None),
    ("G09", "00", "path_once", "exact_stop"),
    ("G15", "17", "frame", "polar_off"),
    ("G16", "17", "frame", "polar"),
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
    ("G44", "08", "length", "negative"),
    ("G49", "08", "length", "cancel"),
    ("G50", "11", "frame", "scale_off"),
    ("G50.1", "22", "frame", "mirror_off"),
    ("G51", "11", "frame", "scale"),
    ("G51.1", "22", "frame", "mirror"),
    ("G52", "00", "frame", "local"),
    ("G53", "00", "machine", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G61", "15", "path", "exact_stop"),
    ("G64", "15", "path", "cutting"),
    ("G68", "16", "frame", "rotate"),
    ("G69", "16", "frame", "rotate_off"),
    ("G73", "09", "cycle", "peck_chip"),
    ("G74", "09", "cycle", "tap_left"),
    ("G76", "09", "cycle", "fine_bore"),
    ("G80", "09", "cycle_cancel", None),
    ("G81", "09", "cycle", "drill"),
    ("G82", "09", "cycle", "drill_dwell"),
    ("G83", "09", "cycle", "peck_deep"),
    ("G84", "09", "cycle", "tap"),
    ("G85", "09", "cycle", "bore_feed"),
    ("G86", "09", "cycle", "bore_stop"),
    ("G87", "09", "cycle", "back_bore"),
    ("G88", "09", "cycle", "bore_manual"),
    ("G89", "09", "cycle", "bore_dwell_feed"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G92", "00", "frame", "origin"),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
    ("G98", "10", "return", "initial"),
    ("G99", "10", "return", "r"),
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
"""Codes whose meaning the IR models."""

CODES = CodeTable(
    ROWS,
    native_g={
        "7.1": "cylindrical interpolation",
        "10": "programmable data input",
        "11": "programmable data input cancel",
        "31": "skip function",
        "65": "macro call",
        "66": "modal macro call",
        "67": "modal macro call cancel",
        "54.1": "additional work coordinate systems",
    },
    native_m={98: "subprogram call", 99: "subprogram return"},
)
"""Fanuc's code table. ``native_g``/``native_m``: codes kept verbatim; they round-trip to Fanuc and are
unsupported anywhere else. Machine builders' codes (M29, G05.1, ...) are in ``machine_codes``."""

CYCLE_WORDS = rs274_cycle_words(CODES, None, max_repeat=9999)
"""The hole-cycle words this table gives (the dialect's ``CYCLE_WORDS``, imported with the table where a run
first reads them: registering the dialect imports neither)."""
