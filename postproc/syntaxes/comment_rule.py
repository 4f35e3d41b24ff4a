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


def _any_case(word: str) -> str:
    """A pattern matching ``word`` (ASCII letters and digits) with each letter in either case, and only so."""
    return "".join(f"[{c.upper()}{c.lower()}]" if c.isalpha() else c for c in word)


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
            re.compile(r"[ \t]*(" + "|".join(_any_case(word) for word in words) + r")\b") if words else None)
        """A comment whose text matches acts: after blanks and tabs, one of ``words``, its letters in either ASCII
        case, as a whole word; ``group(1)`` is the word as written. Not ``re.IGNORECASE``, which also takes the
        dotless i, the long s, the Kelvin sign and the dotted capital I for ASCII letters: rs274 keeps
        ``(PRıNT,x)`` and ``(Mſg,x)`` inert [V: linuxcnc-uspace 2.9's rs274 run here: COMMENT, not MESSAGE]."""
        starts = {case for word in words for case in (word[0].lower(), word[0].upper())} | {" ", "\t"}
        self.quiet: frozenset[str] = frozenset(chr(c) for c in range(128) if chr(c) not in starts)
        """ASCII characters no active comment's text starts with (not a blank, a tab or a word's first letter in
        either case)."""
        seconds: dict[str, set[str]] = {}
        for word in words:
            for initial in (word[0].lower(), word[0].upper()):
                seconds.setdefault(initial, set()).update((word[1].lower(), word[1].upper()) if len(word) > 1 else ())
        self.seconds: dict[str, frozenset[str]] = {
            initial: frozenset(after) for initial, after in seconds.items()
            if all(len(word) > 1 for word in words if word[0].lower() == initial.lower())}
        """A word's first letter (either case) -> the second characters of the words it starts (either case),
        where each has one."""

    def head(self, text: str) -> str | None:
        """The word (as written) that makes a comment holding ``text`` an instruction to the controller; None:
        it does not act."""
        active = self.active
        if active is None or not text:
            return None
        # A cheap test first (the regular expression costs ~2.5k a comment, on every comment written): the
        # pattern, after its blanks, reads a word, in either ASCII case; an ASCII character matches a letter of it only
        # as that letter, in either case (``quiet``, ``seconds``), so a text whose first character, or first
        # two, are ASCII and start no word never matches. Any other text is matched.
        first = text[0]
        if first in self.quiet:
            return None
        after = self.seconds.get(first)
        if after is not None and len(text) > 1:
            second = text[1]
            if second not in after and second < "\x80":
                return None
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
        return f"({safe})" if self.parens else ";" + safe

