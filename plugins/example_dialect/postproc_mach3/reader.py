"""Mach3 reader: the RS274/NGC family lexer (``( )`` and ``;`` comments, no decimal-point scaling), naming
Mach3 in its messages. Mach3 runs no o-words or expressions here (``PARAMETRIC`` is off): they are
located errors, never guessed."""

from __future__ import annotations

from postproc.rs274.ngc_lexer import NgcReader


class Mach3Reader(NgcReader):
    DIALECT = "mach3"
