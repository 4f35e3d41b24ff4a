"""ISO 6983 lexical structure of the RS274 family (Fanuc and its kin): ``%``, O-number (and ISO's
``:``), block delete ``/n``, N, words, ``( )`` comments and ``;`` as end of block.

Plain functions and precompiled regexes (as in tomli). The common line - words only, no comment - is
checked with one full match and split with one ``findall``; columns are computed only for errors.
"""

from __future__ import annotations

import re
from typing import Iterable, Iterator

from postproc.errors import Location, ParseError
from postproc.ir import BlockDelete, Block, Comments, ProgramStart, Sequence, TapeMark

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)"
WORD = re.compile(r"([A-Za-z])[ \t]*(" + NUMBER + ")")
WORDS_ONLY = re.compile(r"(?:[ \t]*+[A-Za-z][ \t]*+[-+]?+(?:\d++\.?+\d*+|\.\d++))*+[ \t]*+;?+[ \t]*+")
"""A line of words only; possessive quantifiers: a block has one reading, never backtrack."""
_BADWORD = re.compile(r"[A-Za-z][ \t]*[-+.\d]*")
_COLON = re.compile(r"[ \t]*:(\d+)")
_SKIP = re.compile(r"[ \t]*/(\d?)")
_COMMENT = re.compile(r"\(([^()]*)\)")


def split_lines(lines: Iterable[str]) -> Iterator[tuple[int, str, str]]:
    """Yield (line number, text, end of line) for each physical line, keeping the exact terminator."""
    number = 0
    for raw in lines:
        number += 1
        if raw.endswith("\n"):
            if raw.endswith("\r\n"):
                yield number, raw[:-2], "\r\n"
            else:
                yield number, raw[:-1], "\n"
        elif raw.endswith("\r"):
            yield number, raw[:-1], "\r"
        else:
            yield number, raw, ""


def lex_block(file: str, number: int, text: str, eol: str) -> Block:
    """Lex one line into a block with its words and lexical sections."""
    block = Block(number, text, eol)
    code = text
    if "(" in code or ")" in code:
        code = _take_comments(file, block, code)
    if "/" in code:
        m = _SKIP.match(code)
        if m:
            block.add(BlockDelete(int(m.group(1) or 1)))
            code = " " * m.end() + code[m.end():]
    colon = _COLON.match(code)
    if colon:
        block.words = [(":", colon.group(1))]
        block.add(ProgramStart(int(colon.group(1)), None))
        code = " " * colon.end() + code[colon.end():]
        if WORDS_ONLY.fullmatch(code):
            block.words.extend(WORD.findall(code))
            return block
    if not WORDS_ONLY.fullmatch(code):
        stripped = code.strip()
        if stripped == "%":
            block.add(TapeMark())
            return block
        raise ParseError(*_explain(file, number, code))
    words = WORD.findall(code)
    block.words = words
    if words:
        letter, num = words[0]
        if letter in "Oo" and "." not in num:
            block.add(ProgramStart(int(num), None))
        elif letter in "Nn":
            if "." in num or num[0] in "+-":
                raise ParseError(f"block number N{num} must be a whole number",
                                 Location(file, number, code.find(letter) + 1))
            block.add(Sequence(int(num)))
    return block


def _take_comments(file: str, block: Block, code: str) -> str:
    """Move comments into a Comments section; blank them out of the code (columns stay right)."""
    texts: list[str] = []
    out: list[str] = []
    pos = 0
    for m in _COMMENT.finditer(code):
        out.append(code[pos:m.start()])
        out.append(" " * (m.end() - m.start()))
        texts.append(m.group(1))
        pos = m.end()
    rest = code[pos:]
    if "(" in rest:
        col = pos + rest.index("(") + 1
        raise ParseError("unclosed comment", Location(file, block.line, col))
    if ")" in rest:
        col = pos + rest.index(")") + 1
        raise ParseError("')' without an opening '('", Location(file, block.line, col))
    out.append(rest)
    if texts:
        block.add(Comments(texts))
    return "".join(out)


def _explain(file: str, line: int, code: str) -> tuple[str, Location]:
    """Find what makes a line malformed (slow path, only on error)."""
    pos = 0
    n = len(code)
    while pos < n:
        ch = code[pos]
        if ch in " \t":
            pos += 1
            continue
        if ch == ";" and not code[pos + 1:].strip():
            break
        if ch == "#" or ch == "[" or code[pos:pos + 2].upper() in ("IF", "WH", "GO") and not WORD.match(code, pos):
            return ("macro variables and expressions are not supported by this reader yet",
                    Location(file, line, pos + 1))
        if ch.isascii() and ch.isalpha():
            after = code[pos + 1:].lstrip(" \t")[:1]
            if after in ("#", "["):
                return ("macro variables and expressions are not supported by this reader yet",
                        Location(file, line, pos + 1))
            m = WORD.match(code, pos)
            bad = _BADWORD.match(code, pos)
            assert bad is not None
            if m and m.end() == bad.end():
                pos = m.end()
                continue
            token = bad.group(0).replace(" ", "").replace("\t", "")
            if len(token) == 1:
                return f"address {token.upper()} needs a value", Location(file, line, pos + 1)
            return f"malformed word {token!r}", Location(file, line, pos + 1)
        if ch == "%":
            return "'%' must stand alone on its line", Location(file, line, pos + 1)
        if ch == "/":
            return "block delete '/' must start the block", Location(file, line, pos + 1)
        if ch.isdigit() or ch in "+-.":
            return f"number without an address at {code[pos:].split()[0]!r}", Location(file, line, pos + 1)
        return f"unexpected character {ch!r}", Location(file, line, pos + 1)
    return "malformed block", Location(file, line, 1)
