"""``postproc.output.line_feeds``: a line written as its two pieces (``write_line``, the straight lanes' way) reaches
the output as the line written whole would (``write``), lone CRs rewritten alike, and with the same account of what
was written (``wrote``, ``content``)."""

from __future__ import annotations

import io

from hypothesis import given
from hypothesis import strategies as st

from postproc.output.line_feeds import BATCH, Batch, LineFeeds

_LINES = st.lists(st.tuples(st.text(alphabet="AX1. \r\n\t", max_size=6), st.sampled_from(["\n", "\r\n", "\r", ""])),
                  max_size=2 * BATCH)


@given(lines=_LINES)
def test_a_line_in_pieces_is_the_line_whole(lines: list[tuple[str, str]]) -> None:
    whole, pieces = io.StringIO(), io.StringIO()
    one, two = LineFeeds(whole), LineFeeds(pieces)
    for text, eol in lines:
        one.write(text + eol)
        two.write_line(text, eol)
        assert (one.wrote, one.content) == (two.wrote, two.content)
    one.flush()
    two.flush()
    assert pieces.getvalue() == whole.getvalue()


def test_lone_crs_are_rewritten_in_pieces_too() -> None:
    """A lone CR ends a line at LF; CR LF stays (hand-derived)."""
    out = io.StringIO()
    feeds = LineFeeds(out)
    for text, eol in [("", "\n"), ("  ", "\r\n"), ("G1 X1.", "\r"), ("A\rB", "\n"), ("C\r", "\n"), ("D", "\r\n")]:
        feeds.write_line(text, eol)
        assert feeds.wrote
    assert feeds.content
    feeds.flush()
    assert out.getvalue() == "\n  \r\nG1 X1.\nA\nB\nC\r\nD\r\n"


@st.composite
def _spliced(draw: st.DrawFn) -> tuple[str, int, int, str, str]:
    """A line's text, where a piece is put in (``at``), how much of the text it replaces (``cut``), the piece, and an
    end of line."""
    text = draw(st.text(alphabet="NX1. \r\n\t", max_size=8))
    at = draw(st.integers(0, len(text)))
    cut = draw(st.integers(0, len(text) - at))
    return text, at, cut, draw(st.sampled_from(["G1", " G0 ", "", " ", "\r"])), draw(st.sampled_from(["\n", "\r\n", "\r"]))


@given(lines=st.lists(_spliced(), max_size=BATCH))
def test_a_spliced_line_is_the_line_whole(lines: list[tuple[str, int, int, str, str]]) -> None:
    """``write_spliced`` (the straight lane's line with its motion code put in) writes what the line made whole
    writes, through a batch and through line feeds, with the same account of what was written."""
    whole, pieces = io.StringIO(), io.StringIO()
    one, two = LineFeeds(whole), LineFeeds(pieces)
    plain_whole, plain_pieces = io.StringIO(), io.StringIO()
    three, four = Batch(plain_whole), Batch(plain_pieces)
    for text, at, cut, insert, eol in lines:
        line = text[:at] + insert + text[at + cut:]
        one.write(line + eol)
        two.write_spliced(text, at, cut, insert, eol)
        assert (one.wrote, one.content) == (two.wrote, two.content)
        three.write_line(line, eol)
        four.write_spliced(text, at, cut, insert, eol)
    for sink in (one, two, three, four):
        sink.flush()
    assert pieces.getvalue() == whole.getvalue()
    assert plain_pieces.getvalue() == plain_whole.getvalue()
