"""RS274/NGC lexical structure (LinuxCNC, grbl): words, ``( )`` and ``;`` comments, ``/`` and ``%``.

What differs from the ISO lexer (``lexer.py``), and why this is a module of its own rather than a flag:

* ``;`` starts a comment that runs to the end of the line (the ISO reading takes ``;`` as end of block).
* ``( )`` comments do not nest: a ``(`` inside a comment is an error ("Nested comment found").
* Spaces and tabs are allowed anywhere outside comments, even inside a number (``X 1 0`` is X10)
  and between its sign and its digits (``X - 1.5``, ``X- .5``), as rs274 reads them: the common line
  is still matched with one regex, the rare spaced-out number takes a slow path. Both regexes are
  possessive and unambiguous, so a line is scanned in linear time whatever it holds.
* O-words (``o100 sub``, ``o<name> call``), parameters (``#1``) and expressions (``[1+2]``) are
  refused with a located error: this reader does not model control flow yet.

Line splitting and the word number syntax are the ISO lexer's. ``NgcReader`` is the family's reader.
"""

from __future__ import annotations

import re
from typing import Iterable, Iterator

from postproc.dialect import Reader
from postproc.errors import Location, ParseError, PostprocError
from postproc.ir import Block, BlockDelete, Comments, Sequence, TapeMark

from .lexer import NUMBER, split_lines

__all__ = ["NgcReader", "lex_block", "split_lines", "strip_comments"]

_WORD = re.compile(r"([A-Za-z])[ \t]*(" + NUMBER + ")")
_WORDS_ONLY = re.compile(r"(?:[ \t]*+[A-Za-z][ \t]*+[-+]?+(?:\d++\.?+\d*+|\.\d++))*+[ \t]*+")
"""A line of words only (``NUMBER`` spelt possessively: one reading, never backtrack)."""
_SPACED_NUMBER = re.compile(r"[ \t]*+(?:[-+][ \t]*+)?+(?:\d[\d \t]*+(?:\.[\d \t]*+)?+|\.[ \t]*+\d[\d \t]*+)")
"""A number with blanks anywhere in it, also around its sign (RS274/NGC ignores them); at least one digit."""
_SKIP = re.compile(r"[ \t]*/")
_COMMENT_CHARS = frozenset("();")
_O_WORDS = "O-words (subprograms, loops, conditions) are not supported by the {} reader"


def lex_block(file: str, number: int, text: str, eol: str, dialect: str) -> Block:
    """Lex one line into a block: words as written (letter case kept), comments, block delete.

    ``dialect`` only names the reader in messages.
    """
    block = Block(number, text, eol)
    code = text
    if "(" in code or ")" in code or ";" in code:
        code = strip_comments(file, block, code)
    if "/" in code:
        m = _SKIP.match(code)
        if m:
            block.add(BlockDelete(1))
            code = " " * m.end() + code[m.end():]
    if _WORDS_ONLY.fullmatch(code):
        words = _WORD.findall(code)
    else:
        if code.strip() == "%":
            block.add(TapeMark())
            return block
        words = _slow_words(file, number, code, dialect)
    block.words = words
    if words:
        for letter, _ in words:
            if letter in "Oo":
                raise ParseError(_O_WORDS.format(dialect), Location(file, number, code.upper().find("O") + 1))
        letter, num = words[0]
        if letter in "Nn":
            if "." in num or num[0] in "+-":
                raise ParseError(f"block number N{num} must be a whole number",
                                 Location(file, number, code.upper().find("N") + 1))
            block.add(Sequence(int(num)))
    return block


def strip_comments(file: str, block: Block, code: str) -> str:
    """Move ``( )`` and ``;`` comments into a Comments section and blank them out of the code,
    so that the columns of the remaining words stay right for error messages."""
    texts: list[str] = []
    out: list[str] = []
    pos = 0
    n = len(code)
    while pos < n:
        ch = code[pos]
        if ch == "(":
            end = code.find(")", pos + 1)
            if end < 0:
                raise ParseError("unclosed comment", Location(file, block.line, pos + 1))
            nested = code.find("(", pos + 1, end)
            if nested >= 0:
                raise ParseError("nested comment: '(' inside a comment", Location(file, block.line, nested + 1))
            texts.append(code[pos + 1:end])
            out.append(" " * (end + 1 - pos))
            pos = end + 1
        elif ch == ")":
            raise ParseError("')' without an opening '('", Location(file, block.line, pos + 1))
        elif ch == ";":
            texts.append(code[pos + 1:])
            out.append(" " * (n - pos))
            pos = n
        else:
            nxt = _next_special(code, pos)
            out.append(code[pos:nxt])
            pos = nxt
    if texts:
        block.add(Comments(texts))
    return "".join(out)


def _next_special(code: str, pos: int) -> int:
    best = len(code)
    for ch in _COMMENT_CHARS:
        i = code.find(ch, pos)
        if 0 <= i < best:
            best = i
    return best


def _slow_words(file: str, line: int, code: str, dialect: str) -> list[tuple[str, str]]:
    """Scan a line the fast regex refused: numbers with blanks inside, or an error to explain."""
    words: list[tuple[str, str]] = []
    pos = 0
    n = len(code)
    while pos < n:
        ch = code[pos]
        if ch in " \t":
            pos += 1
            continue
        if ch in "Oo":
            raise ParseError(_O_WORDS.format(dialect), Location(file, line, pos + 1))
        if ch.isalpha():
            m = _SPACED_NUMBER.match(code, pos + 1)
            j = pos + 1
            while j < n and code[j] in " \t":
                j += 1
            if m is None or not any(c.isdigit() for c in m.group(0)):
                if j < n and code[j] in "#[":
                    raise ParseError(_unsupported_value(code[j], dialect), Location(file, line, j + 1))
                if j >= n or code[j].isalpha():
                    raise ParseError(f"address {ch.upper()} needs a value", Location(file, line, pos + 1))
                raise ParseError(f"malformed word {code[pos:j + 1].strip()!r}", Location(file, line, pos + 1))
            num = "".join(m.group(0).split())
            words.append((ch, num))
            pos = m.end()
            continue
        if ch in "#[":
            raise ParseError(_unsupported_value(ch, dialect), Location(file, line, pos + 1))
        if ch == "%":
            raise ParseError("'%' must stand alone on its line", Location(file, line, pos + 1))
        if ch == "/":
            raise ParseError("block delete '/' must start the block", Location(file, line, pos + 1))
        if ch.isdigit() or ch in "+-.":
            token = code[pos:].split()[0]
            raise ParseError(f"number without an address at {token!r}", Location(file, line, pos + 1))
        raise ParseError(f"unexpected character {ch!r}", Location(file, line, pos + 1))
    return words


def _unsupported_value(ch: str, dialect: str) -> str:
    if ch == "#":
        return f"parameters (#) are not supported by the {dialect} reader"
    return f"expressions ([...]) are not supported by the {dialect} reader"


class NgcReader(Reader):
    """Physical lines -> lexed blocks under the RS274/NGC rules; errors are reported per block and the
    block is kept."""

    DIALECT = ""
    """Names the dialect in lexical error messages."""

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
