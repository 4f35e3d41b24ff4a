"""NumberWriter: the word writer's numbers, the first layer of ``WordWriter`` (``postproc.rs274.writer``).

How a length, feed, speed or register is spelt for the target: explicit decimal points, the set-up's
decimals and per-address places (never silently rounded: a value that would move keeps more places), an
expression in the dialect's spelling, and an axis position whose rounding is carried to the next
incremental word so that it never accumulates. The output settings these read are decided once per run.
"""

from __future__ import annotations

import math
from typing import ClassVar, Final, NoReturn

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect, Writer
from ..errors import ProgramError, UnsupportedError
from ..ir.expr import Expr
from ..ir import Block
from ..numbers import DecimalTexts, EXACT, EXACT_INCH, format_decimal, shortcut_places
from ..ir.state import ModalState
from .expressions import ExprSpelling, spell_word_value

_ROUNDED_UNITS: Final = {"S": "rpm", "A": "deg", "B": "deg", "C": "deg", "F": ""}
"""Units a rounding warning names where they are not the program's length unit ('' for F: the length
unit per minute or revolution)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class NumberWriter(Writer):
    """Spells the numbers of words; ``WordWriter`` builds its words and blocks on it."""

    DIALECT: ClassVar[str] = ""
    """The dialect written (messages name it)."""

    SPELLING: ClassVar[ExprSpelling | None] = None
    """How the dialect writes an expression in a word (``X[#1*2.]``); None: it has no expressions, and a
    computed word is an ``UnsupportedError`` naming it."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        out = ctx.setup.output
        self.mm_places = out.address_places(False)
        self.inch_places = out.address_places(True)
        """``<Output addressDecimals>``: address -> places it is rounded to (mm, inch programs)."""
        self.rounding = bool(self.mm_places or self.inch_places)
        self.rounded_warned: set[str] = set()
        self.at_block: Block | None = None
        """The block being written, where a rounding warning points."""
        self.leading_zero = out.leading_zero
        self.decimals = out.decimals
        self.inch_decimals = out.inch_decimals
        self.exact_mm = shortcut_places(self.decimals, EXACT)
        self.exact_inch = shortcut_places(self.inch_decimals, EXACT_INCH)
        """The most places a number is written with as it is, without rounding (``decimal_text``): decided
        once per run for each unit, not per number."""
        self.mm_texts = DecimalTexts(self.exact_mm, self.leading_zero)
        self.inch_texts = DecimalTexts(self.exact_inch, self.leading_zero)
        """``decimal_text`` in each unit system, remembered per value (``DecimalTexts``)."""
        self.source_numbers = self.leading_zero and not self.rounding
        """A canonical block's axis numbers may be written as the source wrote them (``source_number``):
        canonical numbers have their leading zero, and no address is rounded to places of its own."""
        self.modal = ModalState()
        """What the written program has in force so far (units, distance mode, feed, plane, spindle...)."""
        self.feed_before_units = target is not None and target.FEED_BEFORE_UNITS
        """The target reads an F in a block that changes units in the units before it (``feed_beside_units``)."""
        self.whole_speed = target is not None and target.WHOLE_SPINDLE_SPEED
        """The target's S takes a whole number only (``Dialect.WHOLE_SPINDLE_SPEED``)."""
        self.units_before = self.modal.units
        """Units in force before the block being written."""
        self.carry: dict[str, float] = {}
        """Axis -> where the source program is minus where the written one is (program units): what
        rounding left behind, added to the next incremental word so the sum of increments stays exact."""


    def number(self, value: float, letter: str = "") -> str:
        """A length or feed with an explicit decimal point, trailing zeros dropped ('10.', '0.5').

        Rounds to the output decimals, but never silently: a value that would move by more than
        half a micrometre (or 0.00002 in) keeps up to ``MAX_PLACES`` places instead. An address
        ``letter`` with places of its own (``<Output addressDecimals>``) is rounded to them.
        """
        mm = self.modal.units == "mm"
        if self.rounding and letter:
            places = (self.mm_places if mm else self.inch_places).get(letter)
            if places is not None:
                return self.rounded(value, letter, places, mm)
        text = (self.mm_texts if mm else self.inch_texts).text(value)
        if text is not None:
            return text
        return format_decimal(value, self.decimals if mm else self.inch_decimals, self.leading_zero,
                              EXACT if mm else EXACT_INCH)

    def rounded(self, value: float, letter: str, places: int, mm: bool) -> str:
        """``value`` rounded to the ``places`` the set-up gives ``letter``; the first value of each
        address that rounding moves is a warning (the written program then deviates from the source
        by up to half a unit of the last place)."""
        text = format_decimal(value, places, self.leading_zero, math.inf)
        if letter not in self.rounded_warned and abs(float(text) - value) > (EXACT if mm else EXACT_INCH):
            self.rounded_warned.add(letter)
            unit = _ROUNDED_UNITS.get(letter) or ("mm" if mm else "in")
            if letter == "F":
                unit += "/min" if self.modal.feed_mode != "per_rev" else "/rev"
            shown = text[:-1] if letter == "S" and text.endswith(".") else text
            self.ctx.diagnostics.warn(
                f"<Output {'addressDecimals' if mm else 'inchAddressDecimals'}>: {letter} is rounded to {places} "
                f"places ({value:.6g} written {letter}{shown}); this and later {letter} words may differ from the "
                f"source by up to {0.5 * 10.0 ** -places:g} {unit}",
                self.ctx.at(self.at_block) if self.at_block is not None else None)
        return text

    def whole_rpm(self, rpm: float) -> str:
        """``rpm`` rounded half away from zero; the first speed rounded is a warning."""
        whole = math.floor(abs(rpm) + 0.5) * (1 if rpm >= 0 else -1)
        if "S" not in self.rounded_warned:
            self.rounded_warned.add("S")
            self.ctx.diagnostics.warn(
                f"the {self.DIALECT} dialect takes a whole number in S: {rpm:.6g} is written S{whole} (as the "
                "controller rounds a computed S); this and later S words may differ from the source by up to 0.5",
                self.ctx.at(self.at_block) if self.at_block is not None else None)
        return str(whole)

    @staticmethod
    def integer(value: float | int) -> str:
        return str(int(value))

    def expression(self, expr: Expr, block: Block, what: str = "a computed word") -> str:
        """A word value that is an expression, in the dialect's ``SPELLING`` (``#1``, ``[#1*2.]``)."""
        if self.SPELLING is None:
            self.unsupported(f"{what} (no variables or expressions)", block)
        try:
            return spell_word_value(expr, self.SPELLING)
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

    def length(self, value: float | Expr, block: Block, letter: str = "") -> str:
        """A length, feed or other real word value: a number, or an expression kept symbolically."""
        if isinstance(value, Expr):
            return self.expression(value, block)
        return self.number(value, letter)

    def whole(self, value: float | int | Expr, block: Block) -> str:
        """An integer word value (T, P, L...): a number, or an expression kept symbolically."""
        if isinstance(value, Expr):
            return self.expression(value, block)
        return str(int(value))

    def unsupported(self, what: str, block: Block) -> NoReturn:
        raise UnsupportedError(f"the {self.DIALECT} dialect cannot express {what}",
                               self.ctx.at(block))

    def register(self, value: int | Expr, block: Block) -> str:
        """An offset register (D, H): two digits at least, or a computed number."""
        if isinstance(value, Expr):
            return self.expression(value, block)
        return f"{int(value):02d}"

    def seconds(self, value: float) -> str:
        return format_decimal(value, 3, self.leading_zero)

    def position(self, axis: str, value: float, incremental: bool) -> str:
        """An axis word's number. Rounding never accumulates: in incremental mode the increment written is
        the one that brings the written position nearest the source's (what earlier words rounded away
        is carried), so each written position is within the output resolution of the exact one."""
        return _position(self, axis, value, incremental)

    def feed_number(self, value: float, block: Block) -> str:
        """A feed rate's number; one so small that the written number is 0 is refused: the controller
        would read a zero feed rate, which it refuses for every feed move (``block_rules.ZERO_FEED``)."""
        text = self.number(value, "F")
        if value and float(text) == 0.0:
            raise ProgramError(f"feed rate F{value:g} is written F{text} at the output's resolution: a zero feed "
                               "rate, which the controller refuses for a feed move",
                               self.ctx.at(block, self.ctx.column_of(block, "F")))
        return text

    def speed(self, rpm: float) -> str:
        """A spindle speed: a whole number without a point, else a decimal; ``S0`` places round it to a
        whole number, as does a target whose S takes whole numbers only (rounded half away from zero, as it
        rounds a computed S, with a warning: the speed differs from the source's by up to half a unit)."""
        if self.whole_speed and not float(rpm).is_integer():
            return self.whole_rpm(float(rpm))
        if self.rounding:
            text = self.number(float(rpm), "S")
            if text.endswith("."):
                return text[:-1] or "0"
            return text
        return str(int(rpm)) if float(rpm).is_integer() else self.number(rpm)


def _position(w: NumberWriter, axis: str, value: float, incremental: bool) -> str:
    """``NumberWriter.position``: a module function, so that a plugin's (interpreted) writer does not
    dispatch through Python for each number (no subclass overrides it)."""
    carry = w.carry
    want = value + carry.get(axis, 0.0) if incremental and carry else value
    if not w.rounding:
        text = (w.mm_texts if w.modal.units == "mm" else w.inch_texts).text(want)
        if text is not None:  # written exactly: nothing to carry
            if carry:
                carry.pop(axis, None)
            return text
    text = w.number(want, axis)
    error = want - float(text)
    if error:
        carry[axis] = error
    elif carry:
        carry.pop(axis, None)
    return text
