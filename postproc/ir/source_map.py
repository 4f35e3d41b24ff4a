"""The source map of executed blocks: which file and line a block came from, and through which calls.

A straight program's blocks need nothing: their file is the run's and their line is ``block.line``. A
block the interpreter executes inside a subprogram is an ``ExecutedBlock`` carrying an ``Origin`` (its
file and the call stack), so an error in the third call of a subprogram says so:
``sub.nc:4:1: error: division by zero in #1/#2 (in O2000, called from main.nc line 12, call 3 of 3)``.
Every place that locates a block's error goes through ``locate`` (``Context.at`` does).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import Location
from . import Block

if TYPE_CHECKING:
    from typing import Callable, TextIO


SHOWN = 3
"""Calls a located error names at each end of a deep call stack (``Origin.note``)."""


class CallSite:
    """One level of the call stack: the subprogram entered, where it was called from, which repetition."""

    __slots__ = ("label", "file", "line", "index", "count")

    def __init__(self, label: str, file: str, line: int, index: int = 1, count: int = 1) -> None:
        self.label = label
        """The subprogram as the dialect spells it (``O2000``, ``o<probe>``)."""
        self.file = file
        self.line = line
        self.index = index
        """Which repetition of the call this is, 1-based (0: a modal call, counted by ``count``)."""
        self.count = count

    def describe(self) -> str:
        text = f"in {self.label}, called from {self.file} line {self.line}"
        if self.count > 1:
            text += f", call {self.index} of {self.count}"
        return text

    def __repr__(self) -> str:
        return f"CallSite({self.describe()!r})"


class Origin:
    """Where an executed block comes from: its file and the calls it runs in (innermost first)."""

    __slots__ = ("file", "stack", "_note")

    def __init__(self, file: str, stack: tuple[CallSite, ...] = ()) -> None:
        self.file = file
        self.stack = stack
        self._note: str | None = None

    def note(self) -> str:
        """``in O2000, called from main.nc line 12, call 3 of 3; in ...`` (empty outside calls). A deep stack
        (a recursion up to the call-depth bound) names its innermost and outermost ``SHOWN`` calls and how
        many lie between: one line a reader can take in, not sixty-four."""
        if self._note is None:
            stack = self.stack
            shown = SHOWN
            if len(stack) > 2 * shown + 1:
                sites = [site.describe() for site in stack[:shown]]
                sites.append(f"... {len(stack) - 2 * shown} more")
                sites.extend(site.describe() for site in stack[-shown:])
            else:
                sites = [site.describe() for site in stack]
            self._note = "; ".join(sites)
        return self._note


class ExecutedBlock(Block):
    """A block produced by the interpreter: a ``Block`` that knows its ``Origin``.

    A subclass, so straight programs pay nothing for the source map."""

    __slots__ = ("origin",)

    def __init__(self, line: int, text: str | None, eol: str, words: list[tuple[str, str]],
                 origin: Origin | None) -> None:
        super().__init__(line, text, eol, words)
        self.origin = origin


def locate(file: str, block: Block, col: int = 1) -> Location:
    """The location of column ``col`` of ``block``: its own file and call stack if it was executed
    inside a subprogram, else ``file`` (the run's) and the block's line."""
    origin = block.origin if isinstance(block, ExecutedBlock) else None
    if origin is None:
        return Location(file, block.line, col)
    return Location(origin.file, block.line, col, origin.note())


class OutputMap:
    """Which source line each written line comes from, or which set-up template generated it: filled by
    ``Writer.write`` when a caller asks for it (``translate(..., output_map=OutputMap())``), so a plain
    translation pays nothing. ``lines[i]`` is written line ``i + 1``: ``(source line, None)`` or
    ``(None, template name)``; lines a writer adds on its own (a closing comment) have ``(None, None)``."""

    __slots__ = ("lines", "source", "template", "_open")

    def __init__(self) -> None:
        self.lines: list[tuple[int | None, str | None]] = []
        self.source: int | None = None
        """The source line of the text being written (set by the writer before it writes it)."""
        self.template: str | None = None
        self._open = False
        """The last text written did not end its line."""

    def writer(self, out: "TextIO") -> "Callable[[str], object]":
        def emit(text: str) -> object:
            entry = (self.source, self.template)
            count = text.count("\n") + (0 if text.endswith("\n") else 1)
            if self._open and text:
                count -= 1  # the first of these lines was counted already
            self.lines.extend([entry] * max(count, 0))
            self._open = bool(text) and not text.endswith("\n") or (self._open and not text)
            written = out.write(text)
            self.source = None
            return written
        return emit

    def generated(self) -> list[int]:
        """Written line numbers (1-based) that a template generated."""
        return [i + 1 for i, (_, template) in enumerate(self.lines) if template is not None]
