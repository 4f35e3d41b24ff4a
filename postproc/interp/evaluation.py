"""Evaluation of expression trees, with the vacancy rules of each dialect family.

Every neutral operator and function has one semantics (``postproc.ir.expr``); this module is where it is
defined. What was verified, and how ("rs274" = run through ``/usr/bin/rs274``, LinuxCNC 2.9.0~pre1 as
packaged in Debian 12, with ``(DEBUG, #1)``, pinned in ``tests/test_evaluate.py``; "src" = LinuxCNC
source ``interp_execute.cc``/``interp_read.cc``/``interp_internal.cc``; "[K]" = Fanuc manual facts from
background knowledge and public pages, not checked on a control; "[?]" uncertain):

=================  =========================================================  ==============
neutral            semantics                                                  source
=================  =========================================================  ==============
add sub mul        IEEE double                                                rs274, [K]
div                x/y; y == 0 is an error                                    src, [K] alarm
pow                x**y; x < 0 with a non-integral y is an error               src, rs274
mod_pos            LinuxCNC MOD: fmod(x, y), + |y| if negative (-7 MOD 3 = 2,  rs274, src
                   7 MOD -3 = 1); y == 0 is an error (rs274 refuses it)
rem_int            Fanuc MOD: x, y rounded to integers, remainder with x's     [K]/[?]
                   sign; y == 0 is an error
fmod               C fmod on the reals, the dividend's sign; y == 0 is an     ISG MOD [?]
                   error
eq ne              exact equality (Fanuc: "the same as subtraction")          [K] 15i manual
gt ge lt le        exact (LinuxCNC 2.9.0 GE/LE too: 1 LE 0.9999995 is 0)      rs274, [K]
eq_tol ne_tol      LinuxCNC EQ/NE: equal when |x-y| < 1e-4                    rs274 (master
                   (1 EQ 1.00005 is 1, 1 EQ 1.0002 is 0)                      uses 1e-6)
and or xor         logical: non-zero is true, result 1 or 0 (2 AND 3 = 1)     rs274, src
bitand bitor       Fanuc AND OR XOR: bit by bit on non-negative integers      [K]; non-integers
bitxor                                                                         refused
neg pos not        -x, +x, 1 if x == 0 else 0                                 -
sin cos tan        degrees, computed as the environment's ``Arithmetic`` says     src, rs274
                   (below)
asin acos          degrees, -90..90 and 0..180; |x| > 1 is an error            src, rs274
atan               one argument, -90..90                                      -
atan2              ATAN[y]/[x] in LinuxCNC: -180..180 (ATAN[-1]/[-1] = -135)   rs274, src
atan2_360          Fanuc ATAN[y]/[x] (parameter 6004#0 NAT=0): 0..360          [K]
asin_360 atan_360  Fanuc ASIN / one-argument ATAN with NAT=0: a negative       [K]/[?]
                   result + 360 (270..90)
sqrt               x < 0 is an error                                          src
abs exp            -                                                          src
ln                 x <= 0 is an error                                         src
round              half away from zero (ROUND[-2.5] = -3); under X86_64_C     rs274, [K]
                   through a C int: beyond it an error (rs274 gives
                   -2147483648 for ROUND[3e9])
round_address      Fanuc ROUND inside an NC word: to the least input          [K] (Haas doc
                   increment (``Env.increment``), half away from zero         of Fanuc syntax)
trunc away         Fanuc FIX / FUP: toward / away from zero                   [K]
floor ceil         LinuxCNC FIX / FUP (FIX[-1.5] = -2, FUP[-1.5] = -1)        rs274, src
fract sqr          x - trunc(x); x*x                                           ISG FRACT SQR
exp10 log10        10**x; decimal logarithm, x <= 0 is an error                ISG DEXP LOG
bcd bin            binary -> BCD (BCD[25] = 37) and back; non-negative        [K]
                   integers only, a BIN digit above 9 is an error
whole_in           x if a whole number in low..high, else an error (how a      ISG manual [V]
                   controller converts into an integer type: not published)   types, [?]
exists             1 if the variable exists, by the environment's rule        rs274, src,
                   (``Env.exists``: LinuxCNC EXISTS[#<x>], a numbered one     ISG manual
                   always exists; ISG EXIST[V.P.x], declared or set)
=================  =========================================================  ==============

Precedence and unary minus belong to the spellings (``postproc.rs274.expressions``).

Arithmetic (``Env.arithmetic``, the dialect family's): ``DOUBLE`` computes ``sin(x * pi / 180)`` and
``asin(x) * 180 / pi`` in IEEE double (Fanuc [K]: IEEE double with the trigonometric functions'
absolute error guaranteed, not their relative error; ISG and Fagor [?]: not published, chosen so).
``X86_64_C`` is rs274's C on x86-64: ``sin((x * M_PIl) / 180.0)`` with the argument in ``long double``,
the inverse functions' double result times 180.0 divided by ``M_PIl`` (src; ``postproc.interp.long_double``),
so ``SIN[180]`` is -5.0e-20 (``FIX[SIN[180]]`` = -1) and ``COS[90] LT 0`` is 1 (rs274). SIN, COS, ASIN,
ACOS and ATAN agree bit for bit with the packaged rs274 and glibc; TAN is the correctly rounded
``tanl``, which glibc's misses by one unit in the last place in about 1 case in 20,000 (TAN[271] among
them: ``tests/test_long_double.py``).

Vacancy (``Vacancy.NULL``): a ``Var`` evaluates to None when vacant (so ``#2=#1`` copies vacancy, and
a word whose value is None is omitted); every operator and function reads None as 0 (``#1*5``,
``#1+#1`` and ``-#1`` are 0), except ``eq``/``ne``, which tell vacant from 0 (``#1 EQ #0`` is true,
``#1 EQ 0`` false). ``Vacancy.ZERO``: an unset numbered parameter reads 0, an unset named one is
an error. Results are never None except for a bare variable; NaN and infinities are refused.
"""

from __future__ import annotations

import math
from typing import Callable

from . import long_double
from ..ir.expr import Arithmetic, Binary, Env, EvalError, Expr, Func, Num, Unary, Vacancy, Value, Var, VarKey

TOLERANCE_EQUAL = 1e-4
"""LinuxCNC 2.9.0's tolerance for EQ/NE (``eq_tol``/``ne_tol``)."""

INTEGER_TOLERANCE = 1e-4
"""LinuxCNC accepts a real as an integer (a parameter number) within this distance (read_integer_value)."""


def evaluate(expr: Expr, env: Env) -> Value:
    """The value of ``expr``: a float, or None for a vacant variable read bare (Fanuc only)."""
    if isinstance(expr, Num):
        return expr.value
    if isinstance(expr, Var):
        return _read(expr, env)
    if isinstance(expr, Binary):
        return _binary(expr, env)
    if isinstance(expr, Unary):
        v = _num(evaluate(expr.operand, env))
        if expr.op == "neg":
            return -v
        if expr.op == "pos":
            return v
        return 1.0 if v == 0.0 else 0.0
    if isinstance(expr, Func):
        return _func(expr, env)
    raise EvalError(f"cannot evaluate {type(expr).__name__}")


def evaluate_number(expr: Expr, env: Env, what: str = "a value") -> float:
    """Like ``evaluate`` but a vacant result is an error (``what`` names what needed the value)."""
    v = evaluate(expr, env)
    if v is None:
        raise EvalError(f"{describe(expr)} is vacant where {what} is required")
    return v


def var_key(var: Var, env: Env) -> VarKey:
    """The identity of ``var``: its name, or its number once the index expression is evaluated.

    Fanuc rounds a real index to the nearest integer; LinuxCNC accepts it within 1e-4 of one. Whether
    the number is a variable the program may use is the environment's business (``Env.read``)."""
    if var.name is not None:
        return var.name
    assert var.index is not None
    if isinstance(var.index, Num) and var.index.value.is_integer():
        return int(var.index.value)  # the common case: #12
    value = evaluate(var.index, env)
    if value is None:
        raise EvalError(f"the variable number in {describe(var)} is vacant")
    if env.vacancy is Vacancy.NULL:
        return int(_round_half_away(value))
    nearest = round(value)
    if abs(value - nearest) > INTEGER_TOLERANCE:
        raise EvalError(f"the variable number in {describe(var)} is not an integer ({value:g})")
    return int(nearest)


def _read(var: Var, env: Env) -> Value:
    key = var_key(var, env)
    value = env.read(key)
    if value is None and env.vacancy is Vacancy.ZERO:
        if isinstance(key, str):
            raise EvalError(f"named parameter #<{key}> is not defined")
        return 0.0
    return value


def _num(v: Value) -> float:
    return 0.0 if v is None else v


def _binary(expr: Binary, env: Env) -> float:
    op = expr.op
    a = evaluate(expr.left, env)
    b = evaluate(expr.right, env)
    if op in ("eq", "ne"):
        same = a == b  # None == None; None != 0.0
        return 1.0 if same == (op == "eq") else 0.0
    x, y = _num(a), _num(b)
    fn = _BINARY.get(op)
    if fn is None:
        raise EvalError(f"unknown operator {op!r}")
    return _finite(fn(x, y, expr), expr)


def _div(x: float, y: float, e: Expr) -> float:
    if y == 0.0:
        raise EvalError(f"division by zero in {describe(e)}")
    return x / y


def _pow(x: float, y: float, e: Expr) -> float:
    if x < 0.0 and not y.is_integer():
        raise EvalError(f"negative number raised to a non-integer power in {describe(e)}")
    if x == 0.0 and y < 0.0:
        raise EvalError(f"division by zero in {describe(e)}")
    try:
        return math.pow(x, y)
    except OverflowError:
        raise EvalError(f"the result of {describe(e)} is too large") from None


def _mod_pos(x: float, y: float, e: Expr) -> float:
    if y == 0.0:
        raise EvalError(f"division by zero in {describe(e)}")
    r = math.fmod(x, y)
    return r + abs(y) if r < 0.0 else r


def _rem_int(x: float, y: float, e: Expr) -> float:
    xi, yi = _round_half_away(x), _round_half_away(y)
    if yi == 0.0:
        raise EvalError(f"division by zero in {describe(e)}")
    return math.fmod(xi, yi)


def _fmod(x: float, y: float, e: Expr) -> float:
    if y == 0.0:
        raise EvalError(f"division by zero in {describe(e)}")
    return math.fmod(x, y)


def _bits(x: float, e: Expr) -> int:
    if not x.is_integer() or x < 0.0:
        raise EvalError(f"{describe(e)} needs non-negative integers, not {x:g}")
    return int(x)


def _bool(flag: bool) -> float:
    return 1.0 if flag else 0.0


_BINARY: dict[str, Callable[[float, float, Expr], float]] = {
    "add": lambda x, y, e: x + y,
    "sub": lambda x, y, e: x - y,
    "mul": lambda x, y, e: x * y,
    "div": _div,
    "pow": _pow,
    "mod_pos": _mod_pos,
    "rem_int": _rem_int,
    "fmod": _fmod,
    "gt": lambda x, y, e: _bool(x > y),
    "ge": lambda x, y, e: _bool(x >= y),
    "lt": lambda x, y, e: _bool(x < y),
    "le": lambda x, y, e: _bool(x <= y),
    "eq_tol": lambda x, y, e: _bool(abs(x - y) < TOLERANCE_EQUAL),
    "ne_tol": lambda x, y, e: _bool(abs(x - y) >= TOLERANCE_EQUAL),
    "and": lambda x, y, e: _bool(x != 0.0 and y != 0.0),
    "or": lambda x, y, e: _bool(x != 0.0 or y != 0.0),
    "xor": lambda x, y, e: _bool((x != 0.0) != (y != 0.0)),
    "bitand": lambda x, y, e: float(_bits(x, e) & _bits(y, e)),
    "bitor": lambda x, y, e: float(_bits(x, e) | _bits(y, e)),
    "bitxor": lambda x, y, e: float(_bits(x, e) ^ _bits(y, e)),
}


def _func(expr: Func, env: Env) -> float:
    name = expr.name
    if name == "exists":
        arg = expr.args[0]
        if not isinstance(arg, Var):
            raise EvalError(f"{describe(expr)} needs a variable")
        return _bool(env.exists(var_key(arg, env)))
    values = [_num(evaluate(a, env)) for a in expr.args]
    if name == "round_address":
        return _finite(_round_to_increment(values[0], env.increment), expr)
    fn = _ARITHMETIC_FUNCTIONS[env.arithmetic].get(name)
    if fn is None:
        raise EvalError(f"unknown function {name!r}")
    return _finite(fn(values, expr), expr)


def _deg(r: float) -> float:
    return r * 180.0 / math.pi


def _rad(d: float) -> float:
    return d * math.pi / 180.0


def _unit_range(x: float, e: Expr) -> float:
    if x < -1.0 or x > 1.0:
        raise EvalError(f"the argument of {describe(e)} is outside -1..1 ({x:g})")
    return x


def _plus360(d: float) -> float:
    return d + 360.0 if d < 0.0 else d


def _sqrt(x: float, e: Expr) -> float:
    if x < 0.0:
        raise EvalError(f"square root of a negative number in {describe(e)} ({x:g})")
    return math.sqrt(x)


def _ln(x: float, e: Expr) -> float:
    if x <= 0.0:
        raise EvalError(f"logarithm of a number that is not positive in {describe(e)} ({x:g})")
    return math.log(x)


def _exp(x: float, e: Expr) -> float:
    try:
        return math.exp(x)
    except OverflowError:
        raise EvalError(f"the result of {describe(e)} is too large") from None


def _round_half_away(x: float) -> float:
    return float(math.floor(abs(x) + 0.5)) * (1.0 if x >= 0.0 else -1.0)


def _round_to_increment(x: float, inc: float) -> float:
    """Half away from zero on the decimal spelling (-1.0005 -> -1.001 at 0.001, which binary
    division would get wrong: -1.0005/0.001 = -1000.4999...). ``decimal`` is imported here, where it is used: the
    module is loaded by the structure check of every program with a program number, and ``decimal`` cost that
    ~1 ms of start-up (``python -X importtime``)."""
    from decimal import ROUND_HALF_UP, Decimal
    steps = (Decimal(repr(x)) / Decimal(repr(inc))).quantize(Decimal(1), rounding=ROUND_HALF_UP)
    return float(steps * Decimal(repr(inc)))


def _away(x: float) -> float:
    return float(math.ceil(x)) if x >= 0.0 else float(math.floor(x))


def _bcd(x: float, e: Expr) -> float:
    n = _bits(x, e)
    out, shift = 0, 0
    while n:
        out |= (n % 10) << shift
        n //= 10
        shift += 4
    return float(out)


def _bin(x: float, e: Expr) -> float:
    n = _bits(x, e)
    out, scale = 0, 1
    while n:
        digit = n & 0xF
        if digit > 9:
            raise EvalError(f"{describe(e)}: {x:g} is not a BCD number")
        out += digit * scale
        n >>= 4
        scale *= 10
    return float(out)


_FUNCTIONS: dict[str, Callable[[list[float], Expr], float]] = {
    "sin": lambda v, e: math.sin(_rad(v[0])),
    "cos": lambda v, e: math.cos(_rad(v[0])),
    "tan": lambda v, e: math.tan(_rad(v[0])),
    "asin": lambda v, e: _deg(math.asin(_unit_range(v[0], e))),
    "asin_360": lambda v, e: _plus360(_deg(math.asin(_unit_range(v[0], e)))),
    "acos": lambda v, e: _deg(math.acos(_unit_range(v[0], e))),
    "atan": lambda v, e: _deg(math.atan(v[0])),
    "atan_360": lambda v, e: _plus360(_deg(math.atan(v[0]))),
    "atan2": lambda v, e: _deg(math.atan2(v[0], v[1])),
    "atan2_360": lambda v, e: _plus360(_deg(math.atan2(v[0], v[1]))),
    "sqrt": lambda v, e: _sqrt(v[0], e),
    "abs": lambda v, e: abs(v[0]),
    "round": lambda v, e: _round_half_away(v[0]),
    "trunc": lambda v, e: float(math.trunc(v[0])),
    "away": lambda v, e: _away(v[0]),
    "floor": lambda v, e: float(math.floor(v[0])),
    "ceil": lambda v, e: float(math.ceil(v[0])),
    "ln": lambda v, e: _ln(v[0], e),
    "exp": lambda v, e: _exp(v[0], e),
    "bcd": lambda v, e: _bcd(v[0], e),
    "bin": lambda v, e: _bin(v[0], e),
    "fract": lambda v, e: v[0] - float(math.trunc(v[0])),
    "sqr": lambda v, e: v[0] * v[0],
    "exp10": lambda v, e: _exp10(v[0], e),
    "log10": lambda v, e: _log10(v[0], e),
    "whole_in": lambda v, e: _whole_in(v[0], v[1], v[2]),
}


def _whole_in(x: float, low: float, high: float) -> float:
    if not x.is_integer() or not low <= x <= high:
        raise EvalError(f"{x:.15g} does not fit the variable's type (whole numbers {low:.0f} to {high:.0f}): "
                        f"how the controller converts it is not known")
    return x


def _round_c_int(x: float, e: Expr) -> float:
    """rs274's ROUND, ``(double)(int)(x + (x < 0 ? -0.5 : 0.5))`` (src): the sum in double, then a C
    ``int``. Beyond an int x86-64 gives -2147483648 (rs274: ROUND[3e9]); that is refused, not copied."""
    shifted = x + (-0.5 if x < 0.0 else 0.5)
    if not -2147483649.0 < shifted < 2147483648.0:
        raise EvalError(f"{describe(e)} is beyond the C int that LinuxCNC rounds through ({x:g})")
    return float(math.trunc(shifted))


_X86_64_C: dict[str, Callable[[list[float], Expr], float]] = {
    "sin": lambda v, e: long_double.sin_deg(v[0]),
    "cos": lambda v, e: long_double.cos_deg(v[0]),
    "tan": lambda v, e: long_double.tan_deg(v[0]),
    "asin": lambda v, e: long_double.degrees(math.asin(_unit_range(v[0], e))),
    "acos": lambda v, e: long_double.degrees(math.acos(_unit_range(v[0], e))),
    "atan2": lambda v, e: long_double.degrees(math.atan2(v[0], v[1])),
    "round": lambda v, e: _round_c_int(v[0], e),
}
"""What ``Arithmetic.X86_64_C`` computes differently from IEEE double (the rest is the same)."""

_ARITHMETIC_FUNCTIONS: dict[Arithmetic, dict[str, Callable[[list[float], Expr], float]]] = {
    Arithmetic.DOUBLE: _FUNCTIONS,
    Arithmetic.X86_64_C: {**_FUNCTIONS, **_X86_64_C},
}


def _exp10(x: float, e: Expr) -> float:
    try:
        return math.pow(10.0, x)
    except OverflowError:
        raise EvalError(f"the result of {describe(e)} is too large") from None


def _log10(x: float, e: Expr) -> float:
    if x <= 0.0:
        raise EvalError(f"logarithm of a number that is not positive in {describe(e)} ({x:g})")
    return math.log10(x)


def _finite(v: float, e: Expr) -> float:
    if math.isnan(v) or math.isinf(v):
        raise EvalError(f"the result of {describe(e)} is not a finite number")
    return v


_NOT_CONSTANT = frozenset(("exists", "round_address"))
"""Functions whose value depends on the run even with constant arguments (a variable's existence, the
least input increment of the units in force)."""


def certain_failure(expr: Expr) -> EvalError | None:
    """The error a part of ``expr`` made of constants raises wherever and whenever it runs (``1/0``,
    ``SQRT[-4]``, ``LN[2-2]``, ``#[1/0]``), found by folding the constants bottom up; None if none does.
    A part that reads a variable is not folded: its value is known only when it runs."""
    found = _fold(expr)
    return found if isinstance(found, EvalError) else None


_DIVISIONS = frozenset(("div", "mod_pos", "rem_int", "fmod"))
"""Operators that fail for every dividend when the divisor is 0 (``#1/0``)."""
_Folded = float | None | EvalError
"""The value of a constant part, None for a part that reads a variable, or the error it raises."""


def _fold(expr: Expr) -> _Folded:
    if isinstance(expr, Num):
        return expr.value
    if isinstance(expr, Var):
        index = _fold(expr.index) if expr.index is not None else None
        return index if isinstance(index, EvalError) else None
    parts = [expr.operand] if isinstance(expr, Unary) else [expr.left, expr.right] if isinstance(expr, Binary) \
        else list(expr.args) if isinstance(expr, Func) else []
    constant = True
    folded: _Folded = None
    for part in parts:
        folded = _fold(part)
        if isinstance(folded, EvalError):
            return folded
        constant = constant and folded is not None
    if isinstance(expr, Binary) and expr.op in _DIVISIONS and folded == 0.0:
        return _division_by_zero(expr)
    if not constant or not parts or (isinstance(expr, Func) and expr.name in _NOT_CONSTANT):
        return None
    try:
        return evaluate(expr, _CONSTANTS)
    except EvalError as err:
        return err


_SYMBOLS = {
    "add": "+", "sub": "-", "mul": "*", "div": "/", "pow": "**", "mod_pos": " MOD ", "rem_int": " MOD ",
    "fmod": " MOD ",
    "eq": " EQ ", "ne": " NE ", "gt": " GT ", "ge": " GE ", "lt": " LT ", "le": " LE ", "eq_tol": " EQ ",
    "ne_tol": " NE ", "and": " AND ", "or": " OR ", "xor": " XOR ", "bitand": " AND ", "bitor": " OR ",
    "bitxor": " XOR ",
}


def describe(expr: Expr) -> str:
    """A short RS274-like text of ``expr`` for messages (``#1/#2``, ``SQRT[#1]``), fully bracketed
    below the top level. Dialect writers use ``postproc.rs274.expressions.spell_expr`` instead."""
    return _describe(expr, top=True)


def _describe(expr: Expr, top: bool = False) -> str:
    if isinstance(expr, Num):
        return f"{expr.value:g}"
    if isinstance(expr, Var):
        if expr.name is not None:
            return f"#<{expr.name}>"
        assert expr.index is not None
        if isinstance(expr.index, Num):
            return "#" + _describe(expr.index)
        return f"#[{_describe(expr.index, True)}]"
    if isinstance(expr, Unary):
        sign = {"neg": "-", "pos": "+", "not": "NOT "}[expr.op]
        return sign + _describe(expr.operand)
    if isinstance(expr, Binary):
        text = _describe(expr.left) + _SYMBOLS[expr.op] + _describe(expr.right)
        return text if top else f"[{text}]"
    if isinstance(expr, Func):
        name = expr.name.split("_")[0].upper()
        if len(expr.args) > 2:
            return f"{name}[{', '.join(_describe(a, True) for a in expr.args)}]"
        if len(expr.args) == 2:
            return f"{name}[{_describe(expr.args[0], True)}]/[{_describe(expr.args[1], True)}]"
        return f"{name}[{_describe(expr.args[0], True)}]"
    return type(expr).__name__



class MappingEnv:
    """An ``Env`` over a plain dict (tests): a missing key has no value, read by the vacancy rule the caller
    names (no family's rule is the default)."""

    __slots__ = ("values", "_vacancy", "_increment", "_arithmetic")

    def __init__(self, values: dict[VarKey, float] | None, vacancy: Vacancy,
                 increment: float = 0.001, arithmetic: Arithmetic = Arithmetic.DOUBLE) -> None:
        self.values: dict[VarKey, float] = dict(values or {})
        self._vacancy = vacancy
        self._increment = increment
        self._arithmetic = arithmetic

    @property
    def vacancy(self) -> Vacancy:
        return self._vacancy

    @property
    def arithmetic(self) -> Arithmetic:
        return self._arithmetic

    @property
    def increment(self) -> float:
        return self._increment

    def read(self, key: VarKey) -> Value:
        if key == 0 and self._vacancy is Vacancy.NULL:
            return None  # #0 is always vacant
        return self.values.get(key)

    def exists(self, key: VarKey) -> bool:
        """A name exists when it has a value; a number always does (LinuxCNC's rule)."""
        return not isinstance(key, str) or key in self.values


def _division_by_zero(expr: Binary) -> EvalError:
    return EvalError(f"division by zero in {describe(expr)}")


class _Constants:
    """The environment of a constant part (``_fold``): it reads no variable, so no family's vacancy rule is asked
    for; one that were would be a folding error, reported as such rather than read by some family's rule."""

    __slots__ = ()

    @property
    def vacancy(self) -> Vacancy:
        raise EvalError("a constant part has no variables")

    @property
    def arithmetic(self) -> Arithmetic:
        return Arithmetic.DOUBLE

    @property
    def increment(self) -> float:
        return 0.001

    def read(self, key: VarKey) -> Value:
        raise EvalError("a constant part has no variables")

    def exists(self, key: VarKey) -> bool:
        raise EvalError("a constant part has no variables")


_CONSTANTS = _Constants()
