"""FanucLatheBlockSyntax: Fanuc T's reading of a block, the family's lathe rules with the table of the
set-up's G-code system (A, B or C)."""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.errors import UnsupportedError
from postproc.ir import Block
from postproc.rs274.codes import CodeTable
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
    CODES: ClassVar[CodeTable] = LATHE_CODES["A"]
    MACHINE_DEFAULTS: ClassVar[Defaults] = LATHE_DEFAULTS
    """Haas lathe codes under ``<Controller variant="haas">`` (``machine_codes.HAAS_LATHE``)."""

    def table(self, ctx: Context) -> CodeTable:
        return LATHE_CODES[ctx.setup.input.gcode_system]

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        """A Haas lathe's G40 with I and K: the vector that decides where the block before it ends compensated
        (its own departure rule [V: Haas lathe operator's manual, "Approach and Departure Moves For TNC",
        ``postproc.compensation.rules.HAAS_T``]), which is not modelled: refused by name rather than read as
        an arc centre or left unexplained."""
        if ctx.setup.controller.variant == "haas" and ("I" in values or "K" in values) and any(
                kind == "cutter" and arg == "off" for _, kind, arg, _ in codes.values()) and not any(
                kind == "motion" and arg in ("cw", "ccw") for _, kind, arg, _ in codes.values()):
            up = "I" if "I" in values else "K"
            raise UnsupportedError("I and K in the G40 block (a Haas lathe's departure vector, which sets the "
                                   "compensated end of the block before it) cannot be simulated: its geometry is "
                                   "not in our sources; program the departure without them",
                                   ctx.at(block, ctx.column_of(block, up)))
        super().g_sections(block, ctx, codes, values, used, cycle_block)
