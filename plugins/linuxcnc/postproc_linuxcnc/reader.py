"""LinuxCNC reader: physical lines -> lexed blocks. Errors are reported per block; the block is kept."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.dialect import Reader
from postproc.errors import PostprocError
from postproc.ir import Block

from .lexer import lex_block, split_lines


class NgcReader(Reader):
    DIALECT = "linuxcnc"
    """Names the dialect in lexical error messages (the grbl reader subclasses this one)."""

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        file = self.ctx.file
        dialect = self.DIALECT
        report = self.ctx.diagnostics.error
        for number, text, eol in split_lines(lines):
            try:
                yield lex_block(file, number, text, eol, dialect)
            except PostprocError as err:
                report(err)
                yield Block(number, text, eol)
