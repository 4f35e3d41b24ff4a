"""grblHAL codes: one table, read by the reader and inverted by the writer (sources: ``postproc_grblhal``).

Rows are ``(spelling, modal group, kind, argument)`` (see ``postproc.rs274.codes``), for what grblHAL's
parser (``gcode.c``, ``gc_execute_block``, github.com/grblHAL/core stored commit f80fc34) accepts [V]: grbl
1.1's codes, and G43 (from the tool table), G59.1-G59.3 (nine work systems with ``COMPATIBILITY_LEVEL`` <= 1,
the default), G81/G82 (run as RS274/NGC runs them, ``cycles``), G73/G83 (read as grblHAL runs them, ``pecking``), G95 (a spindle with an encoder),
G98/G99, M6, and in lathe mode G7/G8, G33, G96/G97 (``lathe``). grblHAL writes codes without leading zeros. What a build may lack is checked against the
set-up where it is read or written (``Grblhal``); codes a Fanuc or LinuxCNC program carries that grblHAL
refuses, or runs by rules not modelled here, get a message saying why (``REFUSED_G``/``REFUSED_M``).
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
    ("G76", "01", "motion", "grblhal_thread_cycle"),
    ("G4", "00", "dwell", None),
    ("G17", "02", "plane", "XY"),
    ("G18", "02", "plane", "ZX"),
    ("G19", "02", "plane", "YZ"),
    ("G20", "06", "units", "inch"),
    ("G21", "06", "units", "mm"),
    ("G28", "00", "home", "home"),
    ("G30", "00", "home", "home2"),
    ("G40", "07", "cutter", "off"),
    ("G43", "08", "length", "positive"),
    ("G43.1", "08", "length", "dynamic"),
    ("G49", "08", "length", "cancel"),
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
    ("G61", "15", "path", "exact_path"),
    ("G80", "09", "cycle_cancel", None),
    ("G73", "09", "cycle", "peck_chip"),
    ("G81", "09", "cycle", "drill"),
    ("G82", "09", "cycle", "drill_dwell"),
    ("G83", "09", "cycle", "peck_deep"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G92", "00", "frame", "origin"),
    ("G92.1", "00", "frame", "origin_clear"),
    ("G92.2", "00", "frame", "origin_suspend"),
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
"""Codes whose meaning the IR models and grblHAL runs. G43 reads the tool table (a build with one); G43.1
takes its length from the Z word of its block; G61 is accepted and changes nothing (path blending is off
in every build: ``ENABLE_PATH_BLENDING``, "do NOT enable" in ``config.h``); M6 is accepted by every build
(``$341`` chooses a manual change, or ignores it; an ATC runs it); M7 needs a driver with mist coolant
(``hal.coolant_cap.mist``); M19 is a row for a build with a user M code for it (the set-up says so). G33 (K the
distance per revolution along the path) and G96 S D/G97 are read on a lathe set-up only, with G7/G8
(``lathe``): grblHAL's lathe mode, ``$32``.

G92, G92.1 and G92.2 are LinuxCNC's, read into the frame under its rules (``postproc.frames``), as grbl's
[V: ``gcode.c`` NonModal_SetCoordinateOffset: ``G92 = MPos - WCS - TLO - WPos`` on each named axis, the others
kept, absolute whatever G90/G91, error 26 without an axis word; G92.1 zeroes the offset in force and the stored
one; G92.2 zeroes the offset in force only]. G92.3 stays verbatim (``NATIVE_G``): it restores the offset from
non-volatile storage, which G92 writes only while G92 persistence is on (``$384=0``, the default at
``COMPATIBILITY_LEVEL`` <= 1); with ``$384=1`` it restores whatever an earlier run stored, which no program
says [?: the set-up does not say which]."""

NATIVE_G: dict[str, str] = {
    "5": "cubic spline", "5.1": "quadratic spline", "10": "set offsets and tool data (G10 L1/L2/L10/L11/L20)",
    "28.1": "store G28 position", "30.1": "store G30 position",
    "38.2": "probe toward, error on failure", "38.3": "probe toward", "38.4": "probe away, error on failure",
    "38.5": "probe away", "43.2": "additional tool length offset", "91.1": "incremental arc centres (the default)",
    "92.3": "restore G92 offsets from storage (what they are depends on the $384 setting)",
}
"""grblHAL codes kept verbatim: they round-trip to grblHAL and are unsupported anywhere else [V: gcode.c]."""

_NOT_RUN = ("grblHAL's parser accepts G85, G86 and G89 but its motion control runs only G73 and G81-G84 "
            "(motion_control.c mc_canned_drill), so the block would not move: refused")
G76_ON_A_MILL = ("grblHAL's G76 threading cycle (mc_thread) is read in lathe mode only: a set-up with <Input "
                 "machineType=\"lathe\"/> reads it")
REFUSED_G: dict[str, str] = {
    "84": ("grblHAL's G84 is experimental (a spindle with the at-speed capability reverses at the bottom, "
           "and P is required): not modelled, so a translation expands it"),
    "85": _NOT_RUN, "86": _NOT_RUN, "89": _NOT_RUN,
    "74": "grblHAL has no G74 (left-hand tapping cycle)",
    "41": "cutter radius compensation (G41/G42) is off in grblHAL builds (CUTTER_COMP_ENABLE, experimental)",
    "42": "cutter radius compensation (G41/G42) is off in grblHAL builds (CUTTER_COMP_ENABLE, experimental)",
    "44": "grblHAL has no G44 (negative tool length offset)",
    "64": "grblHAL has no path control modes but G61 (path blending is off in every build)",
    "65": ("grblHAL's G65 P1-P7 are its inbuilt macros (a setting, a tool offset, a parameter, the machine state, "
           "probe selection, spindle delay, Modbus: ngc_params.c), other numbers run a file system plugin's "
           "P<n>.macro file: a Fanuc macro call has no counterpart in the program (not modelled)"),
    "66": "a G66 modal macro call needs a grblHAL macro plugin: not modelled",
    "67": "a G67 modal macro cancel needs a grblHAL macro plugin: not modelled",
}

NATIVE_M: dict[int, str] = {
    48: "feed and speed overrides on", 49: "feed and speed overrides off", 50: "feed override control",
    51: "spindle speed override control", 53: "feed stop control", 56: "parking motion override",
    61: "set current tool", 62: "digital output on, synchronised", 63: "digital output off, synchronised",
    64: "digital output on", 65: "digital output off", 66: "wait on input", 67: "analog output, synchronised",
    68: "analog output",
}
"""grblHAL M codes kept verbatim (a driver with the ports or the setting) [V: gcode.c]."""

REFUSED_M: dict[int, str] = {
    98: "M98 needs a grblHAL macro plugin: not modelled",
    99: "M99 returns from a grblHAL macro or file: not modelled",
    60: "grblHAL's M60 (pallet change pause) is not modelled",
}

USER_M = range(0)
"""User M codes depend on the plugins a build has: none is assumed."""

NO_M19 = "grblHAL has no oriented spindle stop (M19); a set-up with <Cycles orientation=\"m19\"/> accepts it"
"""Why the reader refuses M19 unless the set-up says the machine has it."""
M_GROUPS: dict[int, str] = {**dict.fromkeys((0, 1, 2, 30), "4"), **dict.fromkeys((3, 4, 5, 19), "7"),
                            **dict.fromkeys((7, 8, 9), "8"), **dict.fromkeys((48, 49, 50, 51, 53, 56), "9"),
                            **dict.fromkeys((6, 61), "6"), **dict.fromkeys(range(62, 69), "5")}
"""grblHAL's M-code modal groups (``gcode.c``: M4, M5, M6, M7, M8, M9 groups)."""

CODES = CodeTable(ROWS, native_g=NATIVE_G, native_m=NATIVE_M, refused_g=REFUSED_G, refused_m=REFUSED_M,
                  user_m=USER_M)
"""grblHAL's code table."""

CYCLE_WORDS = rs274_cycle_words(CODES, ("L",))
"""The hole-cycle words this table gives (the dialect's ``CYCLE_WORDS``, imported with the table where a run
first reads them: registering the dialect imports neither)."""
