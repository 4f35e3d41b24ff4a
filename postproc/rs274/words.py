"""How the RS274 family names a block's words: the upper-case address of a letter as written, the axis
letters, and where a word stands in its line (the column an error about it points at). Shared by the
block syntax and the readings split out of it (``length_words``, ``data_setting``)."""

from __future__ import annotations

from typing import Final

from postproc.context import word_columns
from postproc.ir import Block

AXIS_LETTERS: Final = frozenset("XYZABCUVW")
UPPER: Final = {c: c.upper() for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"}
UPPER[":"] = "O"  # ':' is ISO's spelling of the program number address
DATA_KEY: Final = "10"
"""The number of the family's programmable data input code (``DataSetting``)."""


def col_of_word(block: Block, letter: str, num: str) -> int:
    """Column of the word ``letter``+``num`` as written (comments skipped); 1 when not found."""
    for col, found, text in word_columns(block.text or ""):
        if found.upper() == letter.upper() and text == num:
            return col
    return 1


def second_col(block: Block, letter: str) -> int:
    """Column of the second word with ``letter`` (the one that repeats an address)."""
    cols = [col for col, found, _ in word_columns(block.text or "") if found.upper() == letter.upper()]
    return cols[1] if len(cols) > 1 else 1
