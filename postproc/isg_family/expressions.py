"""ISG expressions, read and written: ``P10``, ``V.L.NAME``, ``[P2*COS[P6]]``, ``P1 ** 2``, ``P1 == 2``.

Hand-written in tomli's style (``(text, pos) -> (pos, value)``, linear, no backtracking); an error is an
``ExprSyntaxError`` carrying its 0-based offset. The tables below are read in both directions: the
parser maps ISG's words to neutral names, the writer inverts them.

Variables (a documented, collision-free mapping, so a kept program means the same in every dialect
that has variables):

* ``P<n>`` (1 <= n <= ``P_LAST``) is the neutral numbered variable ``P_BASE + n`` (``P1`` = ``#501``,
  ``P499`` = ``#999``): Fanuc's common variables ``#501``-``#999`` and LinuxCNC's globals, never a
  local, an argument or a system variable on either side. Any other numbered variable has no ISG
  spelling (the writer refuses it, so such a program is flattened for ISG).
* ``V.P.``/``V.L.``/``V.S.`` (self-defined) and ``V.E.``/``V.A.``/``V.G.``/``V.TOOL.``... (the
  machine's) are named variables keeping their full name as written (``"V.L.DEPTH"``): no other
  dialect spells a name with dots, so a program that uses them is flattened elsewhere.

Semantics of ISG's words (DIALECTS.md 1.3; [?] where the manual we read does not say): ``MOD`` is C's
fmod [?], ``INT`` truncates toward zero [?], ``ROUND`` rounds half away from zero [?], ``FRACT`` is
``x - INT[x]``, ``SQR`` squares, ``DEXP``/``LOG`` are base 10, angles in degrees, ``ATAN`` takes one
argument; comparisons are exact [?] and give 1 or 0. Precedence: ``**`` above ``* / MOD`` above
``+ -`` above the comparisons, all left-associative [?]; a sign directly before ``**`` (``-2 ** 2``) is
refused as ambiguous, and written ``[-2] ** 2``.
"""

from __future__ import annotations

from postproc.errors import UnsupportedError
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.rs274.expressions import MAX_DEPTH, ExprSyntaxError, decimal_end, shallow, skip_blanks

class Unmodelled(ExprSyntaxError):
    """A construct ISG has and the IR does not model (an array element): the reader keeps its block
    verbatim, refused by the simulator and by every other dialect."""

    def __init__(self, what: str, pos: int) -> None:
        super().__init__(f"{what} are not modelled", pos)
        self.what = what


P_BASE = 500
"""``P<n>`` is the neutral variable ``P_BASE + n``."""
P_LAST = 499
"""The highest P parameter with a neutral number (``P499`` = ``#999``)."""

BINARY: dict[str, tuple[str, int]] = {
    "==": ("eq", 1), "!=": ("ne", 1), "<": ("lt", 1), ">": ("gt", 1), "<=": ("le", 1), ">=": ("ge", 1),
    "+": ("add", 2), "-": ("sub", 2),
    "*": ("mul", 3), "/": ("div", 3), "MOD": ("fmod", 3),
    "**": ("pow", 4),
}
"""Operator -> (neutral op, precedence; higher binds tighter). All are left-associative."""
FUNCTIONS: dict[str, str] = {
    "ABS": "abs", "SQR": "sqr", "SQRT": "sqrt", "EXP": "exp", "LN": "ln", "DEXP": "exp10", "LOG": "log10",
    "SIN": "sin", "COS": "cos", "TAN": "tan", "ASIN": "asin", "ACOS": "acos", "ATAN": "atan",
    "INT": "trunc", "FRACT": "fract", "ROUND": "round", "EXIST": "exists",
}
"""Function word -> neutral name (one argument each). ``EXIST[V.S.SPEED]`` is 1 when the variable exists
(ISG programming manual, "#VAR" page's example ``$IF EXIST[V.S.EXAMPLE[0]] == TRUE`` [V]); on the
Fagor 8070 it is not known [?] (``FagorVariables.exists`` refuses it)."""
CONSTANTS: dict[str, float] = {"TRUE": 1.0, "FALSE": 0.0}
"""Named constants (the same manual example compares with ``TRUE``; a BOOLEAN is 0 or 1 [V])."""
_INVERSE_BINARY = {op: (word, prec) for word, (op, prec) in BINARY.items()}
_INVERSE_FUNCTIONS = {name: word for word, name in FUNCTIONS.items()}
_COMPARE = 1

_DIGITS = frozenset("0123456789")
_LETTERS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")
_NAME = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_.")
_HEX = frozenset("0123456789abcdefABCDEF")


def p_variable(number: int) -> Var:
    return Var(Num(float(P_BASE + number)))


def p_number(var: Var) -> int | None:
    """The ISG P number of a neutral variable, or None when it has none."""
    index = var.index
    if isinstance(index, Num) and index.value.is_integer() and P_BASE + 1 <= index.value <= P_BASE + P_LAST:
        return int(index.value) - P_BASE
    return None


class _Parser:
    __slots__ = ("text", "depth")

    def __init__(self, text: str) -> None:
        self.text = text
        self.depth = 0

    def deeper(self, pos: int) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ExprSyntaxError(f"expression nested deeper than {MAX_DEPTH} levels", pos)

    def expression(self, pos: int, min_prec: int = 0) -> tuple[int, Expr]:
        start = skip_blanks(self.text, pos)
        signed = self.text[start:start + 1] in ("+", "-")
        pos, left = self.operand(pos)
        while True:
            pos = skip_blanks(self.text, pos)
            end, word = self.operator(pos)
            if word is None:
                return pos, left
            if word == "**" and signed:
                raise ExprSyntaxError("a sign before '**' is ambiguous (is -2 ** 2 4 or -4?): write [-2] ** 2 "
                                      "or -[2 ** 2]", start)
            signed = False
            op, prec = BINARY[word]
            if prec <= min_prec:
                return pos, left
            self.deeper(pos)
            pos, right = self.expression(end, prec)
            self.depth -= 1
            left = Binary(op, left, right)

    def operator(self, pos: int) -> tuple[int, str | None]:
        text = self.text
        two = text[pos:pos + 2]
        if two in ("**", "==", "!=", "<=", ">="):
            return pos + 2, two
        c = text[pos:pos + 1]
        if c and c in "+-*/<>":
            return pos + 1, c
        if text[pos:pos + 3].upper() == "MOD" and text[pos + 3:pos + 4] not in _NAME:
            return pos + 3, "MOD"
        return pos, None

    def operand(self, pos: int) -> tuple[int, Expr]:
        text = self.text
        pos = skip_blanks(text, pos)
        if pos >= len(text):
            raise ExprSyntaxError("expression expected", pos)
        c = text[pos]
        if c in _DIGITS or c == ".":
            return self.number(pos)
        if c == "'":
            return self.based(pos)
        if c == "[":
            self.deeper(pos)
            pos, inner = self.expression(pos + 1)
            pos = expect(text, pos, "]")
            self.depth -= 1
            return pos, inner
        if c in "+-":
            self.deeper(pos)
            end, inner = self.operand(pos + 1)
            self.depth -= 1
            if isinstance(inner, Num) and c == "-":
                return end, Num(-inner.value)
            return end, Unary("neg" if c == "-" else "pos", inner)
        if c in _LETTERS:
            return self.word(pos)
        raise ExprSyntaxError(f"unexpected {c!r} in expression", pos)

    def number(self, pos: int) -> tuple[int, Expr]:
        text, start = self.text, pos
        pos = decimal_end(text, pos)
        if text[start:pos] == ".":
            raise ExprSyntaxError("number expected", start)
        return pos, Num(float(text[start:pos]))

    def based(self, pos: int) -> tuple[int, Expr]:
        """``'16#FA1B'``, ``'0x0ED2'``, ``'H1869f'``, ``'2#1010'``: a whole number in base 16 or 2."""
        text = self.text
        end = text.find("'", pos + 1)
        if end < 0:
            raise ExprSyntaxError("unclosed ' in a hexadecimal or binary constant", pos)
        body = text[pos + 1:end]
        upper = body.upper()
        digits, base = "", 0
        if upper.startswith("16#"):
            digits, base = body[3:], 16
        elif upper.startswith("0X"):
            digits, base = body[2:], 16
        elif upper.startswith("H"):
            digits, base = body[1:], 16
        elif upper.startswith("2#"):
            digits, base = body[2:], 2
        allowed = _HEX if base == 16 else frozenset("01")
        if not digits or not base or any(ch not in allowed for ch in digits):
            raise ExprSyntaxError(f"malformed constant '{body}' (16#.., 0x.., H.. or 2#..)", pos)
        return end + 1, Num(float(int(digits, base)))

    def word(self, pos: int) -> tuple[int, Expr]:
        text = self.text
        n = len(text)
        if text[pos] in "Pp" and pos + 1 < n and text[pos + 1] in _DIGITS:
            end = pos + 1
            while end < n and text[end] in _DIGITS:
                end += 1
            number = int(text[pos + 1:end])
            if not 1 <= number <= P_LAST:
                raise ExprSyntaxError(f"P{number}: P parameters P1 to P{P_LAST} are read (each is a neutral "
                                      f"variable #{P_BASE}+n)", pos)
            if end < n and text[end] == "[":
                raise Unmodelled("P parameter arrays", pos)
            return end, p_variable(number)
        if text[pos] in "Vv" and text[pos + 1:pos + 2] == ".":
            end = pos + 2
            while end < n and text[end] in _NAME:
                end += 1
            name = text[pos:end].rstrip(".")
            if name.count(".") < 2:
                raise ExprSyntaxError(f"malformed variable name {name!r} (V.<kind>.<name>)", pos)
            if end < n and text[end] == "[":
                raise Unmodelled("V. variable arrays", pos)
            return pos + len(name), Var(name=name)
        end = pos
        while end < n and text[end] in _LETTERS:
            end += 1
        word = text[pos:end].upper()
        constant = CONSTANTS.get(word)
        if constant is not None and (end >= n or text[end] not in _NAME):
            return end, Num(constant)
        neutral = FUNCTIONS.get(word)
        if neutral is None:
            raise ExprSyntaxError(f"unknown function or variable {text[pos:end]!r}", pos)
        bracket = skip_blanks(text, end)
        if bracket >= n or text[bracket] != "[":
            raise ExprSyntaxError(f"'[' expected after {word}", bracket)
        self.deeper(bracket)
        after, arg = self.expression(bracket + 1)
        after = expect(text, after, "]")
        self.depth -= 1
        return after, Func(neutral, [arg])


def expect(text: str, pos: int, char: str) -> int:
    pos = skip_blanks(text, pos)
    if pos >= len(text) or text[pos] != char:
        raise ExprSyntaxError(f"'{char}' expected", pos)
    return pos + 1


def parse_expr(text: str, pos: int) -> tuple[int, Expr]:
    """A full expression from ``pos`` (a statement's or an assignment's right-hand side); returns its end
    (before any blanks after it) and its tree."""
    return shallow(pos, _Parser(text).expression(pos))


def parse_word_value(text: str, pos: int) -> tuple[int, Expr]:
    """What follows an address when it is not a plain number: ``[expr]``, ``P1``, ``-P3``, ``V.L.X``."""
    return shallow(pos, _Parser(text).operand(pos))


# ----------------------------------------------------------------------------------------- writing

def spell_number(value: float) -> str:
    """A number as ISG reads it: shortest decimal, no exponent (a point is optional in ISG)."""
    if value != value or value in (float("inf"), float("-inf")):
        raise UnsupportedError(f"{value!r} cannot be written as a number")
    from decimal import Decimal  # imported when an expression is written, not by every start
    text = format(Decimal(repr(value)), "f")
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def spell_var(var: Var) -> str:
    if var.name is not None:
        if not var.name.upper().startswith("V."):
            raise UnsupportedError(f"ISG has no variable named {var.name!r}")
        return var.name
    number = p_number(var)
    if number is None:
        raise UnsupportedError(f"variable {_describe_var(var)} has no ISG spelling (P1-P{P_LAST} are "
                               f"#{P_BASE + 1}-#{P_BASE + P_LAST})")
    return f"P{number}"


def _describe_var(var: Var) -> str:
    index = var.index
    if isinstance(index, Num) and index.value.is_integer():
        return f"#{int(index.value)}"
    return "#[..]"


def spell_expr(expr: Expr, min_prec: int = 0, leading: bool = True) -> str:
    """``expr`` as ISG writes it, bracketed only where precedence needs it."""
    if isinstance(expr, Num):
        text = spell_number(expr.value)
        return text if leading or not text.startswith("-") else f"[{text}]"
    if isinstance(expr, Var):
        return spell_var(expr)
    if isinstance(expr, Unary):
        if expr.op == "not":
            raise UnsupportedError("ISG has no operator for 'not'")
        sign = "-" if expr.op == "neg" else "+"
        inner = spell_expr(expr.operand, 99, False)
        text = sign + inner
        return text if leading else f"[{text}]"
    if isinstance(expr, Binary):
        found = _INVERSE_BINARY.get(expr.op)
        if found is None:
            raise UnsupportedError(f"ISG has no operator for {expr.op!r}")
        word, prec = found
        left = spell_expr(expr.left, prec - 1, leading)
        if word == "**" and left[:1] in ("-", "+"):
            left = f"[{left}]"  # a sign before ** is refused when read (its precedence is not known)
        right = spell_expr(expr.right, prec, False)
        sep = f" {word} " if word == "MOD" or prec == _COMPARE else word
        text = left + sep + right
        return f"[{text}]" if prec <= min_prec else text
    if isinstance(expr, Func) and expr.name == "whole_in":
        return spell_expr(expr.args[0], min_prec, leading)  # ISG stores into a typed variable by assigning
    if isinstance(expr, Func):
        function = _INVERSE_FUNCTIONS.get(expr.name)
        if function is None or len(expr.args) != 1:
            raise UnsupportedError(f"ISG has no function for {expr.name!r}")
        return f"{function}[{spell_expr(expr.args[0])}]"
    raise UnsupportedError(f"cannot write {type(expr).__name__}")


def spell_word_value(expr: Expr) -> str:
    """What follows an address: a number, ``P1``, ``-P1``, ``V.L.X``, else ``[expr]``."""
    if isinstance(expr, (Num, Var)):
        return spell_expr(expr)
    if isinstance(expr, Unary) and expr.op == "neg" and isinstance(expr.operand, Var):
        return "-" + spell_var(expr.operand)
    return f"[{spell_expr(expr)}]"
