"""Custom Macro B's argument specification I: the address of a ``G65``/``G66`` argument -> the local variable
it sets [V for A/B/C -> #1-#3; K for the full table: ../shared/reference/DIALECTS.md 1.1]. A module of its
own: the dialect's class reads it (``Dialect.MACRO_ARGUMENTS``, for ``--arg``) without importing the reader."""

from __future__ import annotations

LETTER_LOCALS: dict[str, int] = {
    "A": 1, "B": 2, "C": 3, "I": 4, "J": 5, "K": 6, "D": 7, "E": 8, "F": 9, "H": 11, "M": 13, "Q": 17,
    "R": 18, "S": 19, "T": 20, "U": 21, "V": 22, "W": 23, "X": 24, "Y": 25, "Z": 26,
}
"""Argument specification I: the address of a G65/G66 argument -> the local variable it sets."""
LOCAL_LETTERS: dict[int, str] = {n: letter for letter, n in LETTER_LOCALS.items()}
