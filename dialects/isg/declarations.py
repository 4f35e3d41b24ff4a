"""ISG's declarations between ``#VAR`` and ``#ENDVAR``, typed or not, and what a simulation does with them.

The manual (ISG/Beckhoff TwinCAT CNC programming manual, "Self-defined variables (#VAR, #ENDVAR,
#DELETE)" [V]): a declaration is ``V.P|S|L|CYC.<name> [: <data type>] [= <initial value> |
"<initial string>"]``, one a line. The data types are BOOLEAN, SGN08, UNS08, SGN16, UNS16, SGN32,
UNS32, REAL64 (the manual's example also writes REAL) and STRING[i] with i from 0 to 126. A variable
declared without an initial value gets its type's (0, FALSE); one without a type is REAL64. Sizes: 1, 2
and 4 bytes (the external-variables manual's table [V]), so the ranges below are those of C's signed and
unsigned integers of that size [K]; a BOOLEAN holds 0 or 1 (the kernel API's union [V]).

Read into the IR:

* REAL, REAL64 or no type: an assignment of the initial value (0 without one);
* BOOLEAN and the integer types: the same through ``whole_in[value, low, high]``: a whole number in the
  type's range is stored, any other value is an error when the program is simulated or flattened (how
  ISG converts one is not published [?]); the reader treats every later assignment to the variable
  the same way (``IsgTypes``);
* STRING: kept verbatim (``NativeCode``, inert: nothing moves), refused by every other dialect by name;
  a STRING variable where a number is needed (an axis value, an assignment) is a located error.

Arrays (``V.P.A[3] = [..]``) and a STRING length computed from parameters (``STRING[P3]``) are not
modelled: the block is kept verbatim and refused elsewhere.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.isg_family.expressions import Unmodelled, parse_expr
from postproc.rs274.expressions import skip_blanks
from postproc.rs274.expressions import ExprSyntaxError

INTEGER_TYPES: dict[str, tuple[int, int]] = {
    "BOOLEAN": (0, 1),
    "SGN08": (-2 ** 7, 2 ** 7 - 1), "UNS08": (0, 2 ** 8 - 1),
    "SGN16": (-2 ** 15, 2 ** 15 - 1), "UNS16": (0, 2 ** 16 - 1),
    "SGN32": (-2 ** 31, 2 ** 31 - 1), "UNS32": (0, 2 ** 32 - 1),
}
"""Each whole-number type and the values it holds."""
REAL_TYPES = frozenset({"REAL64", "REAL"})
STRING_LENGTH = 126
"""The longest ``STRING[i]`` a declaration names."""

_NAME = re.compile(r"[Vv]\.(?:[Pp]|[Ss]|[Ll]|[Cc][Yy][Cc])\.[A-Za-z0-9_]+(?:\.[A-Za-z0-9_]+)*")
_TYPE = re.compile(r"[A-Za-z][A-Za-z0-9]*")
_LENGTH = re.compile(r"\[\s*(\d+)\s*\]")
_STRING = re.compile(r'"[^"]*"')


@dataclass(frozen=True, slots=True)
class Declaration:
    """One declaration: the variable as written, its type in upper case ("" when none) and its initial
    value (an expression, a string literal with its quotes, or None)."""

    name: str
    type: str
    value: Expr | None = None
    string: str | None = None

    @property
    def is_string(self) -> bool:
        return self.type.startswith("STRING")


def parse_declaration(code: str) -> Declaration:
    """The declaration in ``code`` (a line of a ``#VAR`` block, comments blanked). Raises
    ``ExprSyntaxError`` (with the offset) when malformed, ``Unmodelled`` for an array or a computed
    STRING length."""
    pos = skip_blanks(code, 0)
    m = _NAME.match(code, pos)
    if m is None:
        raise ExprSyntaxError("a declaration names a self-defined variable: V.P.<name>, V.S.<name>, "
                              "V.L.<name> or V.CYC.<name>", pos)
    name = m.group()
    pos = skip_blanks(code, m.end())
    if code[pos:pos + 1] == "[":
        raise Unmodelled("V. variable arrays", m.start())
    kind = ""
    if code[pos:pos + 1] == ":":
        pos, kind = _data_type(code, skip_blanks(code, pos + 1))
    value: Expr | None = None
    string: str | None = None
    if code[pos:pos + 1] == "=":
        pos = skip_blanks(code, pos + 1)
        if kind.startswith("STRING"):
            s = _STRING.match(code, pos)
            if s is None:
                raise ExprSyntaxError(f"a {kind} variable starts with a string in double quotes", pos)
            string, pos = s.group(), s.end()
        else:
            pos, value = parse_expr(code, pos)
    pos = skip_blanks(code, pos)
    if pos < len(code.rstrip()):
        raise ExprSyntaxError(f"unexpected {code[pos]!r} after the declaration of {name}", pos)
    return Declaration(name, kind, value, string)


def _data_type(code: str, pos: int) -> tuple[int, str]:
    t = _TYPE.match(code, pos)
    if t is None:
        raise ExprSyntaxError("a data type expected after ':'", pos)
    kind = t.group().upper()
    end = t.end()
    if kind == "STRING":
        at = skip_blanks(code, end)
        length = _LENGTH.match(code, at)
        if length is None:
            if code[at:at + 1] == "[":
                raise Unmodelled("STRING lengths computed from parameters", at)
            raise ExprSyntaxError("STRING needs its length: STRING[<0..126>]", at)
        if int(length.group(1)) > STRING_LENGTH:
            raise ExprSyntaxError(f"a STRING holds at most {STRING_LENGTH} characters", at)
        return skip_blanks(code, length.end()), f"STRING[{int(length.group(1))}]"
    if kind not in INTEGER_TYPES and kind not in REAL_TYPES:
        raise ExprSyntaxError(f"unknown data type {t.group()!r} (BOOLEAN, SGN08, UNS08, SGN16, UNS16, SGN32, "
                              f"UNS32, REAL64, STRING[i])", pos)
    return skip_blanks(code, end), kind


def stored(kind: str, value: Expr) -> Expr:
    """The value as a variable of type ``kind`` stores it: unchanged for a real, checked by ``whole_in``
    for BOOLEAN and the integer types."""
    limits = INTEGER_TYPES.get(kind)
    if limits is None:
        return value
    return Func("whole_in", [value, Num(float(limits[0])), Num(float(limits[1]))])


@dataclass
class IsgTypes:
    """The data types a file has declared so far, by variable name (upper case), with the line."""

    types: dict[str, tuple[str, int]] = field(default_factory=dict)

    def declare(self, declaration: Declaration, line: int) -> None:
        self.types[declaration.name.upper()] = (declaration.type, line)

    def assigned(self, var: Var, value: Expr) -> Expr:
        """A later assignment's value, stored as the variable's type does; a STRING variable refuses a
        number (``ValueError`` with the message)."""
        if var.name is None:
            return value
        found = self.types.get(var.name.upper())
        if found is None:
            return value
        kind, line = found
        if kind.startswith("STRING"):
            raise ValueError(f"{var.name} is a {kind} variable (declared at line {line}): a number cannot be "
                             f"assigned to it")
        return stored(kind, value)

    def string_used(self, expr: Expr) -> str | None:
        """A message when ``expr`` reads a STRING variable, else None: a string has no numeric value, and
        whether one exists (``EXIST``) is not simulated (string variables are kept, not modelled)."""
        for var, tested in _variables(expr):
            found = self.types.get(var.upper())
            if found is not None and found[0].startswith("STRING"):
                if tested:
                    return (f"EXIST[{var}]: {var} is a {found[0]} variable (declared at line {found[1]}), and "
                            f"string variables are not simulated")
                return f"{var} is a {found[0]} variable (declared at line {found[1]}): it has no numeric value"
        return None


def _variables(expr: Expr) -> list[tuple[str, bool]]:
    """The named variables ``expr`` reads, each with True when ``EXIST`` only tests it."""
    out: list[tuple[str, bool]] = []
    stack: list[tuple[Expr, bool]] = [(expr, False)]
    while stack:
        e, tested = stack.pop()
        if isinstance(e, Var):
            if e.name is not None:
                out.append((e.name, tested))
            elif e.index is not None:
                stack.append((e.index, False))
        elif isinstance(e, Unary):
            stack.append((e.operand, False))
        elif isinstance(e, Binary):
            stack += ((e.left, False), (e.right, False))
        elif isinstance(e, Func):
            stack += ((a, e.name == "exists") for a in e.args)
    return out
