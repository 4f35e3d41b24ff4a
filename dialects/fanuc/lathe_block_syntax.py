"""FanucLatheBlockSyntax: Fanuc T's reading of a block, the family's lathe rules with the table of the
set-up's G-code system (A, B or C)."""

from __future__ import annotations

from typing import ClassVar

from postproc.context import Context
from postproc.errors import UnsupportedError
from postproc.ir import Block
from postproc.rs274.codes import CodeTable, g_key
from postproc.rs274.lathe_block_syntax import LatheBlockSyntax
from postproc.rs274.machine_codes import Defaults

from .lathe_codes import LATHE_CODES
from .machine_codes import LATHE_DEFAULTS


class FanucLatheBlockSyntax(LatheBlockSyntax):
    """Lexed words -> neutral sections, for Fanuc lathe controls (0i-TF, 30i-T)."""

    XNAME = "FanucLatheBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "fanuc"
    TITLE: ClassVar[str] = "Fanuc lathe"
    WHOLE_SPINDLE_SPEED: ClassVar[bool] = True
    """A decimal point in S is an alarm: the decimal point programming list of addresses that take one is X, Y,
    Z, U, V, W, A, B, C, I, J, K, R and F [K: Fanuc Series 0i-MB operator's manual B-64114EN/01, 8.3 "Decimal
    point programming"]; "M03 S1000.0; an illegal statement" [K: after Smid, Fanuc Custom Macros]. Parameter
    3451#2 (mills only) admits one decimal place, run rounded [?: third-party, not modelled]."""
    LATHE_OFFSET_INPUT: ClassVar[bool] = True
    """``G10 P X Z R Q`` sets a tool offset (``postproc.rs274.lathe_offset_input``, which cites the manual)."""
    CODES: ClassVar[CodeTable] = LATHE_CODES["A"]
    MACHINE_DEFAULTS: ClassVar[Defaults] = LATHE_DEFAULTS
    """Haas lathe codes under ``<Controller variant="haas">`` (``machine_codes.HAAS_LATHE``)."""

    def table(self, ctx: Context) -> CodeTable:
        return LATHE_CODES[ctx.setup.input.gcode_system]

    def build(self, block: Block, ctx: Context) -> None:
        """A Haas lathe's G40 with I and K: the vector that decides where the block before it ends compensated
        (its own departure rule [V: Haas lathe operator's manual, "Approach and Departure Moves For TNC",
        ``postproc.rs274.cutter_rules.HAAS_T``]), which is not modelled: refused by name rather than read as
        an arc centre or left unexplained. (A wrapper of ``build``: the plain-block lane stays this reading's,
        ``postproc.fast.reading``; such a block is never plain.)"""
        if ctx.setup.controller.variant == "haas" and any(letter in "IKik" for letter, _ in block.words):
            table = self.table(ctx).g
            entries = [table.get(g_key(num)) for letter, num in block.words if letter in "Gg"]
            if any(e is not None and e[1] == "cutter" and e[2] == "off" for e in entries) and not any(
                    e is not None and e[1] == "motion" and e[2] in ("cw", "ccw") for e in entries):
                up = next(letter.upper() for letter, _ in block.words if letter in "IKik")
                raise UnsupportedError("I and K in the G40 block (a Haas lathe's departure vector, which sets the "
                                       "compensated end of the block before it) cannot be simulated: its geometry "
                                       "is not in our sources; program the departure without them",
                                       ctx.at(block, ctx.column_of(block, up)))
        super().build(block, ctx)
