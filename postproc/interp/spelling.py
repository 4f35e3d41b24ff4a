"""How an evaluated word is written back as program text (the words of an executed block)."""

from __future__ import annotations

from ..errors import ProgramError


def spell_number(value: float) -> str:
    """A real as program text with an explicit decimal point and every significant digit, never an
    exponent: 10.0 -> '10.', 0.1 -> '0.1', 1e-07 -> '0.0000001', -0.0 -> '-0.'."""
    text = repr(value)
    if "e" in text or "E" in text:
        from decimal import Decimal  # imported by the rare exponent, not by every start
        text = format(Decimal(text), "f")
    if "." not in text:
        return text + "."
    if text.endswith(".0"):
        return text[:-1]
    return text


def spell_integer(letter: str, value: float) -> str:
    """The text of an address that takes an integer (G, M, N, P...): an error for any other value."""
    if not value.is_integer():
        raise ProgramError(f"address {letter} takes an integer, the expression gives {value:g}")
    return str(int(value))
