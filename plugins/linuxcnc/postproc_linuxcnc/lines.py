"""How long a line LinuxCNC reads (``Linuxcnc.LINE_RULE``, applied to every line written through
``postproc.output.line_format``).

rs274 (linuxcnc-uspace 2.9, run here) reads a line of at most 252 bytes, a ``\\r`` before the ``\\n``
included, comments and spaces included, a character outside ASCII counting its UTF-8 bytes; one more is
"Command too long" [V]. A longer line - a long source comment, a template's long value - has its
longest plain comment shortened to fit (with a warning: a comment carries no motion); a line whose code
alone is too long is refused, located.
"""

from __future__ import annotations

from typing import Final

from .active_comments import COMMENTS

LINE_LENGTH: Final = 252
"""The most bytes rs274 reads in a line, its ``\\r`` included [V]."""


def size(text: str) -> int:
    """``text``'s bytes as written (UTF-8, the bytes a reader kept as surrogates as themselves:
    ``postproc.output.outfile``)."""
    if text.isascii():
        return len(text)
    try:
        return len(text.encode("utf-8", "surrogateescape"))
    except UnicodeEncodeError:  # a surrogate no byte was read as
        return len(text.encode("utf-8", "surrogatepass"))


class LinuxcncLines:
    """The rule of every line written for LinuxCNC (``postproc.output.line_format.LineRule``)."""

    def fits(self, text: str) -> bool:
        """Every line of ``text`` is short enough as it is (the test of a usual block, and of an expanded
        cycle's many lines): each line, with the CR of its end, lies within a piece between two LFs."""
        if text.isascii():
            return len(text) <= LINE_LENGTH or max(map(len, text.split("\n"))) <= LINE_LENGTH
        return all(size(piece) <= LINE_LENGTH for piece in text.split("\n"))

    def fit(self, line: str, eol: str) -> tuple[str, str | None, str | None]:
        over = size(line) + ("\r" in eol) - LINE_LENGTH
        if over <= 0:
            return line, None, None
        passive = [(a, b) for a, b, plain in COMMENTS.comments(line) if plain]
        if passive:
            a, b = max(passive, key=lambda span: size(line[span[0]:span[1]]))
            closed = line[a] == "(" and b - a > 1 and line[b - 1] == ")"
            text = line[a + 1:b - 1 if closed else b]
            keep, removed = len(text), 0
            while keep > 0 and removed < over:
                keep -= 1
                removed += size(text[keep])
            if removed >= over:
                cut = line[a] + text[:keep] + (")" if closed else "")
                return (line[:a] + cut + line[b:], f"a line longer than the {LINE_LENGTH} bytes LinuxCNC reads: "
                        "its comment is shortened", None)
        return line, None, (f"the line is {size(line)} bytes long, more than the {LINE_LENGTH} LinuxCNC "
                            "reads (rs274: \"Command too long\"), and no comment in it can be shortened enough")


LINES: Final = LinuxcncLines()
