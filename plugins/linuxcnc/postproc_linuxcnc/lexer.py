"""RS274/NGC (LinuxCNC) lexical structure: words, ``( )`` and ``;`` comments, ``/`` and ``%``.

What differs from Fanuc's lexer, and why this module exists rather than a flag on that one:

* ``;`` starts a comment that runs to the end of the line (Fanuc reads ``;`` as end of block).
* ``( )`` comments do not nest: a ``(`` inside a comment is an error, as in LinuxCNC
  ("Nested comment found").
* Spaces and tabs are allowed anywhere outside comments, even inside a number (``X 1 0`` is X10):
  the common line is still matched with one regex, the rare spaced-out number takes a slow path.
* O-words (``o100 sub``, ``o<name> call``), parameters (``#1``) and expressions (``[1+2]``) are
  refused with a located error: this reader does not model control flow yet.

Line splitting and the word number syntax are the same as Fanuc's and are imported from there.
"""

from __future__ import annotations

import re

from postproc.rs274.lexer import NUMBER, split_lines
from postproc.errors import Location, ParseError
from postproc.ir import Block, BlockDelete, Comments, Sequence, TapeMark

__all__ = ["lex_block", "split_lines", "strip_comments"]

_WORD = re.compile(r"([A-Za-z])[ \t]*(" + NUMBER + ")")
_WORDS_ONLY = re.compile(r"(?:[ \t]*[A-Za-z][ \t]*" + NUMBER + r")*[ \t]*")
_SPACED_NUMBER = re.compile(r"[-+]?[ \t]*(?:[\d \t]*\.[ \t]*\d[\d \t]*|\d[\d \t]*\.?[\d \t]*)")
"""A number with blanks anywhere in it (RS274/NGC ignores them); must contain at least one digit."""
_SKIP = re.compile(r"[ \t]*/")
_COMMENT_CHARS = frozenset("();")
_O_WORDS = "O-words (subprograms, loops, conditions) are not supported by the {} reader"


def lex_block(file: str, number: int, text: str, eol: str, dialect: str = "linuxcnc") -> Block:
    """Lex one line into a block: words as written (letter case kept), comments, block delete.

    ``dialect`` only names the reader in messages (the grbl reader shares this lexer).
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

