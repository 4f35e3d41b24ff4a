"""Whether a line is already in canonical spelling (``postproc.numbers.CANONICAL_BLOCK``), by one scan
over its bytes.

Compiled (mypyc), the scan costs a fifth of the regex, which was the largest single cost of reading a
CAM line (~8,500 instructions a line). The pure-Python build runs the same scan (there it is slower than
the regex: both builds compute one way, and only the compiled one is the fast one).
``tests/test_canonical_line.py`` holds the scan to the regex on any text.
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import i64

CANONICAL: Final = 1
"""``scan``'s answer for a canonical line without G or M words (a CAM line: N, axes, F)."""
CODES: Final = 2
"""The bit of ``scan_words``'s answer for a line that has a G or M word (a reader then looks for calls)."""
WITH_CODES: Final = CANONICAL | CODES
"""``scan``'s answer for a canonical line that may have G or M words (``CANONICAL`` bit set)."""
WORDS: Final = 4
"""``scan_words``'s answer (with ``CODES`` or not) for a line of plain words that is not canonical."""

_AXIS: Final = 1
_CODE: Final = 2
_KIND: Final = bytes(_AXIS if chr(c) in "XYZABCUVWIJRQF" else _CODE if chr(c) in "GMNOTHDLPS" else 0
                     for c in range(256))
"""Per byte: a letter whose number has a decimal point, a letter of a whole number, or neither."""
_MAX_FRACTION: Final = 6
_LETTERS: Final[list[str]] = [chr(c) for c in range(128)]
"""An ASCII byte's character (compiled: a list item, not a one-character slice of the line)."""


NO_WORDS: Final[list[tuple[str, str]]] = []
"""``scan_words``'s words for a line that is not canonical (one shared list: never appended to)."""


def scan(text: str) -> int:
    """0 unless ``CANONICAL_BLOCK.fullmatch(text)``, by one pass over the bytes: words separated by
    single spaces; a code letter and digits; an axis-type letter and ``-?(0|[1-9][0-9]*)\\.`` with at
    most six decimals and no trailing zero, never ``-0.``. A canonical line is ``CANONICAL``, or
    ``WITH_CODES`` when it has a G or M word (a reader then looks for calls in it)."""
    kind = scan_words(text)[0]
    return kind if kind & CANONICAL else 0


def scan_words(text: str) -> tuple[int, list[tuple[str, str]], int]:
    """``scan``'s answer, with the line's words as a reader keeps them (letter, number as written) and
    the number of its block number when it starts with one (else -1), from the same pass: a canonical
    line needs no split, and its block number no second parse. ``NO_WORDS`` when the answer is 0.

    A line of upper-case words whose numbers are only not canonical (``X10``, ``X1.50``, ``G43.4``) is
    ``WORDS`` (``| CODES`` with a G or M word), with the words ``WORD.findall`` finds in it: such a line
    (a number without a point, as hand-written Fanuc programs have) then needs no regex either. A block
    number must still be digits only, and a sign only ``-`` on an axis-type letter."""
    if not text:
        return 0, NO_WORDS, -1
    try:
        b = text.encode("ascii")  # compiled, a C call; ``str.isascii`` would be a method look-up
    except UnicodeEncodeError:
        return 0, NO_WORDS, -1
    # Positions as i64 (compiled: machine integers, not tagged ones whose every step checks for overflow).
    n: i64 = len(b)
    kind = _KIND
    letters = _LETTERS
    canonical = True
    codes = False
    words: list[tuple[str, str]] = []
    sequence = -1
    i: i64 = 0
    while True:
        start = i
        c = b[i]
        k = kind[c]
        i += 1
        if k == _CODE:
            if c == 71 or c == 77:  # 'G', 'M'
                codes = True
            digits = i
            if start == 0 and c == 78:  # 'N' first: its number is the block's
                sequence = 0
                while i < n and 48 <= b[i] <= 57:
                    sequence = sequence * 10 + b[i] - 48
                    i += 1
                if i < n and b[i] == 46:  # 'N10.': the lexer's to judge
                    return 0, NO_WORDS, -1
            else:
                while i < n and 48 <= b[i] <= 57:
                    i += 1
            if i == digits:
                return 0, NO_WORDS, -1
            if i < n and b[i] == 46:  # 'G43.4': a plain word, not canonical
                canonical = False
                i += 1
                while i < n and 48 <= b[i] <= 57:
                    i += 1
        elif k == _AXIS:
            negative = i < n and b[i] == 45  # '-'
            if negative:
                i += 1
            digits = i
            while i < n and 48 <= b[i] <= 57:
                i += 1
            whole = i - digits
            if i < n and b[i] == 46:  # '.'
                i += 1
                fraction = i
                while i < n and 48 <= b[i] <= 57:
                    i += 1
                places = i - fraction
                if whole == 0:
                    if places == 0:
                        return 0, NO_WORDS, -1
                    canonical = False  # '.5'
                elif (whole > 1 and b[digits] == 48 or places > _MAX_FRACTION
                      or places > 0 and b[i - 1] == 48 or negative and places == 0 and whole == 1 and b[digits] == 48):
                    canonical = False  # '00.5', more than six places, '0.10', '-0.'
            elif whole == 0:
                return 0, NO_WORDS, -1
            else:
                canonical = False  # 'X10': no point
        else:
            return 0, NO_WORDS, -1
        words.append((letters[c], text[start + 1:i]))
        if i == n:
            return (CANONICAL if canonical else WORDS) | (CODES if codes else 0), words, sequence
        if b[i] != 32:
            return 0, NO_WORDS, -1
        i += 1
        if i == n:
            return 0, NO_WORDS, -1
