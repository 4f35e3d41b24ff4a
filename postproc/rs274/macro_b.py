"""Fanuc Custom Macro B statements: one block's text (after ``N``/``/``) -> a control node, and back.

``#i=expr`` (also ``#[expr]=expr``) -> ``Assign``; ``IF [c] GOTO n`` / ``GOTO n`` -> ``Goto`` (``n`` a
number, ``#i`` or ``[expr]``); ``IF [c] THEN #i=expr`` -> ``IfThen``; ``WHILE [c] DO m`` -> ``While``;
``END m`` -> ``EndWhile`` (``m`` 1 to 3, Fanuc's loop identifiers). Words are read in any case, spaces
between tokens are ignored. Canonical spelling (``spell_statement_fanuc``): ``#1=#2+1.``,
``IF [#1 GT 2.] GOTO 10``, ``GOTO #5``, ``IF [#1 EQ 0.] THEN #2=1.``, ``WHILE [#1 LT 10.] DO1``, ``END1``.
Errors are ``ExprSyntaxError``s with the 0-based offset in the given text.
"""

from __future__ import annotations

from ..interp.control import Assign, EndWhile, Goto, IfThen, While
from ..errors import UnsupportedError
from ..ir.expr import Expr, Num, Var
from ..ir import Section
from .expressions import (
    FANUC_SPELLING, ExprSyntaxError, parse_condition, parse_expr, parse_word_value, skip_blanks,
    spell_condition, spell_expr, spell_word_value,
)

LOOP_IDS = ("1", "2", "3")
"""Fanuc's ``DO``/``END`` identifiers."""

_SP = FANUC_SPELLING


def _keyword(text: str, pos: int, word: str) -> int | None:
    """End of ``word`` at ``pos`` (any case), or None."""
    end = pos + len(word)
    return end if text[pos:end].upper() == word else None


def _end(text: str, pos: int) -> None:
    pos = skip_blanks(text, pos)
    if pos < len(text):
        raise ExprSyntaxError(f"unexpected {text[pos]!r} after the statement", pos)


def parse_statement_fanuc(text: str, pos: int = 0) -> Section:
    """The statement at ``pos``, which must run to the end of ``text`` (comments already removed)."""
    pos = skip_blanks(text, pos)
    if pos < len(text) and text[pos] == "#":
        end, assign = _assignment(text, pos)
        _end(text, end)
        return assign
    for word in ("IF", "GOTO", "WHILE", "END"):
        after = _keyword(text, pos, word)
        if after is not None:
            break
    else:
        raise ExprSyntaxError("a macro statement (#i=, IF, GOTO, WHILE, END) expected", pos)
    if word == "GOTO":
        end, target = _target(text, after)
        _end(text, end)
        return Goto(target)
    if word == "END":
        end, label = _loop_id(text, after, "END")
        _end(text, end)
        return EndWhile(label)
    end, cond = parse_condition(text, after, _SP)
    then = skip_blanks(text, end)
    if word == "WHILE":
        after = _keyword(text, then, "DO")
        if after is None:
            raise ExprSyntaxError("DO expected after WHILE [..]", then)
        end, label = _loop_id(text, after, "DO")
        _end(text, end)
        return While(label, cond)
    after = _keyword(text, then, "GOTO")
    if after is not None:
        end, target = _target(text, after)
        _end(text, end)
        return Goto(target, cond)
    after = _keyword(text, then, "THEN")
    if after is None:
        raise ExprSyntaxError("GOTO or THEN expected after IF [..]", then)
    end, assign = _assignment(text, skip_blanks(text, after))
    _end(text, end)
    return IfThen(cond, assign)


def _assignment(text: str, pos: int) -> tuple[int, Assign]:
    if pos >= len(text) or text[pos] != "#":
        raise ExprSyntaxError("'#' expected", pos)
    end, var = parse_word_value(text, pos, _SP)
    if not isinstance(var, Var):
        raise ExprSyntaxError("a variable expected before '='", pos)
    eq = skip_blanks(text, end)
    if eq >= len(text) or text[eq] != "=":
        raise ExprSyntaxError("'=' expected", eq)
    end, value = parse_expr(text, eq + 1, _SP)
    return end, Assign([(var, value)])


def _target(text: str, pos: int) -> tuple[int, Expr]:
    start = skip_blanks(text, pos)
    if start < len(text) and text[start] in "+-":
        raise ExprSyntaxError("a sequence number, '#' or '[' expected after GOTO", start)
    try:
        return parse_word_value(text, start, _SP)
    except ExprSyntaxError as exc:
        if exc.pos == start:
            raise ExprSyntaxError("a sequence number, '#' or '[' expected after GOTO", start) from None
        raise


def _loop_id(text: str, pos: int, word: str) -> tuple[int, str]:
    start = skip_blanks(text, pos)
    end = start
    while end < len(text) and text[end].isdigit():
        end += 1
    label = text[start:end].lstrip("0") or text[start:end]
    if label not in LOOP_IDS:
        raise ExprSyntaxError(f"{word} needs a loop number 1 to 3", start)
    return end, label


def spell_statement_fanuc(node: Section) -> str:
    """The canonical Fanuc text of a statement node; ``UnsupportedError`` for anything Fanuc cannot say
    (a label that is not 1-3, a LinuxCNC-only operator, several assignments in one block)."""
    if isinstance(node, Assign):
        return _spell_assign(node)
    if isinstance(node, Goto):
        goto = f"GOTO {_spell_target(node.target)}"
        return goto if node.cond is None else f"IF {spell_condition(node.cond, _SP)} {goto}"
    if isinstance(node, IfThen):
        return f"IF {spell_condition(node.cond, _SP)} THEN {_spell_assign(node.assign)}"
    if isinstance(node, While):
        return f"WHILE {spell_condition(node.cond, _SP)} DO{_spell_id(node.label)}"
    if isinstance(node, EndWhile):
        return f"END{_spell_id(node.label)}"
    raise UnsupportedError(f"fanuc has no macro statement for {type(node).__name__}")


def _spell_assign(node: Assign) -> str:
    if len(node.items) != 1:
        raise UnsupportedError(f"fanuc assigns one variable per block, not {len(node.items)}")
    var, value = node.items[0]
    return f"{spell_word_value(var, _SP)}={spell_expr(value, _SP)}"


def _spell_target(target: Expr) -> str:
    if isinstance(target, Num) and target.value.is_integer() and target.value >= 0:
        return str(int(target.value))
    return spell_word_value(target, _SP)


def _spell_id(label: str) -> str:
    if label not in LOOP_IDS:
        raise UnsupportedError(f"fanuc loop numbers are 1 to 3, not {label!r}")
    return label
