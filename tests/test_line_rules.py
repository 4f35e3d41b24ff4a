"""The quick test of a target's line rule (``LineRule.fits``, what ``postproc.output.line_format`` runs on every
written text) is held to the rule itself (``LineRule.fit``, line by line): whatever text it passes, every
line of it is one the rule keeps as it is, without a warning. It must also pass an expanded cycle's many
short lines, so that those are not checked line by line."""

from __future__ import annotations

from hypothesis import given, settings, strategies as st
from postproc_grbl.text import LINES as GRBL_LINES
from postproc_linuxcnc.lines import LINES as LINUXCNC_LINES

from postproc.grbl_family.text import short
from postproc.output.line_format import LineRule

RULES: list[LineRule] = [GRBL_LINES, LINUXCNC_LINES]

PIECES = st.sampled_from([
    "G1 X1.5 Y-2.25", "G83 X10. Y5. Z-12. R2. Q3.", " ", "(A COMMENT)", ";NOTE", "\n", "\r\n", "\r", "\x0b",
    "\x0c", "\x1c", "?", "!", "~", "\x7f", "\u00d8", "\u00e9", "\u2028", "\x85", "X" * 40, "Y" * 79, "Z" * 126,
    "(" + "C" * 120 + ")", "\U0001f600", "\udcff", "\ud800",  # four bytes; a kept byte (one); a lone surrogate (three)
])
TEXTS = st.lists(PIECES, max_size=30).map("".join)


def kept_as_written(rule: LineRule, text: str) -> bool:
    """Every line of ``text`` (as ``LineFormat.format`` splits it) passes ``fit`` unchanged, no warning."""
    for line in text.splitlines(keepends=True):
        body = line.rstrip("\r\n")
        if rule.fit(body, line[len(body):]) != (body, None, None):
            return False
    return True


@settings(max_examples=300, deadline=None)
@given(text=TEXTS)
def test_what_the_quick_test_passes_the_rule_keeps(text: str) -> None:
    for rule in RULES:
        if rule.fits(text):
            assert kept_as_written(rule, text), (type(rule).__name__, text)


def test_an_expanded_cycles_lines_pass_the_quick_test() -> None:
    # a G83 of many pecks, expanded: more characters than one line holds, every line short
    text = "G0 X10. Y5.\nG0 Z2.\n" + "G1 Z-3. F100.\nG0 Z2.\nG0 Z-2.9\n" * 12 + "G0 Z2.\n"
    for rule in RULES:
        assert rule.fits(text) and kept_as_written(rule, text)
        assert rule.fits(text.replace("\n", "\r\n"))


def test_a_long_line_among_short_ones_fails_the_quick_test() -> None:
    grbl_long, linuxcnc_long = "G1 X" + "1" * 80, "(" + "C" * 260 + ")"
    assert not GRBL_LINES.fits("G0 X1.\n" + grbl_long + "\nG0 Z2.\n")
    assert not LINUXCNC_LINES.fits("G0 X1.\n" + linuxcnc_long + "\nG0 Z2.\n")
    assert not GRBL_LINES.fits("G0 X1.\n(WHERE?)\n")


def test_a_short_text_passes_whatever_its_characters() -> None:
    """``ByteLengthLines.fits`` passes a text of at most a quarter of its limit in characters without looking at
    them (a character is at most four bytes written): at that bound, four-byte characters fill the line exactly."""
    limit = LINUXCNC_LINES.limit
    full, over = "\U0001f600" * (limit // 4), "\U0001f600" * (limit // 4 + 1)
    assert LINUXCNC_LINES.fits(full) and kept_as_written(LINUXCNC_LINES, full)
    assert not LINUXCNC_LINES.fits(over) and not kept_as_written(LINUXCNC_LINES, over)


@settings(max_examples=300, deadline=None)
@given(text=st.text(alphabet="G1X.\n\r", max_size=400), size=st.integers(min_value=1, max_value=300))
def test_the_piece_length_test_is_the_longest_piece_shorter_than_the_buffer(text: str, size: int) -> None:
    """``short`` (a few searches) says what the longest piece between LFs says, at every length and buffer."""
    assert short(text, size) == (max(map(len, text.split("\n"))) < size), (text, size)
