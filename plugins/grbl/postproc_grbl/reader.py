"""grbl reader: the RS274/NGC lexer (``( )`` and ``;`` comments, no scaling), naming grbl in errors."""

from __future__ import annotations

from postproc.rs274.ngc_lexer import NgcReader


class GrblReader(NgcReader):
    DIALECT = "grbl"
