"""How long a line LinuxCNC reads (``Linuxcnc.LINE_RULE``, applied to every line written through
``postproc.output.line_format``).

rs274 (linuxcnc-uspace 2.9, run here) reads a line of at most 252 bytes, a ``\\r`` before the ``\\n``
included, comments and spaces included, a character outside ASCII counting its UTF-8 bytes; one more is
"Command too long" [V]. A longer line - a long source comment, a template's long value - has its
longest plain comment shortened to fit (with a warning: a comment carries no motion); a line whose code
alone is too long is refused, located. The rule is the core's ``ByteLengthLines`` (compiled: it tests every
line written), made here with LinuxCNC's limit, comment syntax and words.
"""

from __future__ import annotations

from typing import Final

from postproc.output.byte_lines import ByteLengthLines, size as size

from .active_comments import COMMENTS

LINE_LENGTH: Final = 252
"""The most bytes rs274 reads in a line, its ``\\r`` included [V]."""

LINES: Final = ByteLengthLines(LINE_LENGTH, COMMENTS, "LinuxCNC", "rs274: \"Command too long\"")
"""The rule of every line written for LinuxCNC."""
