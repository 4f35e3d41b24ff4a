"""grblHAL's line rules: the family's (``postproc.grbl_family.text``: no real-time character, ASCII) with
grblHAL's line buffer of 257 characters, every character but control characters and leading blanks
counted [V: grblHAL core ``protocol.h`` ``LINE_BUFFER_SIZE``, ``protocol.c`` ``protocol_main_loop``]."""

from __future__ import annotations

from typing import Final

from postproc.grbl_family.text import COMMENTS as COMMENTS, GrblLines, kept_whole

LINE_BUFFER_SIZE: Final = 257
"""grblHAL's ``LINE_BUFFER_SIZE`` (``protocol.h``): 256 characters and a terminator [V]."""
LINES: Final = GrblLines("grblHAL", "grblHAL", LINE_BUFFER_SIZE, kept_whole, " with its spaces and comments")
"""Every line written for grblHAL."""
