"""RS274/NGC lexical structure (LinuxCNC, grbl): words, ``( )`` and ``;`` comments, ``/`` and ``%``.

What differs from the ISO lexer (``lexer.py``), and why this is a module of its own rather than a flag:

* ``;`` starts a comment that runs to the end of the line (the ISO reading takes ``;`` as end of block).
* ``( )`` comments do not nest: a ``(`` inside a comment is an error ("Nested comment found").
* Spaces and tabs are allowed anywhere outside comments, even inside a number (``X 1 0`` is X10)
  and between its sign and its digits (``X - 1.5``, ``X- .5``), as rs274 reads them: the common line
  is still read in one pass (``plain_words``), the rare spaced-out number takes a slow path. The slow
  path's regexes are possessive and unambiguous, so a line is scanned in linear time whatever it holds.
* With an ``OwordParser`` (LinuxCNC: ``NgcReader.PARAMETRIC``), o-word lines (``o100 sub``,
  ``o<name> call [1]``) become a ``Control`` section, parameter assignments anywhere in the line
  (``#1=2 G0 X#1``) one ``Assign`` section (all of them, in order: rs274 reads every value of the line
  first, then assigns), and a word whose value is not a plain number (``X[#1*2]``, ``X#1``,
  ``X-#<depth>``, ``G#10``, ``X SIN[30]``) keeps its text as written in ``block.words`` and its tree in
  ``block.values`` (an ``Expr``). Without one (grbl), each of these is a located error naming it.
  Only lines ``plain_words`` refuses take this road, so a plain line costs nothing more.
  With one too, a bare ``O100`` is a ``ProgramStart`` (``oword``), and the reader's ``read_call`` turns
  the dialect's subprogram call and return words into a ``Call``/``Return`` (LinuxCNC's Fanuc-style
  subprograms: the plugin knows their codes).

Line splitting and the word number syntax are the ISO lexer's. ``NgcReader`` is the family's reader.
"""

from __future__ import annotations

from mypy_extensions import i64, mypyc_attr

import re
from typing import Callable, ClassVar, Final, Iterable, Iterator

from postproc.interp.control import Assign
from postproc.dialect import Reader
from postproc.errors import Location, ParseError, PostprocError, character_name
from postproc.ir.expr import Expr, Var
from postproc.ir import Block, BlockDelete, Comments, Sequence, TapeMark
from postproc.syntaxes.lines import line_runs

from .expressions import LINUXCNC_SPELLING, ExprSyntaxError, parse_word_value
from .lexer import NUMBER
from .line_ends import split_line, split_lines
from .oword import OwordParser, parse_assignments

__all__ = ["NgcReader", "lex_block", "plain_words", "split_lines", "strip_comments"]

_WORD: Final = re.compile(r"([A-Za-z])[ \t]*(" + NUMBER + ")")
_WORDS_ONLY: Final = re.compile(r"(?:[ \t]*+[A-Za-z][ \t]*+[-+]?+(?:\d++\.?+\d*+|\.\d++))*+[ \t]*+")
"""A line of words only (``NUMBER`` spelt possessively: one reading, never backtrack), and ``_WORD`` its words:
the definition ``plain_words`` reads, held to it by ``tests/test_ngc_plain_words.py``; the lexer runs
``plain_words`` alone (a line it leaves, not ASCII included, is ``_slow_words``'s, which reads the same
words from a line of words only)."""
_SPACED_NUMBER: Final = re.compile(r"[ \t]*+(?:[-+][ \t]*+)?+(?:\d[\d \t]*+(?:\.[\d \t]*+)?+|\.[ \t]*+\d[\d \t]*+)")
"""A number with blanks anywhere in it, also around its sign (RS274/NGC ignores them); at least one digit."""
_SKIP: Final = re.compile(r"[ \t]*/")
_COMMENT_CHARS: Final = frozenset("();")
_O_WORDS: Final = "O-words (subprograms, loops, conditions) are not supported by the {} reader"


def lex_block(file: str, number: int, text: str, eol: str, dialect: str,
              oword: OwordParser | None = None, calls: Callable[[Block, str], None] | None = None,
              ignore_slash: Callable[[Location], None] | None = None, polar: bool = False,
              max_number: int = 0, data: bytes = b"", at: i64 = 0) -> Block:
    """Lex one line into a block: words as written (letter case kept), comments, block delete, and
    with ``oword`` (the file's ``OwordParser``) o-words, assignments and expression values.

    ``dialect`` only names the reader in messages. ``calls(block, code)``, given with ``oword``, reads
    the block's call or return words, M codes (``NgcReader.read_call``: a line without an M is not offered;
    ``code``: the line with its comments blanked out, for columns).
    With ``ignore_slash`` (grbl, which has no block delete), every ``/`` outside comments is dropped,
    wherever it stands, and the block runs; ``ignore_slash`` is told where the first one was.
    With ``polar`` (LinuxCNC), ``@`` (polar radius) and ``^`` (polar angle) are addresses too, read as
    rs274's ``read_atsign``/``read_carat`` read them (a real value); the dialect's pipeline gives them
    their meaning. ``max_number`` (not 0): a larger block number is refused, as the controller refuses
    its line (``NgcReader.MAX_BLOCK_NUMBER``). ``data``: ASCII bytes that hold the line's at ``at`` (the line
    check's copy of its piece: ``plain_words``).
    """
    block = Block(number, text, eol)
    code = text
    # Likeliest first: a line of words only, which holds no comment and no '/' (``plain_words`` refuses both), so
    # that none is looked for; any other line has its comments and '/' taken out first, and its words read then.
    words = plain_words(code, data, at)
    if words is None:
        if "(" in code or ")" in code or ";" in code:
            code = strip_comments(file, block, code)
        if ignore_slash is not None and "/" in code:
            ignore_slash(Location(file, number, code.index("/") + 1))
            code = code.replace("/", " ")  # blanks inside a number are ignored: X1/2 is X12, as grbl reads it
        if "/" in code:
            m = _SKIP.match(code)
            if m:
                block.add(BlockDelete(1))
                code = " " * m.end() + code[m.end():]
        if code is not text:
            words = plain_words(code)
    if words is not None:
        for letter, _ in words:
            if letter == "O" or letter == "o":  # (compiled, two comparisons; ``in "Oo"`` is a call a word)
                if oword is None:
                    raise ParseError(_O_WORDS.format(dialect), Location(file, number, code.upper().find("O") + 1))
                words = _slow_words(file, number, code, dialect, block, oword, polar)
                break
    else:
        if code.strip() == "%":
            block.add(TapeMark())
            return block
        words = _slow_words(file, number, code, dialect, block, oword, polar)
    block.words = words
    if words:
        letter, num = words[0]
        if letter in "Nn":
            if "." in num or num[0] in "+-":
                raise ParseError(f"block number N{num} must be a whole number",
                                 Location(file, number, code.upper().find("N") + 1))
            value = int(num)
            if max_number and value > max_number:
                raise ParseError(f"block number N{num} is above {max_number}, the largest the {dialect} controller "
                                 f"reads: it refuses the line (renumber the program)",
                                 Location(file, number, code.upper().find("N") + 1))
            block.add(Sequence(value))
    if calls is not None and words and ("M" in code or "m" in code):
        calls(block, code)
    return block


def plain_words(code: str, data: bytes = b"", at: i64 = 0) -> list[tuple[str, str]] | None:
    """The words of a line of words only, as ``_WORD.findall`` finds them where ``_WORDS_ONLY`` matches the
    whole line; None where it does not, and for any line that is not ASCII (``\\d`` is any Unicode digit:
    the regexes read those). One pass over the line's bytes: compiled, about a tenth of the two regexes
    (the LinuxCNC reading spent ~20k instructions a line in them). ``tests/test_ngc_plain_words.py``
    holds it to the regexes on random lines. ``data``: ASCII bytes that hold the line's at ``at`` (the line
    check's copy of its piece, ``postproc.syntaxes.lines.CheckedLines.runs``), read instead of a copy of the line
    made here (~150 instructions a line)."""
    # Positions are the bytes' (``base`` the line's first): a word's letter and number are cut from the line at
    # their position less ``base``. Positions as i64 (compiled: machine integers; a tagged end that is a sum may be
    # a long one, and every comparison with it took the slow call: ~400 instructions a line).
    base: i64 = 0
    if len(data) > 0:  # (compiled, a length read; ``if data`` is a call)
        b = data
        base = at
    else:
        try:
            b = code.encode("ascii")  # compiled, a C call
        except UnicodeEncodeError:
            return None
    n: i64 = base + len(code)
    words: list[tuple[str, str]] = []
    i: i64 = base
    while True:
        while i < n and (b[i] == 32 or b[i] == 9):  # ' ', '\t'
            i += 1
        if i == n:
            return words
        c = b[i]
        if not (65 <= c <= 90 or 97 <= c <= 122):  # a letter opens every word
            return None
        start = i
        i += 1
        while i < n and (b[i] == 32 or b[i] == 9):
            i += 1
        number = i
        if i < n and (b[i] == 45 or b[i] == 43):  # '-', '+'
            i += 1
        digits = i
        while i < n and 48 <= b[i] <= 57:
            i += 1
        if i > digits:
            if i < n and b[i] == 46:  # '.'
                i += 1
                while i < n and 48 <= b[i] <= 57:
                    i += 1
        elif i < n and b[i] == 46:
            i += 1
            fraction = i
            while i < n and 48 <= b[i] <= 57:
                i += 1
            if i == fraction:
                return None
        else:
            return None
        words.append((code[start - base], code[number - base:i - base]))


def strip_comments(file: str, block: Block, code: str) -> str:
    """Move ``( )`` and ``;`` comments into a Comments section and blank them out of the code,
    so that the columns of the remaining words stay right for error messages."""
    texts: list[str] = []
    out: list[str] = []
    pos = 0
    n = len(code)
    semicolon = False
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
            semicolon = True
        else:
            nxt = _next_special(code, pos)
            out.append(code[pos:nxt])
            pos = nxt
    if texts:
        block.add(Comments(texts, semicolon))
    return "".join(out)


def _next_special(code: str, pos: int) -> int:
    best = len(code)
    for ch in _COMMENT_CHARS:
        i = code.find(ch, pos)
        if 0 <= i < best:
            best = i
    return best


def _slow_words(file: str, line: int, code: str, dialect: str, block: Block,
                oword: OwordParser | None, polar: bool = False) -> list[tuple[str, str]]:
    """Scan a line ``plain_words`` refused: numbers with blanks inside, o-words, assignments and
    expression values (with ``oword``), or an error to explain."""
    words: list[tuple[str, str]] = []
    assigned: list[tuple[Var, Expr]] = []
    pos = 0
    n = len(code)
    try:
        while pos < n:
            ch = code[pos]
            if ch in " \t":
                pos += 1
                continue
            if ch in "Oo":
                if oword is None:
                    raise ParseError(_O_WORDS.format(dialect), Location(file, line, pos + 1))
                if assigned or any(letter not in "Nn" for letter, _ in words):
                    raise ParseError("an o-word opens its line (only '/' and N may come before it)",
                                     Location(file, line, pos + 1))
                block.add(oword.parse(code, pos, line))
                return words
            if ch.isalpha() or (polar and (ch == "@" or ch == "^")):
                m = _SPACED_NUMBER.match(code, pos + 1)
                j = pos + 1
                while j < n and code[j] in " \t":
                    j += 1
                if m is None or not any(c.isdigit() for c in m.group(0)):
                    if oword is not None and _starts_value(code, j):
                        end, value = parse_word_value(code, j, LINUXCNC_SPELLING)
                        words.append((ch, code[j:end]))
                        block.values[ch.upper()] = value
                        pos = end
                        continue
                    if j < n and code[j] in "#[":
                        raise ParseError(_unsupported_value(code[j], dialect), Location(file, line, j + 1))
                    if j >= n or code[j].isalpha():
                        raise ParseError(f"address {ch.upper()} needs a value", Location(file, line, pos + 1))
                    raise ParseError(f"malformed word {code[pos:j + 1].strip()!r}", Location(file, line, pos + 1))
                num = "".join(m.group(0).split())
                words.append((ch, num))
                pos = m.end()
                continue
            if ch == "#" and oword is not None:
                pos, assign = parse_assignments(code, pos)
                assigned.extend(assign.items)
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
            raise ParseError(f"unexpected {character_name(ch)}", Location(file, line, pos + 1))
    except ExprSyntaxError as err:
        if err.location is None:
            err.at(file, line)
        raise
    if assigned:
        block.add(Assign(assigned))
    return words


_VALUE_START: Final = frozenset("#[")


def _starts_value(code: str, j: int) -> bool:
    """An expression value starts at ``j``: ``#``, ``[``, a sign before one of them, or a function
    word followed by ``[`` (``X SIN[30]``)."""
    n = len(code)
    if j >= n:
        return False
    c = code[j]
    if c in _VALUE_START:
        return True
    if c in "+-":
        k = j + 1
        while k < n and code[k] in " \t":
            k += 1
        return k < n and code[k] in _VALUE_START
    if c.isalpha():
        k = j
        while k < n and code[k].isalpha():
            k += 1
        word = code[j:k].upper()
        while k < n and code[k] in " \t":
            k += 1
        return k < n and code[k] == "[" and (word in LINUXCNC_SPELLING.functions or word == "ATAN")
    return False


def _unsupported_value(ch: str, dialect: str) -> str:
    if ch == "#":
        return f"parameters (#) are not supported by the {dialect} reader"
    return f"expressions ([...]) are not supported by the {dialect} reader"


def _ends(words: list[tuple[str, str]]) -> bool:
    """The words hold the program's end, M2 or M30 (with leading zeros: ``M02``)."""
    for a, n in words:
        if (a == "M" or a == "m") and n.lstrip("0") in ("2", "30"):
            return True
    return False


@mypyc_attr(allow_interpreted_subclasses=True)
class NgcReader(Reader):
    """Physical lines -> lexed blocks under the RS274/NGC rules; errors are reported per block and the
    block is kept."""

    DIALECT: ClassVar[str] = ""
    """Names the dialect in lexical error messages."""
    BLOCK_DELETE: ClassVar[bool] = True
    """``/`` at the start of a block skips it when the operator's switch is on; False (grbl): the character
    is ignored wherever it stands and the block runs, with a warning."""
    PARAMETRIC: ClassVar[bool] = False
    """The dialect reads o-words, parameters and expressions (LinuxCNC); else they are errors (grbl)."""
    POLAR: ClassVar[bool] = False
    """The dialect reads ``@`` and ``^`` words (LinuxCNC's polar coordinates); else they are errors."""
    TAPE_MARK_REFUSED: ClassVar[str] = ""
    """Empty: a ``%`` line is a tape mark wherever it stands (a subclass may read it otherwise). Else a ``%`` is
    the program's first line or closes a program opened with one, and any other is refused unless the program
    has already ended (M2/M30), with this quoted in the error as what the controller says (LinuxCNC's rs274:
    "Bad character '%' used"); so is a ``%`` with a comment beside it (``% (end)``, which rs274 refuses so [V: rs274
    2.9 run here], first line or last: it was read as a tape mark and written ``%``, exit 0). Read here, in the family's compiled loop: as a subclass's generator around it,
    the rule cost every line a resumption in Python (~3k instructions)."""
    MAX_BLOCK_NUMBER: ClassVar[int] = 0
    """The largest block number the controller reads (0: any); a larger one is a located error, as the controller
    refuses the whole line (grbl: error 27). A writer to the same controller drops such a number instead
    (``SectionWords.MAX_BLOCK_NUMBER``): there the source is valid on its own controller, here it is not."""

    def parametric(self) -> bool:
        """Whether this reader reads o-words, parameters and expressions: ``PARAMETRIC``, or a choice of the
        set-up's (grblHAL's expressions option) in a subclass's override."""
        return self.PARAMETRIC

    def read_call(self, block: Block, code: str) -> None:
        """Turn a lexed block's subprogram call or return words into its control section (a parametric
        dialect with numbered subprograms overrides this; the family has none). The family's call and return
        words are M codes (LinuxCNC's Fanuc-style ``M98``/``M99``; its o-word calls are read by ``oword``): a
        line without an M is never offered (compiled, an override's call cost every line ~1.1k instructions)."""

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        file = self.ctx.file
        dialect = self.DIALECT
        report = self.ctx.diagnostics.error
        parametric = self.parametric()
        oword = OwordParser() if parametric else None
        calls = self.read_call if parametric else None
        ignore_slash = None if self.BLOCK_DELETE else self._ignored_slash
        polar = self.POLAR
        max_number = self.MAX_BLOCK_NUMBER
        refused = self.TAPE_MARK_REFUSED
        opened: bool | None = None  # (``TAPE_MARK_REFUSED``) whether a ``%`` opened the program; None until the
        ended = False  # first line with content; and whether the program has ended (M2/M30)
        number = 0
        # Checked lines come in runs (``postproc.syntaxes.lines.line_runs``, as the ISO family's Fanuc reader takes
        # them): mostly many texts already split from the end they share (a line cut from its end cost ~400
        # instructions), with the line check's ASCII copy of their piece (``data``: each line's bytes at ``at``, which
        # the word scan reads); other lines come with their ends, each split natively (the generator
        # ``split_lines`` cost ~3.5k instructions a line).
        for texts, end, data in line_runs(lines):
            at: i64 = 0
            for raw in texts:
                number += 1
                if end is None:
                    text, eol = split_line(raw)
                else:
                    text, eol = raw, end
                start = at
                at += len(text) + len(eol)
                try:
                    block = lex_block(file, number, text, eol, dialect, oword, calls, ignore_slash, polar, max_number,
                                      data, start)
                except PostprocError as err:
                    report(err, text)
                    yield Block(number, text, eol)
                    continue
                if refused:
                    sections = block.sections
                    if "TapeMark" in sections:
                        if "Comments" in sections and not ended:  # (rs274 reads a comment-only line, a '%' alone)
                            report(ParseError(f"'%' must stand alone on its line: no comment beside it ({refused})",
                                              Location(file, number, text.find("%") + 1)), text)
                            yield Block(number, text, eol)  # kept as text, as every refused line
                            continue
                        if opened is False and not ended:
                            report(ParseError(f"'%' closes only a program that opens with '%' on its first line "
                                              f"({refused})", Location(file, number, 1)), text)
                            yield Block(number, text, eol)  # kept as text, as every refused line
                            continue
                        opened = opened is None or opened
                    elif sections or block.words:
                        if opened is None:
                            opened = False
                        if not ended and ("M" in text or "m" in text):  # (an M word's letter is in its line)
                            ended = _ends(block.words)
                yield block

    def _ignored_slash(self, where: Location) -> None:
        self.ctx.diagnostics.warn(f"'/' is ignored by {self.DIALECT} (no block delete): the block runs", where)
