"""Fanuc writer: the RS274 word writer with Fanuc's tables (its defaults are Fanuc's spelling)."""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.writer import WordWriter


class FanucWriter(WordWriter):
    DIALECT: ClassVar[str] = "fanuc"
    DWELL_WORD: ClassVar[str] = "X"
