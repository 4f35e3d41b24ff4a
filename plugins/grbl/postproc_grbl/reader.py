"""grbl reader: the RS274/NGC lexer (``( )`` and ``;`` comments, no scaling), naming grbl in errors; ``/`` is
ignored wherever it stands and the block runs, as grbl runs it (with a warning). A ``%`` line is no tape
mark for grbl (its parser has no such word; senders strip it): it is read as an inert comment, so nothing
after it is taken for dead code."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.ir import Block, Comments
from postproc.rs274.ngc_lexer import NgcReader


class GrblReader(NgcReader):
    DIALECT = "grbl"
    BLOCK_DELETE = False
    """grbl 1.1's protocol.c drops every '/' ("Block delete NOT SUPPORTED. Ignore character.")."""

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        for block in super().read(lines):
            if "TapeMark" in block.sections:
                del block.sections["TapeMark"]
                block.sections["Comments"] = Comments(["%"])
            yield block
