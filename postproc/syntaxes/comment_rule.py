"""``CommentRule``: how a comment syntax makes text safe to write inside a comment, compiled (it runs for every
comment a translation writes: an expanded canned cycle's note on each hole, a source comment).

``CommentSyntax`` (``postproc.syntaxes.comments``), the syntax as data, makes one (``CommentSyntax.rule``) and
works through it; a word writer writes another dialect's comments with its target's (``SectionWords``), so
what a controller reads as an active comment is decided once, by its syntax's words, on every path.
"""

from __future__ import annotations

import re
from typing import Callable, Final

from mypy_extensions import mypyc_attr

_BREAKS: Final = dict.fromkeys((*range(0x20), 0x7F, 0x85, 0x2028, 0x2029), " ")
"""Line breaks and control characters (each made a space, ``str.translate``): a line break ends a ``;`` comment
and a block. A table, not a regular expression compiled at every start (~0.5M instructions)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class CommentRule:
    """The working of one ``CommentSyntax``: its ``parens``, its ``clean`` and its active ``words``."""

    def __init__(self, parens: bool, words: tuple[str, ...], clean: Callable[[str], str] | None) -> None:
        for word in words:
            if not (word.isascii() and word.isalnum() and word[0].isalpha()):
                raise ValueError(f"an active comment's word is ASCII letters and digits, from a letter: {word!r}")
        self.parens = parens
        self.clean = clean
        self.active: re.Pattern[str] | None = (
            re.compile(r"[ \t]*(" + "|".join(words) + r")\b", re.IGNORECASE) if words else None)
        """A comment whose text matches acts: after blanks and tabs, one of ``words``, in any case, as a whole
        word; ``group(1)`` is the word as written."""
        self.reach = min(3, *(len(word) for word in words)) if words else 0
        """How many characters of a text ``starts`` tells apart (at most 3, none past the shortest word)."""
        self.starts: frozenset[str] = frozenset(case for word in words for case in _cases(word[:self.reach]))
        """The first ``reach`` characters of an active comment's text with no blank before its word, in every
        case. A text whose first ``reach`` characters are ASCII, start with no blank or tab and are not among
        these never matches ``active``: an ASCII character matches a letter of it, in any case, only as that
        letter (which the case variants hold), a digit only as itself, and a word has ``reach`` characters at
        least. Any other text is matched (``head``)."""

    def head(self, text: str) -> str | None:
        """The word (as written) that makes a comment holding ``text`` an instruction to the controller; None:
        it does not act."""
        active = self.active
        if active is None:
            return None
        start = text[:self.reach]
        if start not in self.starts and start.isascii() and not start.startswith((" ", "\t")):
            return None  # (a cheap test before the regular expression, ~2.5k a comment, on every comment written)
        m = active.match(text)
        return m.group(1) if m is not None else None

    def acts(self, text: str) -> bool:
        """A comment holding ``text`` is an instruction to the controller (``head``)."""
        return self.head(text) is not None

    def inside(self, text: str) -> str:
        """``text`` made safe to stand inside a comment: brackets for parentheses, spaces for line breaks
        and control characters, then the controller's own cleaning (``clean``). Whether the comment it
        stands in acts is the whole comment's business (``text``)."""
        safe = text.replace("(", "[").replace(")", "]")
        if not safe.isprintable():  # every character ``_BREAKS`` maps is unprintable: the common text skips a
            safe = safe.translate(_BREAKS)  # translate that looks each character up in the table (~600 each)
        clean = self.clean
        return clean(safe) if clean is not None else safe

    def text(self, text: str) -> str:
        """``text`` made safe as a whole comment's text: ``inside``, and a ``-`` before a head that would
        make the comment act (``acts``)."""
        safe = self.inside(text)
        return "-" + safe if self.acts(safe) else safe

    def comment(self, text: str) -> str:
        """A whole comment holding ``text`` (safe, as ``text`` makes it): parentheses where they are
        comments, else a ``;`` comment (which must end its line)."""
        safe = self.text(text)
        return "(" + safe + ")" if self.parens else ";" + safe


def _cases(start: str) -> list[str]:
    """``start`` in every case: each letter lower or upper."""
    found = [""]
    for ch in start:
        found = [made + case for made in found for case in sorted({ch.lower(), ch.upper()})]
    return found
