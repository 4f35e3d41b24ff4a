"""Fanuc reader: physical lines -> lexed blocks, Custom Macro B statements and calls included. Errors are
reported per block; the block is kept (as text only)."""

from __future__ import annotations

from mypy_extensions import i64, mypyc_attr

from typing import Iterable, Iterator, cast

from postproc.context import Context
from postproc.dialect import Reader
from postproc.errors import PostprocError
from postproc.ir import Block, Sequence
from postproc.ir.block import MARK_BITS, MARK_MASK

from postproc.syntaxes.lines import BOM, EOF_BYTE, lexable, line_runs

from postproc.rs274.canonical_line import CANONICAL, CODES, LEXED, LineNumbers, line_numbers, scan_marks
from postproc.rs274.lexer import lex_block

from .call_codes import calls, makes_call
from .macro import read_call


@mypyc_attr(allow_interpreted_subclasses=True)
class FanucReader(Reader):
    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        # The generator only counts lines: the work of a line is ``read_line``'s, a plain function (compiled,
        # its locals are C variables, not fields of the generator's frame object). Checked lines come in runs
        # (``postproc.syntaxes.lines.line_runs``): mostly many texts already split from the end they share. The
        # scan leaves a canonical line's numbers in the run's ``LineNumbers`` (the plain-block lane reads them).
        ctx = self.ctx
        numbers = line_numbers(ctx.run_data)
        number = 0
        for texts, end, data in line_runs(lines):
            if end is None:  # lines with their ends
                for raw in texts:
                    number += 1
                    yield read_raw_line(raw, number, ctx, numbers)
            else:  # texts, and their bytes (where the line check has them) one after the other in ``data``
                at: i64 = 0
                step: i64 = len(end)
                for text in cast("list[str]", texts):
                    number += 1
                    yield read_line(text, end, number, ctx, numbers, data, at)
                    at += len(text) + step


def read_raw_line(raw: str, number: int, ctx: Context, numbers: LineNumbers | None = None) -> Block:
    """``read_line`` of a line with its end of line (``raw``)."""
    size: i64 = len(raw)
    last: i64 = ord(raw[size - 1]) if size else 0  # (compiled: the code read in place, no string object)
    if last == 10:  # LF
        if size > 1 and ord(raw[size - 2]) == 13:  # CR LF
            return read_line(raw[:-2], "\r\n", number, ctx, numbers)
        return read_line(raw[:-1], "\n", number, ctx, numbers)
    if last == 13:  # CR
        return read_line(raw[:-1], "\r", number, ctx, numbers)
    return read_line(raw, "", number, ctx, numbers)


def read_line(text: str, eol: str, number: int, ctx: Context, numbers: LineNumbers | None = None, data: bytes = b"",
              at: i64 = 0) -> Block:
    """Line ``number`` of the program (``text``, ending with ``eol``) as a lexed block; a line the reader
    refuses is reported and kept as text only. ``numbers``: where the scan leaves a canonical line's numbers;
    ``data``: the line's ASCII bytes from ``at`` on, where the line check has them (``scan_marks``)."""
    # Likeliest first: a line of words only (a CAM program's every line), read whole by the family's word
    # scan (``postproc.rs274.canonical_line``), which also tells a canonical line (a writer may copy it), a
    # line without a G or M word (no call to look for) and the block number; a program number, or a block
    # number the lexer refuses, is the lexer's, as is every other line. A canonical line's words are left
    # unmade (``marks``: where its letters stand), for the steps that read it from there (the plain-block lane).
    kind, words, sequence, marks = scan_marks(text, data, at, numbers)
    if kind and not kind & LEXED:
        block = Block(number, text, eol, None if marks else words, marks)
        if kind & CANONICAL:
            block.canonical = True
        if sequence >= 0:
            block.sections["Sequence"] = Sequence(sequence)
        if kind & CODES and (_marked_call(text, marks) if marks else makes_call(words)):
            return _with_call(block, ctx, number, text, eol)
        return block
    try:
        if EOF_BYTE in text or number == 1 and text[:1] == BOM:
            block = lex_block(ctx.file, number, lexable(number, text), eol, leader=number == 1)
            block.text = text  # written back as it was
        else:
            block = lex_block(ctx.file, number, text, eol, leader=number == 1)
        if makes_call(block.words):
            read_call(block, ctx)
        return block
    except PostprocError as err:
        ctx.diagnostics.error(err, text)
        return Block(number, text, eol)


def _marked_call(text: str, marks: i64) -> bool:
    """``makes_call`` of a canonical line whose words are left unmade (``marks``): each G and M word's number read
    where it stands and put to the same test (``calls``), no word made (a list of word tuples cost such a line
    ~1,700 instructions with ``makes_call``'s pass over it: callgrind, the copy of a CAM program, one line in 13).
    A canonical line's letters are upper case."""
    count = marks & MARK_MASK
    rest = marks >> MARK_BITS
    at: i64 = rest & MARK_MASK
    size: i64 = len(text)
    i: i64 = 0
    while i < count:
        rest = rest >> MARK_BITS
        following: i64 = rest & MARK_MASK if i + 1 < count else size + 1
        letter = ord(text[at])
        if (letter == 71 or letter == 77) and calls(text[at + 1:following - 1]):  # 'G', 'M'
            return True
        at = following
        i += 1
    return False


def _with_call(block: Block, ctx: Context, number: int, text: str, eol: str) -> Block:
    """``block`` with the macro or subprogram call it makes read (``read_call``: G65, M98, ...); a call the reader
    refuses is reported and the line kept as text only, as any refused line."""
    try:
        read_call(block, ctx)
    except PostprocError as err:
        ctx.diagnostics.error(err, text)
        return Block(number, text, eol)
    return block
