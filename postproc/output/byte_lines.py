"""A line rule (``postproc.output.line_format.LineRule``) for a controller that reads lines of at most so many
bytes, a ``\\r`` before the ``\\n`` included, comments and spaces included, a character outside ASCII counting
its UTF-8 bytes: a longer line has its longest plain (passive) comment shortened to fit, with a warning (a
comment carries no motion); a line whose code alone is too long is refused.

Neutral and compiled with the hot path: ``fits`` runs on every line written (a dialect plugin, which is not
compiled, makes its ``LINE_RULE`` of this class with its limit, comment syntax and wording).
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..syntaxes.comments import CommentSyntax
from .line_format import LineRule


def size(text: str) -> int:
    """``text``'s bytes as written (UTF-8, the bytes a reader kept as surrogates as themselves:
    ``postproc.output.outfile``)."""
    if text.isascii():
        return len(text)
    try:
        return len(text.encode("utf-8", "surrogateescape"))
    except UnicodeEncodeError:  # a surrogate no byte was read as
        return len(text.encode("utf-8", "surrogatepass"))


@mypyc_attr(allow_interpreted_subclasses=True)
class ByteLengthLines(LineRule):
    """The rule of every line written for a controller that reads at most ``limit`` bytes a line."""

    def __init__(self, limit: int, comments: CommentSyntax, controller: str, refusal: str) -> None:
        """``comments``: the controller's comment syntax (which comments are passive, so may be shortened);
        ``controller``: its name in a message; ``refusal``: what the controller says of a longer line, for the
        message of a line no comment of which can be shortened enough."""
        self.limit = limit
        self.comments = comments
        self.controller = controller
        self.refusal = refusal

    def fits(self, text: str) -> bool:
        """Every line of ``text`` is short enough as it is (the test of a usual block, and of an expanded
        cycle's many lines): each line, with the CR of its end, lies within a piece between two LFs."""
        limit = self.limit
        if len(text) * 4 <= limit:  # a character is at most four bytes written (UTF-8; a kept surrogate one):
            return True  # a usual block's text passes without ``isascii``, a generic method call compiled
        if text.isascii():
            if len(text) <= limit:
                return True
            for piece in text.split("\n"):
                if len(piece) > limit:
                    return False
            return True
        for piece in text.split("\n"):
            if size(piece) > limit:
                return False
        return True

    def fit(self, line: str, eol: str) -> tuple[str, str | None, str | None]:
        limit = self.limit
        over = size(line) + ("\r" in eol) - limit
        if over <= 0:
            return line, None, None
        passive = [(a, b) for a, b, plain in self.comments.comments(line) if plain]
        if passive:
            a, b = passive[0]
            longest = size(line[a:b])
            for c, d in passive[1:]:  # the first of the longest, as ``max`` takes it
                length = size(line[c:d])
                if length > longest:
                    a, b, longest = c, d, length
            closed = line[a] == "(" and b - a > 1 and line[b - 1] == ")"
            text = line[a + 1:b - 1 if closed else b]
            keep, removed = len(text), 0
            while keep > 0 and removed < over:
                keep -= 1
                removed += size(text[keep])
            if removed >= over:
                cut = line[a] + text[:keep] + (")" if closed else "")
                return (line[:a] + cut + line[b:], f"a line longer than the {limit} bytes {self.controller} reads: "
                        "its comment is shortened", None)
        return line, None, (f"the line is {size(line)} bytes long, more than the {limit} {self.controller} "
                            f"reads ({self.refusal}), and no comment in it can be shortened enough")
