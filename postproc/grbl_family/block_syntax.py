"""GrblFamilyBlockSyntax: RS274/NGC block rules as the grbl family reads them (each dialect adds its code
table): no M19 in any build [V: neither grbl's nor grblHAL's ``gcode.c`` has an M19 case], so an oriented
stop is read only on a machine whose set-up says it has one (``<Cycles orientation="m19"/>``)."""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.errors import ParseError
from postproc.ir import Block
from postproc.ir.motion import Motion
from postproc.context import word_columns
from postproc.rs274.block_syntax import col_of_word
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax


class GrblFamilyBlockSyntax(NgcWordBlockSyntax):
    """Lexed words -> neutral sections, for a grbl-family controller (subclassed with its table)."""

    __slots__ = ()
    NO_M19: ClassVar[str] = "no oriented spindle stop; a set-up with <Cycles orientation=\"m19\"/> accepts it"
    """Why M19 is refused unless the set-up says the machine has it."""
    MACHINE_MOVE_INCREMENTAL: ClassVar[str] = "absolute"
    """G53 ignores the distance mode: its axis words are machine positions under G91 too [V: grbl 1.1 gcode.c,
    step 20, "ignore if absolute override is active" (NON_MODAL_ABSOLUTE_OVERRIDE skips the G91 sum); grblHAL
    gcode.c the same]."""

    def build(self, block: Block, ctx: Context) -> None:
        super().build(block, ctx)
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in ("cw", "ccw") and not motion.axes \
                and motion.radius is None:
            # grbl 1.1 gcode.c, G2/G3: "if (!axis_words) FAIL(STATUS_GCODE_NO_AXIS_WORDS)" (error 26); grblHAL
            # the same [K: tests/support/grbl_rules.py, written from both parsers]: there is no full circle
            # from I/J/K alone, its end point is programmed (where it starts); an R arc without axis words is
            # refused by the modal step, which names the R
            raise ParseError(f"{self.CONTROL} refuses an arc with no axis word (its centre alone, error 26): "
                             "program its end point (the start point, for a full circle)",
                             ctx.at(block, _motion_col(block)))

    def orient(self, block: Block, ctx: Context, num: str, values: dict[str, Any], used: set[str]) -> None:
        """M19 exists only on machines whose set-up says so (``<Cycles orientation="m19"/>``)."""
        if ctx.setup.cycles.orientation != "m19":
            raise ParseError(self.NO_M19, ctx.at(block, col_of_word(block, "M", num)))
        super().orient(block, ctx, num, values, used)


def _motion_col(block: Block) -> int:
    """Column of the block's G2/G3 word, or of its first word when the arc is modal."""
    columns = list(word_columns(block.text or ""))
    for col, letter, text in columns:
        if letter.upper() == "G" and text.lstrip("0") in ("2", "3", "2.", "3."):
            return col
    return columns[0][0] if columns else 1
