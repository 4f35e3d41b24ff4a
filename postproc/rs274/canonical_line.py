"""Whether a line is already in canonical spelling (``postproc.numbers.CANONICAL_BLOCK``): one answer,
two ways of finding it.

Compiled (mypyc), a scan over the line's bytes costs a fifth of the regex, which was the largest
single cost of reading a CAM line (~8,500 instructions a line); as pure Python the same scan is four
times slower than the regex, so the pure fallback keeps the regex. ``tests/test_canonical_line.py``
checks the two agree on any text.
"""

from __future__ import annotations

from types import FunctionType
from typing import Final

from postproc.numbers import CANONICAL_BLOCK

CANONICAL: Final = 1
"""``scan``'s answer for a canonical line without G or M words (a CAM line: N, axes, F)."""
WITH_CODES: Final = 3
"""``scan``'s answer for a canonical line that may have G or M words (``CANONICAL`` bit set)."""

_AXIS: Final = 1
_CODE: Final = 2
_KIND: Final = bytes(_AXIS if chr(c) in "XYZABCUVWIJRQF" else _CODE if chr(c) in "GMNOTHDLPS" else 0
                     for c in range(256))
"""Per byte: a letter whose number has a decimal point, a letter of a whole number, or neither."""
_MAX_FRACTION: Final = 6


def scan(text: str) -> int:
    """0 unless ``CANONICAL_BLOCK.fullmatch(text)``, by one pass over the bytes: words separated by
    single spaces; a code letter and digits; an axis-type letter and ``-?(0|[1-9][0-9]*)\\.`` with at
    most six decimals and no trailing zero, never ``-0.``. A canonical line is ``CANONICAL``, or
    ``WITH_CODES`` when it has a G or M word (a reader then looks for calls in it)."""
    if not text:
        return 0
    try:
        b = text.encode("ascii")  # compiled, a C call; ``str.isascii`` would be a method look-up
    except UnicodeEncodeError:
        return 0
    n = len(b)
    kind = _KIND
    found = CANONICAL
    i = 0
    while True:
        c = b[i]
        k = kind[c]
        i += 1
        if k == _CODE:
            if c == 71 or c == 77:  # 'G', 'M'
                found = WITH_CODES
            start = i
            while i < n and 48 <= b[i] <= 57:
                i += 1
            if i == start:
                return 0
        elif k == _AXIS:
            negative = i < n and b[i] == 45  # '-'
            if negative:
                i += 1
            start = i
            if i < n and b[i] == 48:  # a lone leading '0'
                i += 1
            else:
                while i < n and 48 <= b[i] <= 57:
                    i += 1
            if i == start or i >= n or b[i] != 46:  # digits, then '.'
                return 0
            i += 1
            fraction = i
            while i < n and 48 <= b[i] <= 57:
                i += 1
            if i - fraction > _MAX_FRACTION or i > fraction and b[i - 1] == 48:
                return 0
            if negative and i == fraction and fraction - start == 2 and b[start] == 48:
                return 0  # '-0.'
        else:
            return 0
        if i == n:
            return found
        if b[i] != 32:
            return 0
        i += 1
        if i == n:
            return 0


def by_regex(text: str) -> int:
    """The regex's answer as ``scan`` gives it, but for the codes (the pure-Python fallback's way:
    ``WITH_CODES`` for every canonical line, so a reader always looks for calls)."""
    return WITH_CODES if CANONICAL_BLOCK.fullmatch(text) is not None else 0


COMPILED: Final = not isinstance(scan, FunctionType)
"""True when this module runs compiled (a compiled function is not a Python function object)."""


def classify(text: str) -> int:
    """``scan``'s answer (0, ``CANONICAL`` or ``WITH_CODES``), the cheaper way for how this module runs."""
    return scan(text) if COMPILED else by_regex(text)
