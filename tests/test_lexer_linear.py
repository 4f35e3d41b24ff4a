"""The ISO lexer's error path is linear in the line (a 3.6 MB bad line once took 58 s): counted, not timed.

The line is a ``str`` that counts every character its indexing and slicing hand out; the lexer's work on
it (apart from the regexes, which match where they stand and never backtrack over the line) is bounded
by a constant times its length. Re-slicing the rest of the line at each letter, as ``_explain`` did,
costs a quadratic number of characters and fails the bound at once.
"""

from __future__ import annotations

from typing import Any

import pytest

from postproc.errors import ParseError
from postproc.rs274.lexer import lex_block


class CountingStr(str):
    """A line that counts the characters its ``[]`` returns."""

    taken = 0

    def __getitem__(self, key: Any) -> str:
        part = str.__getitem__(self, key)
        CountingStr.taken += len(part)
        return part


BAD_LINES = [
    ("X1.5 Y2 " * 4000 + "Q1.2.3", "t.nc:1:32001: error: malformed word 'Q1.2.3'"),
    ("X1.5 Y2 " * 4000 + "!", "t.nc:1:32001: error: unexpected character '!'"),
    ("X1.5 ; " * 4000 + "Y", "t.nc:1:8: error: only comments may follow ';' (the end of the block) on its line: "
                              "put the next block on a line of its own"),
    ("X1.5 Y2 " * 4000 + "1.", "t.nc:1:32001: error: number without an address at '1.'"),
    ("X1.5 Y2 " * 4000 + "B #1 !", "t.nc:1:32001: error: macro variables and expressions are not supported by this "
                                   "reader yet"),
]
MACRO_MESSAGES = {4: "t.nc:1:32006: error: unexpected character '!'"}
"""Where a reader with Custom Macro B reads further: ``B #1`` is a computed word."""


@pytest.mark.parametrize("macro", [True, False], ids=["macro", "plain"])
@pytest.mark.parametrize("case", range(len(BAD_LINES)))
def test_explaining_a_long_bad_line_takes_linear_work(case: int, macro: bool) -> None:
    text, message = BAD_LINES[case]
    if macro:
        message = MACRO_MESSAGES.get(case, message)
    line = CountingStr(text)
    CountingStr.taken = 0
    with pytest.raises(ParseError) as info:
        lex_block("t.nc", 1, line, "\n", macro)
    assert str(info.value) == message
    assert CountingStr.taken <= 4 * len(text), f"{CountingStr.taken} characters handed out for {len(text)}"
