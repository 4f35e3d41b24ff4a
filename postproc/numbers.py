"""How the RS274 family spells numbers canonically: explicit decimal point, no trailing zeros.

Shared by readers (which can tell a block is already canonical while they lex it) and writers (which
then copy it instead of reformatting every number).
"""

from __future__ import annotations

import functools
import re

MAX_PLACES = 6
"""Most decimal places any written number carries (0.001 um; finer than any controller's increment)."""

_NUMBER = r"-?(?:0|[1-9]\d*)\.(?:\d{0,5}[1-9])?"
_WORD = rf"(?:[XYZABCUVWIJRQF](?!-0\.(?: |$)){_NUMBER}|[GMNOTHDLPS]\d+)"
CANONICAL_BLOCK = re.compile(rf"{_WORD}(?: {_WORD})*")
"""A block ``normalized`` would write unchanged (K is left out: its kind depends on the block)."""


@functools.cache
def canonical_number_re(places: int, leading_zero: bool) -> re.Pattern[str]:
    """Numbers already in ``number()``'s form: explicit point, no trailing zeros, at most ``places``."""
    frac = rf"(?:\d{{0,{places - 1}}}[1-9])?" if places > 0 else ""
    whole = r"(?:0|[1-9]\d*)" if leading_zero else r"(?:[1-9]\d*)?"
    zero = "0." if leading_zero else r"0\."
    return re.compile(rf"(?!-0\.$)(?!{zero}$)-?{whole}\.{frac}|0\.")
