"""GrblFamilyBlockSyntax: RS274/NGC block rules as the grbl family reads them (each dialect adds its code
table): no M19 in any build [V: neither grbl's nor grblHAL's ``gcode.c`` has an M19 case], so an oriented
stop is read only on a machine whose set-up says it has one (``<Cycles orientation="m19"/>``)."""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.errors import ParseError
from postproc.ir import Block
from postproc.rs274.block_syntax import col_of_word
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax


class GrblFamilyBlockSyntax(NgcWordBlockSyntax):
    """Lexed words -> neutral sections, for a grbl-family controller (subclassed with its table)."""

    __slots__ = ()
    NO_M19: ClassVar[str] = "no oriented spindle stop; a set-up with <Cycles orientation=\"m19\"/> accepts it"
    """Why M19 is refused unless the set-up says the machine has it."""

    def orient(self, block: Block, ctx: Context, num: str, values: dict[str, Any], used: set[str]) -> None:
        """M19 exists only on machines whose set-up says so (``<Cycles orientation="m19"/>``)."""
        if ctx.setup.cycles.orientation != "m19":
            raise ParseError(self.NO_M19, ctx.at(block, col_of_word(block, "M", num)))
        super().orient(block, ctx, num, values, used)
