"""The sink a writer's text goes to: ``Batch`` hands the texts of many blocks to the output at once, and
``LineFeeds`` (a batch) also writes a source's lone CR line ends (kept as read) as LF, for a controller that ends
a line at LF only, so a CR-only file does not reach it as one long line (a dialect's writer wraps its output
in ``LineFeeds``; CR LF stays as it is).

Why a batch: ``Writer.write`` emits a text a block, and a text file's ``write`` costs about as much as the
straight lane's whole work on a CAM block (compiled, ~700 instructions: encoding and the file's own pending
list); appended here and joined once every ``BATCH`` texts, the file sees one ``write`` per batch. The output
is the same text in the same order: ``Writer.write`` hands what is pending to the output when it ends,
however it ends (``flush``), so a caller that reads the output after the writer (or after its error) finds
every text emitted.

Compiled with the hot path: every block's text passes here (a plugin's class runs interpreted).
"""

from __future__ import annotations

import re
from typing import Final, TextIO

from mypy_extensions import mypyc_attr

_LONE_CR: Final = re.compile(r"\r(?!\n)")
BATCH: Final = 512
"""Texts joined into one ``write`` of the output (a CAM block's is ~40 characters: ~20 kB a write; a line put
in two pieces, ``write_line``, counts two)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Batch:
    """``out``, written ``BATCH`` texts at a time; ``flush`` hands it what is pending (it does not flush
    ``out`` itself)."""

    def __init__(self, out: TextIO) -> None:
        self.out = out
        self.pending: list[str] = []

    def write(self, text: str) -> int:
        pending = self.pending
        pending.append(text)
        if len(pending) >= BATCH:
            self.flush()
        return len(text)

    def write_line(self, text: str, eol: str) -> None:
        """``write(text + eol)`` without the joined string (~250 instructions a line compiled): both pieces wait,
        and are joined with the batch."""
        pending = self.pending
        pending.append(text)
        pending.append(eol)
        if len(pending) >= BATCH:
            self.flush()

    def flush(self) -> None:
        pending = self.pending
        if pending:
            text = pending[0] if len(pending) == 1 else "".join(pending)
            pending.clear()
            self.out.write(text)


@mypyc_attr(allow_interpreted_subclasses=True)
class LineFeeds(Batch):
    """``out`` with lone CR line ends written as LF, and whether any text was written (``wrote``: at once,
    not when the batch reaches ``out``) and whether any of it was more than blank lines (``content``)."""

    def __init__(self, out: TextIO) -> None:
        super().__init__(out)
        self.wrote = False
        """Text was written."""
        self.content = False
        """Text other than blank lines was written (a comment counts: the program has begun)."""

    def write(self, text: str) -> int:
        if text:
            self.wrote = True
            if not self.content and text.strip():
                self.content = True
        return super().write(_LONE_CR.sub("\n", text) if "\r" in text else text)

    def write_line(self, text: str, eol: str) -> None:
        """``write(text + eol)``: as two pieces where the text holds no CR and the end of line is LF or CR LF (no lone
        CR to rewrite: a straight lane's line, ``Batch.write_line``, no string joined); else as one text (a lone CR
        may be the text's end and the end of line its LF)."""
        if (eol == "\n" or eol == "\r\n") and "\r" not in text:
            self.wrote = True
            if not self.content and text.strip():
                self.content = True
            super().write_line(text, eol)
        else:
            self.write(text + eol)
