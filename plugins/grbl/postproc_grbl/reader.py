"""grbl reader: the RS274/NGC lexer (``( )`` and ``;`` comments, no scaling), naming grbl in errors."""

from __future__ import annotations

from postproc_linuxcnc.reader import NgcReader


class GrblReader(NgcReader):
    DIALECT = "grbl"
