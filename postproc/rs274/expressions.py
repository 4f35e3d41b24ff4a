"""Reading and writing expressions in an RS274 dialect's own spelling.

One ``ExprSpelling`` per dialect is data (function words, operator words with precedence, variable
syntax), read in both directions: the parser maps words to neutral names, the writer inverts the
same tables. The parser is hand-written in tomli's style, ``(text, pos) -> (pos, value)``: linear time,
no backtracking, a ``ParseError`` carrying the 0-based offset (``ExprSyntaxError.pos``) that the caller
turns into a column. Nesting (brackets, unary signs, indirection) is bounded by the spelling.

Spelling choices (both dialects): an operator written as a word has a space on each side (``#1 GT 2.``,
``#1 MOD 3``), symbols have none (``#1+2.``); numbers have an explicit decimal point and no exponent
(``2.``, ``0.5``); a negative number or a negated operand on the right of an operator is bracketed
(``#1*[-2.]``); a unary minus binds to the next operand only (LinuxCNC: ``-2**2`` is 4).
"""

from __future__ import annotations

from dataclasses import field

from ..errors import Location, ParseError, UnsupportedError
from ..ir.expr import MAX_XML_DEPTH, Binary, Expr, Func, Num, Unary, Var, nests_deeper
from ..records import record

MAX_DEPTH = 64
"""Deepest nesting any spelling accepts (brackets, signs and indirection together)."""


class ExprSyntaxError(ParseError):
    """A malformed expression; ``pos`` is the 0-based offset in the text given to the parser."""

    def __init__(self, message: str, pos: int) -> None:
        super().__init__(message)
        self.pos = pos

    def at(self, file: str, line: int, offset: int = 0) -> "ExprSyntaxError":
        """Locate the error: the parsed text started at column ``offset + 1`` of ``line``."""
        return self.located(Location(file, line, offset + self.pos + 1))  # type: ignore[return-value]


@record(frozen=True)
class ExprSpelling:
    """How one dialect writes expressions. Word keys are upper case; reading ignores case."""

    name: str
    binary: dict[str, tuple[str, int]]
    """Operator word or symbol -> (neutral op, precedence; higher binds tighter). All are left-associative."""
    functions: dict[str, str]
    """One-argument function word -> neutral name."""
    atan2: str | None
    """Neutral name of the two-argument ``ATAN[y]/[x]``, or None."""
    atan1: str | None
    """Neutral name of a one-argument ``ATAN[x]``, or None if ``ATAN`` needs ``/[x]``."""
    binary_functions: dict[str, str] = field(default_factory=dict)
    """Two-argument function word written ``F[a,b]`` -> neutral binary op (Fanuc ``POW``)."""
    word_functions: dict[str, str] = field(default_factory=dict)
    """Function words that mean something else inside an NC word (Fanuc ``ROUND`` -> ``round_address``)."""
    named_variables: bool = False
    """``#<name>`` exists."""
    double_hash: bool = False
    """``##1`` means ``#[#1]``."""
    bare_binary: bool = True
    """A statement's right-hand side may be an unbracketed binary expression (Fanuc ``#3=#1+#2``)."""
    functions_as_word_values: bool = False
    """An address may be followed directly by a function (LinuxCNC ``X SIN[30]``)."""
    parameters: tuple[int, int] | None = None
    """The numbered variables that exist, first and last (None: whatever the program names); a program
    naming another (Custom Macro B's vacant ``#0``, a Fanuc tool offset ``#10100``) cannot be kept
    symbolically for the dialect."""
    max_brackets: int = MAX_DEPTH
    """Deepest bracket nesting the controller accepts."""
    max_brackets_note: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "_inverse_binary", {op: (w, p) for w, (op, p) in self.binary.items()})
        object.__setattr__(self, "_inverse_functions", {n: w for w, n in self.functions.items()})

    def spell_binary(self, op: str) -> tuple[str, int] | None:
        inv: dict[str, tuple[str, int]] = getattr(self, "_inverse_binary")
        return inv.get(op)

    def spell_function(self, name: str) -> str | None:
        inv: dict[str, str] = getattr(self, "_inverse_functions")
        return inv.get(name)


_COMPARE = 0
FANUC_SPELLING = ExprSpelling(
    name="fanuc",
    binary={
        "EQ": ("eq", _COMPARE), "NE": ("ne", _COMPARE), "GT": ("gt", _COMPARE), "GE": ("ge", _COMPARE),
        "LT": ("lt", _COMPARE), "LE": ("le", _COMPARE),
        "+": ("add", 1), "-": ("sub", 1), "OR": ("bitor", 1), "XOR": ("bitxor", 1),
        "*": ("mul", 2), "/": ("div", 2), "AND": ("bitand", 2), "MOD": ("rem_int", 2),
    },
    functions={
        "SIN": "sin", "COS": "cos", "TAN": "tan", "ASIN": "asin_360", "ACOS": "acos", "SQRT": "sqrt",
        "ABS": "abs", "ROUND": "round", "FIX": "trunc", "FUP": "away", "LN": "ln", "EXP": "exp",
        "BIN": "bin", "BCD": "bcd",
    },
    atan2="atan2_360",
    atan1="atan_360",
    binary_functions={"POW": "pow"},
    word_functions={"ROUND": "round_address"},
    max_brackets=5,
    max_brackets_note=" (Fanuc alarm 118)",
)
"""Fanuc Custom Macro B. Precedence: functions, then ``* / AND MOD``, then ``+ - OR XOR``, then the
comparisons (which appear inside ``IF``/``WHILE`` brackets). Brackets nest at most 5 deep, counting a
function's brackets and the word's own (``X[...]``) and condition's (``IF [...]``)."""

LINUXCNC_SPELLING = ExprSpelling(
    name="linuxcnc",
    binary={
        "AND": ("and", 1), "OR": ("or", 1), "XOR": ("xor", 1),
        "EQ": ("eq_tol", 2), "NE": ("ne_tol", 2), "GT": ("gt", 2), "GE": ("ge", 2), "LT": ("lt", 2),
        "LE": ("le", 2),
        "+": ("add", 3), "-": ("sub", 3),
        "*": ("mul", 4), "/": ("div", 4), "MOD": ("mod_pos", 4),
        "**": ("pow", 5),
    },
    functions={
        "SIN": "sin", "COS": "cos", "TAN": "tan", "ASIN": "asin", "ACOS": "acos", "SQRT": "sqrt",
        "ABS": "abs", "ROUND": "round", "FIX": "floor", "FUP": "ceil", "LN": "ln", "EXP": "exp",
        "EXISTS": "exists",
    },
    atan2="atan2",
    atan1=None,
    named_variables=True,
    double_hash=True,
    bare_binary=False,
    functions_as_word_values=True,
    parameters=(1, 5601),
)
"""LinuxCNC (interp_internal.cc ``precedence``): ``**`` above ``* / MOD`` above ``+ -`` above the
comparisons above ``AND OR XOR``; binary expressions only inside brackets. Parameters #1-#5601: rs274
refuses ``#0`` and ``#5602`` ("Parameter number out of range") [V: rs274 run here]."""

_SPACE = frozenset(" \t")
_DIGITS = frozenset("0123456789")
_NUMBER_START = frozenset("0123456789.")
_LETTERS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")
_NAME_CHARS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_")


def decimal_end(text: str, pos: int) -> int:
    """Where the unsigned decimal number from ``pos`` ends: digits, then a point and digits (either side may be
    empty: ``12``, ``1.5``, ``.5``, ``2.``; a lone ``.`` is the caller's to refuse). The expressions and the
    word readers of every family scan a number so."""
    n = len(text)
    while pos < n and text[pos] in _DIGITS:
        pos += 1
    if pos < n and text[pos] == ".":
        pos += 1
        while pos < n and text[pos] in _DIGITS:
            pos += 1
    return pos


def skip_blanks(text: str, pos: int) -> int:
    """The first position from ``pos`` that is not a blank (space or tab): the expressions, o-words and
    Macro B statements of the family read past blanks so."""
    n = len(text)
    while pos < n and text[pos] in _SPACE:
        pos += 1
    return pos


class _Parser:
    """State of one parse: the text, the spelling, the current nesting depth."""

    __slots__ = ("text", "sp", "brackets", "depth", "in_word")

    def __init__(self, text: str, sp: ExprSpelling, in_word: bool, brackets: int = 0) -> None:
        self.text = text
        self.sp = sp
        self.brackets = brackets
        self.depth = 0
        self.in_word = in_word

    def error(self, message: str, pos: int) -> ExprSyntaxError:
        return ExprSyntaxError(message, pos)

    def deeper(self, pos: int) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise self.error(f"expression nested deeper than {MAX_DEPTH} levels", pos)

    def open_bracket(self, pos: int) -> None:
        self.brackets += 1
        if self.brackets > self.sp.max_brackets:
            raise self.error(f"brackets nested deeper than {self.sp.max_brackets} levels"
                             f"{self.sp.max_brackets_note}", pos)
        self.deeper(pos)

    def close_bracket(self) -> None:
        self.brackets -= 1
        self.depth -= 1

    def expression(self, pos: int, min_prec: int = -1) -> tuple[int, Expr]:
        """Precedence climbing: operands bind to operators at or above ``min_prec``."""
        pos, left = self.operand(pos)
        while True:
            pos = skip_blanks(self.text, pos)
            op_end, word = self.operator(pos)
            if word is None:
                return pos, left
            op, prec = self.sp.binary[word]
            if prec <= min_prec:
                return pos, left
            self.deeper(pos)
            pos, right = self.expression(op_end, prec)
            self.depth -= 1
            left = Binary(op, left, right)

    def operator(self, pos: int) -> tuple[int, str | None]:
        """The binary operator at ``pos`` (its end and spelling), or None."""
        text = self.text
        if pos >= len(text):
            return pos, None
        c = text[pos]
        if c == "*" and text.startswith("**", pos) and "**" in self.sp.binary:
            return pos + 2, "**"
        if c in "+-*/":
            return pos + 1, c
        if c in _LETTERS:
            end = pos
            while end < len(text) and text[end] in _LETTERS:
                end += 1
            word = text[pos:end].upper()
            if word in self.sp.binary:
                return end, word
            raise self.error(f"unknown operator {text[pos:end]!r}", pos)
        return pos, None

    def operand(self, pos: int) -> tuple[int, Expr]:
        text = self.text
        pos = skip_blanks(text, pos)
        if pos >= len(text):
            raise self.error("expression expected", pos)
        c = text[pos]
        if c in _NUMBER_START:
            return self.number(pos, 1.0)
        if c == "#":
            return self.variable(pos)
        if c == "[":
            self.open_bracket(pos)
            pos, inner = self.expression(pos + 1)
            pos = self.expect(pos, "]", "']' expected")
            self.close_bracket()
            return pos, inner
        if c in "+-":
            after = skip_blanks(text, pos + 1)
            if after < len(text) and text[after] in _NUMBER_START:
                return self.number(after, -1.0 if c == "-" else 1.0)
            self.deeper(pos)
            end, inner = self.operand(pos + 1)
            self.depth -= 1
            return end, Unary("neg" if c == "-" else "pos", inner)
        if c in _LETTERS:
            return self.function(pos)
        raise self.error(f"unexpected {c!r} in expression", pos)

    def expect(self, pos: int, char: str, message: str) -> int:
        pos = skip_blanks(self.text, pos)
        if pos >= len(self.text) or self.text[pos] != char:
            raise self.error(message, pos)
        return pos + 1

    def number(self, pos: int, sign: float) -> tuple[int, Expr]:
        text, start = self.text, pos
        pos = decimal_end(text, pos)
        digits = text[start:pos]
        if digits == ".":
            raise self.error("number expected", start)
        return pos, Num(sign * float(digits))

    def variable(self, pos: int) -> tuple[int, Expr]:
        text = self.text
        start = pos
        pos = skip_blanks(text, pos + 1)
        if pos >= len(text):
            raise self.error("variable number expected after '#'", pos)
        c = text[pos]
        if c in _DIGITS:
            end = pos
            while end < len(text) and text[end] in _DIGITS:
                end += 1
            if end < len(text) and text[end] == ".":
                raise self.error("a variable number has no decimal point", end)
            return end, Var(Num(float(text[pos:end])))
        if c == "[":
            self.open_bracket(pos)
            end, index = self.expression(pos + 1)
            end = self.expect(end, "]", "']' expected")
            self.close_bracket()
            return end, Var(index)
        if c == "<" and self.sp.named_variables:
            end = pos + 1
            while end < len(text) and text[end] in _NAME_CHARS:
                end += 1
            if end == pos + 1 or end >= len(text) or text[end] != ">":
                raise self.error("named parameter expected: #<name> with letters, digits and _", end)
            return end + 1, Var(name=text[pos + 1:end].lower())
        if c == "#" and self.sp.double_hash:
            self.deeper(pos)
            end, inner = self.variable(pos)
            self.depth -= 1
            return end, Var(inner)
        raise self.error("variable number expected after '#'", start + 1)

    def function(self, pos: int) -> tuple[int, Expr]:
        text, sp = self.text, self.sp
        end = pos
        while end < len(text) and text[end] in _LETTERS:
            end += 1
        word = text[pos:end].upper()
        bracket = skip_blanks(text, end)
        if bracket >= len(text) or text[bracket] != "[":
            if word in sp.functions or word == "ATAN" or word in sp.binary_functions:
                raise self.error(f"'[' expected after {word}", bracket)
            raise self.error(f"unknown function {text[pos:end]!r}", pos)
        if word == "ATAN" and (sp.atan1 or sp.atan2):
            return self.atan(bracket, pos)
        if word in sp.binary_functions:
            self.open_bracket(bracket)
            after, a = self.expression(bracket + 1)
            after = self.expect(after, ",", f"',' expected in {word}[a,b]")
            after, b = self.expression(after)
            after = self.expect(after, "]", "']' expected")
            self.close_bracket()
            return after, Binary(sp.binary_functions[word], a, b)
        name = sp.word_functions.get(word) if self.in_word else None
        name = name or sp.functions.get(word)
        if name is None:
            raise self.error(f"unknown function {text[pos:end]!r}", pos)
        self.open_bracket(bracket)
        if name == "exists":
            after, arg = self.operand(bracket + 1)
            if not isinstance(arg, Var):
                raise self.error("EXISTS needs a parameter: EXISTS[#<name>]", bracket + 1)
        else:
            after, arg = self.expression(bracket + 1)
        after = self.expect(after, "]", "']' expected")
        self.close_bracket()
        return after, Func(name, [arg])

    def atan(self, bracket: int, start: int) -> tuple[int, Expr]:
        sp, text = self.sp, self.text
        self.open_bracket(bracket)
        pos, y = self.expression(bracket + 1)
        pos = skip_blanks(text, pos)
        if pos < len(text) and text[pos] == "," and sp.atan2 and sp.binary_functions:
            pos, x = self.expression(pos + 1)  # Fanuc 30i: ATAN[y,x]
            pos = self.expect(pos, "]", "']' expected")
            self.close_bracket()
            return pos, Func(sp.atan2, [y, x])
        pos = self.expect(pos, "]", "']' expected")
        self.close_bracket()
        slash = skip_blanks(text, pos)
        if slash < len(text) and text[slash] == "/" and sp.atan2:
            br = skip_blanks(text, slash + 1)
            if br >= len(text) or text[br] != "[":
                raise self.error("'[' expected after ATAN[..]/", br)
            self.open_bracket(br)
            pos, x = self.expression(br + 1)
            pos = self.expect(pos, "]", "']' expected")
            self.close_bracket()
            return pos, Func(sp.atan2, [y, x])
        if sp.atan1 is None:
            raise self.error("ATAN needs two arguments: ATAN[y]/[x]", slash)
        return pos, Func(sp.atan1, [y])


def parse_expr(text: str, pos: int, spelling: ExprSpelling, brackets: int = 0) -> tuple[int, Expr]:
    """Read a full expression (operators included) starting at ``pos``; returns the end and the tree.

    ``brackets`` is the nesting the caller already opened (``IF [`` counts 1 toward Fanuc's 5)."""
    return shallow(pos, _Parser(text, spelling, in_word=False, brackets=brackets).expression(pos))


def parse_word_value(text: str, pos: int, spelling: ExprSpelling) -> tuple[int, Expr]:
    """Read what follows an address: a number, ``#n``, ``-#n``, ``#<name>``, ``[expr]``, ``-[expr]``
    (and, in LinuxCNC, a function such as ``SIN[30]``). No binary operator at the top level."""
    p = _Parser(text, spelling, in_word=True)
    start = skip_blanks(text, pos)
    if start < len(text) and text[start] in _LETTERS and not spelling.functions_as_word_values:
        raise ExprSyntaxError("a value, '#' or '[' expected", start)
    return shallow(pos, p.operand(pos))


def parse_condition(text: str, pos: int, spelling: ExprSpelling) -> tuple[int, Expr]:
    """Read a bracketed condition ``[expr]`` (``IF [..]``, ``WHILE [..]``); returns the inner tree."""
    start = skip_blanks(text, pos)
    if start >= len(text) or text[start] != "[":
        raise ExprSyntaxError("'[' expected", start)
    p = _Parser(text, spelling, in_word=False)
    p.open_bracket(start)
    end, cond = shallow(start, p.expression(start + 1))
    end = p.expect(end, "]", "']' expected")
    return end, cond


def shallow(pos: int, parsed: tuple[int, Expr]) -> tuple[int, Expr]:
    """``parsed`` (an expression read from ``pos``) if it is at most ``MAX_XML_DEPTH`` levels deep, counting
    each operator of a chain (``postproc.ir.expr.nests_deeper``); else a located error. Every reader's
    expressions pass here."""
    if nests_deeper(parsed[1]):
        raise ExprSyntaxError(f"expression nested deeper than {MAX_XML_DEPTH} levels (each operator of a chain "
                              "counts one)", pos)
    return parsed


# ----------------------------------------------------------------------------------------- writing


def spell_number(value: float) -> str:
    """Shortest decimal spelling with an explicit point and no exponent: ``2.``, ``-0.5``, ``0.1``."""
    if value != value or value in (float("inf"), float("-inf")):
        raise UnsupportedError(f"{value!r} cannot be written as a number")
    from decimal import Decimal  # imported when an expression is written, not by every start
    text = format(Decimal(repr(value)), "f")
    if "." not in text:
        return text + "."
    text = text.rstrip("0")
    if text.startswith("-0.") and text == "-0.":
        return "0."
    return text


def _ends_in_one_argument_atan(e: Expr) -> bool:
    """True when ``e`` is written ending in a one-argument ``ATAN[..]`` (its rightmost operand, through a
    sign: ``-ATAN[a]/b`` reads as the two-argument form too)."""
    while isinstance(e, (Binary, Unary)):
        e = e.right if isinstance(e, Binary) else e.operand
    return isinstance(e, Func) and len(e.args) == 1 and e.name.startswith("atan")


class _Writer:
    __slots__ = ("sp", "in_word", "max_brackets")

    def __init__(self, sp: ExprSpelling, in_word: bool) -> None:
        self.sp = sp
        self.in_word = in_word
        self.max_brackets = 0

    def spell(self, e: Expr, min_prec: int, brackets: int, leading: bool) -> str:
        """``e`` as operand of an operator of precedence ``min_prec`` (-1: at the top). ``leading``:
        nothing is written before it (so a sign needs no bracket)."""
        if isinstance(e, Binary):
            binary = self.sp.spell_binary(e.op)
            if binary is None:
                for word, op in self.sp.binary_functions.items():
                    if op == e.op:
                        inner = (self.spell(e.left, -1, brackets + 1, True) + ","
                                 + self.spell(e.right, -1, brackets + 1, True))
                        return self.bracketed(word, inner, brackets)
                raise UnsupportedError(f"{self.sp.name} has no operator for {e.op!r}")
            word, prec = binary
            wrap = prec <= min_prec
            inner_brackets = brackets + 1 if wrap else brackets
            left = self.spell(e.left, prec - 1, inner_brackets, leading or wrap)
            right = self.spell(e.right, prec, inner_brackets, False)
            if word == "/" and _ends_in_one_argument_atan(e.left):
                left = self.bracketed("", left, inner_brackets)  # ATAN[a]/.. reads as the two-argument form
            sep = f" {word} " if word[0].isalpha() else word
            text = left + sep + right
            return self.bracketed("", text, brackets) if wrap else text
        if isinstance(e, Num):
            text = spell_number(e.value)
            if text.startswith("-") and not leading:
                return self.bracketed("", text, brackets)
            return text
        if isinstance(e, Var):
            return self.var(e, brackets)
        if isinstance(e, Unary):
            if e.op == "not":
                raise UnsupportedError(f"{self.sp.name} has no operator for 'not'")
            sign = "-" if e.op == "neg" else "+"
            operand = e.operand
            if isinstance(operand, (Binary, Unary)) or (isinstance(operand, Num)):
                inner = sign + self.bracketed("", self.spell(operand, -1, brackets + 1, True), brackets)
            else:
                inner = sign + self.spell(operand, 99, brackets, False)
            return inner if leading else self.bracketed("", inner, brackets)
        if isinstance(e, Func):
            return self.func(e, brackets)
        raise UnsupportedError(f"cannot write {type(e).__name__}")

    def bracketed(self, word: str, inner: str, brackets: int) -> str:
        self.max_brackets = max(self.max_brackets, brackets + 1)
        return f"{word}[{inner}]"

    def var(self, e: Var, brackets: int) -> str:
        if e.name is not None:
            if not self.sp.named_variables:
                raise UnsupportedError(f"{self.sp.name} has no named variables (#<{e.name}>)")
            if not e.name or not _NAME_CHARS.issuperset(e.name):
                # the reader's rule read the other way: another dialect's name (ISG V.L.X) is no such name
                raise UnsupportedError(f"{self.sp.name} names a variable with letters, digits and _ only, not "
                                       f"{e.name!r}")
            return f"#<{e.name}>"
        assert e.index is not None
        if isinstance(e.index, Num) and e.index.value.is_integer() and e.index.value >= 0:
            number = int(e.index.value)
            bounds = self.sp.parameters
            if bounds is not None and not bounds[0] <= number <= bounds[1]:
                raise UnsupportedError(f"{self.sp.name} has no #{number} (its parameters are #{bounds[0]}-"
                                       f"#{bounds[1]})")
            return f"#{number}"
        return "#" + self.bracketed("", self.spell(e.index, -1, brackets + 1, True), brackets)

    def function_word(self, name: str) -> str | None:
        """The word for a one-argument function here; a word that means something else inside an
        NC word (Fanuc ROUND) cannot spell the statement meaning there, nor the word meaning outside."""
        sp = self.sp
        if name == sp.atan1:
            return "ATAN"
        if self.in_word:
            for special, neutral in sp.word_functions.items():
                if neutral == name:
                    return special
        word = sp.spell_function(name)
        if word is not None and self.in_word and word in sp.word_functions:
            return None
        return word

    def func(self, e: Func, brackets: int) -> str:
        sp = self.sp
        if len(e.args) == 2:
            if e.name != sp.atan2:
                raise UnsupportedError(f"{sp.name} has no function for {e.name!r}")
            y = self.bracketed("ATAN", self.spell(e.args[0], -1, brackets + 1, True), brackets)
            x = self.bracketed("", self.spell(e.args[1], -1, brackets + 1, True), brackets)
            return f"{y}/{x}"
        word = self.function_word(e.name)
        if word is None:
            where = ""
            if e.name in sp.word_functions.values():
                where = " outside an NC word"
            elif self.in_word and e.name in sp.functions.values():
                where = " inside an NC word"
            raise UnsupportedError(f"{sp.name} has no function for {e.name!r}{where}")
        return self.bracketed(word, self.spell(e.args[0], -1, brackets + 1, True), brackets)


def _check_depth(w: _Writer, text: str) -> str:
    if w.max_brackets > w.sp.max_brackets:
        raise UnsupportedError(f"{text} nests brackets {w.max_brackets} deep; {w.sp.name} allows "
                               f"{w.sp.max_brackets}{w.sp.max_brackets_note}")
    return text


def spell_expr(expr: Expr, spelling: ExprSpelling, brackets: int = 0) -> str:
    """``expr`` as a statement's right-hand side (``#3=`` + this), bracketed where the dialect needs it
    (LinuxCNC brackets every binary expression: ``[#1+2.]``; Fanuc writes ``#1+2.``). Raises
    ``UnsupportedError`` for an operator or function the dialect lacks, or nesting it refuses."""
    w = _Writer(spelling, in_word=False)
    if isinstance(expr, Binary) and not spelling.bare_binary:
        text = w.bracketed("", w.spell(expr, -1, brackets + 1, True), brackets)
    else:
        text = w.spell(expr, -1, brackets, True)
    return _check_depth(w, text)


def spell_condition(expr: Expr, spelling: ExprSpelling) -> str:
    """``[cond]`` for ``IF``/``WHILE``."""
    w = _Writer(spelling, in_word=False)
    return _check_depth(w, w.bracketed("", w.spell(expr, -1, 1, True), 0))


def spell_word_value(expr: Expr, spelling: ExprSpelling) -> str:
    """What follows an address: ``2.``, ``#1``, ``-#1``, ``#<x>``, or ``[expr]`` / ``-[expr]``."""
    w = _Writer(spelling, in_word=True)
    if isinstance(expr, (Num, Var)) or (isinstance(expr, Unary) and isinstance(expr.operand, Var)):
        text = w.spell(expr, -1, 0, True)
    elif isinstance(expr, Func) and spelling.functions_as_word_values:
        text = w.spell(expr, -1, 0, True)
    elif isinstance(expr, Unary) and expr.op == "neg":
        text = "-" + w.bracketed("", w.spell(expr.operand, -1, 1, True), 0)
    else:
        text = w.bracketed("", w.spell(expr, -1, 1, True), 0)
    return _check_depth(w, text)
