"""Fanuc milling (0i-MF / 30i-M) G and M code tables: code -> (modal group, function, argument).

The reading side maps codes to neutral functions; the writing side inverts the same tables, so one
table is the single place where Fanuc's spelling of a neutral idea lives.
"""

from __future__ import annotations

G_CODES: dict[str, tuple[str, str, object]] = {
    "0": ("01", "motion", "rapid"),
    "1": ("01", "motion", "linear"),
    "2": ("01", "motion", "cw"),
    "3": ("01", "motion", "ccw"),
    "4": ("00", "dwell", None),
    "9": ("00", "path_once", "exact_stop"),
    "17": ("02", "plane", "XY"),
    "18": ("02", "plane", "ZX"),
    "19": ("02", "plane", "YZ"),
    "20": ("06", "units", "inch"),
    "21": ("06", "units", "mm"),
    "28": ("00", "home", "home"),
    "30": ("00", "home", "home2"),
    "40": ("07", "cutter", "off"),
    "41": ("07", "cutter", "left"),
    "42": ("07", "cutter", "right"),
    "43": ("08", "length", "positive"),
    "44": ("08", "length", "negative"),
    "49": ("08", "length", "cancel"),
    "53": ("00", "machine", None),
    "54": ("14", "offset", 1),
    "55": ("14", "offset", 2),
    "56": ("14", "offset", 3),
    "57": ("14", "offset", 4),
    "58": ("14", "offset", 5),
    "59": ("14", "offset", 6),
    "61": ("15", "path", "exact_stop"),
    "64": ("15", "path", "cutting"),
    "73": ("09", "cycle", "peck_chip"),
    "74": ("09", "cycle", "tap_left"),
    "76": ("09", "cycle", "fine_bore"),
    "80": ("09", "cycle_cancel", None),
    "81": ("09", "cycle", "drill"),
    "82": ("09", "cycle", "drill_dwell"),
    "83": ("09", "cycle", "peck_deep"),
    "84": ("09", "cycle", "tap"),
    "85": ("09", "cycle", "bore_feed"),
    "86": ("09", "cycle", "bore_stop"),
    "87": ("09", "cycle", "back_bore"),
    "88": ("09", "cycle", "bore_manual"),
    "89": ("09", "cycle", "bore_dwell_feed"),
    "90": ("03", "distance", "absolute"),
    "91": ("03", "distance", "incremental"),
    "94": ("05", "feed_mode", "per_min"),
    "95": ("05", "feed_mode", "per_rev"),
    "98": ("10", "return", "initial"),
    "99": ("10", "return", "r"),
}
"""Codes whose meaning the IR models."""

NATIVE_G: dict[str, str] = {
    "5.1": "AI contour control", "7.1": "cylindrical interpolation", "8": "look-ahead control",
    "10": "programmable data input", "11": "programmable data input cancel",
    "15": "polar coordinates cancel", "16": "polar coordinates", "31": "skip function",
    "50": "scaling cancel", "51": "scaling", "50.1": "programmable mirror image cancel",
    "51.1": "programmable mirror image", "52": "local coordinate system", "65": "macro call",
    "66": "modal macro call", "67": "modal macro call cancel", "68": "coordinate rotation",
    "69": "coordinate rotation cancel", "92": "work coordinate system setting",
    "54.1": "additional work coordinate systems",
}
"""Fanuc codes kept verbatim: they round-trip to Fanuc and are unsupported anywhere else."""

M_CODES: dict[int, tuple[str, object]] = {
    0: ("program", "stop"),
    1: ("program", "optional_stop"),
    2: ("program", "end"),
    30: ("program", "end_rewind"),
    3: ("spindle", "cw"),
    4: ("spindle", "ccw"),
    5: ("spindle", "stop"),
    19: ("orient", None),
    6: ("tool_change", None),
    7: ("coolant", "mist"),
    8: ("coolant", "flood"),
    9: ("coolant", "off"),
}

NATIVE_M: dict[int, str] = {29: "rigid tapping", 98: "subprogram call", 99: "subprogram return"}


def g_key(text: str) -> str:
    """Canonical key of a G code number as written: '00' -> '0', '043.40' -> '43.4'."""
    if "." in text:
        whole, _, frac = text.partition(".")
        frac = frac.rstrip("0")
        return f"{int(whole or '0')}.{frac}" if frac else str(int(whole or "0"))
    return str(int(text))

