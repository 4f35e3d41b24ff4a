"""The ISG/Fagor family's lexical structure of one block: comments, block skip, ``%`` headers, ``N`` numbers and labels, DIN
words (``G01X10Y20``, ``XP1``, ``X-P3``, ``X[P2*COS[P6]]``), assignments (``P10=20.5``,
``V.L.X=P1*2``), calls (``LL name``, ``L file``), and where a ``$`` statement or a ``#`` command starts.

A linear scan, each character looked at a bounded number of times; columns are offsets into the
block's text (comments blanked to spaces, so columns stay right). ISG's grammar is the default; a
``Grammar`` names what another dialect of the family reads differently.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from postproc.errors import Location, ParseError
from postproc.ir.expr import Expr, Var
from postproc.rs274.expressions import ExprSyntaxError, decimal_end, skip_blanks

from .expressions import parse_expr, parse_word_value

_DIGITS = frozenset("0123456789")
_LETTERS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")
_NAME = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.")
_FILE_NAME = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.-/\\")
_BLANKS = frozenset(" \t")
"""Inside a main program's name: Beckhoff's own streaming-mode sample starts ``% TestProgram for streaming
mode`` [V: TwinCAT CNC sample programs]; a subroutine's name (``%L name``) is a file name, without them."""
SKIP_LEVELS = 10
"""Block skip levels ``/1`` ... ``/10`` (plain ``/`` is level 1)."""


@dataclass(frozen=True, slots=True)
class Grammar:
    """Where a family dialect's lexical rules differ from ISG's."""

    parens: bool = True
    """``( .. )`` is a comment (ISG); False: a ``(`` is left in the code for the dialect to judge."""
    bare_dwell_time: bool = True
    """A time right after the dwell code without its address (ISG ``G04 3.0``) is its ``X`` word."""
    assigned_g: frozenset[str] = frozenset()
    """G numbers written ``G<n>=<whole number>`` (Fagor's zero offset selection), lexed as one code
    word whose number is ``<n>=<value>``."""
    p_words_after: frozenset[str] = frozenset()
    """G numbers (without leading zeros) after which ``P<number>`` is a plain word, not a parameter
    (Fagor's multiple machining: ``G163 X20 K6 P2.005`` skips points 2 to 5)."""


ISG_GRAMMAR = Grammar()


@dataclass
class Lexed:
    """What one block holds, before any meaning: the reader turns it into a ``Block``."""

    comments: list[str] = field(default_factory=list)
    skip: int = 0
    header: tuple[str, str] | None = None
    """``("main", name)``, ``("sub", name)`` or ``("tape", "")`` for a ``%`` line."""
    number: str | None = None
    """The block number's text (``10``, ``[10+P30]``)."""
    number_value: Expr | None = None
    label: bool = False
    """``N100:``: the number is a jump label."""
    label_name: str | None = None
    """``[NAME]``: a named jump label."""
    words: list[tuple[str, str]] = field(default_factory=list)
    values: dict[str, Expr] = field(default_factory=dict)
    assigns: list[tuple[Var, Expr]] = field(default_factory=list)
    statement: int | None = None
    """Offset of a ``$`` statement (it runs to the end of the block)."""
    command: int | None = None
    """Offset of a ``#`` command (it runs to the end of the block)."""
    call: tuple[str, str, int] | None = None
    """``("LL"|"L", name, offset)``."""


def command_words(code: str) -> list[str]:
    """Upper-case words of a command line (``#COMMENT END``, ``$IF ...``), without its block number: both
    readers of the family compare a command by them."""
    words = code.upper().split()
    if words and words[0][:1] == "N" and words[0][1:].isdigit():
        words = words[1:]
    return words


def strip_comments(file: str, line: int, text: str, lexed: Lexed, parens: bool = True) -> str:
    """Blank out ``( .. )`` (nesting; an unclosed one runs to the end; only when ``parens``) and ``;``
    to the end; keep their texts in ``lexed.comments``. A ``"..."`` string (``#MSG ["done :)"]``) is
    text, not a comment's start or end."""
    if not parens:
        cut = text.find(";")
        if cut < 0:
            return text
        lexed.comments.append(text[cut + 1:])
        return text[:cut] + " " * (len(text) - cut)
    if "(" not in text and ")" not in text and ";" not in text:
        return text
    out: list[str] = []
    depth = 0
    start = 0
    pos = 0
    n = len(text)
    while pos < n:
        c = text[pos]
        if depth:
            if c == "(":
                depth += 1
            elif c == ")":
                depth -= 1
                if depth == 0:
                    lexed.comments.append(text[start + 1:pos])
                    out.append(" " * (pos - start + 1))
            pos += 1
            continue
        if c == '"':
            close = text.find('"', pos + 1)
            end = n if close < 0 else close + 1
            out.append(text[pos:end])
            pos = end
            continue
        if c == "(":
            depth = 1
            start = pos
        elif c == ")":
            raise ParseError("')' without an opening '('", Location(file, line, pos + 1))
        elif c == ";":
            lexed.comments.append(text[pos + 1:])
            out.append(" " * (n - pos))
            return "".join(out)
        else:
            out.append(c)
        pos += 1
    if depth:
        lexed.comments.append(text[start + 1:])  # an unclosed comment runs to the end of the block
        out.append(" " * (n - start))
    return "".join(out)


def lex(file: str, line: int, code: str, lexed: Lexed, grammar: Grammar = ISG_GRAMMAR) -> Lexed:
    """Lex the code of one block into ``lexed`` (its comments already taken by ``strip_comments``)."""
    try:
        _lex(file, line, code, lexed, grammar)
    except ExprSyntaxError as err:
        raise err.at(file, line) from None
    return lexed


def _error(file: str, line: int, pos: int, message: str) -> ParseError:
    return ParseError(message, Location(file, line, pos + 1))


def _lex(file: str, line: int, code: str, lexed: Lexed, grammar: Grammar) -> None:
    n = len(code)
    pos = skip_blanks(code, 0)
    if pos < n and code[pos] == "/":
        end = pos + 1
        while end < n and code[end] in _DIGITS:
            end += 1
        level = int(code[pos + 1:end]) if end > pos + 1 else 1
        if not 1 <= level <= SKIP_LEVELS:
            raise _error(file, line, pos, f"block skip level /{level} (levels are /1 to /{SKIP_LEVELS})")
        lexed.skip = level
        pos = skip_blanks(code, end)
    if pos < n and code[pos] == "%":
        _header(file, line, code, pos, lexed)
        return
    if pos < n and code[pos] in "Nn":
        pos = _number(file, line, code, pos, lexed)
    if pos < n and code[pos] == "[":
        end = code.find("]", pos)
        name = code[pos + 1:end].strip() if end > 0 else ""
        if not name or any(ch not in _NAME or ch == "." for ch in name):
            raise _error(file, line, pos, "a jump label is [NAME] with letters, digits and _")
        lexed.label_name = name
        pos = skip_blanks(code, end + 1)
    if pos < n and code[pos] == "$":
        lexed.statement = pos
        return
    if pos < n and code[pos] == "#":
        lexed.command = pos
        return
    while pos < n:
        c = code[pos]
        if c in " \t":
            pos += 1
            continue
        if c in "Ll" and _is_call(code, pos):
            pos = _call(file, line, code, pos, lexed)
            continue
        if grammar.bare_dwell_time and _dwell_time(code, pos, lexed):
            pos = _word(file, line, " " + code[pos:], 0, lexed, "X") - 1 + pos
            continue
        if c in _LETTERS:
            plain = c in "Pp" and bool(grammar.p_words_after) and any(
                w[0] in "Gg" and w[1].lstrip("0") in grammar.p_words_after for w in lexed.words)
            pos = _word(file, line, code, pos, lexed, plain=plain)
            if grammar.assigned_g and lexed.words and lexed.words[-1][0] in "Gg" \
                    and lexed.words[-1][1] in grammar.assigned_g:
                pos = _assigned(file, line, code, pos, lexed)
            continue
        if c == "$":
            raise _error(file, line, pos, "a control statement ($...) must start its block (only N and / may "
                                          "come before it)")
        if c == "#":
            raise _error(file, line, pos, "a # command must be alone in its block (only N may come before it)")
        if c == "%":
            raise _error(file, line, pos, "'%' must start its line")
        raise _error(file, line, pos, f"unexpected character {c!r}")


def _assigned(file: str, line: int, code: str, pos: int, lexed: Lexed) -> int:
    """``G159=3``: the code word just read takes ``=<whole number>`` (blanks allowed around ``=``)."""
    eq = skip_blanks(code, pos)
    letter, number = lexed.words[-1]
    if code[eq:eq + 1] != "=":
        raise _error(file, line, pos - len(number) - 1, f"{letter}{number} needs a value: {letter}{number}=<n>")
    start = skip_blanks(code, eq + 1)
    end = start
    while end < len(code) and code[end] in _DIGITS:
        end += 1
    if end == start or code[end:end + 1] == ".":
        raise _error(file, line, start, f"{letter}{number}= takes a whole number")
    lexed.words[-1] = (letter, f"{number}={int(code[start:end])}")
    return end


def _header(file: str, line: int, code: str, pos: int, lexed: Lexed) -> None:
    rest = code[pos + 1:].strip()
    if not rest:
        lexed.header = ("tape", "")
        return
    if rest[:1] in "Ll" and rest[1:2] in (" ", "\t"):
        name = rest[1:].strip()
        if not name or any(ch not in _FILE_NAME for ch in name):
            raise _error(file, line, pos, f"a local subroutine needs a name: %L <name>, not {rest!r}")
        lexed.header = ("sub", name)
        return
    if any(ch not in _FILE_NAME and ch not in _BLANKS for ch in rest):
        raise _error(file, line, pos, f"malformed program name {rest!r}")
    lexed.header = ("main", rest)


def _number(file: str, line: int, code: str, pos: int, lexed: Lexed) -> int:
    """``N10``, ``N100:`` (a jump label), ``N[10+P30]``."""
    n = len(code)
    start = skip_blanks(code, pos + 1)
    if start < n and code[start] == "[":
        end, value = parse_word_value(code, start)
        lexed.number = code[start:end]
        lexed.number_value = value
    else:
        end = start
        while end < n and code[end] in _DIGITS:
            end += 1
        if end == start:
            raise _error(file, line, pos, "a block number N needs a whole number or [expression]")
        if end < n and code[end] == ".":
            raise _error(file, line, pos, f"block number N{code[start:end]}. must be a whole number")
        lexed.number = code[start:end]
    after = skip_blanks(code, end)
    if after < n and code[after] == ":":
        if lexed.number_value is not None:
            raise _error(file, line, pos, "a jump label N<number>: takes a whole number here")
        lexed.label = True
        end = after + 1
    return skip_blanks(code, end)


def _is_call(code: str, pos: int) -> bool:
    """``L name`` or ``LL name``: the blank after the address is mandatory, and a name is no number."""
    end = pos + 2 if code[pos + 1:pos + 2] in ("L", "l") else pos + 1
    if code[end:end + 1] not in (" ", "\t"):
        return False
    first = code[skip_blanks(code, end):skip_blanks(code, end) + 1]
    return first != "" and first not in _DIGITS and first not in "+-.[Pp"


def _call(file: str, line: int, code: str, pos: int, lexed: Lexed) -> int:
    if lexed.call is not None:
        raise _error(file, line, pos, "one subroutine call per block")
    local = code[pos + 1:pos + 2] in ("L", "l")
    start = skip_blanks(code, pos + (2 if local else 1))
    end = start
    n = len(code)
    while end < n and code[end] in _FILE_NAME:
        end += 1
    name = code[start:end]
    if not name:
        raise _error(file, line, start, "a subroutine call needs a name")
    if name.upper() == "CYCLE" or name.upper().startswith("V."):
        raise _error(file, line, pos, f"'{code[pos:end].strip()}' (cycle and variable calls) is not read yet")
    lexed.call = ("LL" if local else "L", name, pos)
    return end


def _dwell_time(code: str, pos: int, lexed: Lexed) -> bool:
    """``G04 3.0``, ``G04 P1``, ``G04 V.L.TIME``: a time right after ``G04``, read as its ``X`` word."""
    if not lexed.words or lexed.words[-1][0] not in "Gg" or lexed.words[-1][1].lstrip("0") != "4":
        return False
    c = code[pos]
    nxt = code[pos + 1:pos + 2]
    return c.isdigit() or c in "+-.[" or c in "Pp" and nxt.isdigit() or c in "Vv" and nxt == "."


def _word(file: str, line: int, code: str, pos: int, lexed: Lexed, address: str | None = None,
          plain: bool = False) -> int:
    """An address and its value; ``address`` given: ``code[pos]`` is a blank standing for it (a dwell's
    time written without its X); ``plain``: ``P<number>`` is a word, not a parameter."""
    n = len(code)
    c = address or code[pos]
    up = c.upper()
    if address is None and (up == "P" and not plain and pos + 1 < n and code[pos + 1] in _DIGITS
                            or up == "V" and code[pos + 1:pos + 2] == "."):
        end, target = parse_word_value(code, pos)
        eq = skip_blanks(code, end)
        if eq >= n or code[eq] != "=" or code[eq + 1:eq + 2] == "=":
            raise _error(file, line, pos, f"'{code[pos:end]}' alone: a parameter is set with "
                                          f"{code[pos:end]}=<value> or used as an address's value (X{code[pos:end]})")
        assert isinstance(target, Var)
        end, value = parse_expr(code, eq + 1)
        lexed.assigns.append((target, value))
        return end
    start = skip_blanks(code, pos + 1)
    if start < n and code[start] == "=":
        start = skip_blanks(code, start + 1)  # X=10 is X10
    end = start
    if end < n and code[end] in "+-":
        end += 1
    digits = end
    end = decimal_end(code, end)
    number = code[start:end]
    if end > digits and number not in ("+.", "-.", "."):
        if end < n and code[end] in ".[":
            raise _error(file, line, pos, f"malformed word {code[pos:end + 1]!r}")
        if up not in "GM" and (up in lexed.values or any(w[0].upper() == up for w in lexed.words)):
            raise _error(file, line, pos, f"address {up} appears twice in one block")
        lexed.words.append((c, number))
        return end
    if start < n and (code[start] in "[PpVv'" or code[start] in "+-" and code[start + 1:start + 2] in "[PpVv"):
        end, value = parse_word_value(code, start)
        if up in lexed.values or any(w[0].upper() == up for w in lexed.words):
            raise _error(file, line, pos, f"address {up} appears twice in one block")
        lexed.words.append((c, code[start:end]))
        lexed.values[up] = value
        return end
    if start < n and code[start] in _LETTERS:
        end = pos
        while end < n and code[end] in _NAME:
            end += 1
        raise _error(file, line, pos, f"unknown word {code[pos:end]!r}")
    raise _error(file, line, pos, f"address {up} needs a value")
