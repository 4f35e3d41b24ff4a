"""IsgBlockSyntax: ISG's reading of a block's DIN words, the family's word rules with ISG's table.

A number without a decimal point is in mm/inch (``X10`` = 10 mm, the opposite of Fanuc's default),
whatever the set-up's ``Input`` says. A computed block number (``N[10+P30]``) only names the block.
"""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.block_syntax import WordBlockSyntax
from postproc.rs274.codes import CodeTable

from .codes import CODES


class IsgBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, for Beckhoff TwinCAT CNC (ISG kernel) controls."""

    XNAME = "IsgBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "isg"
    TITLE: ClassVar[str] = "ISG"
    CODES: ClassVar[CodeTable] = CODES
    POINTLESS_IN_UNITS: ClassVar[bool] = True
