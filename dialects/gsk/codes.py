"""GSK 980TDc lathe codes: one table, read by the reader and inverted by the writer.

The layout is Fanuc lathe G-code system A (DIALECTS.md 1.2): G90/G92/G94 single cycles, G70-G76 compound
cycles, G32 threading, G50 coordinate setting and spindle clamp, G98/G99 feed per minute/revolution,
U/W incremental addresses. G18 selects the ZX plane, the only one a two-axis lathe turns in (a G17/G19 is an
unknown code) [?: issue 29 and Fanuc T practice; the 980TDc G-code list was not reached]. Rows are ``(spelling, modal group, kind, argument)`` (``postproc.rs274.codes``).
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable

ROWS = (
    ("G00", "01", "motion", "rapid"),
    ("G01", "01", "motion", "linear"),
    ("G02", "01", "motion", "cw"),
    ("G03", "01", "motion", "ccw"),
    ("G04", "00", "dwell", None),
    ("G18", "16", "plane", "ZX"),
    ("G20", "06", "units", "inch"),
    ("G21", "06", "units", "mm"),
    ("G28", "00", "home", "home"),
    ("G30", "00", "home", "home2"),
    ("G32", "01", "motion", "thread"),
    ("G40", "07", "cutter", "off"),
    ("G41", "07", "cutter", "left"),
    ("G42", "07", "cutter", "right"),
    ("G50", "00", "coordinate_set", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G70", "00", "lathe_cycle", "turn_finish"),
    ("G71", "00", "lathe_cycle", "turn_rough"),
    ("G72", "00", "lathe_cycle", "face_rough"),
    ("G73", "00", "lathe_cycle", "pattern_repeat"),
    ("G74", "00", "lathe_cycle", "face_peck"),
    ("G75", "00", "lathe_cycle", "groove"),
    ("G76", "00", "lathe_cycle", "thread_multi"),
    ("G90", "01", "lathe_cycle", "turn_single"),
    ("G92", "01", "lathe_cycle", "thread_single"),
    ("G94", "01", "lathe_cycle", "face_single"),
    ("G96", "02", "spindle_mode", "css"),
    ("G97", "02", "spindle_mode", "rpm"),
    ("G98", "05", "feed_mode", "per_min"),
    ("G99", "05", "feed_mode", "per_rev"),
    ("M00", "", "program", "stop"),
    ("M01", "", "program", "optional_stop"),
    ("M02", "", "program", "end"),
    ("M03", "", "spindle", "cw"),
    ("M04", "", "spindle", "ccw"),
    ("M05", "", "spindle", "stop"),
    ("M08", "", "coolant", "flood"),
    ("M09", "", "coolant", "off"),
    ("M30", "", "program", "end_rewind"),
)
"""Codes whose meaning the IR models."""

CODES = CodeTable(
    ROWS,
    native_g={"31": "skip function", "65": "macro operation (G65 H)"},
    native_m={98: "subprogram call", 99: "subprogram return"},
)
"""GSK's code table. ``native_g``/``native_m``: kept verbatim; they round-trip to GSK only."""
