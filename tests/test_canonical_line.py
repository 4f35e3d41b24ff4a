"""The ISO word scan (``postproc.rs274.canonical_line.scan_words``) agrees with its definition: the regexes it
replaces (``WORDS_ONLY`` matching the whole line, ``WORD.findall`` its words) and the specification of a
canonical line (``postproc.numbers.CANONICAL_BLOCK``).

Generated lines mix near-canonical words (signs, leading and trailing zeros, long fractions, ``-0.``, blanks,
lower case, ``;``) with stray characters, so every answer occurs often; the suite runs compiled and pure, so
the compiled scan is checked too."""

from __future__ import annotations

from hypothesis import example, given, settings, strategies as st

from postproc.ir.block import MARK_WORDS, Block, marked_words
from postproc.numbers import CANONICAL_BLOCK
from postproc.rs274.canonical_line import (CANONICAL, CODES, LEXED, NO_WORDS, WORDS, LineNumbers, line_numbers,
                                           scan_marks, scan_words)
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
    st.lists(st.sampled_from([" ", " ", " ", "  ", "", "\t", "é", ";", "\uff11", "\U0001d7cf", "\u00a0"]),
             min_size=6, max_size=6),
    st.sampled_from(["", "", " ", ";", "; ", ";;", "0", "\u0661", "\U0001d7cf"]),
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


@given(st.from_regex(r"[0-9]{1,30}", fullmatch=True))
def test_a_block_number_of_any_length_reads_as_int_reads_it(digits: str) -> None:
    """The scan sums a block number of up to 18 digits (leading zeros and all) as a machine integer and reads a
    longer one by ``int``: the same number either way, up to the line check's 30 digits."""
    line = f"N{digits} X1."
    assert scan_words(line)[2] == scan_marks(line)[2] == int(digits)


def _marks_agree(line: str) -> None:
    """``scan_marks`` answers as ``scan_words`` does, its words unmade (marks) only on a canonical line of at most
    ``MARK_WORDS`` words and 255 characters, from which ``marked_words`` and a block's ``words`` make the same."""
    kind, words, sequence = scan_words(line)
    marked_kind, marked, marked_sequence, marks = scan_marks(line)
    assert (marked_kind, marked_sequence) == (kind, sequence)
    if marks:
        assert kind & CANONICAL and len(words) <= MARK_WORDS and len(line) <= 255
        assert marked is NO_WORDS and marked_words(line, marks) == words
        block = Block(1, line, "\n", None, marks)
        assert block.marks == marks and block.spelled() == line
        assert block.words == words and block.marks == 0 and block.spelled() == ""  # made once, then kept
        assert block.words is block.words
    else:
        assert marked == words
        assert not (kind & CANONICAL and 0 < len(words) <= MARK_WORDS and len(line) <= 255)


@settings(max_examples=3000)
@given(_line)
def test_marks_make_the_scans_words(line: str) -> None:
    _marks_agree(line)


@given(st.lists(st.sampled_from(["N10", "G1", "X1.5", "Y-0.25", "Z100.", "F1500.", "M3", "I0.5", "T12"]),
                min_size=1, max_size=9), st.integers(0, 240))
def test_marks_on_canonical_lines_of_every_length(words: list[str], pad: int) -> None:
    line = " ".join(words)
    _marks_agree(line)
    _marks_agree(line + " X" + "1" * pad + ".")  # up to and past 255 characters


def test_a_marked_block_is_the_block_of_its_words() -> None:
    """Equal to the block read with its words made, as XML too; words set or a text changed before they are made
    keep the block right (they come from the line as read)."""
    line = "N10 X1.5 Y-2."
    _, words, _, marks = scan_marks(line)
    assert marks and Block(1, line, "\n", None, marks) == Block(1, line, "\n", list(scan_words(line)[1]))
    changed = Block(1, line, "\n", None, marks)
    changed.changed()
    assert changed.text is None and changed.words == [("N", "10"), ("X", "1.5"), ("Y", "-2.")]
    replaced = Block(1, line, "\n", None, marks)
    replaced.words = [("X", "2.")]
    assert replaced.marks == 0 and replaced.words == [("X", "2.")]
    from lxml import etree
    made = Block(1, line, "\n", [("N", "10"), ("X", "1.5"), ("Y", "-2.")])
    assert etree.tostring(Block(1, line, "\n", None, marks).make_xml_source()) == etree.tostring(
        made.make_xml_source())
    import copy
    import pickle
    for twin in (copy.copy(Block(1, line, "\n", None, marks)), pickle.loads(pickle.dumps(Block(1, line, "\n", None,
                                                                                            marks)))):
        assert twin.words == made.words


@settings(max_examples=1000)
@given(_line, _line, _line)
def test_the_scan_of_a_line_read_from_its_pieces_bytes_is_the_scan_of_the_line(before: str, line: str, after: str) -> None:
    # the Fanuc reader's scan reads a line's bytes where the line check's ASCII copy of its piece holds them
    # (``scan_marks(text, data, at)``): the same answer as the line's own
    if (before + line + after).isascii():
        data = (before + "\n" + line + "\n" + after).encode("ascii")
        assert scan_marks(line, data, len(before) + 1) == scan_marks(line)


_decimal = st.builds(
    lambda sign, zeros, whole, frac: sign + zeros + whole + "." + frac,
    st.sampled_from(["", "-", "+"]),
    st.sampled_from(["", "", "0", "000"]),
    st.text("0123456789", max_size=16),
    st.text("0123456789", max_size=16),
).filter(lambda num: any(c.isdigit() for c in num))


@settings(max_examples=2000)
@given(_decimal, st.sampled_from(["", "N10 ", "G1 X1. "]), st.sampled_from("XYZIJRF"))
@example("5.", "", "X")
@example(".5", "", "X")
@example("-.5", "", "X")
@example("+0005.50", "", "X")
@example("-0.", "", "X")
@example("123456789012345.", "", "X")  # 15 digits: summed
@example("1234567890123456.7", "", "X")  # 17: by ``decimal_value``
@example("9007199254740993.", "", "X")  # 2**53 + 1: no float holds it
@example("0.000000000000000000001", "", "X")
@example("-99999999999999999999999999.9999", "G1 X1. ", "Y")
def test_the_scans_values_are_floats_bit_for_bit(num: str, before: str, letter: str) -> None:
    """The value the scan reads of an axis-type number with a decimal point as it passes its digits (what it leaves in
    ``LineNumbers`` for the plain-block lane) is ``float``'s, bit for bit, for any spelling: signs, leading and
    trailing zeros, ``.5``, ``5.``, and more digits than a float holds. Where the line is canonical, it is held
    for that line, under its words' places, with its block number."""
    line = f"{before}{letter}{num} Z2."
    numbers = LineNumbers()
    kind, _, sequence, marks = scan_marks(line, numbers=numbers)
    index = before.count(" ")
    assert numbers.value(index).hex() == float(num).hex()
    assert numbers.value(index + 1) == 2.0
    if marks:
        assert numbers.text is line and numbers.sequence == sequence
        if before == "G1 X1. ":
            assert numbers.value(1) == 1.0
    else:
        assert numbers.text is None
        assert not kind & CANONICAL or len(line) > 255


def test_a_line_not_left_unmade_leaves_no_numbers() -> None:
    """The numbers held are a line's only while it is the last scanned unmade: a scan that makes its words (a line
    not canonical, or refused) holds none, so a lane never takes another line's values for it."""
    numbers = LineNumbers()
    first = "N10 G1 X1.5 Y-2."
    assert scan_marks(first, numbers=numbers)[3] and numbers.text is first and numbers.sequence == 10
    assert (numbers.value(2), numbers.value(3)) == (1.5, -2.0)
    for line in ("N20 X1.50", "X1. Y2. Z3. A4. B5. C6. U7.", "X", "G1 X1.5 (A)", "N30 X1.5 Y-2."):
        scan_marks(line, numbers=numbers)
        assert numbers.text is (line if line == "N30 X1.5 Y-2." else None)
    assert scan_words(first)[2] == 10 and numbers.text is not first  # (the words' scan holds nothing)


def test_a_run_holds_one_line_numbers() -> None:
    """The reader and the lane of a run ask for its ``LineNumbers`` (``Context.run_data``) and get the same."""
    run_data: dict[str, object] = {}
    numbers = line_numbers(run_data)
    assert line_numbers(run_data) is numbers and line_numbers({}) is not numbers
