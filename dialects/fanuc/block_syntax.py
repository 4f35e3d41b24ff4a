"""FanucBlockSyntax: Fanuc milling's reading of a block, the RS274 family's word rules with Fanuc's table."""

from __future__ import annotations

from typing import ClassVar, Mapping

from mypy_extensions import mypyc_attr

from postproc.rs274.block_syntax import WordBlockSyntax
from postproc.rs274.codes import CodeTable
from postproc.rs274.machine_codes import Defaults
from postproc.frames.section import LAYERED

from .codes import CODES
from .machine_codes import DEFAULTS


@mypyc_attr(allow_interpreted_subclasses=True)
class FanucBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, for Fanuc milling controls."""

    XNAME = "FanucBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "fanuc"
    TITLE: ClassVar[str] = "Fanuc milling"
    WHOLE_SPINDLE_SPEED: ClassVar[bool] = True
    """A decimal point in S is an alarm: the decimal point programming list of addresses that take one is X, Y,
    Z, U, V, W, A, B, C, I, J, K, R and F [K: Fanuc Series 0i-MB operator's manual B-64114EN/01, 8.3 "Decimal
    point programming"]; "M03 S1000.0; an illegal statement" [K: after Smid, Fanuc Custom Macros]. Parameter
    3451#2 (mills only) admits one decimal place, run rounded [?: third-party, not modelled]."""
    CODES: ClassVar[CodeTable] = CODES
    FAMILY: ClassVar[str] = "fanuc"
    FRAME_RULES: ClassVar[str] = LAYERED
    MACHINE_DEFAULTS: ClassVar[Defaults] = DEFAULTS
    BASE_VARIANT: ClassVar[str] = "fanuc"
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {
        2: ("work_offset", 0, 6), 20: ("work_offset_extended", 1, 300),
        10: ("tool_length", 1, 999), 11: ("tool_length_wear", 1, 999),
        12: ("cutter_offset", 1, 999), 13: ("cutter_offset_wear", 1, 999),
    }
    """G10 L2 P0-P6 (P0 the external offset, P1-P6 G54-G59), L20 P1-P300 (G54.1 P1-P300), L10-L13 the
    tool offset memory C: length geometry/wear, radius geometry/wear (R)."""
