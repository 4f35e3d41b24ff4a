"""GSK 980TDc reader: physical lines -> lexed blocks (the ISO lexer of the RS274 family: ``%``, ``O``
numbers, ``N`` numbers, ``/`` block skip, ``( )`` comments). Errors are reported per block; the block
is kept as text only.

A first line ``%<title>`` (Fanuc's leader, where the control skips what follows the ``%``: ``TapeMark.title``)
is not confirmed on the 980TDc [?: its manual was not reached here, DIALECTS.md 1.2; searched "GSK980TDc program
file format %"]: it is kept verbatim (``NativeCode``, inert: the simulation passes it, as the control would skip
it), so a copy to GSK writes it unchanged and every other target refuses it by name. A later ``%`` with text
stays an error, as on Fanuc."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.dialect import Reader
from postproc.errors import PostprocError
from postproc.ir import Block, NativeCode
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
            if number == 1 and _titled(text):
                yield _title(number, text, eol)
                continue
            try:
                yield lex_block(file, number, text, eol)
            except PostprocError as err:
                report(err)
                yield Block(number, text, eol)


TITLE_WHAT = "a title after the first '%' (whether the GSK 980TDc skips it, as Fanuc does, is not confirmed)"


def _titled(text: str) -> bool:
    """The line is a ``%`` with text after it (blanks and a BOM aside)."""
    stripped = text.lstrip("\ufeff").strip(" \t")
    return stripped[:1] == "%" and stripped[1:].strip(" \t") != ""


def _title(number: int, text: str, eol: str) -> Block:
    block = Block(number, text, eol)
    block.add(NativeCode("gsk", TITLE_WHAT, text, inert=True))
    return block
