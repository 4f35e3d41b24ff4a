"""FanucLatheBlockSyntax: Fanuc T's reading of a block, the family's lathe rules with the table of the
set-up's G-code system (A, B or C)."""

from __future__ import annotations

from typing import ClassVar

from postproc.context import Context
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
