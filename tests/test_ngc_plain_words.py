"""``ngc_lexer.plain_words``, the byte scan of a line of words only, against its definition: the two regexes
it replaces (``_WORDS_ONLY`` matching the whole line, then ``_WORD.findall``), on random lines made of what
such a line holds and of what breaks one, and on lines a program has."""

from __future__ import annotations

import pytest
from hypothesis import given, settings, strategies as st

from postproc.rs274.ngc_lexer import _WORD, _WORDS_ONLY, lex_block, plain_words


def _by_regex(code: str) -> list[tuple[str, str]] | None:
    return _WORD.findall(code) if _WORDS_ONLY.fullmatch(code) else None


PIECES = st.sampled_from(["X", "y", "G", "n", "O", "1", "0", "25", ".", "-", "+", " ", "\t", "  ", "#", "[", "(",
                          ";", "%", "@", "\r", "é", "\u0661", "Z-.5", "F1500.", "G01", "X 1", "- 2"])
LINES = st.lists(PIECES, max_size=12).map("".join)


@settings(max_examples=3000, deadline=None)
@given(code=st.one_of(LINES, st.text(max_size=20)))
def test_plain_words_is_the_regexes_on_ascii_lines(code: str) -> None:
    words = plain_words(code)
    if code.isascii():
        assert words == _by_regex(code)
    else:  # not ASCII: left to the regexes (a Unicode digit is a digit to them)
        assert words is None


@pytest.mark.parametrize("code, words", [
    ("N70 G01 X0.3008 Y-0.2031 Z-3.956 F1500.", [("N", "70"), ("G", "01"), ("X", "0.3008"), ("Y", "-0.2031"),
                                                 ("Z", "-3.956"), ("F", "1500.")]),
    ("  x .5\tY+2 ", [("x", ".5"), ("Y", "+2")]),
    ("X1Y2", [("X", "1"), ("Y", "2")]),
    ("", []),
    ("X - 1", None),  # a blank after the sign: the slow path reads it (rs274 ignores the blank)
    ("X.", None),
    ("X1.2.3", None),
    ("%", None),
])
def test_plain_words_reads_lines_as_written(code: str, words: list[tuple[str, str]] | None) -> None:
    assert plain_words(code) == words == _by_regex(code)


def test_a_line_with_unicode_digits_is_read_by_the_slow_path_as_the_regexes_read_it() -> None:
    block = lex_block("t.ngc", 1, "G1 X\u0661\u0662", "\n", "linuxcnc")
    assert block.words == [("G", "1"), ("X", "\u0661\u0662")]


@settings(max_examples=1000, deadline=None)
@given(before=LINES, code=LINES, after=LINES)
def test_plain_words_read_from_the_pieces_bytes_are_the_lines(before: str, code: str, after: str) -> None:
    # the NGC readers' scan reads a line's bytes where the line check's ASCII copy of its piece holds them
    # (``plain_words(code, data, at)``, a run's lines): the same words as the line's own
    if (before + code + after).isascii():
        data = (before + "\n" + code + "\n" + after).encode("ascii")
        assert plain_words(code, data, len(before) + 1) == plain_words(code)
