"""GSK 980TDc reader: physical lines -> lexed blocks (the ISO lexer of the RS274 family: ``%``, ``O``
numbers, ``N`` numbers, ``/`` block skip, ``( )`` comments). Errors are reported per block; the block
is kept as text only."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.dialect import Reader
from postproc.errors import PostprocError
from postproc.ir import Block
from postproc.rs274.lexer import lex_block


class GskReader(Reader):
    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        file = self.ctx.file
        report = self.ctx.diagnostics.error
        number = 0
        for raw in lines:
            number += 1
            if raw[-2:] == "\r\n":
                text, eol = raw[:-2], "\r\n"
            elif raw[-1:] in ("\n", "\r"):
                text, eol = raw[:-1], raw[-1:]
            else:
                text, eol = raw, ""
            try:
                yield lex_block(file, number, text, eol)
            except PostprocError as err:
                report(err)
                yield Block(number, text, eol)
