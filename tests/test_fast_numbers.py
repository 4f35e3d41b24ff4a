"""The writers' number shortcut (``exact_decimal``) spells every value exactly as the general rounding
does: checked against exact decimal arithmetic (``decimal.Decimal``), on random values and on the
values CAM programs are made of (few places)."""

from __future__ import annotations

import math
from decimal import ROUND_HALF_EVEN, Decimal, localcontext

from hypothesis import example, given
from hypothesis import strategies as st

from postproc.numbers import (
    EXACT, EXACT_INCH, TEXTS_KEPT, DecimalTexts, canonical_number, canonical_number_re, decimal_text, exact_decimal,
    format_decimal, shortcut_places,
)

PLACES = st.integers(min_value=0, max_value=10)


def _quantized(value: float, places: int) -> Decimal:
    with localcontext(prec=1000):  # every digit of any double
        return Decimal(value).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_EVEN)


def _reference(value: float, places: int, leading_zero: bool, exact: float) -> str:
    """What ``format_decimal`` documents, in exact decimal arithmetic: the value rounded half-even to
    ``places`` (as printf rounds the exact binary value), or to the places half a micrometre needs
    (``WITHIN``) when that reads back further than ``exact``; trailing zeros dropped, the point kept,
    no '-0.', an optional leading zero."""
    rounded = _quantized(value, places)
    if abs(float(rounded) - value) > exact:
        rounded = _quantized(value, max(places, WITHIN[exact]))
    text = f"{rounded:f}"
    text = text.rstrip("0") if "." in text else text + "."
    if text in ("-0.", "0."):
        return "0."
    if not leading_zero:
        if text.startswith("0."):
            return text[1:]
        if text.startswith("-0."):
            return "-" + text[2:]
    return text


WITHIN = {EXACT: 6, EXACT_INCH: 8, math.inf: 0}
"""Places within half a micrometre: 0.0000005 mm, 0.00000002 in (0.5e-8 <= 5e-7 / 25.4 < 0.5e-7)."""
EXACTS = st.sampled_from(sorted(WITHIN))


@st.composite
def few_places(draw: st.DrawFn, most: int = 7) -> float:
    """A value as CAM programs write them: an integer count of 10**-k, k = 0..most."""
    k = draw(st.integers(min_value=0, max_value=most))
    n = draw(st.integers(min_value=-(10 ** 13), max_value=10 ** 13))
    return n / 10 ** k


@given(value=few_places() | st.floats(allow_nan=False, allow_infinity=False, width=64), places=PLACES,
       leading_zero=st.booleans(), exact=EXACTS)
@example(value=-0.0, places=3, leading_zero=True, exact=EXACT)
@example(value=0.5, places=3, leading_zero=False, exact=EXACT)
@example(value=-0.25, places=0, leading_zero=False, exact=EXACT)
@example(value=1.2345, places=3, leading_zero=True, exact=math.inf)
@example(value=0.12345678, places=4, leading_zero=True, exact=EXACT_INCH)
@example(value=999999.9999999, places=7, leading_zero=True, exact=EXACT)
@example(value=1e-05, places=6, leading_zero=True, exact=EXACT)
def test_the_shortcut_spells_what_rounding_spells(value: float, places: int, leading_zero: bool,
                                                   exact: float) -> None:
    text = exact_decimal(value, places, leading_zero, exact)
    if text is None:
        return  # the caller rounds (format_decimal's general path)
    assert text == _reference(value, places, leading_zero, exact)
    assert float(text) == value  # exact: nothing to carry, no warning to give
    assert format_decimal(value, places, leading_zero, exact) == text


@given(value=few_places() | st.floats(min_value=-1e29, max_value=1e29, width=64), places=PLACES,
       leading_zero=st.booleans(), exact=EXACTS)
def test_format_decimal_spells_what_it_documents(value: float, places: int, leading_zero: bool,
                                                 exact: float) -> None:
    assert format_decimal(value, places, leading_zero, exact) == _reference(value, places, leading_zero, exact)


@given(value=few_places(most=6), places=st.integers(min_value=0, max_value=6), leading_zero=st.booleans())
def test_cam_numbers_take_the_shortcut(value: float, places: int, leading_zero: bool) -> None:
    """Between 0.0001 and a million (and 0), a value with at most 6 places is always written by the
    shortcut in mm (smaller ones are spelt with an exponent by ``repr``: the general path)."""
    if abs(value) < 1e6 and (abs(value) >= 1e-4 or value == 0):
        assert exact_decimal(value, places, leading_zero) == _reference(value, places, leading_zero, EXACT)


_CANONICAL_NUMBER = st.builds(
    lambda sign, whole, fraction: f"{sign}{whole}.{fraction}".rstrip("0") if fraction else f"{sign}{whole}.",
    st.sampled_from(["", "-"]),
    st.one_of(st.just("0"), st.integers(min_value=1, max_value=10 ** 9).map(str)),
    st.text("0123456789", max_size=6).map(lambda f: f.rstrip("0")),
).filter(lambda t: t not in ("-0.", "") and not t.endswith("-0."))


@given(_CANONICAL_NUMBER, st.integers(min_value=0, max_value=8))
@example("-3.859", 6)
@example("0.000001", 6)
@example("999999999.999999", 6)
@example("999999.999999", 6)
def test_a_canonical_number_is_written_as_it_reads(text: str, most: int) -> None:
    """Why ``WordWriter.source_number`` may copy a canonical block's axis number: with no more places than
    the writer writes exactly, the exact spelling of the float it reads as is the text itself."""
    from postproc.numbers import CANONICAL_BLOCK, as_written, decimal_text

    assert CANONICAL_BLOCK.fullmatch("X" + text)
    value = float(text)
    places = len(text) - text.index(".") - 1
    assert as_written(text, value, most) is (places <= most and abs(value) < 1e6)
    if as_written(text, value, most):
        assert decimal_text(value, most, True) == text


@given(values=st.lists(few_places() | st.floats(width=64) | st.sampled_from([0.0, -0.0, 2.0, -5.0]), max_size=60),
       places=PLACES, leading_zero=st.booleans())
def test_remembered_texts_are_the_spelled_ones(values: list[float], places: int, leading_zero: bool) -> None:
    """A writer's ``DecimalTexts`` answers each value (repeated, signed zeros, nan, out of range) as
    ``decimal_text`` does, and forgets past its bound."""
    most = shortcut_places(places, EXACT)
    texts = DecimalTexts(most, leading_zero)
    for value in values + values:
        assert texts.text(value) == decimal_text(value, most, leading_zero)
        assert len(texts.texts) <= TEXTS_KEPT


def test_remembered_texts_stay_bounded() -> None:
    texts = DecimalTexts(4, True)
    for i in range(TEXTS_KEPT + 10):
        assert texts.text(i / 4) == decimal_text(i / 4, 4, True)
    assert 0 < len(texts.texts) <= TEXTS_KEPT


_NUMBER_TEXT = st.text("0123456789.-+e", max_size=10)


@given(text=_NUMBER_TEXT, places=st.integers(min_value=0, max_value=8), leading_zero=st.booleans())
@example(text="0.", places=6, leading_zero=True)
@example(text="0.", places=6, leading_zero=False)
@example(text="-0.", places=6, leading_zero=True)
@example(text="0.5", places=6, leading_zero=False)
@example(text=".5", places=6, leading_zero=False)
@example(text=".5", places=6, leading_zero=True)
@example(text="01.", places=6, leading_zero=True)
@example(text="1.50", places=6, leading_zero=True)
@example(text="1.1234567", places=6, leading_zero=True)
@example(text="-10.25", places=2, leading_zero=True)
@example(text="10", places=6, leading_zero=True)
@example(text=".", places=6, leading_zero=False)
def test_the_canonical_number_scan_agrees_with_its_regex(text: str, places: int, leading_zero: bool) -> None:
    """``canonical_number`` (the writers' test of a number as written, one pass) is the regex it replaced."""
    expected = canonical_number_re(places, leading_zero).fullmatch(text) is not None
    assert canonical_number(text, places, leading_zero) is expected
