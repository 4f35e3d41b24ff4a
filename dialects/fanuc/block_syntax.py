"""FanucBlockSyntax: Fanuc milling's reading of a block, the RS274 family's word rules with Fanuc's table."""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.block_syntax import WordBlockSyntax
from postproc.rs274.codes import CodeTable

from .codes import CODES


class FanucBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, for Fanuc milling controls."""

    XNAME = "FanucBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "fanuc"
    TITLE: ClassVar[str] = "Fanuc milling"
    CODES: ClassVar[CodeTable] = CODES
