"""grbl 1.1 codes: one table, read by the reader and inverted by the writer (sources: ``postproc_grbl``).

Rows are ``(spelling, modal group, kind, argument)`` (see ``postproc.rs274.codes``), copied from the
LinuxCNC rows for what grbl's parser (``grbl/gcode.c``) accepts; grbl writes codes without leading
zeros. Codes a Fanuc or LinuxCNC program commonly carries and grbl rejects get a message saying why in
``REFUSED_G``/``REFUSED_M``. M19 is a row (a grbl build may have it), but the reader accepts it only
when the set-up says so (``NO_M19``).
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
    ("G43.1", "08", "length", "dynamic"),
    ("G49", "08", "length", "cancel"),
    ("G53", "00", "machine", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G61", "15", "path", "exact_path"),
    ("G80", "09", "cycle_cancel", None),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G92", "00", "frame", "origin"),
    ("G92.1", "00", "frame", "origin_clear"),
    ("G93", "05", "feed_mode", "inverse_time"),
    ("G94", "05", "feed_mode", "per_min"),
    ("M0", "", "program", "stop"),
    ("M1", "", "program", "optional_stop"),
    ("M2", "", "program", "end"),
    ("M3", "", "spindle", "cw"),
    ("M4", "", "spindle", "ccw"),
    ("M5", "", "spindle", "stop"),
    ("M7", "", "coolant", "mist"),
    ("M8", "", "coolant", "flood"),
    ("M9", "", "coolant", "off"),
    ("M19", "", "orient", None),
    ("M30", "", "program", "end_rewind"),
)
"""Codes whose meaning the IR models and grbl runs (G43.1 takes its length from the Z word of its block:
a tool length offset ``dynamic``; G61 is accepted and has no effect in grbl; M1 is
accepted and ignored; M7 needs ENABLE_M7 in config.h). G92 and G92.1 are LinuxCNC's, read into the frame under
its rules (``postproc.frames``): G92 makes the current point read its words, ``G92 = MPos - WCS - TLO - WPos``
on each named axis, absolute whatever G90/G91, kept through a work system change until G92.1 clears it [V: grbl
1.1 ``gcode.c``, NON_MODAL_SET_COORDINATE_OFFSET; error 26 without an axis word]."""

NATIVE_G: dict[str, str] = {
    "10": "set work offsets (G10 L2/L20)", "28.1": "store G28 position", "30.1": "store G30 position",
    "38.2": "probe toward, error on failure", "38.3": "probe toward", "38.4": "probe away, error on failure",
    "38.5": "probe away", "91.1": "incremental arc centres (the default)",
}
"""grbl codes kept verbatim: they round-trip to grbl and are unsupported anywhere else."""

_NO_CYCLES = "grbl has no canned cycles (G73-G89, G98/G99): translate the program from a dialect that has them"
REFUSED_G: dict[str, str] = {
    **{code: _NO_CYCLES for code in ("73", "74", "76", "81", "82", "83", "84", "85", "86", "87", "88", "89",
                                     "98", "99")},
    "41": "cutter radius compensation (G41/G42) is not supported by grbl",
    "42": "cutter radius compensation (G41/G42) is not supported by grbl",
    "43": "grbl has no tool table: G43 is not supported (grbl's G43.1 takes the offset itself)",
    "44": "grbl has no tool table: G44 is not supported (grbl's G43.1 takes the offset itself)",
    "64": "grbl has no path control modes but G61 (the exact path, its one mode)",
    "95": "grbl has no feed per revolution (G95)",
}

NATIVE_M: dict[int, str] = {56: "parking motion override"}

REFUSED_M: dict[int, str] = {
    6: "grbl 1.1 rejects M6 (no tool changer)",
    98: "grbl has no subprograms (M98/M99)",
    99: "grbl has no subprograms (M98/M99)",
}

USER_M = range(0)
"""grbl has no user M codes."""

NO_M19 = "grbl has no oriented spindle stop (M19); a set-up with <Cycles orientation=\"m19\"/> accepts it"
"""Why the reader refuses M19 unless the set-up says the machine has it."""
M_GROUPS: dict[int, str] = {**dict.fromkeys((0, 1, 2, 30), "4"), **dict.fromkeys((3, 4, 5, 19), "7"),
                            **dict.fromkeys((7, 8, 9), "8"), 56: "9"}
"""grbl's M-code modal groups (``gcode.c``: MODAL_GROUP_M4, M7, M8, M9; M19 where a build has it)."""

CODES = CodeTable(ROWS, native_g=NATIVE_G, native_m=NATIVE_M, refused_g=REFUSED_G, refused_m=REFUSED_M,
                  user_m=USER_M)
"""grbl's code table."""

CYCLE_WORDS = rs274_cycle_words(CODES, ("L",))
"""The hole-cycle words this table gives (the dialect's ``CYCLE_WORDS``, imported with the table where a run
first reads them: registering the dialect imports neither)."""
