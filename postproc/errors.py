"""One error hierarchy and one error level for reading, lowering, writing and configuration.

Every diagnostic carries a location so the command line can print ``FILE:LINE:COL: error: message``.
Columns are computed only when a diagnostic is raised (see ``Location``), never on the hot path.
"""

from __future__ import annotations

import enum
import re
import sys
from typing import TextIO

from .records import record


def character_name(ch: str) -> str:
    """A character as a diagnostic names it. Programs are read with ``surrogateescape``, so a byte that is
    not UTF-8 arrives as a lone surrogate (0xFF as U+DCFF): it is named as the byte the file holds."""
    code = ord(ch)
    if 0xDC80 <= code <= 0xDCFF:
        return f"byte 0x{code - 0xDC00:02X} (not UTF-8)"
    if ch.isascii() and ch.isprintable():
        return f"character {ch!r}"
    return f"character {ch!r} (U+{code:04X})"


@record(frozen=True, slots=True)
class Location:
    """Where a diagnostic points: 1-based line and column in a named file."""

    file: str
    line: int
    col: int = 1
    note: str = ""
    """Where the place sits in the program's execution (``in O2000, called from main.nc line 12``), or ''."""

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.col}"


class PostprocError(Exception):
    """Root of every error postproc reports to a user."""

    severity = "error"

    def __init__(self, message: str, location: Location | None = None, *, needs: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.location = location
        self.needs = needs
        """The address whose missing value this error is about (``F`` for a feed move with no feed rate):
        after a refused line that programmed it, the error is that line's consequence (``Diagnostics``)."""

    def located(self, location: Location) -> "PostprocError":
        """Attach a location if the error has none yet (errors raised deep inside know no file)."""
        if self.location is None:
            self.location = location
        return self

    def __str__(self) -> str:
        where = f"{self.location}: " if self.location else ""
        note = f" ({self.location.note})" if self.location and self.location.note else ""
        return f"{where}{self.severity}: {self.message}{note}"


class ParseError(PostprocError):
    """Malformed input text: a bad word, an unclosed comment, a conflicting code."""


class ProgramError(PostprocError):
    """Well-formed text that makes no sense: a cycle without its depth, a contradictory level."""


class UnsupportedError(PostprocError):
    """The target dialect or machine cannot express a construct."""

    section: str | None = None
    """The key of the block's section the writer refused, where it knows it (``--on-unsupported warn``
    then writes the block without that section: ``postproc.output.partial_block``)."""


class ConfigError(PostprocError):
    """A machine set-up, pipeline file or template is invalid."""


class UsageError(PostprocError):
    """Wrong command-line usage (exit status 2)."""


class ErrorLevel(enum.Enum):
    """How diagnostics are handled; shared by reading, lowering and writing (as in sqlglot)."""

    IGNORE = "ignore"
    WARN = "warn"
    RAISE = "raise"
    """Collect every error, keep going, raise them together at the end."""
    IMMEDIATE = "immediate"
    """Raise at the first error."""


class ErrorList(PostprocError):
    """Several collected errors, raised together."""

    def __init__(self, errors: list[PostprocError], notes: list[str] | None = None) -> None:
        super().__init__(f"{len(errors)} error(s)")
        self.errors = errors
        self.notes = notes or []
        """What the list leaves out (the cap cut it, consequences of refused lines), for the user."""

    def __str__(self) -> str:
        return "\n".join(str(e) for e in self.errors)


class Warning_(PostprocError):
    """A diagnostic that does not change the exit status."""

    severity = "warning"


class Diagnostics:
    """Collects errors and warnings according to an ``ErrorLevel``.

    Readers and writers report through one instance, so a run prints every problem it found
    (up to ``max_errors``) instead of stopping at the first.
    """

    def __init__(self, level: ErrorLevel = ErrorLevel.RAISE, max_errors: int = 50,
                 warn_stream: TextIO | None = None) -> None:
        self.level = level
        self.max_errors = max_errors
        self.errors: list[PostprocError] = []
        self.warnings: list[PostprocError] = []
        self._warn_stream = warn_stream
        self.refused_words: dict[str, int] = {}
        """Address -> the first refused line that programmed it (its value never took effect)."""
        self.consequences: dict[str, int] = {}
        """Address -> how many errors about its missing value were left out (consequences of a refused line)."""

    def error(self, err: PostprocError, text: str | None = None) -> None:
        """Report an error; ``text``: the refused line, whose words then never took effect (an error
        that ``needs`` one of them later is its consequence and is left out, counted)."""
        if self.level is ErrorLevel.IMMEDIATE:
            raise err
        if self.level is ErrorLevel.IGNORE:
            return
        if err.needs and err.needs in self.refused_words:
            self.consequences[err.needs] = self.consequences.get(err.needs, 0) + 1
            return
        if text is not None and err.location is not None:
            for letter in addresses(text):
                self.refused_words.setdefault(letter, err.location.line)
        if self.level is ErrorLevel.WARN:
            self.warn(err.message, err.location)
            return
        self.errors.append(err)
        if len(self.errors) >= self.max_errors:
            raise ErrorList(self.errors, [f"stopped at {self.max_errors} errors: the rest of the program "
                                          "was not checked"] + self._consequence_note())

    def warn(self, message: str, location: Location | None = None) -> None:
        w = Warning_(message, location)
        self.warnings.append(w)
        stream = self._warn_stream if self._warn_stream is not None else sys.stderr
        print(w, file=stream)

    def check(self) -> None:
        """Raise the collected errors, if any."""
        if self.errors:
            raise ErrorList(self.errors, self._consequence_note())

    def _consequence_note(self) -> list[str]:
        return [f"{count} more error(s) left out: they follow from the refused line {self.refused_words[letter]}, "
                f"whose {letter} never took effect" for letter, count in sorted(self.consequences.items())]


# A pattern text, not a compiled pattern: compiled where first used (``re``'s cache), so a start that
# reports no error compiles none (each ``re.compile`` at import costs every start ~0.3-1M instructions).
_ADDRESS = r"([A-Za-z])\s*[-+.\d#\[]"
_COMMENT = r"\([^)]*\)?|;.*"


def addresses(text: str) -> set[str]:
    """The upper-case addresses of the words on a line (comments left out)."""
    return {m.group(1).upper() for m in re.finditer(_ADDRESS, re.sub(_COMMENT, " ", text))}
