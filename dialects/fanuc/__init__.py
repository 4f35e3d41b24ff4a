"""Fanuc 0i/30i milling dialect: reader, writer, reading pipeline and capability table."""

from __future__ import annotations

from typing import Callable

from postproc.dialect import Dialect
from postproc.hookspecs import hookimpl
from postproc.rs274.cycle_words import rs274_cycle_words
from postproc.rs274.order_of_execution import stops_before_motion
from postproc.xmlio import XFactory

from .codes import CODES

from .block_syntax import FanucBlockSyntax
from .program import FanucProgramSyntax
from .reader import FanucReader
from .writer import FanucWriter

ALL_MILLING_CYCLES = frozenset({
    "drill", "drill_dwell", "peck_chip", "peck_deep", "tap", "tap_left", "bore_feed", "bore_stop",
    "bore_dwell_feed", "fine_bore", "back_bore", "bore_manual",
})


class Fanuc(Dialect):
    NAME = "fanuc"
    DESCRIPTION = "Fanuc 0i/30i milling, Custom Macro B and subprograms"
    READER = FanucReader
    WRITER = FanucWriter
    PIPELINE_FILE = "fanuc.xml"
    CYCLE_WORDS = rs274_cycle_words(CODES, None, max_repeat=9999)
    """R level, Q peck/shift, P dwell (ms); K, L or K+L repeats (0-9999) per the set-up; cycles named
    G73-G89."""
    NATIVE_CYCLES = ALL_MILLING_CYCLES
    """G73, G74, G76, G81-G89 all run natively."""
    FAMILY = "fanuc"
    """Machine builders' codes (``machine_codes``) pass verbatim between Fanuc-family controls."""
    PROGRAMS = True
    """Custom Macro B variables, expressions, IF/GOTO, WHILE, M98/G65 subprograms."""
    LOWERING = (stops_before_motion,)
    """A spindle stop or coolant off that the source made before its block's motion goes in a block of
    its own before it (Fanuc makes them after the motion)."""


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Fanuc)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    FanucBlockSyntax.reg(factory)
    FanucProgramSyntax.reg(factory)
