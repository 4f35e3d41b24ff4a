"""LatheBlockSyntax: the RS274 family's lathe reading of a block (Fanuc T system A/B/C, GSK 980TDc).

What differs from the milling reading (``WordBlockSyntax``), all of it through the dialect's lathe code
table, never by number:

- ``U``/``W`` are incremental X/Z: a motion keeps them as axis keys ``U``/``W`` (``Motion`` on a lathe),
  so ``X20. W-5.`` mixes an absolute X with an incremental Z as the controller does;
- the coordinate setting code (G50 in system A, G92 in B/C) sets the work coordinates with X/Z, and
  clamps the spindle with S; the spindle speed mode codes (G96/G97) make ``SpindleMode``;
- a lathe cycle block (G70-G76, G90/G92/G94 in system A) keeps its words as written for the cycle step
  (``postproc.rs274.lathe_cycles``), whose meanings depend on the cycle and on which of its two blocks
  this is; a block with X/Z/U/W and no motion code while a single cycle (G90/G92/G94) is in force
  repeats it at the new point, as the controller does.
"""

from __future__ import annotations

from typing import Any

from postproc.errors import ParseError, ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, CycleCall, Feed, Motion, SpindleSpeed, ToolSelect
from postproc.ir.lathe_sections import CoordinateSet, SpindleClamp, SpindleMode
from postproc.context import Context

from .block_syntax import WordBlockSyntax, col_of_word
from .codes import g_key
from .lathe_axes import LATHE_INCREMENTS

SINGLE_KEY = "LatheBlockSyntax.single"
"""``ctx.state.extra`` key: (kind, code as written) of the single cycle in force, or absent."""
CYCLE_AXES = frozenset("XZUW")
ONE_AXIS_WORDS = tuple((axis, increment) for increment, axis in LATHE_INCREMENTS.items())
"""(absolute, incremental) address of one axis (X and U, Z and W): refused together in one block (``g_sections``,
and the plain-block lane that leaves such a block to it, ``postproc.fast.plain.PlainLatheLane``)."""
_UPPER = {c: c.upper() for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"}


class LatheBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections for a lathe; subclasses give the table (``table``)."""

    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        words = block.words
        if not words or block.values:
            super().build(block, ctx)
            return
        table = self.table(ctx).g
        cycle: tuple[str, str] | None = None
        motion = False
        cancel: str | None = None
        for letter, num in words:
            if _UPPER.get(letter) == "G":
                entry = table.get(g_key(num))
                if entry is not None and entry[1] == "lathe_cycle":
                    cycle = (str(entry[2]), "G" + num)
                elif entry is not None and entry[0] == "01":
                    motion = True
                elif entry is not None and entry[1] == "cycle_cancel":
                    cancel = num
        extra = ctx.state.extra
        if cancel is not None and not motion and SINGLE_KEY in extra:
            codes = self.table(ctx)
            rapid, linear = codes.spell("motion", "rapid"), codes.spell("motion", "linear")
            raise ProgramError(f"G{cancel} while the single cycle {extra[SINGLE_KEY][1]} is in force: whether it ends "
                               "it differs between controls (Haas: it does [K], Fanuc T: only a motion code does "
                               f"[K]); program {rapid} or {linear} instead",
                               ctx.at(block, col_of_word(block, "G", cancel)))
        if cycle is not None:
            self._cycle_block(block, ctx, cycle[0], cycle[1])
            if table[g_key(cycle[1][1:])][0] == "01":
                extra[SINGLE_KEY] = cycle
            return
        single = extra.get(SINGLE_KEY)
        if single is not None and not motion and any(_UPPER.get(w[0]) in CYCLE_AXES for w in words):
            self._cycle_block(block, ctx, single[0], None)
            return
        if motion:
            extra.pop(SINGLE_KEY, None)
        super().build(block, ctx)

    def _cycle_block(self, block: Block, ctx: Context, kind: str, code: str | None) -> None:
        """A cycle block: its code, F/S/T and M codes become sections; the other words stay in
        ``block.words`` for the cycle step, which knows what they mean in this cycle."""
        seen: dict[str, str] = {}
        mcodes: list[tuple[int, str]] = []
        values: dict[str, Any] = {}
        for letter, num in block.words:
            up = _UPPER.get(letter, letter)
            if up == "G":
                if code is None or num != code[1:]:
                    raise ParseError(f"G{num} cannot share a block with a lathe cycle "
                                     f"({code or 'a repeat of the single cycle'}); program it in a block of its own",
                                     ctx.at(block, col_of_word(block, "G", num)))
                continue
            if up == "M":
                if "." in num:
                    raise ParseError(f"M code M{num} takes no decimal point", ctx.at(block, col_of_word(block, "M", num)))
                mcodes.append((int(num), num))
                continue
            if up in seen:
                raise ParseError(f"address {up} appears twice in one block", ctx.at(block, ctx.column_of(block, up, nth=2)))
            seen[up] = num
            if up == "N" or up == "O":
                continue
            if up == "F":
                block.add(Feed(_number(block, ctx, up, num)))
            elif up == "S":
                if "." in num and self.WHOLE_SPINDLE_SPEED:
                    raise ParseError(f"address S takes no decimal point (S{num})", ctx.at(block, ctx.column_of(block, up)))
                block.add(SpindleSpeed(_number(block, ctx, up, num)))
            elif up == "T":
                if "." in num or num[:1] in "+-":
                    raise ParseError(f"address T takes a whole number ({up}{num})", ctx.at(block, ctx.column_of(block, up)))
                block.add(ToolSelect(int(num)))
        block.add(CycleCall(kind))
        used = {"N", "O"}
        self.m_sections(block, ctx, mcodes, values, used)

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        """The lathe's own codes first (coordinate setting, spindle mode), then the family's."""
        dwell_u = any(kind == "dwell" for _, kind, _, _ in codes.values()) and "U" in values \
            and "X" not in values and "P" not in values
        if dwell_u:
            values["X"] = values.pop("U")  # a lathe's G04 U is the dwell in seconds, as G04 X
        for absolute, increment in ONE_AXIS_WORDS:
            if absolute in values and increment in values:
                raise ProgramError(f"{absolute} and {increment} in one block: the absolute and the incremental "
                                   f"{absolute} of one move", ctx.at(block, ctx.column_of(block, increment)))
        for group, (_, kind, arg, num) in list(codes.items()):
            if kind == "lathe_cycle":
                # only a block with computed words comes here (``build`` reads the others itself)
                raise ProgramError(f"G{num} with computed words cannot be read: a lathe cycle's words must be "
                                   "numbers", ctx.at(block, col_of_word(block, "G", num)))
            if kind == "spindle_mode":
                block.add(SpindleMode(str(arg)))
                del codes[group]
            elif kind == "coordinate_set":
                del codes[group]
                axes = {k: _real(v) for k, v in values.items() if k in "XZ"}
                if "S" in values:
                    block.add(SpindleClamp(_real(values.pop("S"))))  # the clamp, not a speed
                elif not axes:
                    raise ProgramError(f"G{num} needs X/Z (coordinate setting) or S (spindle speed clamp)",
                                       ctx.at(block, col_of_word(block, "G", num)))
                if axes:
                    block.add(CoordinateSet(axes))
                    used.update(axes)
                if "U" in values or "W" in values:
                    up = "U" if "U" in values else "W"
                    raise ProgramError(f"G{num} sets absolute coordinates: {up} has no meaning here",
                                       ctx.at(block, ctx.column_of(block, up)))
        super().g_sections(block, ctx, codes, values, used, cycle_block)
        if dwell_u:  # the word stays what it was read as (U), for the block's XML
            values["U"] = values.pop("X")
            used.add("U")
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and motion.center is not None and "Y" in motion.center:
            raise ProgramError("an arc centre J is outside the ZX plane of a lathe", ctx.at(block, ctx.column_of(block, "J")))


def _real(value: Any) -> Any:
    """A number as a float, or a computed value (``Expr``, a program kept symbolically) as it is."""
    return value if isinstance(value, Expr) else float(value)


def _number(block: Block, ctx: Context, up: str, num: str) -> float:
    try:
        return float(num)
    except ValueError:
        raise ParseError(f"address {up} needs a number ({up}{num})", ctx.at(block, ctx.column_of(block, up))) from None
