"""LinuxCNC (RS274/NGC, milling) G and M code tables in the Fanuc tables' format.

Spread from Fanuc's tables (as sqlglot dialects spread their parent's) and overridden where the same
number means something else or does not exist. Sources: LinuxCNC ``docs/src/gcode/g-code.adoc`` and
``m-code.adoc``, and DIALECTS.md §2.1 "LinuxCNC / RS274-NGC baseline".
"""

from __future__ import annotations

from dialects.fanuc.codes import G_CODES as FANUC_G
from dialects.fanuc.codes import M_CODES as FANUC_M

_NOT_IN_LINUXCNC = ("9", "44", "76", "87", "88")
"""Fanuc codes LinuxCNC lacks (G9, G44) or gives another meaning (G76 threading; G87/G88 follow the
NIST RS274/NGC words and motion, not Fanuc's: they are kept verbatim, see ``NATIVE_G``)."""

G_CODES: dict[str, tuple[str, str, object]] = {
    **{k: v for k, v in FANUC_G.items() if k not in _NOT_IN_LINUXCNC},
    "59.1": ("14", "offset", 7),
    "59.2": ("14", "offset", 8),
    "59.3": ("14", "offset", 9),
    "61.1": ("15", "path", "exact_stop"),
    "93": ("05", "feed_mode", "inverse_time"),
}
"""Codes whose meaning the IR models; group numbers follow Fanuc's so the shared block logic applies.
G61 (exact path) and G61.1 (exact stop) both read as exact stop: the IR does not tell them apart."""

NATIVE_G: dict[str, str] = {
    "5": "cubic spline", "5.1": "quadratic spline", "5.2": "NURBS block", "5.3": "NURBS block end",
    "7": "lathe diameter mode", "8": "lathe radius mode", "10": "set offsets (G10 L)",
    "17.1": "UV plane", "18.1": "WU plane", "19.1": "VW plane", "28.1": "store G28 position",
    "30.1": "store G30 position", "33": "spindle-synchronised motion", "33.1": "rigid tapping",
    "38.2": "probe toward, error on failure", "38.3": "probe toward", "38.4": "probe away, error on failure",
    "38.5": "probe away", "41.1": "dynamic cutter compensation left",
    "42.1": "dynamic cutter compensation right", "43.1": "dynamic tool length offset",
    "43.2": "additional tool length offset", "70": "lathe finishing cycle", "71": "lathe roughing cycle",
    "71.1": "lathe roughing cycle", "71.2": "lathe roughing cycle", "72": "lathe facing cycle",
    "72.1": "lathe facing cycle", "72.2": "lathe facing cycle", "76": "threading cycle",
    "87": "RS274/NGC back boring (I/J shift, K top)", "88": "RS274/NGC manual boring",
    "91.1": "incremental arc centres (the default)", "92": "coordinate system offset",
    "92.1": "reset G92 offsets", "92.2": "reset G92 offsets, keep parameters",
    "92.3": "restore G92 offsets", "96": "constant surface speed", "97": "spindle speed in rpm",
}
"""LinuxCNC codes kept verbatim: they round-trip to LinuxCNC and are unsupported anywhere else."""

REFUSED_G: dict[str, str] = {
    "90.1": "absolute arc centres (G90.1) are not supported by the linuxcnc reader yet",
}
"""Codes that would change how later blocks read: refused rather than kept verbatim."""

M_CODES: dict[int, tuple[str, object]] = dict(FANUC_M)
"""M0-M9 and M19 mean the same as on Fanuc (M19 takes its angle from R on LinuxCNC)."""

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
    98: "subprogram calls (M98/M99) are not supported by the linuxcnc reader",
    99: "subprogram calls (M98/M99) are not supported by the linuxcnc reader",
}

USER_M = range(100, 200)
"""M100-M199 run user programs; kept verbatim."""
