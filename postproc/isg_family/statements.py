"""ISG control statements (``$IF`` ... ``$ENDIF``, ``$SWITCH``, ``$FOR``, ``$WHILE``, ``$DO``, ``$REPEAT``,
``$BREAK``, ``$CONTINUE``, ``$GOTO``), read into the neutral control sections and written back.

The reader pairs statements with a stack (``Nesting``): each construct gets a label of its own (its
number in the file), so the neutral sections pair the same way the program does, and a statement that
closes nothing, or a construct never closed, is a located error.

Truth: ISG takes a condition as true when its absolute value is at least 0.5. A comparison gives 1 or 0,
so it is kept as it is; any other condition ``c`` becomes the neutral ``ABS[c] >= 0.5`` (``truth``),
which is what it means, and which ``untruth`` reads back.
"""

from __future__ import annotations

from postproc.interp.control import (
    Break, Case, Continue, Default, Do, DoWhile, Else, ElseIf, EndFor, EndIf, EndSwitch, EndWhile, For, Goto,
    GotoLabel, If, Switch, Until, While,
)
from postproc.errors import Location, ParseError, UnsupportedError
from postproc.ir.expr import Binary, Expr, Func, Num, Var
from postproc.ir import Section
from postproc.rs274.expressions import ExprSyntaxError, skip_blanks

from .expressions import expect, parse_expr, spell_expr

CASE_TOLERANCE = 0.001
"""``$CASE`` matches when the values differ by less than this (DIALECTS.md 1.3)."""
_COMPARISONS = frozenset({"eq", "ne", "lt", "gt", "le", "ge"})

OPENERS = {"IF": "IF", "SWITCH": "SWITCH", "FOR": "FOR", "WHILE": "WHILE", "DO": "DO", "REPEAT": "REPEAT"}
CLOSERS = {"ENDIF": "IF", "ENDSWITCH": "SWITCH", "ENDFOR": "FOR", "ENDWHILE": "WHILE", "ENDDO": "DO",
           "UNTIL": "REPEAT"}
_LOOPS = frozenset({"FOR", "WHILE", "DO", "REPEAT"})


def truth(cond: Expr) -> Expr:
    if isinstance(cond, Binary) and cond.op in _COMPARISONS:
        return cond
    return Binary("ge", Func("abs", [cond]), Num(0.5))


def untruth(cond: Expr) -> Expr:
    """The ISG condition of a neutral one: ``ABS[c] >= 0.5`` -> ``c``; a comparison as it is; any other
    condition ``c`` (true when non-zero, SINUMERIK's ``LOOP`` among them) as the comparison ``c != 0``,
    which gives 1 exactly then."""
    if isinstance(cond, Binary):
        if (cond.op == "ge" and isinstance(cond.left, Func) and cond.left.name == "abs"
                and isinstance(cond.right, Num) and cond.right.value == 0.5):
            return cond.left.args[0]
        if cond.op in _COMPARISONS:
            return cond
    return Binary("ne", cond, Num(0.0))


class Nesting:
    """The open constructs while a file is read: (kind, label, line)."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.stack: list[tuple[str, str, int]] = []
        self.count = 0

    def open(self, kind: str, line: int) -> str:
        self.count += 1
        label = str(self.count)
        self.stack.append((kind, label, line))
        return label

    def close(self, kind: str, word: str, line: int, col: int) -> str:
        if not self.stack or self.stack[-1][0] != kind:
            found = f" (the innermost open construct is ${self.stack[-1][0]} from line {self.stack[-1][2]})" \
                if self.stack else ""
            raise ParseError(f"${word} does not close an open ${kind}{found}", Location(self.file, line, col))
        return self.stack.pop()[1]

    def current(self, kind: str, word: str, line: int, col: int) -> str:
        if not self.stack or self.stack[-1][0] != kind:
            raise ParseError(f"${word} outside ${kind} ... $END{kind}", Location(self.file, line, col))
        return self.stack[-1][1]

    def innermost(self, kinds: frozenset[str], word: str, line: int, col: int) -> str:
        for kind, label, _ in reversed(self.stack):
            if kind in kinds:
                return label
        raise ParseError(f"${word} outside a loop{' or $SWITCH' if 'SWITCH' in kinds else ''}",
                         Location(self.file, line, col))


def parse_statement(code: str, pos: int, nesting: Nesting, line: int) -> Section:
    """The statement at ``pos`` (``$`` included), to the end of the block."""
    file = nesting.file
    try:
        return _statement(code, pos, nesting, line)
    except ExprSyntaxError as err:
        raise err.at(file, line) from None


def _statement(code: str, pos: int, nesting: Nesting, line: int) -> Section:
    file = nesting.file
    end = pos + 1
    n = len(code)
    while end < n and code[end].isalpha():
        end += 1
    word = code[pos + 1:end].upper()
    col = pos + 1
    rest = skip_blanks(code, end)

    def done(at: int, section: Section) -> Section:
        at = skip_blanks(code, at)
        if at < n:
            raise ParseError(f"unexpected {code[at:].strip()[:20]!r} after ${word}", Location(file, line, at + 1))
        return section

    def condition() -> tuple[int, Expr]:
        return parse_expr(code, rest)

    if word == "IF":
        at, cond = condition()
        goto = skip_blanks(code, at)
        if code[goto:goto + 5].upper() == "$GOTO":
            target_at, target = _goto_target(code, goto + 5, file, line)
            if isinstance(target, str):
                return done(target_at, GotoLabel(target, truth(cond)))
            return done(target_at, Goto(target, truth(cond)))
        return done(at, If(nesting.open("IF", line), truth(cond)))
    if word == "ELSEIF":
        at, cond = condition()
        return done(at, ElseIf(nesting.current("IF", word, line, col), truth(cond)))
    if word == "ELSE":
        return done(rest, Else(nesting.current("IF", word, line, col)))
    if word == "SWITCH":
        at, value = condition()
        return done(at, Switch(nesting.open("SWITCH", line), value, CASE_TOLERANCE))
    if word == "CASE":
        at, value = condition()
        return done(at, Case(nesting.current("SWITCH", word, line, col), value))
    if word == "DEFAULT":
        return done(rest, Default(nesting.current("SWITCH", word, line, col)))
    if word == "FOR":
        return _for(code, rest, nesting, line, done)
    if word == "WHILE":
        at, cond = condition()
        return done(at, While(nesting.open("WHILE", line), truth(cond)))
    if word in ("DO", "REPEAT"):
        return done(rest, Do(nesting.open(word, line)))
    if word in CLOSERS:
        kind = CLOSERS[word]
        label = nesting.close(kind, word, line, col)
        if word == "ENDDO":
            at, cond = condition()
            return done(at, DoWhile(label, truth(cond)))
        if word == "UNTIL":
            at, cond = condition()
            return done(at, Until(label, truth(cond)))
        closing = {"IF": EndIf, "SWITCH": EndSwitch, "FOR": EndFor, "WHILE": EndWhile}[kind]
        return done(rest, closing(label))
    if word == "BREAK":
        return done(rest, Break(nesting.innermost(_LOOPS | {"SWITCH"}, word, line, col)))
    if word == "CONTINUE":
        return done(rest, Continue(nesting.innermost(_LOOPS, word, line, col)))
    if word == "GOTO":
        at, target = _goto_target(code, end, file, line)
        return done(at, GotoLabel(target) if isinstance(target, str) else Goto(target))
    raise ParseError(f"unknown control statement ${code[pos + 1:end]}", Location(file, line, col))


def _goto_target(code: str, pos: int, file: str, line: int) -> tuple[int, Expr | str]:
    """``N<expr>`` (a number label) or ``[NAME]`` (a named one)."""
    at = skip_blanks(code, pos)
    if code[at:at + 1] == "[":
        end = code.find("]", at)
        name = code[at + 1:end].strip() if end > 0 else ""
        if not name or any(not (ch.isalnum() or ch == "_") for ch in name):
            raise ParseError("$GOTO [NAME] needs a label name of letters, digits and _", Location(file, line, at + 1))
        return end + 1, name
    if code[at:at + 1].upper() != "N":
        raise ParseError("$GOTO needs a label N<number>", Location(file, line, at + 1))
    return parse_expr(code, at + 1)


def _for(code: str, pos: int, nesting: Nesting, line: int, done: object) -> Section:
    """``$FOR P1 = start, end, step``."""
    file = nesting.file
    at, counter = parse_expr(code, pos)
    if not isinstance(counter, Var):
        raise ParseError("$FOR needs a counter parameter: $FOR P1 = start, end, step", Location(file, line, pos + 1))
    at = expect(code, at, "=")
    at, start = parse_expr(code, at)
    at = expect(code, at, ",")
    at, end = parse_expr(code, at)
    at = expect(code, at, ",")
    at, step = parse_expr(code, at)
    section = For(nesting.open("FOR", line), counter, start, end, step)
    return done(at, section)  # type: ignore[operator,no-any-return]


def spell_statement(section: Section) -> str:
    """A control section in ISG's spelling (the label is implied by the nesting)."""
    if isinstance(section, If):
        return "$IF " + spell_expr(untruth(section.cond))
    if isinstance(section, ElseIf):
        return "$ELSEIF " + spell_expr(untruth(section.cond))
    if isinstance(section, Else):
        return "$ELSE"
    if isinstance(section, EndIf):
        return "$ENDIF"
    if isinstance(section, While):
        return "$WHILE " + spell_expr(untruth(section.cond))
    if isinstance(section, EndWhile):
        return "$ENDWHILE"
    if isinstance(section, Do):
        return "$DO"
    if isinstance(section, DoWhile):
        return "$ENDDO " + spell_expr(untruth(section.cond))
    if isinstance(section, Until):
        return "$ENDDO " + _negated(section.cond)  # a written $DO closes with $ENDDO: loop while not cond
    if isinstance(section, For):
        return (f"$FOR {spell_expr(section.counter)} = {spell_expr(section.start)}, {spell_expr(section.end)}, "
                f"{spell_expr(section.step)}")
    if isinstance(section, EndFor):
        return "$ENDFOR"
    if isinstance(section, Switch):
        if section.tolerance != CASE_TOLERANCE:
            raise UnsupportedError(f"a switch whose cases match within {section.tolerance:g} (ISG's $CASE: "
                                   f"{CASE_TOLERANCE:g})")
        return "$SWITCH " + spell_expr(section.value)
    if isinstance(section, Case):
        return "$CASE " + spell_expr(section.value)
    if isinstance(section, Default):
        return "$DEFAULT"
    if isinstance(section, EndSwitch):
        return "$ENDSWITCH"
    if isinstance(section, Break):
        return "$BREAK"
    if isinstance(section, Continue):
        return "$CONTINUE"
    if isinstance(section, GotoLabel):
        jump = f"$GOTO [{section.label}]"
        return jump if section.cond is None else "$IF " + spell_expr(untruth(section.cond)) + " " + jump
    if isinstance(section, Goto):
        target = "$GOTO N" + _label(section.target)
        if section.cond is None:
            return target
        return "$IF " + spell_expr(untruth(section.cond)) + " " + target
    raise UnsupportedError(f"ISG has no statement for {type(section).__name__}")


def _negated(cond: Expr) -> str:
    """An ISG condition true exactly when the neutral ``cond`` is false."""
    inner = untruth(cond)
    if isinstance(inner, Binary) and inner.op in _COMPARISONS:
        return f"[{spell_expr(inner)}] == 0"
    return f"ABS[{spell_expr(inner)}] < 0.5"


def _label(target: Expr) -> str:
    if isinstance(target, Num) and target.value.is_integer() and target.value >= 0:
        return str(int(target.value))
    return "[" + spell_expr(target) + "]"
