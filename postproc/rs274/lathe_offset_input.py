"""The lathe form of programmable data input (Fanuc T ``G10 P_ X_ Z_ R_ Q_``, no L): it writes one tool offset,
its X and Z, its tool nose radius and its imaginary tool nose direction, into the program's own copy of the
offset memory (``postproc.compensation.tool_table``), which the lathe offsets (``T0102``) and tool nose radius
compensation (G41/G42, lathe cycles included) then read.

The format [V: Fanuc Series 16i/18i/160i/180i-TB operator's manual B-63524EN/01, 14.5.2 "Changing of tool
offset value (programmable data input) (G10)", text read in the stored pages
(cncmanuals.com/fanuc/150/series-16i-18i-160i-180i-tb-operators-manual/page/311)]: ``G10 P_ X_ Y_ Z_ R_ Q_`` or
``G10 P_ U_ V_ W_ C_ Q_``; P 1-64 a wear offset, 10000 + (1-64) a geometry offset (P0, the work coordinate
system shift, is another function: kept verbatim, as before); X, Z, R absolute (R the nose radius), U, W, C
the same added to the offset; Q the imaginary tool nose number. Offsets above 64 exist with the option
[K]; a T code names at most 99 (two digits), so P 1-99 and 10001-10099 are read.

Kept out, each a located refusal (``ProgramError`` for what the manual forbids, ``UnsupportedError`` for
what is not modelled): a Haas lathe's (``<Controller variant="haas">``: its settings are its own G10 L forms
[?], kept verbatim as before), Y/V (a Y-axis offset: the lathe model has X and Z only), X with U or Z with W or R with C
in one block, a Q that is no whole number 0-9, the block in incremental mode (G91: whether X, Z and R then add
is not in that text [?]), a computed value (the offset it sets is known when the program runs), any other
word (the form takes these alone). X follows the set-up's ``<Tool x>``: a diameter on a lathe programmed in
diameters [K: Fanuc parameter ORC (No. 5004#1) = 0, the factory setting, offsets in the X axis's own
programming]. A wear offset's Q sets the offset's one direction (the tip has no wear) [K].
"""

from __future__ import annotations

from typing import Any, Final

from postproc.compensation.tool_table import LATHE_TIP, LATHE_VALUES
from postproc.context import Context
from postproc.errors import ProgramError, UnsupportedError
from postproc.ir.expr import Expr
from postproc.ir import Block, DataSetting

GEOMETRY: Final = "lathe_offset"
"""Neutral table: a lathe tool offset's geometry (X, Z, R, Q; U, W, C its increments)."""
WEAR: Final = "lathe_offset_wear"
"""Neutral table: a lathe tool offset's wear (X, Z, R; U, W, C its increments; Q the offset's direction)."""
LETTERS: Final = frozenset("XZRUWCQ")
_PAIRS: Final = (("X", "U"), ("Z", "W"), ("R", "C"))
"""Each quantity's letter that sets it and the letter that adds to it, in the order of ``LATHE_VALUES``."""
MEANING: Final = {"Q": LATHE_TIP, **{letter: key for pair, keys in zip(_PAIRS, LATHE_VALUES)
                                     for letter, key in zip(pair, keys)}}
"""Letter -> the neutral key its value goes under in the setting (``postproc.compensation.tool_table``)."""
_ALLOWED: Final = LETTERS | {"P", "N", "O"}


def lathe_offset_setting(block: Block, ctx: Context, number: str, values: dict[str, Any], used: set[str],
                         family: str, incremental: bool, letter_of: dict[str, str]) -> DataSetting | None:
    """``G10 P X Z R Q`` (``number``: the G word as written) -> its ``DataSetting``; None where the block is not
    this form (P0, a computed P, no P: the caller keeps it verbatim). ``letter_of`` maps a written letter to its
    upper case (``O`` for ISO's ``:``)."""

    def at(letter: str) -> Any:
        return ctx.at(block, ctx.column_of(block, letter, number if letter == "G" else None))

    if ctx.setup.controller.variant == "haas":
        return None  # [?] a Haas lathe's offset settings are its own G10 L forms: not modelled, kept verbatim
    p = values.get("P")
    if isinstance(p, Expr) or not isinstance(p, (int, float)) or isinstance(p, bool) or not float(p).is_integer():
        return None
    p = int(p)
    if p == 0:
        return None
    if 1 <= p <= 99:
        table, index = WEAR, p
    elif 10001 <= p <= 10099:
        table, index = GEOMETRY, p - 10000
    else:
        raise ProgramError(f"G{number} P{p}: a lathe offset is P1-P99 (wear) or P10001-P10099 (geometry)", at("P"))
    other = sorted(set(values) - _ALLOWED)
    if other:
        raise UnsupportedError(f"{other[0]} in a lathe offset setting (G{number} P{p}): the form takes X, Z, R, "
                               "U, W, C and Q only (a Y-axis offset is not modelled)", at(other[0]))
    for absolute, increment in _PAIRS:
        if absolute in values and increment in values:
            raise ProgramError(f"G{number} P{p}: {absolute} and {increment} set the same value (one absolutely, "
                               "one by an increment)", at(increment))
    data: dict[str, float | Expr] = {}
    for letter in sorted(LETTERS & set(values)):
        value = values[letter]
        if isinstance(value, Expr):
            raise UnsupportedError(f"a computed {letter} in a lathe offset setting (G{number} P{p}): the offset it "
                                   "sets is known when the program runs", at(letter))
        data[letter] = float(value)
    if not data:
        raise ProgramError(f"G{number} P{p} sets nothing (no X, Z, R, U, W, C or Q)", at("G"))
    tip: float | None = None
    if "Q" in data:  # a number, not a length: read as written (the decimal-point rule made it increments)
        raw = next(num for letter, num in block.words if letter_of.get(letter) == "Q")
        try:
            tip = float(raw)
        except ValueError:
            tip = -1.0
        data["Q"] = tip
    if tip is not None and (not float(tip).is_integer() or not 0 <= tip <= 9):
        raise ProgramError(f"G{number} P{p} Q{tip:g}: the imaginary tool nose number is 0 to 9", at("Q"))
    if incremental:
        raise UnsupportedError(f"G{number} P{p} in incremental mode: whether X, Z and R then add to the offset is "
                               "not confirmed [?] (program it in absolute mode, with U, W, C for increments)",
                               at("G"))
    used.update(("P", *data))
    keep = {"P", *data}
    text = " ".join(letter + num for letter, num in block.words
                    if letter_of.get(letter) in keep or letter_of.get(letter) == "G" and num == number)
    return DataSetting(family, table, index, {MEANING[letter]: value for letter, value in data.items()}, False, text)
