"""How long a line LinuxCNC reads (``Linuxcnc.LINE_RULE``, applied to every line written through
``postproc.line_format``).

rs274 (linuxcnc-uspace 2.9, run here) reads a line of at most 252 characters, a ``\\r`` before the
``\\n`` included, comments and spaces included; one more is "Command too long" [V]. A longer line -
a long source comment, a template's long value - has its longest plain comment shortened to fit (with
a warning: a comment carries no motion); a line whose code alone is too long is refused, located.
"""

from __future__ import annotations

from typing import Final

from .active_comments import COMMENTS

LINE_LENGTH: Final = 252
"""The most characters rs274 reads in a line, its ``\\r`` included [V]."""


class LinuxcncLines:
    """The rule of every line written for LinuxCNC (``postproc.line_format.LineRule``)."""

    def fits(self, text: str) -> bool:
        """``text`` (one or more lines) is short enough as a whole, so every line of it is."""
        return len(text) <= LINE_LENGTH

    def fit(self, line: str, eol: str) -> tuple[str, str | None, str | None]:
        over = len(line) + ("\r" in eol) - LINE_LENGTH
        if over <= 0:
            return line, None, None
        passive = [(a, b) for a, b, plain in COMMENTS.comments(line) if plain]
        if passive:
            a, b = max(passive, key=lambda span: span[1] - span[0])
            closed = line[b - 1] == ")" and line[a] == "("
            keep = (b - a) - over - (1 if closed else 0)
            if keep >= 1:  # the comment's opening character and at least nothing of its text
                cut = line[a:a + keep] + (")" if closed else "")
                return (line[:a] + cut + line[b:], f"a line longer than the {LINE_LENGTH} characters LinuxCNC "
                        "reads: its comment is shortened", None)
        return line, None, (f"the line is {len(line)} characters long, more than the {LINE_LENGTH} LinuxCNC "
                            "reads (rs274: \"Command too long\"), and no comment in it can be shortened enough")


LINES: Final = LinuxcncLines()
