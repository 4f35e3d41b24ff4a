"""The ISO word scan: the words of a line of words only, read in one pass over its characters, and whether the
line is already in canonical spelling (``postproc.numbers.CANONICAL_BLOCK``) from the same pass.

This is the family's one reading of plain words (``postproc.rs274.lexer`` reads every line's words with
it; the Fanuc reader reads a whole plain line with it): a line of words only is what ``WORDS_ONLY``
matches whole, its words what ``WORD.findall`` finds, for ASCII text. Those two regexes are the definition;
``tests/test_canonical_line.py`` holds the scan to them (and to ``CANONICAL_BLOCK``) on random lines.
Compiled (mypyc), the scan costs a fraction of the regexes, which were the largest single cost of reading a
CAM line (~8,500 instructions a line); the pure-Python build runs the same scan (slower there than the
regexes: both builds compute one way, and only the compiled one is the fast one).
"""

from __future__ import annotations

from typing import Any, Final

from mypy_extensions import i64, mypyc_attr

from ..ir.block import MARK_BITS, MARK_MASK, MARK_WORDS
from ..numbers import DECIMAL_DIGITS, decimal_value

CANONICAL: Final = 1
"""The bit of ``scan_words``'s answer for a canonical line (``CANONICAL_BLOCK``): upper-case words separated by
single spaces, a code letter and digits, an axis-type letter and ``-?(0|[1-9][0-9]*)\\.`` with at most six
decimals and no trailing zero, never ``-0.``."""
CODES: Final = 2
"""The bit of ``scan_words``'s answer for a line that has a G or M word (a reader then looks for calls)."""
WORDS: Final = 4
"""The bit of ``scan_words``'s answer for any line of words only (set whenever the answer is not 0)."""
LEXED: Final = 8
"""The bit of ``scan_words``'s answer for a line whose first word the lexer judges: an O (a program number),
or an N whose number is not digits only (an error)."""

_AXIS: Final = 8
"""An upper-case letter whose canonical number has a decimal point."""
_CODE: Final = 9
"""An upper-case letter whose canonical number is digits only."""
_LETTER: Final = 10
"""Any other letter: a plain word, never a canonical one (K, whose kind depends on the block; lower case)."""
_CLASS: Final = bytes(_AXIS if chr(c) in "XYZABCUVWIJRQF" else _CODE if chr(c) in "GMNOTHDLPS"
                      else _LETTER if chr(c).isascii() and chr(c).isalpha() else 0 for c in range(256))
"""Per byte, the letter it is to the scan (0: not a letter)."""
_MAX_FRACTION: Final = 6
_I64_DIGITS: Final = 18
"""The most digits a block number summed as an ``i64`` may have (a longer one, leading zeros and all, by ``int``)."""
_LETTERS: Final[list[str]] = [chr(c) for c in range(128)]
"""An ASCII byte's character (compiled: a list item, not a one-character slice of the line)."""


NO_WORDS: Final[list[tuple[str, str]]] = []
"""``scan_words``'s words for a line that is not words only (one shared list: never appended to)."""

NUMBERS_KEY: Final = "canonical_line.numbers"
"""``Context.run_data`` key: the run's ``LineNumbers`` (``line_numbers``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class LineNumbers:
    """The numbers of the line ``scan_marks`` left unmade last in a run (``text``, None before the first or
    while a scan is under way): each axis-type word's value, as the scan read it, by the word's place in the
    line's ``Block.marks``, and its block number. The reader's scan fills it, and the plain-block lane
    (``postproc.fast.plain``), which reads the block from its marks, takes the values from it instead of reading
    each number again; a block whose line is not the one held (a step read ahead) is scanned again for them. One
    per run (``line_numbers``): a run is read in one thread, and the scan and the lane meet here without a field
    of the block."""

    __slots__ = ("text", "sequence", "v0", "v1", "v2", "v3", "v4", "v5")

    def __init__(self) -> None:
        self.text: str | None = None
        """The line whose numbers are held (compared by identity: the block holds the reader's string)."""
        self.sequence = -1
        """Its block number (``scan_words``'s third answer: -1 where its first word is no N)."""
        # The values unboxed, one field a word (compiled: a double each, no float object made until the lane
        # stores one; a list would box each value here and hold it).
        self.v0 = 0.0
        self.v1 = 0.0
        self.v2 = 0.0
        self.v3 = 0.0
        self.v4 = 0.0
        self.v5 = 0.0

    def value(self, index: i64) -> float:
        """The value held for the axis-type word at ``index`` (below ``MARK_WORDS``) of ``text``."""
        if index == 0:
            return self.v0
        if index == 1:
            return self.v1
        if index == 2:
            return self.v2
        if index == 3:
            return self.v3
        if index == 4:
            return self.v4
        return self.v5


def line_numbers(run_data: dict[str, Any]) -> LineNumbers:
    """The run's ``LineNumbers`` (``Context.run_data``), made at the first asking (by the reader or the lane,
    whichever asks first: each asks once a run)."""
    numbers = run_data.get(NUMBERS_KEY)
    if not isinstance(numbers, LineNumbers):
        numbers = run_data[NUMBERS_KEY] = LineNumbers()
    return numbers


def scan_words(text: str) -> tuple[int, list[tuple[str, str]], int]:
    """The line's kind (0: not a line of words only, or not ASCII; else ``WORDS``, with ``CANONICAL``,
    ``CODES`` and ``LEXED`` as they apply), its words as a reader keeps them (letter, number as written,
    blanks left out) and the number of its block number when its first word is an N with digits only (else
    -1), from one pass: a canonical line needs no split, and its block number no second parse.
    ``NO_WORDS`` when the kind is 0."""
    kind, words, sequence, _ = _scan(text, True, b"", 0, None)
    return kind, words, sequence


def scan_marks(text: str, data: bytes = b"", at: i64 = 0,
               numbers: LineNumbers | None = None) -> tuple[int, list[tuple[str, str]], int, i64]:
    """``scan_words``'s reading of the line, from the same pass, with the words of a canonical line of at most
    ``MARK_WORDS`` words and 255 characters left unmade: their letters' places packed as ``Block.marks`` holds
    them (``postproc.ir.block.marked_words`` makes the same words from them), and ``NO_WORDS`` in their place.
    Any other line's words come made, with 0 marks. ``data``: ASCII bytes that hold the line's at ``at`` (the
    line check's copy of a piece of lines, ``postproc.syntaxes.lines.CheckedLines.runs``), read instead of a copy
    of the line made here. ``numbers``: where a line left unmade leaves its axis-type words' values and its block
    number, read in the same pass (``LineNumbers``)."""
    kind, words, sequence, marks = _scan(text, False, data, at, numbers)
    if kind and not marks:
        kind, words, sequence, _ = _scan(text, True, data, at, None)  # (a line not canonical, or too long to mark)
    return kind, words, sequence, marks


def _scan(text: str, keep: bool, data: bytes, at: i64,
          numbers: LineNumbers | None) -> tuple[int, list[tuple[str, str]], int, i64]:
    """The scan (``scan_words``); ``keep`` False: the words' letters' places packed (the fourth answer, or 0
    where they do not fit or the line is not canonical) instead of the words made, and such a line's numbers
    left in ``numbers`` (where given). ``data``: the line's bytes from ``at`` on (``scan_marks``); empty: the
    line's own ASCII copy, made here."""
    # The line's bytes read each once, into ``ch`` (-1 past the end), as ``i`` moves on (a test of the same byte
    # read it again: ~100 instructions a line, callgrind). Compiled, a byte of a ``bytes`` is read in place with
    # a bounds check (a character of a ``str`` costs twice that: its kind and data told again each time), from
    # the line check's ASCII copy of the piece where the reader has it (``data``), else from a copy of the line.
    # Positions as i64 (compiled: machine integers, not tagged ones whose every step checks for overflow);
    # digits and blanks told by comparisons (a table look-up is a second index, with its own checks).
    # A number's digits are summed as they pass (``mantissa``, a machine integer: three instructions a digit);
    # where the line is left unmade, its axis-type words' values are kept from them (``numbers``),
    # ``decimal_value``'s exact quotient of at most ``DECIMAL_DIGITS`` digits, ``decimal_value`` itself for more
    # (whose sum, past 18 digits, is not used: it wraps compiled); ``tests/test_canonical_line.py`` compares them
    # bit for bit with ``float``.
    if numbers is not None:
        numbers.text = None  # (what it holds is no longer a line's until this scan ends)
    if len(data) > 0:  # (compiled, a length read; ``if data`` is a call, ~30 instructions)
        b = data
        base = at
    else:
        try:
            b = text.encode("ascii")  # compiled, a C call; ``str.isascii`` would be a method look-up
        except UnicodeEncodeError:
            return 0, NO_WORDS, -1, 0
        base = 0
    n: i64 = len(text)
    table = _CLASS
    letters = _LETTERS
    canonical = True
    kind = WORDS
    words: list[tuple[str, str]] = [] if keep else NO_WORDS
    count: i64 = 0  # words met
    marks: i64 = 0  # their letters' places (``keep`` False), from bit MARK_BITS up
    sequence = -1
    i: i64 = 0
    ch: i64 = b[base] if n else -1  # the character at i
    while ch == 32 or ch == 9:  # ' ', '\t'
        i += 1
        ch = b[base + i] if i < n else -1
    if i != 0 or ch < 0:  # blanks first, or no word at all
        canonical = False
    while ch >= 0:  # at a word's letter, or what stands there
        c = ch
        k = table[c] if c < 256 else 0  # (a code past the table's 256: no letter)
        if k < _AXIS:
            if c != 59:  # ';'
                return 0, NO_WORDS, -1, 0
            i += 1
            ch = b[base + i] if i < n else -1
            while ch == 32 or ch == 9:
                i += 1
                ch = b[base + i] if i < n else -1
            if ch >= 0:
                return 0, NO_WORDS, -1, 0
            canonical = False  # ';': the end of block, written out
            break
        i += 1
        ch = b[base + i] if i < n else -1
        if ch == 32 or ch == 9:
            canonical = False  # 'X 1.': a blank between the letter and its number
            while ch == 32 or ch == 9:
                i += 1
                ch = b[base + i] if i < n else -1
        start = i
        negative = ch == 45  # '-'
        signed = negative or ch == 43  # '-', '+'
        if signed:
            if ch == 43 or k != _AXIS:  # '+1.', 'T-1': plain, not canonical
                canonical = False
            i += 1
            ch = b[base + i] if i < n else -1
        digits = i
        lead = ch  # the number's first character
        first_n = (c == 78 or c == 110) and count == 0  # 'N', 'n' first: its number is the block's
        mantissa: i64 = 0  # the number's digits (not a block number's), whole and places, as one integer
        if first_n:
            number: i64 = 0  # (a machine integer: no checked multiplication a digit; summed up to 18 digits)
            while 48 <= ch <= 57:
                if i - digits < _I64_DIGITS:
                    number = number * 10 + (ch - 48)
                i += 1
                ch = b[base + i] if i < n else -1
            sequence = number
            if i - digits > _I64_DIGITS:
                sequence = int(text[digits:i])
        else:
            while 48 <= ch <= 57:
                mantissa = mantissa * 10 + (ch - 48)
                i += 1
                ch = b[base + i] if i < n else -1
        whole = i - digits
        point = ch == 46  # '.'
        if point:
            i += 1
            ch = b[base + i] if i < n else -1
            fraction = i
            final: i64 = 0  # the last decimal place
            scale = 1.0  # ten to the places (exact: a value is kept from at most DECIMAL_DIGITS digits)
            while 48 <= ch <= 57:
                final = ch
                mantissa = mantissa * 10 + (ch - 48)
                scale = scale * 10.0
                i += 1
                ch = b[base + i] if i < n else -1
            places = i - fraction
            if whole == 0:
                if places == 0:  # 'X.' is no number
                    return 0, NO_WORDS, -1, 0
                canonical = False  # '.5'
            elif (k != _AXIS or whole > 1 and lead == 48 or places > _MAX_FRACTION
                  or places > 0 and final == 48
                  or signed and places == 0 and whole == 1 and lead == 48):
                canonical = False  # 'G1.5', '00.5', more than six places, '0.10', '-0.'
            if numbers is not None and k == _AXIS and count < MARK_WORDS:
                if whole + places > DECIMAL_DIGITS:
                    value = decimal_value(text[start:i])
                else:
                    value = float(mantissa) / scale
                    if negative:
                        value = -value
                if count == 0:  # (its field stored here: compiled, a store, where a method call cost ~30 a word)
                    numbers.v0 = value
                elif count == 1:
                    numbers.v1 = value
                elif count == 2:
                    numbers.v2 = value
                elif count == 3:
                    numbers.v3 = value
                elif count == 4:
                    numbers.v4 = value
                else:
                    numbers.v5 = value
        else:
            if whole == 0:  # a letter without a number
                return 0, NO_WORDS, -1, 0
            if k != _CODE:
                canonical = False  # 'X10': no point
        if c == 71 or c == 77 or c == 103 or c == 109:  # 'G', 'M', 'g', 'm'
            kind |= CODES
        if first_n:
            if point or signed:
                kind |= LEXED  # 'N10.', 'N-1': the lexer's to judge
                sequence = -1
        elif (c == 79 or c == 111) and count == 0:  # 'O', 'o' first: a program number, the lexer's
            kind |= LEXED
        if keep:
            words.append((letters[c], text[start:i]))
        elif count < MARK_WORDS:
            marks |= (start - 1) << (MARK_BITS * (count + 1))  # (a canonical word's letter stands just before)
        count += 1
        if ch == 32:  # a space, then (likeliest) the next word's letter
            i += 1
            ch = b[base + i] if i < n else -1
            if ch < 0:
                canonical = False  # a blank at the end
                break
            if ch < 256 and table[ch] >= _AXIS:
                continue
        elif ch < 0:
            break
        elif ch == 59 or ch < 256 and table[ch] >= _AXIS:  # ';', or the next word at once ('X1Y2')
            canonical = False
            continue
        elif ch != 9:
            return 0, NO_WORDS, -1, 0
        canonical = False  # canonical: one space between words, no tab
        while ch == 32 or ch == 9:
            i += 1
            ch = b[base + i] if i < n else -1
    if keep or not canonical or count > MARK_WORDS or n > MARK_MASK:
        return (kind | CANONICAL if canonical else kind), words, sequence, 0
    if numbers is not None:
        numbers.sequence = sequence
        numbers.text = text
    return kind | CANONICAL, words, sequence, marks | count
