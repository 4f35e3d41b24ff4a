"""grbl 1.1's line rules and comments: the family's (``postproc.grbl_family.text``) with grbl 1.1's line
buffer of 80 characters, counted without spaces and comments [V: ``grbl/protocol.c``, ``protocol.h``]."""

from __future__ import annotations

from typing import Final

from postproc.grbl_family.text import (
    COMMENTS as COMMENTS, GRBL_KEPT, GRBL_LINE_BUFFER_SIZE, GrblLines, REALTIME as _REALTIME, grbl_safe as grbl_safe,
    kept as kept, plain_ascii as plain_ascii, shortened as shortened,
)

LINE_BUFFER_SIZE: Final = GRBL_LINE_BUFFER_SIZE
KEPT: Final = GRBL_KEPT
LINES: Final = GrblLines("grbl", "grbl 1.1", LINE_BUFFER_SIZE, kept, " without spaces and comments")
"""Every line written for grbl 1.1."""
