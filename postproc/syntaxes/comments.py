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
from typing import Callable

from ..records import record

_BREAKS = dict.fromkeys((*range(0x20), 0x7F, 0x85, 0x2028, 0x2029), " ")
"""Line breaks and control characters (each made a space, ``str.translate``): a line break ends a ``;`` comment
and a block. A table, not a regular expression compiled at every start (~0.5M instructions)."""


@record(frozen=True)  # made at every start (dialect.py): a dataclass's generated methods cost ~0.4 ms
class CommentSyntax:
    """How one controller writes comments. The dialect declares it; nothing here names a controller."""

    parens: bool = True
    """``(`` ... ``)`` is a comment."""
    nested: bool = False
    """Parentheses nest inside a comment (otherwise the first ``)`` ends it)."""
    semicolon: bool = False
    """``;`` starts a comment that runs to the end of the line."""
    active: re.Pattern[str] | None = None
    """A comment whose text matches is an instruction to the controller, not a comment."""
    clean: Callable[[str], str] | None = None
    """Characters the controller acts on even inside a comment, replaced (grbl's real-time commands)."""

    def inside(self, text: str) -> str:
        """``text`` made safe to stand inside a comment: brackets for parentheses, spaces for line breaks
        and control characters, then the controller's own cleaning (``clean``). Whether the comment it
        stands in acts is the whole comment's business (``text``, ``comments``)."""
        safe = text.replace("(", "[").replace(")", "]")
        if not safe.isprintable():  # every character ``_BREAKS`` maps is unprintable: the common text skips a
            safe = safe.translate(_BREAKS)  # translate that looks each character up in the table (~600 each)
        return self.clean(safe) if self.clean is not None else safe

    def text(self, text: str) -> str:
        """``text`` made safe as a whole comment's text: ``inside``, and a ``-`` before a head that would
        make the comment act (``active``)."""
        safe = self.inside(text)
        if self.active is not None and self.active.match(safe):
            safe = "-" + safe
        return safe

    def comment(self, text: str) -> str:
        """A whole comment holding ``text`` (safe, as ``text`` makes it): parentheses where they are
        comments, else a ``;`` comment (which must end its line)."""
        safe = self.text(text)
        return f"({safe})" if self.parens else ";" + safe

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
        return self.active is None or self.active.match(text) is None
