"""LinuxCNC O-word lines and parameter assignments: one line's text -> control nodes, and back.

Grammar (checked against LinuxCNC's ``rs274``, ``interp_read.cc`` ``read_o``/``read_items``):

- An o-word line is ``o<label> <keyword> [args]``: ``sub``, ``endsub [v]``, ``call [a] [b] ..``,
  ``return [v]``, ``if [c]``, ``elseif [c]``, ``else``, ``endif``, ``while [c]``, ``endwhile``, ``do``,
  ``repeat [n]``, ``endrepeat``, ``break``, ``continue``. The o-word opens the line (after the caller's
  ``/`` and ``N``); nothing but comments may follow the statement (``( .. )``, or ``;`` to the end of the
  line), and a comment may also sit between call arguments, nowhere else (rs274: "Unexpected character
  after O-word"). A line cannot hold an o-word and other words; ``G0 X1 o100 ..`` is "Bad character 'o'".
- rs274 deletes blanks and lower-cases everything outside comments before reading a line, so ``O100``,
  ``o 1 0 0``, ``o100 end if`` and ``o<My Sub>`` (= ``o<mysub>``) are all accepted; this reader does the
  same for the label and the keyword. The keyword is found as rs274 finds it, by prefix in its order
  (``o1 ifsin[1]`` is ``if`` then a missing ``[``; ``o1 dox`` is ``do`` then an unexpected ``x``).
  The condition, count or argument must start with ``[``
  ("Left bracket missing after 'while'"); ``o100 while[#1 LT 3]`` needs no blank.
- The label is kept as the text rs274 keys it by: a number as decimal text without leading zeros
  (``o0100`` and ``o100`` are the same label, ``"100"``; ``o1.0`` is ``"1"``), a name with its angle
  brackets, blanks removed, lower-cased (``o<Name>`` is ``"<name>"``). Names here use letters, digits,
  ``_``, ``-`` and ``.`` (rs274 takes anything up to ``>``; a name is also a file name, so the rest is
  refused).
- rs274 also evaluates a computed number (``o#5 call``, ``o[#5+1] call``): for ``call`` the name is then
  an expression (``Call(Var(Num(5.0)), ...)``); on any other keyword it is refused, since a structure
  whose label is known only when it runs cannot be matched before it runs.
- A bare ``O100`` (``o100``, ``O 1 0 0``, ``O0100``, ``N10 O100``, followed by nothing but comments) is a
  ``ProgramStart(100)``: LinuxCNC's Fanuc-style subprogram start, called by ``M98 P100`` and ended by
  ``M99`` (see ``ngc_calls``); met in the flow of the program it does nothing (rs274: on the first line it
  is the program's name, elsewhere the lines after it simply run). A bare ``o<name>`` or ``o#1`` is refused.

Which construct ``o1 while [c]`` is depends on what came before: it ends a ``do`` loop if a ``do``
with label ``1`` is open in the same scope (rs274 looks the label up in the labels it has met), and
starts a ``while`` loop otherwise. ``parse_oword_line`` takes the open ``do`` labels as an argument;
``OwordParser`` (one per program file) keeps them, line by line, per scope (the main program, or the
subprogram being defined: rs274 scopes labels by subprogram), and refuses a label reused by another
opening statement in the same scope (rs274 "duplicate O-word label", or worse, a ``while`` taken for
the end of an earlier ``do``), a ``break``/``continue`` whose label is not a ``while`` or ``do`` loop
(rs274 "no matching while/do label": they do not leave a ``repeat``), and nested or unmatched
``sub``/``endsub``. Matching the other closers (``endif``, ``endwhile``, ...) is the program store's job.

Assignments (``#1=5``, ``#<x>=[#1+2]``, ``#[#1+1]=-#2``; several per line, set in parallel) are read by
``parse_assignments`` from a ``#`` item; the right-hand side is a word value (``#1=1+2`` is an rs274
error: it needs ``[1+2]``). rs274 reads an assignment anywhere in a line (``G0 X1 #1=2`` is valid),
so the caller calls it at every item that starts with ``#``.

Canonical spelling: ``o100 if [#1 LT 3.]``, ``o<name> call [1.] [#2]``, ``o100 endsub [#1]``,
``#1=5. #<x>=[#1+2.]``. Errors are ``ExprSyntaxError``s with the 0-based offset in the given text
(``.at(file, line, offset)`` locates them).
"""

from __future__ import annotations

from typing import Callable, Container

from ..interp.control import (
    Assign, Break, Call, Continue, Do, DoWhile, Else, ElseIf, EndIf, EndRepeat, EndWhile, If, Repeat,
    Return, SubEnd, SubStart, While,
)
from ..errors import UnsupportedError
from ..ir.expr import Expr, Num, Var
from ..ir import ProgramStart, Section
from .expressions import (
    LINUXCNC_SPELLING, ExprSyntaxError, parse_condition, parse_word_value, skip_blanks, spell_condition,
    spell_word_value,
)

MAX_CALL_ARGS = 30
"""``o.. call`` takes at most 30 arguments, ``#1``-``#30`` ("Too many subroutine parameters")."""
MAX_PARAMETER = 5601
"""Numbered parameters are ``#1``-``#5601`` (RS274NGC_MAX_PARAMETERS - 1)."""
READONLY_PARAMETERS = frozenset([*range(5021, 5030), *range(5400, 5414), *range(5420, 5429)])
"""Parameters a program may read but not set (``interp_array.cc``: machine position, current tool,
current position): rs274 "Parameter is readonly"."""

_SP = LINUXCNC_SPELLING
_BLANK = frozenset(" \t")
_DIGITS = frozenset("0123456789")
_LETTERS = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ")
_NAME_CHARS = _LETTERS | _DIGITS | frozenset("_-.")

_NO_ARGS = {"else": Else, "endif": EndIf, "endwhile": EndWhile, "do": Do, "endrepeat": EndRepeat,
            "break": Break, "continue": Continue}
_WITH_COND = {"if": If, "elseif": ElseIf}
_KEYWORD_ORDER = ("sub", "endsub", "call", "do", "while", "repeat", "if", "elseif", "else", "endif", "break",
                  "continue", "endwhile", "endrepeat", "return")
"""rs274's order of trial (``read_o``): ``elseif`` before ``else``; no keyword is a prefix of a later one."""
_OPENERS = frozenset(["if", "while", "do", "repeat"])
_VALUE_KEYWORDS = {"endsub": SubEnd, "return": Return}


def _run(text: str, pos: int, chars: frozenset[str]) -> tuple[list[int], str]:
    """Characters of ``chars`` from ``pos``, blanks between them ignored (as rs274 deletes blanks);
    returns the offset after each one, and the characters."""
    out: list[str] = []
    ends: list[int] = []
    p = pos
    while True:
        p = skip_blanks(text, p)
        if p >= len(text) or text[p] not in chars:
            return ends, "".join(out)
        out.append(text[p])
        p += 1
        ends.append(p)


def _keyword(text: str, pos: int) -> tuple[int, str]:
    """The command at ``pos`` as rs274 finds it: the first keyword (in its order) that the letters
    there start with (``o1 ifsin[1]`` is ``if`` followed by ``sin``); "" if none."""
    ends, letters = _run(text, pos, _LETTERS)
    letters = letters.lower()
    for word in _KEYWORD_ORDER:
        if letters.startswith(word):
            return ends[len(word) - 1], word
    return pos, letters


# ------------------------------------------------------------------------------------------ reading


def parse_oword_line(text: str, pos: int = 0, do_labels: Container[str] = frozenset()) -> Section:
    """The o-word statement at ``pos`` (an ``o``, after the caller's ``/`` and ``N``), which, with its
    comments, must run to the end of ``text``. ``o<L> while [c]`` is a ``DoWhile`` when ``L`` is in
    ``do_labels`` (the open ``do`` loops of the current scope: see ``OwordParser``), else a ``While``."""
    return _read_line(text, pos, do_labels)[0]


def _read_line(text: str, pos: int, do_labels: Container[str]) -> tuple[Section, str, int]:
    """The statement, its keyword and the offset of its label."""
    start = skip_blanks(text, pos)
    if start >= len(text) or text[start] not in "oO":
        raise ExprSyntaxError("o-word expected", start)
    label_pos = skip_blanks(text, start + 1)
    after_label, label = _label(text, label_pos)
    kw_pos = skip_blanks(text, after_label)
    end, keyword = _keyword(text, kw_pos)
    if end == kw_pos:
        if keyword:
            raise ExprSyntaxError(f"unknown o-word command {keyword!r}", kw_pos)
        if _at_end(text, kw_pos):
            if isinstance(label, str) and label.isdigit():
                return ProgramStart(int(label)), "", label_pos
            raise ExprSyntaxError("a bare o-word starts a Fanuc-style subprogram and takes a number, "
                                  "not a name or an expression", start)
        raise ExprSyntaxError("o-word command (sub, call, if, while, do, repeat, ...) expected", kw_pos)
    if keyword == "call":
        end, args = _call_args(text, end)
        _end(text, end)
        return Call(label, args, None, "macro"), keyword, label_pos
    if not isinstance(label, str):
        raise ExprSyntaxError(f"a computed o-number (o#.., o[..]) is read only with call, not with "
                              f"{keyword}", label_pos)
    node: Section
    if keyword == "sub":
        node = SubStart(label)
    elif keyword in _VALUE_KEYWORDS:
        value = None
        if skip_blanks(text, end) < len(text) and text[skip_blanks(text, end)] == "[":
            end, value = _bracketed(text, end, keyword)
        node = SubEnd(label, value) if keyword == "endsub" else Return(label, value)
    elif keyword in _NO_ARGS:
        node = _NO_ARGS[keyword](label)
    else:
        end, arg = _bracketed(text, end, keyword)
        if keyword == "repeat":
            node = Repeat(label, arg)
        elif keyword == "while":
            node = DoWhile(label, arg) if label in do_labels else While(label, arg)
        else:
            node = _WITH_COND[keyword](label, arg)
    _end(text, end)
    return node, keyword, label_pos


def _label(text: str, pos: int) -> tuple[int, str | Expr]:
    if pos < len(text) and text[pos] == "<":
        close = text.find(">", pos + 1)
        if close < 0:
            raise ExprSyntaxError("'>' expected: an o-word name is written o<name>", len(text))
        name: list[str] = []
        for i in range(pos + 1, close):
            c = text[i]
            if c in _BLANK:
                continue
            if c not in _NAME_CHARS:
                raise ExprSyntaxError(f"o-word names use letters, digits, '_', '-' and '.', not {c!r}", i)
            name.append(c.lower())
        if not name:
            raise ExprSyntaxError("empty o-word name", pos)
        return close + 1, "<" + "".join(name) + ">"
    if pos < len(text) and text[pos] in "#[":
        return parse_word_value(text, pos, _SP)
    ends, digits = _run(text, pos, _DIGITS)
    if not digits:
        raise ExprSyntaxError("o-word number or <name> expected", pos)
    end = ends[-1]
    dot = skip_blanks(text, end)
    if dot < len(text) and text[dot] == ".":
        ends, fraction = _run(text, dot + 1, _DIGITS)
        if fraction.strip("0"):
            raise ExprSyntaxError(f"o-word number {digits}.{fraction} is not a whole number", pos)
        end = ends[-1] if ends else dot + 1
    return end, str(int(digits))


def _bracketed(text: str, pos: int, keyword: str) -> tuple[int, Expr]:
    start = skip_blanks(text, pos)
    if start >= len(text) or text[start] != "[":
        raise ExprSyntaxError(f"'[' expected after {keyword}", start)
    return parse_condition(text, start, _SP)


def _call_args(text: str, pos: int) -> tuple[int, dict[int, Expr]]:
    args: dict[int, Expr] = {}
    while True:
        pos = skip_blanks(text, pos)
        if pos < len(text) and text[pos] == "(":
            pos = _comment(text, pos)
            continue
        if pos >= len(text) or text[pos] != "[":
            return pos, args
        if len(args) == MAX_CALL_ARGS:
            raise ExprSyntaxError(f"too many call arguments: at most {MAX_CALL_ARGS} (#1-#{MAX_CALL_ARGS})", pos)
        pos, args[len(args) + 1] = parse_condition(text, pos, _SP)


def _comment(text: str, pos: int) -> int:
    """The end of the ``( .. )`` comment at ``pos`` (its text is the caller's: ``strip_comments``)."""
    close = text.find(")", pos + 1)
    if close < 0:
        raise ExprSyntaxError("unclosed comment", pos)
    nested = text.find("(", pos + 1, close)
    if nested >= 0:
        raise ExprSyntaxError("nested comment: '(' inside a comment", nested)
    return close + 1


def _at_end(text: str, pos: int) -> bool:
    """Only blanks and comments from ``pos`` on."""
    while True:
        pos = skip_blanks(text, pos)
        if pos >= len(text) or text[pos] == ";":
            return True
        if text[pos] != "(":
            return False
        pos = _comment(text, pos)


def _end(text: str, pos: int) -> None:
    while True:
        pos = skip_blanks(text, pos)
        if pos >= len(text) or text[pos] == ";":
            return
        if text[pos] != "(":
            raise ExprSyntaxError(f"unexpected {text[pos]!r} after the o-word statement (only a comment "
                                  f"may follow)", pos)
        pos = _comment(text, pos)


class OwordParser:
    """Reads the o-word lines of one program file in order, knowing what came before: which ``do``
    loops are open (so ``o1 while [c]`` is their end), which labels the current scope has used, and
    which subprogram is being defined (labels are scoped per subprogram, as in rs274).

    ``parse(text, pos, line)``: ``line`` only names earlier lines in messages."""

    __slots__ = ("_sub", "_used", "_open_do", "_main")

    def __init__(self) -> None:
        self._sub: tuple[str, int] | None = None
        """The subprogram being defined and the line of its ``sub``."""
        self._used: dict[str, tuple[str, int]] = {}
        """Label -> (opening keyword, line) in the current scope."""
        self._open_do: set[str] = set()
        self._main: tuple[dict[str, tuple[str, int]], set[str]] = (self._used, self._open_do)
        """The main program's scope, kept while a subprogram is defined."""

    def parse(self, text: str, pos: int = 0, line: int = 0) -> Section:
        node, keyword, label_pos = _read_line(text, pos, self._open_do)
        label = getattr(node, "label", None)
        if isinstance(node, DoWhile):
            self._open_do.discard(node.label)
        elif isinstance(node, (Break, Continue)):
            seen = self._used.get(node.label)
            if seen is None or seen[0] not in ("while", "do"):
                what = f"o{node.label} is the {seen[0]} on line {seen[1]}" if seen else f"no loop o{node.label} is open"
                raise ExprSyntaxError(f"{keyword} leaves a while or do loop only: {what}", label_pos)
        elif keyword in _OPENERS and isinstance(label, str):
            self._open(label, keyword, line, label_pos)
        elif isinstance(node, SubStart):
            if self._sub is not None:
                raise ExprSyntaxError(f"o{node.name} sub inside the definition of o{self._sub[0]} (line "
                                      f"{self._sub[1]}): subprogram definitions do not nest", label_pos)
            self._sub = (node.name, line)
            self._used, self._open_do = {}, set()
        elif isinstance(node, SubEnd):
            if self._sub is None or self._sub[0] != node.name:
                now = f"o{self._sub[0]} sub (line {self._sub[1]}) is being defined" if self._sub else "no sub is open"
                raise ExprSyntaxError(f"o{node.name} endsub does not end a definition: {now}", label_pos)
            self._sub = None
            self._used, self._open_do = self._main
        return node

    def _open(self, label: str, keyword: str, line: int, label_pos: int) -> None:
        seen = self._used.get(label)
        if seen is not None:
            scope = f"o{self._sub[0]}" if self._sub else "the main program"
            hint = (" (LinuxCNC would read it as the end of that do loop)" if seen[0] == "do" and keyword == "while"
                    else "")
            raise ExprSyntaxError(f"label o{label} is already used by the {seen[0]} on line {seen[1]} in "
                                  f"{scope}{hint}: each if or loop needs its own label", label_pos)
        self._used[label] = (keyword, line)
        if keyword == "do":
            self._open_do.add(label)


def parse_assignments(text: str, pos: int = 0) -> tuple[int, Assign]:
    """The parameter assignments starting at the ``#`` at ``pos`` (``#1=5 #<x>=[#1+1]``, as many as
    follow one another); returns the offset just after the last right-hand side, and the ``Assign``."""
    items: list[tuple[Var, Expr]] = []
    pos = skip_blanks(text, pos)
    while True:
        if pos >= len(text) or text[pos] != "#":
            raise ExprSyntaxError("'#' expected", pos)
        end, var = parse_word_value(text, pos, _SP)
        if not isinstance(var, Var):  # parse_word_value at '#' reads a variable; this narrows the type
            raise ExprSyntaxError("a parameter expected before '='", pos)
        _check_target(var, pos)
        eq = skip_blanks(text, end)
        if eq >= len(text) or text[eq] != "=":
            raise ExprSyntaxError("'=' expected", eq)
        end, value = parse_word_value(text, eq + 1, _SP)
        items.append((var, value))
        pos = skip_blanks(text, end)
        if pos < len(text) and text[pos] in "+-*/":
            raise ExprSyntaxError("LinuxCNC reads one value after '=': bracket an expression, #1=[#2+1]", pos)
        if pos >= len(text) or text[pos] != "#":
            return end, Assign(items)


def _check_target(var: Var, pos: int) -> None:
    index = var.index
    if not isinstance(index, Num):
        return
    n = index.value
    if not (1 <= n <= MAX_PARAMETER):
        raise ExprSyntaxError(f"parameter number out of range: #{n:g} (LinuxCNC has #1-#{MAX_PARAMETER})", pos)
    if n in READONLY_PARAMETERS:
        raise ExprSyntaxError(f"#{n:g} is read-only in LinuxCNC", pos)


# ------------------------------------------------------------------------------------------ writing


def spell_oword(node: Section) -> str:
    """The canonical LinuxCNC text of an o-word statement; ``UnsupportedError`` for what an o-word
    cannot say (a Fanuc ``GOTO``, an ``M98``-style call sharing the caller's locals, a call with a
    repeat count or with arguments that are not ``#1``..``#n``, a return without a label)."""
    kind = _SPELLERS.get(type(node))
    if kind is None:
        raise UnsupportedError(f"linuxcnc has no o-word for {type(node).__name__}")
    return kind(node)


def _label_text(label: str | Expr) -> str:
    if isinstance(label, str):
        if label.startswith("<") and label.endswith(">") and len(label) > 2 and all(
                c in _NAME_CHARS and not c.isupper() for c in label[1:-1]):
            return label
        if label.isdigit() and label == str(int(label)):
            return label
        raise UnsupportedError(f"{label!r} is not a LinuxCNC o-word label (a number, or <name> in lower case)")
    if isinstance(label, Num) and label.value.is_integer() and label.value >= 0:
        return str(int(label.value))
    return spell_word_value(label, _SP)


def _head(node: Section, keyword: str) -> str:
    label: str = getattr(node, "label", None) or getattr(node, "name")
    return f"o{_label_text(label)} {keyword}"


def _cond(node: Section, keyword: str) -> str:
    return f"{_head(node, keyword)} {spell_condition(getattr(node, 'cond'), _SP)}"


def _value(node: SubEnd | Return, keyword: str) -> str:
    if node.name is None:
        raise UnsupportedError("a LinuxCNC return names its subprogram: o<name> return (this Return has no name)")
    head = _head(node, keyword)
    return head if node.value is None else f"{head} {spell_condition(node.value, _SP)}"


def _return(node: Return) -> str:
    if node.target is not None:
        raise UnsupportedError("a LinuxCNC return cannot continue at a sequence number")
    return _value(node, "return")


def _call(node: Call) -> str:
    if node.kind != "macro":
        raise UnsupportedError("an o-word call gives the subprogram its own #1-#30; this call shares the "
                               "caller's locals (a subprogram call)")
    if node.repeat is not None:
        raise UnsupportedError("an o-word call has no repeat count")
    keys = sorted(node.args)
    if keys != list(range(1, len(keys) + 1)) or len(keys) > MAX_CALL_ARGS:
        shown = ", ".join(f"#{k}" for k in keys)
        raise UnsupportedError(f"an o-word call sets #1 to #n in order (at most #{MAX_CALL_ARGS}); this call "
                               f"sets {shown}")
    args = "".join(f" {spell_condition(node.args[k], _SP)}" for k in keys)
    return f"o{_label_text(node.name)} call{args}"


_SPELLERS: dict[type[Section], Callable[..., str]] = {
    SubStart: lambda n: _head(n, "sub"),
    SubEnd: lambda n: _value(n, "endsub"),
    Return: _return,
    Call: _call,
    If: lambda n: _cond(n, "if"),
    ElseIf: lambda n: _cond(n, "elseif"),
    Else: lambda n: _head(n, "else"),
    EndIf: lambda n: _head(n, "endif"),
    While: lambda n: _cond(n, "while"),
    EndWhile: lambda n: _head(n, "endwhile"),
    Do: lambda n: _head(n, "do"),
    DoWhile: lambda n: _cond(n, "while"),
    Repeat: lambda n: f"{_head(n, 'repeat')} {spell_condition(n.count, _SP)}",
    EndRepeat: lambda n: _head(n, "endrepeat"),
    Break: lambda n: _head(n, "break"),
    Continue: lambda n: _head(n, "continue"),
}


def spell_assignments(assign: Assign) -> str:
    """``#1=5. #<x>=[#1+2.]``: each right-hand side as a word value, one blank between assignments."""
    out = []
    for var, value in assign.items:
        if isinstance(var.index, Num) and not (1 <= var.index.value <= MAX_PARAMETER
                                                and var.index.value not in READONLY_PARAMETERS):
            raise UnsupportedError(f"LinuxCNC cannot set #{var.index.value:g} (settable: #1-#{MAX_PARAMETER}, "
                                   f"not the read-only ones)")
        out.append(f"{spell_word_value(var, _SP)}={spell_word_value(value, _SP)}")
    return " ".join(out)
