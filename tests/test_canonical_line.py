"""The byte scan of canonical lines agrees with the regex it replaces (``postproc.rs274.canonical_line``),
the specification of a canonical line (``postproc.numbers.CANONICAL_BLOCK``).

Generated lines mix near-canonical words (signs, leading and trailing zeros, long fractions, ``-0.``)
with stray characters, so both answers occur often; the suite runs compiled and pure, so the compiled
scan is checked too."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from postproc.numbers import CANONICAL_BLOCK
from postproc.rs274.canonical_line import CANONICAL, CODES, NO_WORDS, WITH_CODES, WORDS, scan, scan_words
from postproc.rs274.lexer import WORD, WORDS_ONLY

_LETTERS = "XYZABCUVWIJKRQFGMNOTHDLPSxg(#"
_number = st.builds(
    lambda sign, whole, point, frac: sign + whole + point + frac,
    st.sampled_from(["", "-", "+", "--"]),
    st.sampled_from(["", "0", "00", "1", "10", "123", "01", "9"]),
    st.sampled_from([".", "", ".."]),
    st.text("0123456789", max_size=8),
)
_word = st.builds(lambda letter, number: letter + number, st.sampled_from(_LETTERS), _number)
_line = st.builds(
    lambda words, seps, tail: "".join(w + s for w, s in zip(words, seps)) + tail,
    st.lists(_word, min_size=1, max_size=6),
    st.lists(st.sampled_from([" ", " ", " ", "  ", "", "\t", "é"]), min_size=6, max_size=6),
    st.sampled_from(["", "", " ", ";", "0"]),
)


@settings(max_examples=3000)
@given(_line)
def test_scan_agrees_with_the_regex_on_word_like_lines(line: str) -> None:
    expected = CANONICAL_BLOCK.fullmatch(line) is not None
    found = scan(line)
    assert bool(found) is expected
    if expected:  # CANONICAL promises no G or M word: a reader then skips looking for calls
        assert found == (WITH_CODES if "G" in line or "M" in line else CANONICAL)
    kind, words, sequence = scan_words(line)
    assert kind & (CANONICAL | CODES) == found or kind & WORDS
    if expected:  # the words a reader keeps, and the block number, from the same pass
        assert kind == found
        assert words == [(w[0], w[1:]) for w in line.split(" ")]
        assert sequence == (int(line.split(" ")[0][1:]) if line.startswith("N") else -1)
    elif kind:
        _assert_plain_words(line, kind, words, sequence)
    else:
        assert words is NO_WORDS and not words and sequence == -1


def _assert_plain_words(line: str, kind: int, words: list[tuple[str, str]], sequence: int) -> None:
    """A plain line that is not canonical: the reader's regex path (``WORDS_ONLY``, ``WORD.findall``,
    a digits-only block number) would have taken it, with these words; upper case and single spaces."""
    assert kind in (WORDS, WORDS | CODES)
    assert WORDS_ONLY.fullmatch(line) and words == WORD.findall(line)
    assert line == " ".join(letter + number for letter, number in words) and line == line.upper()
    assert bool(kind & CODES) is any(letter in "GM" for letter, _ in words)
    if line.startswith("N"):
        assert words[0][1].isdigit() and sequence == int(words[0][1])
    else:
        assert sequence == -1


@settings(max_examples=1000)
@given(st.text(max_size=30))
def test_scan_agrees_with_the_regex_on_any_text(line: str) -> None:
    assert bool(scan(line)) is (CANONICAL_BLOCK.fullmatch(line) is not None)


def test_the_cases_that_matter_by_hand() -> None:
    assert scan("N80 X0.9596 Y0.4583 Z-3.859") == CANONICAL
    assert scan_words("N0080 X0.9596 F1500.") == (CANONICAL, [("N", "0080"), ("X", "0.9596"), ("F", "1500.")], 80)
    assert scan_words("G1 X1. N20") == (WITH_CODES, [("G", "1"), ("X", "1."), ("N", "20")], -1)
    assert scan("G01 X0. F1500.") == WITH_CODES and scan("N10 M98 P1000") == WITH_CODES
    assert scan("X10.") and scan("X-0.5") and scan("X1.123456")
    for line in ("X-0.", "X-0. Y1.", "X0.10", "X00.1", "X1.1234567", "X.5", "G", "X1", "X1. ", " X1.",
                 "X1.  Y2.", "K1.", "x1.", "X1.e5", "X+1.", "", "G1.", "N10X1."):
        assert not scan(line), line
    # plain words that are not canonical: their words without the regex
    assert scan_words("N920 X-28.4869 Y42829") == (WORDS, [("N", "920"), ("X", "-28.4869"), ("Y", "42829")], 920)
    assert scan_words("G43.4 X1.50 Y-.5 Z00.1") == (WORDS | CODES, [("G", "43.4"), ("X", "1.50"), ("Y", "-.5"),
                                                                   ("Z", "00.1")], -1)
    assert scan_words("X-0. Y1.1234567") == (WORDS, [("X", "-0."), ("Y", "1.1234567")], -1)
    for line in ("N10. X1", "X+1", "X1 ", "X1  Y2", "x1", "X-", "X.", "K1", "T-1", "X1;", "X1\tY2"):
        assert scan_words(line) == (0, NO_WORDS, -1), line
