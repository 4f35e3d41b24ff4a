"""How the RS274 family reads a word's number into a section: as a real or a whole number (a computed
value, ``Expr``, as it is), a G10 index, a dwell P in seconds as milliseconds, and the divisor of the
decimal-point rule (a point-less number counts least input increments)."""

from __future__ import annotations

from typing import Any, Final

from postproc.context import Context
from postproc.errors import ParseError
from postproc.ir.expr import Expr
from postproc.ir import Block


def real(value: Any) -> Any:
    """A section's real value: the number as a float, or a computed value (``Expr``) as it is."""
    return value if isinstance(value, Expr) else float(value)


def whole(value: Any) -> Any:
    """A section's integer value: the number as an int, or a computed value (``Expr``) as it is."""
    return value if isinstance(value, Expr) else int(value)


def whole_index(value: Any) -> int | None:
    """A whole-number word (G10's L and P) as an int; None when absent, computed or fractional."""
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not float(value).is_integer():
        return None
    return int(value)


def milliseconds(block: Block, ctx: Context, num: str) -> int:
    """A dwell P written with a decimal point, in seconds (the Haas rule), as the whole milliseconds a
    point-less P means, so both spellings read alike."""
    ms = float(num) * 1000.0
    if abs(ms - round(ms)) > 1e-6:
        raise ParseError(f"dwell P{num} (seconds) is finer than a millisecond",
                         ctx.at(block, ctx.column_of(block, "P")))
    return int(round(ms))


_INCREMENTS_PER_MM: Final = {"IS-A": 100, "IS-B": 1000, "IS-C": 10000}


def increments_divisor(ctx: Context, units: str) -> int:
    """Divisor turning a point-less value into program units (0 for calculator-type input)."""
    inp = ctx.setup.input
    if inp.decimal_point == "calculator":
        return 0
    base = _INCREMENTS_PER_MM[inp.increment_system]
    return base if units == "mm" else base * 10
