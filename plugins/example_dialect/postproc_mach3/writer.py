"""The Mach3 writer: RS274/NGC words spelt from ``CODES``, fixed-width axis words. In a module of its own so
that registering the dialect (every run, ``postproc dialects``) does not import the word writer it extends
(``Mach3.WRITER`` is ``Lazy``)."""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.ir.expr import Expr
from postproc.ir import Block, Motion
from postproc.rs274.codes import CodeTable
from postproc.rs274.writer import WordWriter

from .codes import CODES


class Mach3Writer(WordWriter):
    """Spells codes from ``CODES``; axis words fixed-width. An unchanged block read from Mach3 is copied
    as it was (the base class does it), so a Mach3 program reads back byte for byte."""

    DIALECT: ClassVar[str] = "mach3"
    CODES: ClassVar[CodeTable] = CODES
    """No M19 row: an oriented spindle stop is an unsupported construct here."""
    DWELL_WORD: ClassVar[str] = "P"
    """G4 P<seconds>."""
    TOOL_TABLE_LACK: ClassVar[str] = (
        "Mach3's G10 L1 tool table setting and whether it acts on the active tool as LinuxCNC's does are [?]: not "
        "confirmed from its manual, not written here")
    CYCLE_CANCEL_IS_MOTION: ClassVar[bool] = True
    """G80 and G0 are one modal group (RS274/NGC): a block with a motion code leaves G80 out."""
    BARE_FEED_MOTION_NEEDS_FEED: ClassVar[bool] = True
    """A bare ``G1`` with no feed rate in force is refused (RS274/NGC), as this dialect's reader does: the
    code only sets the mode, and every later move writes its own, so it is left out."""
    WORK_OFFSET_SETTING: ClassVar[str] = "G10 L2"
    """G10 L2 P1-P6 sets fixture P's origin, absolutely whatever G90/G91 (``codes.NATIVE_G`` [K])."""
    WORK_OFFSET_COUNT: ClassVar[int] = 6
    AXIS_DECIMALS: ClassVar[int] = 4
    """Axis, centre and radius words carry at least this many decimals (more only where fewer would
    round the value)."""

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        if s.mode is None:
            self.unsupported("a canned-cycle repetition without its cycle", block)
        if self.left_out(s, block) or s.mode in ("home", "home2") and not s.axes:
            return []  # a return naming no axis moves none (Fanuc); a bare G28 here would move every axis
        words = self._code("home" if s.mode in ("home", "home2") else "motion", s.mode, f"{s.mode} motion", block)
        if self.rounding:  # rounded by the set-up: the base's position() carries what rounding left behind
            incremental = self.modal.distance == "incremental" and "MachineCoordinates" not in block.sections
            words.extend(axis + (self.pad(self.position(axis, value, incremental), axis) if isinstance(value, float)
                                 else self.fixed(value, block, axis)) for axis, value in s.axes.items())
        else:
            words.extend(axis + self.fixed(value, block, axis) for axis, value in s.axes.items())
        if s.center is not None:
            words.extend(letter + self.fixed(s.center[axis], block, letter)
                         for axis, letter in (("X", "I"), ("Y", "J"), ("Z", "K")) if axis in s.center)
        if s.radius is not None:
            words.append("R" + self.fixed(s.radius, block, "R"))
        return words

    def program_start(self, s: Any, block: Block) -> str:
        """This dialect reads no O-words (no subprograms): a program number survives as a comment."""
        name = f"O{int(s.number):04d}" if s.number is not None else str(s.name)
        return self.comment(name)

    def pad(self, text: str, letter: str) -> str:
        """A rounded number with the trailing zeros of its address's places (``X1.50`` for two)."""
        places = (self.mm_places if self.modal.units == "mm" else self.inch_places).get(letter)
        if places is None:
            return text
        return text + "0" * (places - (len(text) - text.index(".") - 1))

    def fixed(self, value: Any, block: Block, letter: str) -> str:
        if isinstance(value, Expr):  # a computed word: this dialect has no expressions (PROGRAMS is False)
            self.unsupported("a computed word", block)
        mm = self.modal.units == "mm"
        places = (self.mm_places if mm else self.inch_places).get(letter) if self.rounding else None
        if places is not None:  # the set-up's <Output addressDecimals>: rounded, then fixed width
            return self.pad(self.rounded(float(value), letter, places, mm), letter)
        # at least AXIS_DECIMALS places; where that would round the value (an inch program converted,
        # a computed value), Python's shortest exact spelling of the float instead
        value = float(value)
        text = f"{value:.{self.AXIS_DECIMALS}f}"
        if float(text) != value:
            text = repr(value)
            if "e" in text or "E" in text or "." not in text:  # inf/nan never reach here: the reader refuses them
                text = f"{value:.20f}".rstrip("0")
            places = len(text) - text.index(".") - 1
            text += "0" * max(0, self.AXIS_DECIMALS - places)
        return text[1:] if text.startswith("-") and float(text) == 0 else text
