"""Example dialect plugin: a Fanuc-like mill control that writes G0/G1 and 4-decimal axis words.

A plugin needs only what this module shows: a code table (its own rows, read and written alike), a
``Dialect`` subclass, a writer, and a ``hookimpl`` that registers the dialect. It touches no postproc globals and is found through its entry point.
"""

from __future__ import annotations

from typing import Callable, ClassVar

from postproc.dialect import Dialect
from postproc.hookspecs import hookimpl
from postproc.ir import Block, Motion
from postproc.rs274.codes import CodeTable
from postproc.rs274.order_of_execution import stops_before_motion
from postproc.rs274.writer import WordWriter

CODES = CodeTable((
    ("G0", "01", "motion", "rapid"),
    ("G1", "01", "motion", "linear"),
    ("G2", "01", "motion", "cw"),
    ("G3", "01", "motion", "ccw"),
    ("G04", "00", "dwell", None),
    ("G09", "00", "path_once", "exact_stop"),
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
    ("G53", "00", "machine", None),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G61", "15", "path", "exact_stop"),
    ("G64", "15", "path", "cutting"),
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
    ("M30", "", "program", "end_rewind"),
))
"""The controller's codes, read and written from these rows: Fanuc's spelling with motion codes
without a leading zero, and no oriented spindle stop (M19)."""


class ExampleWriter(WordWriter):
    """Spells codes from ``CODES``; axis words fixed-width."""

    DIALECT: ClassVar[str] = "example"
    CODES: ClassVar[CodeTable] = CODES
    """No M19 row: an oriented spindle stop is an unsupported construct here."""
    DWELL_WORD: ClassVar[str] = "X"
    """G04 X<seconds>."""
    AXIS_DECIMALS: ClassVar[int] = 4
    """Axis, centre and radius words always carry exactly this many decimals."""

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        if s.mode is None:
            self.unsupported("a canned-cycle repetition without its cycle", block)
        words = self._code("home" if s.mode in ("home", "home2") else "motion", s.mode, f"{s.mode} motion", block)
        words.extend(axis + self.fixed(value) for axis, value in s.axes.items())
        if s.center is not None:
            words.extend(letter + self.fixed(s.center[axis])
                         for axis, letter in (("X", "I"), ("Y", "J"), ("Z", "K")) if axis in s.center)
        if s.radius is not None:
            words.append("R" + self.fixed(s.radius))
        return words

    def fixed(self, value: float) -> str:
        text = f"{value:.{self.AXIS_DECIMALS}f}"
        return text[1:] if text.startswith("-") and float(text) == 0 else text


class Example(Dialect):
    NAME = "example"
    DESCRIPTION = "Example plugin: Fanuc-like mill, G0/G1 and 4-decimal axis words (write only)"
    WRITER = ExampleWriter
    NATIVE_CYCLES = frozenset()
    """No canned cycles: they are expanded into plain moves before writing."""
    SPINDLE_ORIENTATION = False
    """No oriented spindle stop (M19)."""
    LOWERING = (stops_before_motion,)
    """Fanuc-like: a block stops the spindle and the coolant after its motion, so a stop the source made
    before the motion (LinuxCNC, grbl) is written in a block of its own before it."""


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Example)
