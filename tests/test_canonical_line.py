"""The ISO word scan (``postproc.rs274.canonical_line.scan_words``) agrees with its definition: the regexes it
replaces (``WORDS_ONLY`` matching the whole line, ``WORD.findall`` its words) and the specification of a
canonical line (``postproc.numbers.CANONICAL_BLOCK``).

Generated lines mix near-canonical words (signs, leading and trailing zeros, long fractions, ``-0.``, blanks,
lower case, ``;``) with stray characters, so every answer occurs often; the suite runs compiled and pure, so
the compiled scan is checked too."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st

from postproc.numbers import CANONICAL_BLOCK
from postproc.rs274.canonical_line import CANONICAL, CODES, LEXED, NO_WORDS, WORDS, scan_words
from postproc.rs274.lexer import WORD, WORDS_ONLY

_LETTERS = "XYZABCUVWIJKRQFGMNOTHDLPSExgnmo(#:%/"
_number = st.builds(
    lambda sign, whole, point, frac: sign + whole + point + frac,
    st.sampled_from(["", "-", "+", "--", " ", "\t-"]),
    st.sampled_from(["", "0", "00", "1", "10", "123", "01", "9"]),
    st.sampled_from([".", "", ".."]),
    st.text("0123456789", max_size=8),
)
_word = st.builds(lambda letter, number: letter + number, st.sampled_from(_LETTERS), _number)
_line = st.builds(
    lambda lead, words, seps, tail: lead + "".join(w + s for w, s in zip(words, seps)) + tail,
    st.sampled_from(["", "", "", " ", "\t"]),
    st.lists(_word, min_size=0, max_size=6),
    st.lists(st.sampled_from([" ", " ", " ", "  ", "", "\t", "é", ";"]), min_size=6, max_size=6),
    st.sampled_from(["", "", " ", ";", "; ", ";;", "0", "\u0661"]),
)


def _expected(line: str) -> tuple[int, list[tuple[str, str]], int]:
    """What ``scan_words`` answers, from the regexes."""
    if not line.isascii() or not WORDS_ONLY.fullmatch(line):
        return 0, NO_WORDS, -1
    words = WORD.findall(line)
    kind = WORDS
    if CANONICAL_BLOCK.fullmatch(line):
        kind |= CANONICAL
    if any(letter in "GMgm" for letter, _ in words):
        kind |= CODES
    sequence = -1
    if words and words[0][0] in "Oo":
        kind |= LEXED
    elif words and words[0][0] in "Nn":
        if words[0][1].isdigit():
            sequence = int(words[0][1])
        else:
            kind |= LEXED
    return kind, words, sequence


@settings(max_examples=3000)
@given(_line)
def test_the_scan_is_the_regexes_on_word_like_lines(line: str) -> None:
    assert scan_words(line) == _expected(line)


@settings(max_examples=1000)
@given(st.text(max_size=30))
def test_the_scan_is_the_regexes_on_any_text(line: str) -> None:
    assert scan_words(line) == _expected(line)


def test_the_cases_that_matter_by_hand() -> None:
    assert scan_words("N80 X0.9596 Y0.4583 Z-3.859")[0] == WORDS | CANONICAL
    assert scan_words("N0080 X0.9596 F1500.") == (WORDS | CANONICAL, [("N", "0080"), ("X", "0.9596"), ("F", "1500.")],
                                                  80)
    assert scan_words("G1 X1. N20") == (WORDS | CANONICAL | CODES, [("G", "1"), ("X", "1."), ("N", "20")], -1)
    assert scan_words("G01 X0. F1500.")[0] == scan_words("N10 M98 P1000")[0] == WORDS | CANONICAL | CODES
    for line in ("X10.", "X-0.5", "X1.123456"):
        assert scan_words(line)[0] == WORDS | CANONICAL, line
    # plain words that are not canonical
    for line in ("X-0.", "X-0. Y1.", "X0.10", "X00.1", "X1.1234567", "X.5", "X1", "X1. ", " X1.", "X1.  Y2.",
                 "K1.", "x1.", "X+1.", "T1.", "N10X1.", "X1.;", "X 1.", "X1.\tY2.", "T-1"):
        assert scan_words(line)[0] == WORDS, line
    assert scan_words("N920 X-28.4869 Y42829") == (WORDS, [("N", "920"), ("X", "-28.4869"), ("Y", "42829")], 920)
    assert scan_words("g43.4 X1.50 Y-.5 Z00.1") == (WORDS | CODES, [("g", "43.4"), ("X", "1.50"), ("Y", "-.5"),
                                                                    ("Z", "00.1")], -1)
    assert scan_words("n 10 x - 1") == (0, NO_WORDS, -1)  # a blank after the sign: not a word
    assert scan_words("n 10 x -1 ;") == (WORDS, [("n", "10"), ("x", "-1")], 10)
    assert scan_words("") == scan_words(" ;") == (WORDS, [], -1)
    # the first word the lexer judges: a program number, a block number that is not digits only
    for line in ("O1234", "o12 X1.", "N10. X1", "N+5"):
        assert scan_words(line)[0] & LEXED, line
    # not a line of words only
    for line in ("X", "X.", "X-", "X1.2.3", "X1;Y2", "X1;;", "(C)", "X1(C)", "/X1", ":12", "%", "#1=2", "X[1]",
                 "X1.\u00e9", "X\u0661"):
        assert scan_words(line) == (0, NO_WORDS, -1), line
