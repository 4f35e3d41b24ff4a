"""GskBlockSyntax: the GSK 980TDc reading of a block, the RS274 family's lathe rules with GSK's table."""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.codes import CodeTable
from postproc.rs274.lathe_block_syntax import LatheBlockSyntax

from .codes import CODES


class GskBlockSyntax(LatheBlockSyntax):
    """Lexed words -> neutral sections, for the GSK 980TDc lathe control."""

    XNAME = "GskBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "gsk"
    TITLE: ClassVar[str] = "GSK 980TDc"
    CODES: ClassVar[CodeTable] = CODES
