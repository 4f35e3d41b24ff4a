"""FanucBlockSyntax: Fanuc milling's reading of a block, the RS274 family's word rules with Fanuc's table."""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.block_syntax import WordBlockSyntax
from postproc.rs274.codes import CodeTable
from postproc.rs274.machine_codes import Defaults

from .codes import CODES
from .machine_codes import DEFAULTS


class FanucBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, for Fanuc milling controls."""

    XNAME = "FanucBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "fanuc"
    TITLE: ClassVar[str] = "Fanuc milling"
    CODES: ClassVar[CodeTable] = CODES
    FAMILY: ClassVar[str] = "fanuc"
    MACHINE_DEFAULTS: ClassVar[Defaults] = DEFAULTS
    BASE_VARIANT: ClassVar[str] = "fanuc"
