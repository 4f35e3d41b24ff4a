"""ISO 6983 lexical structure of the RS274 family (Fanuc and its kin): ``%`` (on a program's first line
with the leader's title, for a reader that asks: ``lex_block(leader=...)``), O-number (and ISO's
``:``), block delete ``/n``, N, words, ``( )`` comments and ``;`` as end of block; and Custom Macro B:
a statement after N (``#1=..``, ``IF``, ``GOTO``, ``WHILE``, ``END``) and computed word values
(``X[#1*2.]``, ``X#1``, ``X-#3``, ``G#10``).

Plain functions and precompiled regexes (as in tomli). The common line - words only, no comment - is
read by the family's word scan (``canonical_line.scan_words``: one pass over its bytes, compiled), whose
definition is ``WORDS_ONLY`` (a line of words only) and ``WORD`` (its words); only a line it refuses is
scanned by hand for macro syntax (linear: each character is looked at a bounded number of times), and
columns are computed only for errors.

A computed word keeps its text as written in ``block.words`` (``("X", "[#1*2.]")``) and its tree in
``block.values`` (``values["X"]``); a statement is an ``Assign`` or ``Control`` section and has no words.
"""

from __future__ import annotations

import re

from postproc.errors import Location, ParseError, character_name
from postproc.ir import BlockDelete, Block, Comments, ProgramStart, Sequence, TapeMark

from .canonical_line import scan_words
from .expressions import FANUC_SPELLING, ExprSyntaxError, parse_word_value
from .line_ends import split_line as split_line, split_lines as split_lines  # (the readers' line splitting, compiled)
from .macro_b import parse_statement_fanuc

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)"
WORD = re.compile(r"([A-Za-z])[ \t]*(" + NUMBER + ")")
WORDS_ONLY = re.compile(r"(?:[ \t]*+[A-Za-z][ \t]*+[-+]?+(?:\d++\.?+\d*+|\.\d++))*+[ \t]*+;?+[ \t]*+")
"""A line of words only; possessive quantifiers: a block has one reading, never backtrack. The definition the
word scan reads (``canonical_line.scan_words``, held to it by ``tests/test_canonical_line.py``); the reading
itself runs the scan."""
_BADWORD = re.compile(r"[A-Za-z][ \t]*[-+.\d]*")
_COLON = re.compile(r"[ \t]*:(\d+)")
_SKIP = re.compile(r"[ \t]*/(\d?)")
_COMMENT = re.compile(r"\(([^()]*)\)")
_BLANKS = re.compile(r"[ \t]*+")
_TOKEN = re.compile(r"\S+")
"""What ``str.split()`` would take as the token at a position (matched where it stands, not split off)."""


def lex_block(file: str, number: int, text: str, eol: str, macro: bool = True, leader: bool = False) -> Block:
    """Lex one line into a block with its words and lexical sections (``macro``: Custom Macro B too;
    ``leader``: the line is the program's first, where a ``%`` may carry a title)."""
    block = Block(number, text, eol)
    code = text
    if leader and "%" in code:
        title = _leader_title(code)
        if title is not None:
            block.add(TapeMark(title or None))
            return block
    if "(" in code or ")" in code:
        code = _take_comments(file, block, code)
    if ";" in code:
        code = _end_of_block(file, number, code)
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
        kind, words, _ = scan_words(code)
        if kind:
            block.words.extend(words)
            return block
    kind, words, _ = scan_words(code)  # a line of words only: the family's word scan reads it
    if not kind:
        stripped = code.strip()
        if stripped == "%":
            block.add(TapeMark())
            return block
        if not macro:
            raise ParseError(*_explain(file, number, code))
        words = _lex_macro(file, block, code)
    block.words = words
    if words:
        letter, num = words[0]
        if letter in "Oo" and "." not in num:
            if not (num.isascii() and num.isdigit()):
                raise ParseError(f"a program number is a constant, not O{num}",
                                 Location(file, number, code.find(letter) + 1))
            block.add(ProgramStart(int(num), None))
        elif letter in "Nn":
            if not (num.isascii() and num.isdigit()):
                raise ParseError(f"block number N{num} must be a whole number",
                                 Location(file, number, code.find(letter) + 1))
            block.add(Sequence(int(num)))
    return block


def _leader_title(code: str) -> str | None:
    """What follows the ``%`` that opens a program's first line, as written (blanks around it dropped),
    or None when the line does not start with ``%``. The control reads the ``%`` and skips the rest of the
    line, the leader, where a title may stand (``%O1200(TOKARKA)``) [V: Fanuc 16i/18i-TB operator's manual
    B-63524EN/01, memory card file format; Fanuc Data Server manual B-64014EN/03, ``% TITLE ;``]. Only
    that first line: a later ``%`` with text stays an error (no manual found that allows it) [?]."""
    stripped = code.strip(" \t")
    if stripped[:1] != "%":
        return None
    return stripped[1:].strip(" \t")


_LETTER = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")
_STATEMENT_WORDS = ("IF", "GOTO", "WHILE", "END")


def _lex_macro(file: str, block: Block, code: str) -> list[tuple[str, str]]:
    """Scan a line with macro syntax: words (computed or not), then at most one statement, which must
    come first after N. Anything else is explained as on a plain line."""
    words: list[tuple[str, str]] = []
    n = len(code)
    last = len(code.rstrip()) - 1
    """Where a ';' that only ends the block stands (nothing but blanks after it)."""
    pos = 0
    try:
        while pos < n:
            c = code[pos]
            if c == " " or c == "\t":
                pos += 1
                continue
            if c == ";" and pos == last:
                break
            statement = c == "#" or (c in _LETTER and pos + 1 < n and code[pos + 1] in _LETTER)
            if statement:
                if c != "#" and not any(code.startswith(w, pos) or code[pos:pos + len(w)].upper() == w
                                        for w in _STATEMENT_WORDS):
                    raise ParseError(*_explain(file, block.line, code, pos))
                if any(letter.upper() != "N" for letter, _ in words):
                    raise ParseError("a macro statement must start its block (only N may come before it)",
                                     Location(file, block.line, pos + 1))
                end = code.rfind(";") if code.rstrip().endswith(";") else n
                section = parse_statement_fanuc(code[:end], pos)
                block.add(section)
                return words
            if c in _LETTER:
                p = pos + 1
                while p < n and code[p] in " \t":
                    p += 1
                if p < n and (code[p] in "#[" or code[p] in "+-" and code[p + 1:p + 2] in ("#", "[")):
                    end, value = parse_word_value(code, p, FANUC_SPELLING)
                    words.append((c, code[p:end]))
                    if c.upper() in block.values:
                        raise ParseError(f"address {c.upper()} appears twice in one block",
                                         Location(file, block.line, pos + 1))
                    block.values[c.upper()] = value
                    pos = end
                    continue
                m = WORD.match(code, pos)
                if m is not None and (m.end() >= n or code[m.end()] not in ".#["):
                    words.append((m.group(1), m.group(2)))
                    pos = m.end()
                    continue
            raise ParseError(*_explain(file, block.line, code, pos))
    except ExprSyntaxError as err:
        raise err.at(file, block.line) from None
    return words


def _end_of_block(file: str, number: int, code: str) -> str:
    """The code up to its first ``;`` (the end of block, EOB), the rest blanked out. Controls show EOB as
    ``;`` and shop programs type it: ``G01 Z.1 M09; (Retract);`` is a block and a block holding only a
    comment [K: Haas 96-8000 mill operator's manual, blocks printed ending `` ;`` (``N50 M99 P10 ;``); Fanuc
    0i-F operator's manual, EOB shown as ``;``]. What follows a ``;`` on the line (comments, already taken,
    blanks and further ``;``) may not be words: a second block on one line is refused, never run as part
    of the first nor dropped."""
    end = code.index(";")
    rest = code[end + 1:]
    for pos, ch in enumerate(rest):
        if ch != " " and ch != "\t" and ch != ";":
            raise ParseError("only comments may follow ';' (the end of the block) on its line: put the next "
                             "block on a line of its own", Location(file, number, end + 2 + pos))
    return code[:end + 1] + " " * len(rest)


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


def _explain(file: str, line: int, code: str, pos: int = 0) -> tuple[str, Location]:
    """Find what makes a line malformed, from ``pos`` on (slow path, only on error). Linear in the line:
    each word is matched once where it stands, nothing after it is copied."""
    n = len(code)
    last = len(code.rstrip()) - 1
    while pos < n:
        ch = code[pos]
        if ch in " \t":
            pos += 1
            continue
        if ch == ";" and pos == last:
            break
        if ch == "#" or ch == "[" or code[pos:pos + 2].upper() in ("IF", "WH", "GO", "EN") and not WORD.match(code, pos):
            return ("macro variables and expressions are not supported by this reader yet",
                    Location(file, line, pos + 1))
        if ch.isascii() and ch.isalpha():
            after = _BLANKS.match(code, pos + 1)
            assert after is not None
            if code[after.end():after.end() + 1] in ("#", "["):
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
            number = _TOKEN.match(code, pos)
            assert number is not None
            return f"number without an address at {number.group(0)!r}", Location(file, line, pos + 1)
        return f"unexpected {character_name(ch)}", Location(file, line, pos + 1)
    return "malformed block", Location(file, line, 1)
