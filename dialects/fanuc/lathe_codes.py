"""Fanuc lathe (0i-TF / 30i-T) codes, one table per G-code system A, B and C (DIALECTS.md 1.1).

The set-up's ``machineType="lathe"`` selects these tables instead of the milling one, and its
``gcodeSystem`` selects the column: the same number means a different thing in each (G92 is the
threading cycle in A and coordinate setting in B and C; G98/G99 are feed modes in A only). Rows are
``(spelling, modal group, kind, argument)`` as in ``codes.py``; groups follow the Fanuc T manuals
(01 motion and the single cycles, 00 one-shot codes and G70-G76, 02 spindle speed mode, 16 planes).
G80 is the canned-cycle cancel in every system [K: Fanuc 0i-TF G-code list, "G80: canned cycle for drilling
cancel"; Haas lathe operator's manual G80 "Canned Cycle Cancel", which Haas programs write in their first
block, ``G00 G18 G20 G40 G80 G99``]: the drilling cycles it cancels stay verbatim (system A), and a G80
while a single cycle (G90/G92/G94) is in force is refused (``LatheBlockSyntax``: whether it ends one differs
between controls).
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable, Row

COMMON: tuple[Row, ...] = (
    ("G00", "01", "motion", "rapid"),
    ("G01", "01", "motion", "linear"),
    ("G02", "01", "motion", "cw"),
    ("G03", "01", "motion", "ccw"),
    ("G04", "00", "dwell", None),
    ("G17", "16", "plane", "XY"),
    ("G18", "16", "plane", "ZX"),
    ("G19", "16", "plane", "YZ"),
    ("G28", "00", "home", "home"),
    ("G30", "00", "home", "home2"),
    ("G40", "07", "cutter", "off"),
    ("G41", "07", "cutter", "left"),
    ("G42", "07", "cutter", "right"),
    ("G53", "00", "machine", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G80", "09", "cycle_cancel", None),
    ("G96", "02", "spindle_mode", "css"),
    ("G97", "02", "spindle_mode", "rpm"),
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
"""Codes every G-code system spells alike."""

CYCLES_AB: tuple[Row, ...] = (
    ("G70", "00", "lathe_cycle", "turn_finish"),
    ("G71", "00", "lathe_cycle", "turn_rough"),
    ("G72", "00", "lathe_cycle", "face_rough"),
    ("G73", "00", "lathe_cycle", "pattern_repeat"),
    ("G74", "00", "lathe_cycle", "face_peck"),
    ("G75", "00", "lathe_cycle", "groove"),
    ("G76", "00", "lathe_cycle", "thread_multi"),
)

SYSTEM_A: tuple[Row, ...] = COMMON + CYCLES_AB + (
    ("G20", "06", "units", "inch"),
    ("G21", "06", "units", "mm"),
    ("G32", "01", "motion", "thread"),
    ("G50", "00", "coordinate_set", None),
    ("G90", "01", "lathe_cycle", "turn_single"),
    ("G92", "01", "lathe_cycle", "thread_single"),
    ("G94", "01", "lathe_cycle", "face_single"),
    ("G98", "05", "feed_mode", "per_min"),
    ("G99", "05", "feed_mode", "per_rev"),
)
"""System A: U/W for incremental moves, G50 coordinate setting, G98/G99 feed per minute/revolution."""

SYSTEM_B: tuple[Row, ...] = COMMON + CYCLES_AB + (
    ("G20", "06", "units", "inch"),
    ("G21", "06", "units", "mm"),
    ("G33", "01", "motion", "thread"),
    ("G77", "01", "lathe_cycle", "turn_single"),
    ("G78", "01", "lathe_cycle", "thread_single"),
    ("G79", "01", "lathe_cycle", "face_single"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G92", "00", "coordinate_set", None),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
)
"""System B: G90/G91 distance modes, G92 coordinate setting, G94/G95 feed modes."""

SYSTEM_C: tuple[Row, ...] = COMMON + (
    ("G70", "06", "units", "inch"),
    ("G71", "06", "units", "mm"),
    ("G20", "01", "lathe_cycle", "turn_single"),
    ("G21", "01", "lathe_cycle", "thread_single"),
    ("G24", "01", "lathe_cycle", "face_single"),
    ("G33", "01", "motion", "thread"),
    ("G72", "00", "lathe_cycle", "turn_finish"),
    ("G73", "00", "lathe_cycle", "turn_rough"),
    ("G74", "00", "lathe_cycle", "face_rough"),
    ("G75", "00", "lathe_cycle", "pattern_repeat"),
    ("G76", "00", "lathe_cycle", "face_peck"),
    ("G77", "00", "lathe_cycle", "groove"),
    ("G78", "00", "lathe_cycle", "thread_multi"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G92", "00", "coordinate_set", None),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
)
"""System C: the cycles renumbered G72-G78, G70/G71 inch/metric."""

NATIVE_G = {
    "7.1": "cylindrical interpolation",
    "10": "programmable data input",
    "11": "programmable data input cancel",
    "31": "skip function",
    "65": "macro call",
    "66": "modal macro call",
    "67": "modal macro call cancel",
    "112": "polar coordinate interpolation",
    "113": "polar coordinate interpolation cancel",
}
"""Codes kept verbatim (they round-trip to Fanuc and are unsupported anywhere else)."""

NATIVE_M = {98: "subprogram call", 99: "subprogram return"}

LATHE_CODES: dict[str, CodeTable] = {
    "A": CodeTable(SYSTEM_A, native_g={**NATIVE_G, **{str(n): "lathe drilling cycle" for n in (83, 84, 85, 87, 88, 89)}},
                   native_m=NATIVE_M),
    "B": CodeTable(SYSTEM_B, native_g={**NATIVE_G, "98": "drilling cycle return to the initial level",
                                       "99": "drilling cycle return to the R level"}, native_m=NATIVE_M),
    "C": CodeTable(SYSTEM_C, native_g={**NATIVE_G, "98": "drilling cycle return to the initial level",
                                       "99": "drilling cycle return to the R level"}, native_m=NATIVE_M),
}
"""Fanuc's lathe code tables by G-code system (the set-up's ``gcodeSystem``)."""
