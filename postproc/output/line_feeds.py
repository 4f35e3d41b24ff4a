"""The output of a writer for a controller that ends a line at LF only: a source's lone CR line ends (kept as
read) are written as LF, so a CR-only file does not reach it as one long line (a dialect's writer wraps its
output in ``LineFeeds``; CR LF stays as it is).

Compiled with the hot path: every block's text passes here (a plugin's class runs interpreted).
"""

from __future__ import annotations

import re
from typing import Final, TextIO

from mypy_extensions import mypyc_attr

_LONE_CR: Final = re.compile(r"\r(?!\n)")


@mypyc_attr(allow_interpreted_subclasses=True)
class LineFeeds:
    """``out`` with lone CR line ends written as LF, and whether any text was written (``wrote``)."""

    def __init__(self, out: TextIO) -> None:
        self.out = out
        self.wrote = False
        """Text was written."""

    def write(self, text: str) -> int:
        if text:
            self.wrote = True
        return self.out.write(_LONE_CR.sub("\n", text) if "\r" in text else text)
