"""Fanuc's call and return codes (M98, M99, G65, G66, G67) and the reader's test for a block that may make one.

Apart from ``macro`` (which reads the call) only to be compiled with the reader (pyproject ``compiled``): the
reader asks ``makes_call`` of every line with a G or M word, a tenth of a CAM program's lines, and the call into
the interpreted ``macro`` module cost each such line ~2,500 instructions (callgrind, 20k-line CAM program), a
compiled call some 150.
"""

from __future__ import annotations

from typing import Final

CALL_CODES: Final = frozenset((("M", "98"), ("M", "99"), ("G", "65"), ("G", "66"), ("G", "67")))
"""(letter, number without leading zeros) of the calls and returns ``macro.read_call`` reads."""
_CALL_NUMBERS: Final = frozenset(num for _, num in CALL_CODES)


def makes_call(words: list[tuple[str, str]]) -> bool:
    """Whether a block of these words may make a call or return (``read_call`` then reads it): a G or M word
    whose number, its leading zeros left out, is a call's. Judged on the words, never on the text: the reader
    takes ``M098`` for M98 as ``codes.py`` takes ``G000`` for G0, and the lexer reads ``M 98`` and ``g65`` as the
    words M98 and G65, so a test on the text (``"M9" in text``) left those calls as plain codes. A word the test
    passes that is no call (``g98``) costs ``read_call`` one look at the block."""
    for letter, num in words:
        if letter in "GgMm" and calls(num):
            return True
    return False


def calls(num: str) -> bool:
    """Whether a G or M word's number, as written, is a call's or a return's, its leading zeros left out
    (``makes_call``'s test of a word; the reader asks it of a canonical line's G and M words where they stand)."""
    return num.lstrip("0") in _CALL_NUMBERS
