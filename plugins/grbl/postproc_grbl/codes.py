"""grbl 1.1 G and M code tables, in the Fanuc tables' format (see ``postproc_grbl`` for the sources).

Only what grbl's parser (``grbl/gcode.c``) accepts is in ``G_CODES``/``M_CODES``; codes a Fanuc or
LinuxCNC program commonly carries and grbl rejects get a message saying why in ``REFUSED_G``/``REFUSED_M``.
"""

from __future__ import annotations

from postproc_linuxcnc.codes import G_CODES as NGC_G

_ACCEPTED = ("0", "1", "2", "3", "4", "17", "18", "19", "20", "21", "28", "30", "40", "49", "53",
             "54", "55", "56", "57", "58", "59", "61", "80", "90", "91", "93", "94")

G_CODES: dict[str, tuple[str, str, object]] = {k: NGC_G[k] for k in _ACCEPTED}
"""Codes whose meaning the IR models and grbl runs (G61 is accepted and has no effect in grbl)."""

NATIVE_G: dict[str, str] = {
    "10": "set work offsets (G10 L2/L20)", "28.1": "store G28 position", "30.1": "store G30 position",
    "38.2": "probe toward, error on failure", "38.3": "probe toward", "38.4": "probe away, error on failure",
    "38.5": "probe away", "43.1": "dynamic tool length offset", "91.1": "incremental arc centres (the default)",
    "92": "coordinate system offset", "92.1": "clear G92 offsets",
}
"""grbl codes kept verbatim: they round-trip to grbl and are unsupported anywhere else."""

_NO_CYCLES = "grbl has no canned cycles (G73-G89, G98/G99): translate the program from a dialect that has them"
REFUSED_G: dict[str, str] = {
    **{code: _NO_CYCLES for code in ("73", "74", "76", "81", "82", "83", "84", "85", "86", "87", "88", "89",
                                     "98", "99")},
    "41": "cutter radius compensation (G41/G42) is not supported by grbl",
    "42": "cutter radius compensation (G41/G42) is not supported by grbl",
    "43": "grbl has no tool table: G43 is not supported (grbl's G43.1 takes the offset itself)",
    "64": "grbl has no path control modes but G61 (it always blends)",
    "95": "grbl has no feed per revolution (G95)",
}

M_CODES: dict[int, tuple[str, object]] = {
    0: ("program", "stop"), 1: ("program", "optional_stop"), 2: ("program", "end"),
    30: ("program", "end_rewind"), 3: ("spindle", "cw"), 4: ("spindle", "ccw"), 5: ("spindle", "stop"),
    7: ("coolant", "mist"), 8: ("coolant", "flood"), 9: ("coolant", "off"),
}
"""M1 is accepted and ignored by grbl; M7 needs ENABLE_M7 in config.h."""

NATIVE_M: dict[int, str] = {56: "parking motion override"}

REFUSED_M: dict[int, str] = {
    6: "grbl 1.1 rejects M6 (no tool changer)",
    19: "grbl has no oriented spindle stop (M19); a set-up with <Cycles orientation=\"m19\"/> accepts it",
    98: "grbl has no subprograms (M98/M99)",
    99: "grbl has no subprograms (M98/M99)",
}

USER_M = range(0)
"""grbl has no user M codes."""
