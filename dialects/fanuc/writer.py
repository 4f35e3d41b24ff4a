"""Fanuc writer: the RS274 word writer spelling every code from Fanuc's table (G00, M03, G04 X seconds)."""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.codes import CodeTable
from postproc.rs274.writer import WordWriter

from .codes import CODES


class FanucWriter(WordWriter):
    DIALECT: ClassVar[str] = "fanuc"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "X"
