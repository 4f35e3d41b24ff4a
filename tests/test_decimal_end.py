"""``postproc.rs274.expressions.decimal_end``: the one scan of an unsigned decimal number the expression parsers
and word readers of every family share, against a regular expression of the same grammar."""

from __future__ import annotations

import re

from hypothesis import given
from hypothesis import strategies as st

from postproc.rs274.expressions import decimal_end

NUMBER = re.compile(r"[0-9]*(?:\.[0-9]*)?")
texts = st.text(alphabet="0123456789.+-eEX# ", max_size=12)


@given(texts, st.integers(min_value=0, max_value=14))
def test_decimal_end_is_the_regular_expressions_match(text: str, pos: int) -> None:
    pos = min(pos, len(text))
    assert decimal_end(text, pos) == NUMBER.match(text, pos).end()  # type: ignore[union-attr]


def test_decimal_end_examples() -> None:
    assert [decimal_end(t, 0) for t in ("12", "1.5", ".5", "2.", ".", "1.2.3", "X1", "")] == [2, 3, 2, 2, 1, 3, 0, 0]
