"""The readers' line splitting (``postproc.rs274.line_ends``): a physical line is its text and its end of line,
kept exactly, so that a copy writes the line back as it was read; the NGC reader splits each line itself
(``split_line``) where the other readers take ``split_lines``' numbered lines."""

from __future__ import annotations

import io

from hypothesis import given, strategies as st

from postproc.rs274.line_ends import split_line, split_lines

LINES = st.text(alphabet=st.sampled_from(["G", "1", " ", "\r", "\n", "(", "%", "\t", "é"]), max_size=12)


@given(raw=LINES)
def test_a_line_is_its_text_and_its_end(raw: str) -> None:
    text, eol = split_line(raw)
    assert text + eol == raw
    if raw.endswith("\r\n"):
        assert eol == "\r\n"
    elif raw.endswith("\n") or raw.endswith("\r"):
        assert eol == raw[-1]
    else:
        assert eol == ""


@given(program=LINES)
def test_numbered_lines_are_a_stream_s_lines(program: str) -> None:
    """``split_lines`` numbers the lines a text stream gives (universal newlines off: the ends kept)."""
    lines = io.StringIO(program, newline="").readlines()
    got = list(split_lines(lines))
    assert [n for n, _, _ in got] == list(range(1, len(lines) + 1))
    assert "".join(text + eol for _, text, eol in got) == program
    assert all("\n" not in text and not text.endswith("\r") for _, text, _ in got)
