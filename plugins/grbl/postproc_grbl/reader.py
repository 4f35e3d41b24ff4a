"""grbl reader: the RS274/NGC lexer (``( )`` and ``;`` comments, no scaling), naming grbl in errors; ``/`` is
ignored wherever it stands and the block runs, as grbl runs it (with a warning)."""

from __future__ import annotations

from postproc.rs274.ngc_lexer import NgcReader


class GrblReader(NgcReader):
    DIALECT = "grbl"
    BLOCK_DELETE = False
    """grbl 1.1's protocol.c drops every '/' ("Block delete NOT SUPPORTED. Ignore character.")."""
