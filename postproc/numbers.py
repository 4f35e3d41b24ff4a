"""How the RS274 family spells numbers canonically: explicit decimal point, no trailing zeros.

Shared by readers (which can tell a block is already canonical while they lex it) and writers (which
then copy it instead of reformatting every number).
"""

from __future__ import annotations

import functools
import math
import re

from .errors import ProgramError

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


EXACT = 5e-7
"""Half a unit of the ``MAX_PLACES``-th place: the most a written number (mm) may differ from its value."""
EXACT_INCH = EXACT / 25.4
"""The same half micrometre in inches (an inch number needs 8 places to stay within it)."""


def format_decimal(value: float, places: int, leading_zero: bool = True, exact: float = EXACT) -> str:
    """A number with an explicit decimal point and no trailing zeros ('50.', '0.5', '-.25').

    Rounds to ``places`` decimals (0 writes whole numbers as '50.'), but never silently: a value that
    would move by more than ``exact`` (in its own unit: ``EXACT`` for mm, ``EXACT / 25.4`` for inches)
    keeps as many places as that needs instead. Zero is never negative ('0.', not '-0.'). A
    non-finite value (a number beyond the float range, or not a number) cannot be written: a
    ``ProgramError`` (the writer locates it at its block).
    """
    text = exact_decimal(value, places, leading_zero, exact)
    if text is not None:
        return text
    text = f"{value:.{places}f}"
    if text[-1] > "9":  # 'inf', '-inf' or 'nan': no digit last
        raise ProgramError(f"cannot write the number {value!r}: it is beyond the range of a float"
                           if value == value else "cannot write a value that is not a number (nan)")
    if abs(float(text) - value) > exact:
        text = f"{value:.{max(places, _places_within(exact))}f}"
    if "." in text:
        text = text.rstrip("0")
    else:
        text += "."  # no places: a whole number ('50' -> '50.')
    if text == "-0.":
        return "0."
    if not leading_zero:
        if text[:2] == "0." and text != "0.":
            return text[1:]
        if text[:3] == "-0.":
            return "-" + text[2:]
    return text


_SHORT_RANGE = 1e6
"""Below this magnitude a float is within 6e-11 of its shortest decimal (half its spacing, 2**-34), less
than half a unit of the 9th place (5e-10): ``exact_decimal``'s shortcut is sound for up to 9 places."""
_STEP = (1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9)
"""10**-k: the least a decimal with k places (its last digit not 0) lies from every coarser decimal."""


def exact_decimal(value: float, places: int, leading_zero: bool = True, exact: float = EXACT) -> str | None:
    """``format_decimal(value, places, leading_zero, exact)`` for a value whose shortest decimal
    (``repr``) it writes unchanged, else None (the caller formats it).

    Why it is the same text, for a value below ``_SHORT_RANGE`` (within 6e-11 of its shortest decimal r,
    which has k places): with k <= ``places``, r is the nearest multiple of 10**-places, so rounding to
    ``places`` gives r padded with zeros, which ``format_decimal`` strips again. With more places, the
    nearest multiple of 10**-places lies at least 10**-k - 6e-11 from the value: when that is more than
    ``exact``, ``format_decimal`` keeps more places (``_places_within``, at least k), which gives r again.
    Most CAM numbers take this path: one ``repr``, no rounding, no float parse.
    """
    if not -_SHORT_RANGE < value < _SHORT_RANGE or places > 9:  # also false for nan
        return None
    text = repr(value)
    dot = text.find(".")
    if dot < 0 or "e" in text:  # 1e-05: tiny numbers are written in full by the caller
        return None
    if text[-2:] == ".0":
        text = text[:-1]
        if text == "-0.":
            return "0."
    else:
        k = len(text) - dot - 1
        if k > places and (k > 9 or _STEP[k] - 1e-10 <= exact):
            return None
    if not leading_zero:
        if text[:2] == "0." and text != "0.":
            return text[1:]
        if text[:3] == "-0.":
            return "-" + text[2:]
    return text


@functools.cache
def _places_within(exact: float) -> int:
    """Fewest decimal places whose rounding moves a value by at most ``exact`` (6 for ``EXACT``)."""
    return max(0, math.ceil(-math.log10(2.0 * exact) - 1e-9))
