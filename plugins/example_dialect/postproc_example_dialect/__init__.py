"""Example dialect plugin: a Fanuc-like mill control that writes G0/G1 and 4-decimal axis words.

A plugin needs only what this module shows: a ``Dialect`` subclass, a writer, and a ``hookimpl`` that
registers the dialect. It touches no postproc globals and is found through its entry point.
"""

from __future__ import annotations

from typing import Callable, ClassVar

from postproc.dialect import Dialect
from postproc.hookspecs import hookimpl
from postproc.ir import Block, Motion
from postproc.rs274.writer import WordWriter


class ExampleWriter(WordWriter):
    """Fanuc's spelling, except motion codes without a leading zero and fixed-width axis words."""

    DIALECT: ClassVar[str] = "example"
    MOTION: ClassVar[dict[str, str]] = {**WordWriter.MOTION, "rapid": "G0", "linear": "G1", "cw": "G2", "ccw": "G3"}
    ORIENT: ClassVar[str | None] = None
    """No M19: an oriented spindle stop is an unsupported construct here."""
    AXIS_DECIMALS: ClassVar[int] = 4
    """Axis, centre and radius words always carry exactly this many decimals."""

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        if s.mode is None:
            self.unsupported("a canned-cycle repetition without its cycle", block)
        words = self._code(self.MOTION, s.mode, f"{s.mode} motion", block)
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


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Example)
