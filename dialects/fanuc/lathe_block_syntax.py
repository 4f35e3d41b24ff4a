"""FanucLatheBlockSyntax: Fanuc T's reading of a block, the family's lathe rules with the table of the
set-up's G-code system (A, B or C)."""

from __future__ import annotations

from typing import ClassVar

from postproc.context import Context
from postproc.rs274.codes import CodeTable
from postproc.rs274.lathe_block_syntax import LatheBlockSyntax

from .lathe_codes import LATHE_CODES


class FanucLatheBlockSyntax(LatheBlockSyntax):
    """Lexed words -> neutral sections, for Fanuc lathe controls (0i-TF, 30i-T)."""

    XNAME = "FanucLatheBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "fanuc"
    TITLE: ClassVar[str] = "Fanuc lathe"
    CODES: ClassVar[CodeTable] = LATHE_CODES["A"]

    def table(self, ctx: Context) -> CodeTable:
        return LATHE_CODES[ctx.setup.input.gcode_system]
