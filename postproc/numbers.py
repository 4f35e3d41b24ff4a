"""How the RS274 family spells numbers canonically: explicit decimal point, no trailing zeros.

Shared by readers (which can tell a block is already canonical while they lex it) and writers (which
then copy it instead of reformatting every number).
"""

from __future__ import annotations

import functools
import math
import re
from typing import Final

from mypy_extensions import i64, mypyc_attr

from .errors import ProgramError

MAX_PLACES: Final = 6
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


def canonical_number(num: str, places: int, leading_zero: bool) -> bool:
    """Whether ``canonical_number_re(places, leading_zero).fullmatch(num)``, by one pass over the text
    (compiled, the regex's cached look-up and match cost most of writing a word of a block that is
    not canonical): an explicit point, at most ``places`` places without a trailing zero, a whole part
    ``0`` or without leading zeros (none at all without ``leading_zero``), never ``-0.``. Characters are
    compared by their codes (compiled, ``"0" <= num[i]`` compared two strings through Python: ~2k
    instructions a number, callgrind of ``--normalize``)."""
    n = len(num)
    if n == 2 and num == "0.":
        return True
    i = 1 if n and num[0] == "-" else 0
    whole = i
    while i < n and 48 <= ord(num[i]) <= 57:  # '0' to '9'
        i += 1
    digits = i - whole
    if digits > 1 and num[whole] == "0" or digits == 1 and num[whole] == "0" and (not leading_zero or whole == 1
                                                                                   and i + 1 == n):
        return False  # '01.', '0.5' without leading zeros, '-0.'
    if digits == 0 and leading_zero or i >= n or num[i] != ".":
        return False
    i += 1
    fraction = n - i
    if fraction > places:
        return False
    while i < n:
        if not 48 <= ord(num[i]) <= 57:
            return False
        i += 1
    return fraction == 0 or num[n - 1] != "0"


EXACT: Final = 5e-7
"""Half a unit of the ``MAX_PLACES``-th place: the most a written number (mm) may differ from its value."""
EXACT_INCH: Final = EXACT / 25.4
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
    if len(text) > MAX_DIGITS and sum(ch.isdigit() for ch in (text.rstrip("0") if "." in text else text)) > MAX_DIGITS:
        raise ProgramError(f"cannot write the number {value:.6g}: it takes more than {MAX_DIGITS} digits, more than "
                           "any controller reads (and than every reader here reads back)")
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


MAX_DIGITS: Final = 30
"""The most digits of one number a program may hold (``postproc.syntaxes.lines`` refuses a longer one where it reads
it): more than any controller's registers hold. ``format_decimal`` refuses to write a longer one, so no
writer writes a number its own reader (or its controller) refuses."""

_SHORT_RANGE: Final = 1e6
SHORT_RANGE: Final = _SHORT_RANGE
"""``as_written`` holds for a canonical number of at most ``most`` places below this magnitude (a writer
whose ``most`` covers every canonical number, ``MAX_PLACES``, tests only the magnitude)."""
"""Below this magnitude a float is within 6e-11 of its shortest decimal (half its spacing, 2**-34), less
than half a unit of the 9th place (5e-10): ``exact_decimal``'s shortcut is sound for up to 9 places."""
_SCALE: Final[list[float]] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9]
"""10**k, exact in a float (a list: compiled, a tuple of floats is unboxed whole at every use)."""

_POWERS: Final[list[float]] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15]
"""10**k for k up to 15, exact in a float."""
DECIMAL_DIGITS: Final = 15
"""Most digits ``decimal_value`` computes itself: below 10**15 < 2**53 every such integer is a float."""


def decimal_value(num: str) -> float:
    """``float(num)``, computed here for a plain decimal (a minus, digits with at most one point, 15
    digits at most) and by ``float`` for anything else (``+``, an exponent, more digits, no digit).

    Its digits as an integer and the power of ten its places divide by are both exact in a float, so
    their quotient, correctly rounded by the division, is the correctly rounded value of the decimal:
    the value ``float`` returns (Clinger's fast path, which ``float`` takes too, behind its underscore,
    space and locale handling; ``tests/test_numbers.py`` compares the two bit for bit). Compiled, it
    saves a CAM block of two or three coordinates some 600 of its 22,000 instructions (callgrind). The
    pure-Python build runs the same loop (slower there than ``float``'s C, by design: both builds compute
    one way, and only the compiled one is the fast one)."""
    n: i64 = len(num)
    i: i64 = 0
    negative = False
    if n > 0 and num[0] == "-":
        negative = True
        i = 1
    mantissa: i64 = 0
    digits: i64 = 0
    places: i64 = -1
    while i < n:
        c: i64 = ord(num[i])
        if 48 <= c <= 57:
            mantissa = mantissa * 10 + (c - 48)
            digits += 1
            if places >= 0:
                places += 1
        elif c == 46 and places < 0:  # '.'
            places = 0
        else:
            return float(num)
        i += 1
        if digits > DECIMAL_DIGITS:
            return float(num)
    if digits == 0:
        return float(num)
    value = float(mantissa) / _POWERS[places] if places > 0 else float(mantissa)
    return -value if negative else value


def shortcut_places(places: int, exact: float = EXACT) -> int:
    """The most places ``decimal_text`` may write for ``format_decimal(.., places, .., exact)``: a value
    with k places is written as it is when k <= ``places``, or when the nearest number with ``places``
    places lies further than ``exact`` from it (at least 10**-k - 6e-11 away), since ``format_decimal``
    then keeps enough places for all k of them. -1: no shortcut (more than 9 places)."""
    if places > 9:
        return -1
    most = places
    while most < 9 and 1.0 / _SCALE[most + 1] - 1e-10 > exact:
        most += 1
    return most


def decimal_text(value: float, most: int, leading_zero: bool = True) -> str | None:
    """``value`` written exactly with at most ``most`` places (from ``shortcut_places``), trailing zeros
    dropped, or None when it needs more (the caller rounds it with ``format_decimal``).

    Why this is ``format_decimal``'s text: below ``_SHORT_RANGE``, n = value * 10**most rounded is exact
    when value has at most ``most`` places, and n / 10**most then reads back as value; a decimal that reads
    back as value lies within 6e-11 of it, so rounding value to any of the places ``format_decimal`` tries
    gives that decimal (``shortcut_places`` says why it tries enough of them). Below 1e15, value * 10**most
    is within 0.25 of n, so truncating it +- 0.5 finds n. Integer arithmetic: no ``repr``, no rounding
    check, no float parse; most CAM numbers take this path.
    """
    if not -_SHORT_RANGE < value < _SHORT_RANGE or most < 0:  # also false for nan
        return None
    scale = _SCALE[most]
    scaled = value * scale  # within 0.25 of an integer when value has at most ``most`` places
    n = int(scaled + 0.5) if scaled >= 0.0 else int(scaled - 0.5)  # that integer (int() truncates)
    if n / scale != value:
        return None
    if n == 0:
        return "0."  # never '-0.'
    sign = "-" if n < 0 else ""
    digits = str(-n if n < 0 else n)
    if not most:
        return f"{sign}{digits}."
    if len(digits) <= most:
        if not leading_zero:
            return f"{sign}.{'0' * (most - len(digits))}{digits.rstrip('0')}"
        digits = "0" * (most + 1 - len(digits)) + digits
    return f"{sign}{digits[:-most]}.{digits[-most:].rstrip('0')}"  # one string built, not three


TEXTS_KEPT: Final = 4096
"""The most values a ``DecimalTexts`` remembers (then it forgets them all and starts again)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class DecimalTexts:
    """``decimal_text(value, most, leading_zero)`` for one writer's ``most`` and ``leading_zero``,
    remembered per value: a canned cycle's expansion writes the same few numbers (its R plane, its
    depth, the hole's X and Y) again and again, and spelling one costs ~2,000 instructions where a
    look-up costs ~100 (cycles to LinuxCNC: 27 numbers a hole). Equal floats spell the same (0.0 and
    -0.0 both '0.'); a value ``decimal_text`` cannot write exactly is not remembered."""

    def __init__(self, most: int, leading_zero: bool) -> None:
        self.most = most
        self.leading_zero = leading_zero
        self.texts: dict[float, str] = {}

    def text(self, value: float) -> str | None:
        texts = self.texts
        text = texts.get(value)
        if text is not None:
            return text
        text = decimal_text(value, self.most, self.leading_zero)
        if text is not None:
            if len(texts) >= TEXTS_KEPT:
                texts.clear()
            texts[value] = text
        return text


def as_written(text: str, value: float, most: int) -> bool:
    """Whether ``decimal_text(value, most)`` is ``text``, for ``text`` a canonical number (``CANONICAL_BLOCK``:
    leading zero, no trailing zero) and ``value`` the float read from it: it is when the text has at most
    ``most`` places and the value is in ``decimal_text``'s range, for ``decimal_text`` then spells the decimal
    the float reads back as, which is the text. A writer then copies the number instead of spelling it."""
    point = text.find(".")
    return 0 <= point and len(text) - point - 1 <= most and -_SHORT_RANGE < value < _SHORT_RANGE


def exact_decimal(value: float, places: int, leading_zero: bool = True, exact: float = EXACT) -> str | None:
    """``format_decimal(value, places, leading_zero, exact)`` for a value it writes exactly, else None
    (``decimal_text`` with ``shortcut_places``; a writer computes those places once per run)."""
    return decimal_text(value, shortcut_places(places, exact), leading_zero)


@functools.cache
def _places_within(exact: float) -> int:
    """Fewest decimal places whose rounding moves a value by at most ``exact`` (6 for ``EXACT``)."""
    return max(0, math.ceil(-math.log10(2.0 * exact) - 1e-9))
