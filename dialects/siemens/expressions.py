"""SINUMERIK expressions, read and written: ``R1``, ``DEPTH``, ``(R2*COS(R6))``, ``POT(R1)``, ``R1==2``.

Hand-written like the ISG family's parser (``(text, pos) -> (pos, value)``, linear, no backtracking); an
error is an ``ExprSyntaxError`` carrying its 0-based offset, and a construct the IR does not model is an
``Unmodelled`` one (the reader keeps its block verbatim, refused by every other dialect by name).

Variables (a documented mapping, the same numbers as ISG's ``P`` parameters):

* ``R<n>`` (0 <= n <= ``R_LAST``) is the neutral numbered variable ``R_BASE + n`` (``R0`` = ``#500``,
  ``R499`` = ``#999``): Fanuc's common variables and LinuxCNC's globals. A higher R has no neutral
  number here: a located error.
* A user variable (``DEF REAL DEPTH``) is a named variable, lower-cased (SINUMERIK names are not
  case-sensitive [K]).
* ``$`` names are system variables (``$P_ACT_X``, ``$MC_...``): machine-only values, a located error
  when a run needs one (``variables``); an indexed one (``$AA_IM[X]``) is kept verbatim.

Operators and their priority [K: SINUMERIK 840D sl Job planning, "Operators and arithmetic functions" and
"Priority of the operators" (manualslib.de manual 82116); the liufang-robot SPEC lists the same
operators]: ``NOT`` first, then ``* / DIV MOD``, ``+ -``, ``AND``, ``XOR``, ``OR``, and the comparisons
``== <> > < >= <=`` last. Because a comparison binds more loosely than ``AND`` there (``R1>1 AND R2<2`` is
not two comparisons joined), a comparison inside a logical operator without parentheses, and a chain of
comparisons, are refused: the program must say it with parentheses, which every SINUMERIK reads alike.
``DIV`` (integer division) and the bit operators ``B_AND``... are not modelled (kept verbatim); ``MOD``
is the remainder with the dividend's sign (C's fmod) [?: the manual defines it for INT operands].

Functions [K: same chapter; degrees for the angles]: ``SIN COS TAN ASIN ACOS`` (one argument),
``ATAN2(y, x)`` (-180..180), ``SQRT ABS LN EXP``, ``POT`` (the square), ``TRUNC`` (toward zero),
``ROUND`` (half away from zero [?]). Numbers: ``1.5``, ``.5``, ``1.874EX8``, ``2EX-3`` (the ``EX`` exponent).
"""

from __future__ import annotations

from postproc.errors import UnsupportedError
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.isg_family.expressions import Unmodelled
from postproc.rs274.expressions import MAX_DEPTH, ExprSyntaxError, decimal_end, shallow, skip_blanks

R_BASE = 500
"""``R<n>`` is the neutral variable ``R_BASE + n``."""
R_LAST = 499
"""The highest R parameter with a neutral number (``R499`` = ``#999``)."""

ARITHMETIC: dict[str, tuple[str, int]] = {
    "+": ("add", 3), "-": ("sub", 3), "*": ("mul", 4), "/": ("div", 4), "MOD": ("fmod", 4),
}
"""Operator -> (neutral op, priority; higher binds tighter); all left-associative."""
LOGICAL: dict[str, tuple[str, int]] = {"OR": ("or", 0), "XOR": ("xor", 1), "AND": ("and", 2)}
COMPARISONS: dict[str, str] = {"==": "eq", "<>": "ne", "<=": "le", ">=": "ge", "<": "lt", ">": "gt"}
FUNCTIONS: dict[str, str] = {
    "SIN": "sin", "COS": "cos", "TAN": "tan", "ASIN": "asin", "ACOS": "acos", "ATAN2": "atan2",
    "SQRT": "sqrt", "ABS": "abs", "LN": "ln", "EXP": "exp", "POT": "sqr", "TRUNC": "trunc", "ROUND": "round",
}
"""Function word -> neutral name (``ATAN2`` takes two arguments, every other one)."""
UNMODELLED_WORDS = frozenset({"DIV", "B_AND", "B_OR", "B_XOR", "B_NOT"})
"""Operators the IR has no exact counterpart for: their block is kept verbatim."""
WORDS = frozenset(("NOT", *ARITHMETIC, *LOGICAL, *UNMODELLED_WORDS, "TO", "GOTO", "GOTOF", "GOTOB", "GOTOC"))
"""Words that end an operand (an operator) or an expression (``FOR .. TO``, ``IF .. GOTOF``)."""

_INVERSE_ARITHMETIC = {op: (word, prec) for word, (op, prec) in ARITHMETIC.items()}
_INVERSE_LOGICAL = {op: (word, prec) for word, (op, prec) in LOGICAL.items()}
_INVERSE_COMPARISONS = {op: word for word, op in COMPARISONS.items()}
_INVERSE_FUNCTIONS = {name: word for word, name in FUNCTIONS.items()}

_DIGITS = frozenset("0123456789")
_LETTERS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_$")
_NAME = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_$")


def name_at(text: str, pos: int) -> int:
    """The end of the name starting at ``pos``."""
    n = len(text)
    while pos < n and text[pos] in _NAME:
        pos += 1
    return pos


def r_variable(number: int, pos: int = 0) -> Var:
    if not 0 <= number <= R_LAST:
        raise ExprSyntaxError(f"R{number}: only R0-R{R_LAST} have a neutral number here", pos)
    return Var(Num(float(R_BASE + number)))


def r_number(var: Var) -> int | None:
    """The R number of a neutral numbered variable, or None when it has none."""
    index = var.index
    if isinstance(index, Num) and index.value.is_integer() and R_BASE <= index.value <= R_BASE + R_LAST:
        return int(index.value) - R_BASE
    return None


def parse_expr(text: str, pos: int) -> tuple[int, Expr]:
    """The expression starting at ``pos``: (end offset, expression)."""
    return shallow(pos, _Parser(text).top(pos))


def parse_variable(text: str, pos: int) -> tuple[int, Var]:
    """``R12``, ``NAME``, ``$NAME`` at ``pos`` (an assignment's target, a loop counter)."""
    end, value = _Parser(text).variable(pos)
    return end, value


class _Parser:
    __slots__ = ("text", "depth", "joined")

    def __init__(self, text: str) -> None:
        self.text = text
        self.depth = 0
        self.joined = False
        """A logical operator joined operands at the level being read (outside parentheses)."""

    def deeper(self, pos: int) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ExprSyntaxError(f"expression nested deeper than {MAX_DEPTH} levels", pos)

    def top(self, pos: int) -> tuple[int, Expr]:
        """A comparison of two logical expressions, or one logical expression."""
        saved = self.joined
        self.joined = False
        start = skip_blanks(self.text, pos)
        pos, left = self.logical(start)
        at = skip_blanks(self.text, pos)
        end, word = self.comparison(at)
        if word is None:
            self.joined = saved
            return pos, left
        if self.joined:
            raise ExprSyntaxError("a comparison after AND/OR/XOR without parentheses: SINUMERIK compares "
                                  "last, so write the comparisons in parentheses: (R1>1) AND (R2<2)", at)
        pos, right = self.logical(end)
        if self.joined:
            raise ExprSyntaxError("a comparison before AND/OR/XOR without parentheses: SINUMERIK compares "
                                  "last, so write the comparisons in parentheses: (R1>1) AND (R2<2)", at)
        after = skip_blanks(self.text, pos)
        if self.comparison(after)[1] is not None:
            raise ExprSyntaxError("a chain of comparisons: write it with parentheses", after)
        self.joined = saved
        return pos, Binary(COMPARISONS[word], left, right)

    def comparison(self, pos: int) -> tuple[int, str | None]:
        two = self.text[pos:pos + 2]
        if two in COMPARISONS:
            return pos + 2, two
        one = self.text[pos:pos + 1]
        if one in ("<", ">"):
            return pos + 1, one
        if one == "=" and two != "==":
            return pos, None
        return pos, None

    def logical(self, pos: int, min_prec: int = -1) -> tuple[int, Expr]:
        pos, left = self.arithmetic(pos)
        while True:
            at = skip_blanks(self.text, pos)
            end, word = self.word_operator(at, LOGICAL)
            if word is None:
                return pos, left
            op, prec = LOGICAL[word]
            if prec <= min_prec:
                return pos, left
            self.joined = True
            self.deeper(at)
            pos, right = self.logical(end, prec)
            self.depth -= 1
            left = Binary(op, left, right)

    def word_operator(self, pos: int, table: dict[str, tuple[str, int]]) -> tuple[int, str | None]:
        end = name_at(self.text, pos)
        word = self.text[pos:end].upper()
        if word in UNMODELLED_WORDS:
            raise Unmodelled(f"the operator {word}", pos)
        return (end, word) if word in table else (pos, None)

    def arithmetic(self, pos: int, min_prec: int = 2) -> tuple[int, Expr]:
        pos, left = self.operand(pos)
        while True:
            at = skip_blanks(self.text, pos)
            c = self.text[at:at + 1]
            if c and c in "+-*/":
                end, word = at + 1, c
            else:
                end, found = self.word_operator(at, ARITHMETIC)
                if found is None:
                    return pos, left
                word = found
            op, prec = ARITHMETIC[word]
            if prec <= min_prec:
                return pos, left
            self.deeper(at)
            pos, right = self.arithmetic(end, prec)
            self.depth -= 1
            left = Binary(op, left, right)

    def operand(self, pos: int) -> tuple[int, Expr]:
        text = self.text
        pos = skip_blanks(text, pos)
        if pos >= len(text):
            raise ExprSyntaxError("expression expected", pos)
        c = text[pos]
        if c in _DIGITS or c == ".":
            return self.number(pos)
        if c == "(":
            self.deeper(pos)
            pos, inner = self.top(pos + 1)
            pos = skip_blanks(text, pos)
            if text[pos:pos + 1] != ")":
                raise ExprSyntaxError("')' expected", pos)
            self.depth -= 1
            return pos + 1, inner
        if c in "+-":
            self.deeper(pos)
            end, inner = self.operand(pos + 1)
            self.depth -= 1
            if isinstance(inner, Num) and c == "-":
                return end, Num(-inner.value)
            return end, Unary("neg" if c == "-" else "pos", inner)
        if c in _LETTERS:
            end = name_at(text, pos)
            word = text[pos:end].upper()
            if word == "NOT":
                self.deeper(pos)
                end, inner = self.operand(end)
                self.depth -= 1
                return end, Unary("not", inner)
            if word in ("TRUE", "FALSE"):
                return end, Num(1.0 if word == "TRUE" else 0.0)
            if word in FUNCTIONS or text[skip_blanks(text, end):skip_blanks(text, end) + 1] == "(" and word[:1] != "$":
                return self.function(pos, end, word)
            return self.variable(pos)
        raise ExprSyntaxError(f"unexpected {c!r} in expression", pos)

    def number(self, pos: int) -> tuple[int, Expr]:
        text, start, n = self.text, pos, len(self.text)
        pos = decimal_end(text, pos)
        mantissa = text[start:pos]
        if mantissa == ".":
            raise ExprSyntaxError("number expected", start)
        exponent = 0
        if text[pos:pos + 2].upper() == "EX":
            at = pos + 2
            sign = text[at:at + 1]
            digits = at + 1 if sign in ("+", "-") and sign else at
            end = digits
            while end < n and text[end] in _DIGITS:
                end += 1
            if end == digits:
                raise ExprSyntaxError("EX needs a whole exponent (1.5EX3, 2EX-3)", pos)
            exponent = int(text[at:end])
            pos = end
        return pos, Num(float(f"{mantissa}e{exponent}") if exponent else float(mantissa))

    def function(self, pos: int, end: int, word: str) -> tuple[int, Expr]:
        name = FUNCTIONS.get(word)
        if name is None:
            raise Unmodelled(f"the function {word}", pos)
        at = skip_blanks(self.text, end)
        if self.text[at:at + 1] != "(":
            raise ExprSyntaxError(f"{word} needs its argument in parentheses: {word}(..)", end)
        args: list[Expr] = []
        self.deeper(at)
        at += 1
        while True:
            at, arg = self.top(at)
            args.append(arg)
            at = skip_blanks(self.text, at)
            c = self.text[at:at + 1]
            if c == ",":
                at += 1
                continue
            if c == ")":
                break
            raise ExprSyntaxError("',' or ')' expected", at)
        self.depth -= 1
        wanted = 2 if name == "atan2" else 1
        if len(args) != wanted:
            raise ExprSyntaxError(f"{word} takes {wanted} argument{'s' if wanted > 1 else ''}", pos)
        return at + 1, Func(name, args)

    def variable(self, pos: int) -> tuple[int, Var]:
        text = self.text
        end = name_at(text, pos)
        word = text[pos:end]
        if not word or text[pos] in _DIGITS:
            raise ExprSyntaxError("a variable expected", pos)
        if text[skip_blanks(text, end):skip_blanks(text, end) + 1] == "[":
            raise Unmodelled("array elements and indexed system variables", pos)
        up = word.upper()
        if up[0] == "R" and up[1:].isdigit():
            return end, r_variable(int(up[1:]), pos)
        if up in WORDS:
            raise ExprSyntaxError(f"'{word}' is an operator, not a value", pos)
        return end, Var(name=word.lower())


# -- writing ---------------------------------------------------------------------------------------

def spell_number(value: float) -> str:
    """A number as SINUMERIK reads it: decimal, ``EX`` for an exponent."""
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    text = repr(value)
    if "e" in text:
        mantissa, _, exponent = text.partition("e")
        return f"{mantissa}EX{int(exponent)}"
    return text


def spell_var(var: Var) -> str:
    if var.name is not None:
        if var.name.startswith("$"):
            return var.name.upper()
        if not var.name or not all(c in _NAME for c in var.name) or var.name[0] in _DIGITS:
            raise UnsupportedError(f"the variable name {var.name!r} has no SINUMERIK spelling")
        return var.name.upper()
    number = r_number(var)
    if number is None:
        raise UnsupportedError(f"variable #{_index(var)} (only #{R_BASE}-#{R_BASE + R_LAST} are R parameters)")
    return f"R{number}"


def _index(var: Var) -> str:
    return spell_number(var.index.value) if isinstance(var.index, Num) else "[..]"


_UNARY_PREC = 5
_TOP = -100
"""``outer`` of an expression that stands alone (a word's value, a condition, a function's argument)."""


def spell_expr(expr: Expr, outer: int = _TOP) -> str:
    """``expr`` in SINUMERIK's spelling, with parentheses where a priority needs them."""
    if isinstance(expr, Num):
        text = spell_number(expr.value)
        return f"({text})" if expr.value < 0 and outer != _TOP else text
    if isinstance(expr, Var):
        return spell_var(expr)
    if isinstance(expr, Unary):
        inner = spell_expr(expr.operand, _UNARY_PREC)
        text = {"neg": "-", "pos": "+", "not": "NOT "}[expr.op] + inner
        return f"({text})" if outer != _TOP else text
    if isinstance(expr, Func):
        word = _INVERSE_FUNCTIONS.get(expr.name)
        if word is None:
            raise UnsupportedError(f"the function {expr.name} has no SINUMERIK spelling")
        return f"{word}({', '.join(spell_expr(a) for a in expr.args)})"
    if isinstance(expr, Binary):
        if expr.op in _INVERSE_COMPARISONS:
            text = f"{spell_expr(expr.left, -1)}{_INVERSE_COMPARISONS[expr.op]}{spell_expr(expr.right, -1)}"
            return f"({text})" if outer != _TOP else text
        found = _INVERSE_ARITHMETIC.get(expr.op) or _INVERSE_LOGICAL.get(expr.op)
        if found is None:
            raise UnsupportedError(f"the operator {expr.op} has no SINUMERIK spelling")
        word, prec = found
        if expr.op in _INVERSE_LOGICAL:
            prec -= 10  # the logical operators bind more loosely than every arithmetic one
        left = spell_expr(expr.left, prec)
        right = spell_expr(expr.right, prec + 1)  # left-associative: an equal right operand needs parentheses
        sep = f" {word} " if word.isalpha() else word
        text = f"{left}{sep}{right}"
        return f"({text})" if outer > prec else text
    raise UnsupportedError(f"an expression {type(expr).__name__} has no SINUMERIK spelling")


def plain_number(text: str) -> bool:
    """A number an address takes without ``=`` (``X10``, ``X-2.5``; an expression needs ``X=..``): digits with at
    most one point, after an optional sign. The reader's words and the frame statements' values read it alike."""
    body = text[1:] if text[:1] in "+-" else text
    return bool(body) and body.replace(".", "", 1).isdigit()
