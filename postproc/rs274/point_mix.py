"""A warning for input that looks wrong under least-increment input (the Fanuc default): a program that
writes one axis both with and without a decimal point. A CAM "generic" post writing ``Z16`` for 16 mm
reads as 0.016 mm there; the warning names the point-less word and the set-up option that changes the
rule. One warning per program, at the first point-less word of the first axis found mixed.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from postproc.context import NOT_SET, Context
from postproc.errors import Location
from postproc.ir import Block


@mypyc_attr(allow_interpreted_subclasses=True)
class PointMix:
    """Per axis, the first line written with a point and the first point-less word (its location)."""

    __slots__ = ("pointed", "bare", "done")

    def __init__(self) -> None:
        self.pointed: dict[str, int] = {}
        self.bare: dict[str, tuple[Location, str, float, str]] = {}
        self.done = False

    def saw_pointed(self, ctx: Context, axis: str, line: int) -> None:
        if axis in self.pointed:
            return
        self.pointed[axis] = line
        if axis in self.bare:
            self._warn(ctx, axis)

    def saw_bare(self, ctx: Context, block: Block, axis: str, num: str, value: float, units: str) -> None:
        if axis in self.bare or int(num) == 0:  # zero is zero either way
            return
        unit = "mm" if units == "mm" else "in"
        self.bare[axis] = (ctx.at(block, ctx.column_of(block, axis, num)), num, value, unit)
        if axis in self.pointed:
            self._warn(ctx, axis)

    def _warn(self, ctx: Context, axis: str) -> None:
        where, num, value, unit = self.bare[axis]
        ctx.diagnostics.warn(
            f"{axis}{num} has no decimal point, so it counts least input increments ({value:g} {unit}), while "
            f"line {self.pointed[axis]} writes {axis} with one: if the program means {num} {unit}, set "
            "<Input decimalPoint=\"calculator\"/> in the machine set-up", where)
        self.done = True
        ctx.point_mix = None  # one warning per program: nothing left to look for


def point_mix(ctx: Context) -> PointMix | None:
    """This run's tracker while it is still looking (None once it warned, or under calculator input);
    kept in ``ctx.point_mix``, which is None from then on, so the hot path skips the call."""
    mix = ctx.point_mix
    if mix is NOT_SET:
        mix = ctx.point_mix = PointMix() if ctx.setup.input.decimal_point == "least-increment" else None
    return mix if isinstance(mix, PointMix) and not mix.done else None
