"""``postproc.output.line_feeds``: a line written as its two pieces (``write_line``, the straight lanes' way) reaches
the output as the line written whole would (``write``), lone CRs rewritten alike, and with the same account of what
was written (``wrote``, ``content``)."""

from __future__ import annotations

import io

from hypothesis import given
from hypothesis import strategies as st

from postproc.output.line_feeds import BATCH, LineFeeds

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
