"""A controller's comment syntax as data (``Dialect.COMMENTS``): the one place that decides what text is
safe inside a comment, and where a written line's comments are.

Text from outside the program's code - a file name, a ``--define`` value, a set-up's name, another
dialect's comment - reaches a target only inside a comment, so it must neither end the comment early
(a closing parenthesis, a line break) nor make it one the controller acts on (LinuxCNC runs
``(MSG,`` ``(DEBUG,`` ``(LOGOPEN,`` ... comments; grbl acts on ``!`` anywhere). ``text`` makes any text
safe; ``comments`` finds the comments of a written line, so a template's output can be checked to hold
every value inside a passive one (``postproc.output.template_values``).
"""

from __future__ import annotations

import re
from functools import cached_property
from typing import Callable

from ..records import record
from .comment_rule import CommentRule


@record(frozen=True)  # made at every start (dialect.py): a dataclass's generated methods cost ~0.4 ms
class CommentSyntax:
    """How one controller writes comments. The dialect declares it; nothing here names a controller."""

    parens: bool = True
    """``(`` ... ``)`` is a comment."""
    nested: bool = False
    """Parentheses nest inside a comment (otherwise the first ``)`` ends it)."""
    semicolon: bool = False
    """``;`` starts a comment that runs to the end of the line."""
    active_words: tuple[str, ...] = ()
    """A comment whose text starts, after blanks and tabs, with one of these words (in any case, a whole word)
    is an instruction to the controller, not a comment (``CommentRule.head``)."""
    clean: Callable[[str], str] | None = None
    """Characters the controller acts on even inside a comment, replaced (grbl's real-time commands)."""

    @cached_property
    def rule(self) -> CommentRule:
        """The syntax's compiled working (``postproc.syntaxes.comment_rule``), made when first used: every
        comment made safe goes through it, a word writer's too."""
        return CommentRule(self.parens, self.active_words, self.clean)

    def inside(self, text: str) -> str:
        """``text`` made safe to stand inside a comment (``CommentRule.inside``)."""
        return self.rule.inside(text)

    def text(self, text: str) -> str:
        """``text`` made safe as a whole comment's text (``CommentRule.text``)."""
        return self.rule.text(text)

    def comment(self, text: str) -> str:
        """A whole comment holding ``text`` (``CommentRule.comment``)."""
        return self.rule.comment(text)

    def comments(self, line: str) -> list[tuple[int, int, bool]]:
        """The comments of one written line: (start, end, passive) with ``line[start:end]`` the comment
        including its delimiters; an unclosed parenthesis runs to the end of the line."""
        found: list[tuple[int, int, bool]] = []
        i, n = 0, len(line)
        while i < n:
            ch = line[i]
            if ch == "(" and self.parens:
                depth, j = 1, i + 1
                while j < n and depth:
                    if line[j] == ")":
                        depth -= 1
                    elif line[j] == "(" and self.nested:
                        depth += 1
                    j += 1
                found.append((i, j, self._passive(line[i + 1:j - 1 if depth == 0 else j])))
                i = j
            elif ch == ";" and self.semicolon:
                found.append((i, n, True))
                return found
            else:
                i += 1
        return found

    def _passive(self, text: str) -> bool:
        return not self.rule.acts(text)
