"""Expression trees: the neutral nodes a word value, an assignment or a condition is made of.

A tree is built from ``Num``, ``Var``, ``Unary``, ``Binary`` and ``Func``. Each operator and function
name means one exact semantics (listed in ``BINARY_OPS``, ``UNARY_OPS`` and ``FUNCTIONS``); a dialect
maps its own spelling to the neutral name whose semantics match its controller, so the same word
(``FIX``, ``MOD``, ``AND``) may map to different neutral names in different dialects.

XML: ``<Num value="1.5"/>``, ``<Var name="depth"/>`` or ``<Var><Num value="1.0"/></Var>``,
``<Unary op="neg">E</Unary>``, ``<Binary op="add">E E</Binary>``, ``<Func name="sin">E...</Func>``.
Children are read by this module (only expression elements are allowed inside an expression).
"""

from __future__ import annotations

import enum
from typing import TYPE_CHECKING, Any, Protocol, Union

from ..errors import ConfigError, ProgramError
from ..xmlio import register_computed_value_reader, XFactory, XmlNode, where, lxml_etree

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

Value = Union[float, None]
"""What an expression evaluates to: a number, or None for Fanuc's vacant value."""

VarKey = Union[int, str]
"""A variable's identity: its number (``#12``) or its lower-cased name (``#<depth>`` -> ``"depth"``)."""


class EvalError(ProgramError):
    """An expression cannot be evaluated (division by zero, a vacant value where one is required, a
    value only the machine knows...). It carries no location: the caller locates it."""


class Expr(XmlNode):
    """Base of every expression node."""

    __slots__ = ()

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        raise NotImplementedError(type(self).__name__)


class Num(Expr):
    """A literal number."""

    XNAME = "Num"
    __slots__ = ("value",)
    value: float

    def __init__(self, value: float) -> None:
        self.value = float(value)

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Num":
        return cls(float(_attr(el, "value")))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        return etree.Element(self.XNAME, value=repr(self.value))

    def _key(self) -> tuple[Any, ...]:
        return (self.value,)

    def __repr__(self) -> str:
        return f"Num({self.value!r})"


class Var(Expr):
    """A variable: numbered (``index``, an expression: ``#1`` or ``#[#2+1]``) or named (``name``,
    lower-cased, without the angle brackets: ``#<_global>`` -> ``"_global"``). Exactly one is set."""

    XNAME = "Var"
    __slots__ = ("index", "name")
    index: Expr | None
    name: str | None

    def __init__(self, index: Expr | None = None, name: str | None = None) -> None:
        if (index is None) == (name is None):
            raise ValueError("a variable has either a number or a name")
        self.index = index
        self.name = name

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Var":
        kids = _children(el)
        name = el.get("name")
        if name is not None:
            if kids:
                raise ConfigError("<Var> has either a name or an index expression, not both", where(el))
            return cls(name=name)
        if len(kids) != 1:
            raise ConfigError("<Var> needs a name or exactly one index expression", where(el))
        return cls(kids[0])

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        if self.name is not None:
            el.set("name", self.name)
        elif self.index is not None:
            el.append(self.index.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.index, self.name)

    def __repr__(self) -> str:
        return f"Var(name={self.name!r})" if self.name is not None else f"Var({self.index!r})"


class Unary(Expr):
    """A unary operator (``UNARY_OPS``)."""

    XNAME = "Unary"
    __slots__ = ("op", "operand")
    op: str
    operand: Expr

    def __init__(self, op: str, operand: Expr) -> None:
        if op not in UNARY_OPS:
            raise ValueError(f"unknown unary operator {op!r}")
        self.op = op
        self.operand = operand

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Unary":
        kids = _children(el)
        if len(kids) != 1:
            raise ConfigError("<Unary> needs exactly one operand", where(el))
        return cls(_attr(el, "op"), kids[0])

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, op=self.op)
        el.append(self.operand.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.op, self.operand)

    def __repr__(self) -> str:
        return f"Unary({self.op!r}, {self.operand!r})"


class Binary(Expr):
    """A binary operator (``BINARY_OPS``): arithmetic, comparison or logical."""

    XNAME = "Binary"
    __slots__ = ("op", "left", "right")
    op: str
    left: Expr
    right: Expr

    def __init__(self, op: str, left: Expr, right: Expr) -> None:
        if op not in BINARY_OPS:
            raise ValueError(f"unknown binary operator {op!r}")
        self.op = op
        self.left = left
        self.right = right

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Binary":
        kids = _children(el)
        if len(kids) != 2:
            raise ConfigError("<Binary> needs exactly two operands", where(el))
        return cls(_attr(el, "op"), kids[0], kids[1])

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, op=self.op)
        el.append(self.left.make_xml_source(base_dir, rel_file, exhibition_only))
        el.append(self.right.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.op, self.left, self.right)

    def __repr__(self) -> str:
        return f"Binary({self.op!r}, {self.left!r}, {self.right!r})"


class Func(Expr):
    """A function call (``FUNCTIONS`` gives each name's number of arguments)."""

    XNAME = "Func"
    __slots__ = ("name", "args")
    name: str
    args: list[Expr]

    def __init__(self, name: str, args: list[Expr]) -> None:
        arity = FUNCTIONS.get(name)
        if arity is None:
            raise ValueError(f"unknown function {name!r}")
        if len(args) != arity:
            raise ValueError(f"function {name!r} takes {arity} argument(s), not {len(args)}")
        self.name = name
        self.args = list(args)

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Func":
        return cls(_attr(el, "name"), _children(el))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, name=self.name)
        for arg in self.args:
            el.append(arg.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.name, tuple(self.args))

    def __repr__(self) -> str:
        return f"Func({self.name!r}, {self.args!r})"


UNARY_OPS: frozenset[str] = frozenset({"neg", "pos", "not"})
"""``neg`` -x, ``pos`` +x, ``not``: 1 if x is 0 else 0."""

ARITHMETIC_OPS: frozenset[str] = frozenset({"add", "sub", "mul", "div", "pow", "mod_pos", "rem_int", "fmod"})
"""``pow`` x**y; ``mod_pos`` LinuxCNC's MOD (fmod, then +|y| if negative: result in [0, |y|));
``rem_int`` Fanuc's MOD (operands rounded to integers, remainder with the dividend's sign); ``fmod``
C's fmod on the reals (remainder with the dividend's sign, -7 fmod 3 = -1)."""

COMPARISON_OPS: frozenset[str] = frozenset({"eq", "ne", "gt", "ge", "lt", "le", "eq_tol", "ne_tol"})
"""Comparisons give 1.0 or 0.0. ``eq ne gt ge lt le`` are exact (Fanuc; LinuxCNC's GT GE LT LE);
``eq_tol``/``ne_tol`` are LinuxCNC's EQ/NE, which count values closer than ``TOLERANCE_EQUAL`` as equal."""

LOGICAL_OPS: frozenset[str] = frozenset({"and", "or", "xor", "bitand", "bitor", "bitxor"})
"""``and or xor`` are logical (non-zero is true, result 1.0 or 0.0: LinuxCNC); ``bitand bitor bitxor``
work bit by bit on integers (Fanuc)."""

BINARY_OPS: frozenset[str] = ARITHMETIC_OPS | COMPARISON_OPS | LOGICAL_OPS

FUNCTIONS: dict[str, int] = {
    "sin": 1, "cos": 1, "tan": 1, "asin": 1, "asin_360": 1, "acos": 1,
    "atan": 1, "atan_360": 1, "atan2": 2, "atan2_360": 2,
    "sqrt": 1, "abs": 1, "round": 1, "round_address": 1, "trunc": 1, "away": 1, "floor": 1, "ceil": 1,
    "ln": 1, "exp": 1, "bin": 1, "bcd": 1, "exists": 1, "fract": 1, "sqr": 1, "exp10": 1, "log10": 1,
    "whole_in": 3,
}
"""Every neutral function and its number of arguments; angles in degrees. ``asin``/``atan`` give
-90..90, ``atan2`` -180..180 (LinuxCNC); ``asin_360``/``atan_360``/``atan2_360`` add 360 to a negative
result (Fanuc's default ranges); ``round`` is half away from zero, ``round_address`` rounds to the
least input increment (Fanuc ROUND inside an NC word); ``trunc`` toward zero, ``away`` away from zero
(Fanuc FIX, FUP), ``floor``/``ceil`` (LinuxCNC FIX, FUP); ``bin``/``bcd`` convert BCD <-> binary;
``exists`` is 1 if its operand, a named variable, has a value; ``fract`` x - trunc(x) (sign of x);
``sqr`` x*x; ``exp10`` 10**x; ``log10`` the decimal logarithm (x <= 0 is an error); ``whole_in[x, low,
high]`` is x when x is a whole number from low to high, else an error: a value stored into an integer
type whose conversion no source states (ISG's UNS32, BOOLEAN... variables)."""

EXPR_CLASSES: tuple[type[Expr], ...] = (Num, Var, Unary, Binary, Func)

_BY_TAG: dict[str, type[Expr]] = {cls.XNAME: cls for cls in EXPR_CLASSES}

MAX_XML_DEPTH = 200
"""Deepest expression read from XML (deeper trees are refused rather than exhausting the stack)."""


def nests_deeper(expr: Expr, limit: int = MAX_XML_DEPTH) -> bool:
    """Whether ``expr`` is more than ``limit`` levels deep, found without recursion. The readers bound their
    own recursion (brackets, signs), but a chain ``1+1+...+1`` gets one level per operator from a loop, and
    what evaluates, folds, writes and saves an expression recurses over it: a reader refuses a deeper one
    at its text (the XML reader takes no deeper one either)."""
    stack: list[tuple[Expr, int]] = [(expr, 1)]
    while stack:
        node, depth = stack.pop()
        if depth > limit:
            return True
        if isinstance(node, Binary):
            stack.append((node.left, depth + 1))
            stack.append((node.right, depth + 1))
        elif isinstance(node, Unary):
            stack.append((node.operand, depth + 1))
        elif isinstance(node, Func):
            stack.extend((arg, depth + 1) for arg in node.args)
        elif isinstance(node, Var) and node.index is not None:
            stack.append((node.index, depth + 1))
    return False


def expr_from_xml(el: etree._Element) -> Expr:
    """Read one expression element (and its children). Only expression elements are accepted."""
    depth = 0
    parent = el.getparent()
    while parent is not None and isinstance(parent.tag, str) and parent.tag in _BY_TAG:
        depth += 1
        parent = parent.getparent()
    if depth > MAX_XML_DEPTH:
        raise ConfigError(f"expression nested deeper than {MAX_XML_DEPTH} levels", where(el))
    tag = el.tag if isinstance(el.tag, str) else ""
    cls = _BY_TAG.get(tag)
    if cls is None:
        raise ConfigError(f"<{tag}> is not an expression", where(el))
    try:
        return cls.from_xml(el)
    except ValueError as exc:
        raise ConfigError(f"invalid <{tag}>: {exc}", where(el)) from None


def _children(el: etree._Element) -> list[Expr]:
    return [expr_from_xml(child) for child in el if isinstance(child.tag, str)]


def _attr(el: etree._Element, name: str) -> str:
    raw = el.get(name)
    if raw is None:
        raise ConfigError(f"<{el.tag!s}> needs attribute {name!r}", where(el))
    return str(raw)


def register_expressions(factory: XFactory | None = None) -> None:
    """Register every expression node with ``factory`` (the default one if None); idempotent."""
    for cls in EXPR_CLASSES:
        cls.reg(factory)


class Vacancy(enum.Enum):
    """How a variable without a value reads: named after the behaviour, a family base's ``Env`` chooses it
    (the RS274 family's: ``postproc.rs274.variables``, Macro B ``NULL``, RS274/NGC ``ZERO``)."""

    NULL = "null"
    """Vacant is a value of its own (``#0``, unset locals and commons): ``Var`` evaluates to None;
    arithmetic, functions and ``GT GE LT LE`` treat it as 0; ``EQ``/``NE`` tell it from 0. A computed
    variable number is rounded to the nearest integer."""
    ZERO = "zero"
    """No vacancy: an unset numbered parameter reads 0, an unset named parameter is an error. A computed
    variable number must be an integer."""


class Arithmetic(enum.Enum):
    """How the controller computes the neutral functions: the dialect family's rule, as vacancy is.
    Both mean the same functions (``SIN`` is the sine of degrees); they differ in the last bits, which
    ``FIX``, ``FUP`` and the comparisons turn into whole units (``postproc.interp.evaluation``)."""

    DOUBLE = "double"
    """IEEE double throughout; an angle in degrees becomes radians as ``x * pi / 180`` in double, so
    ``SIN[180]`` is 1.2246e-16 and ``COS[90]`` 6.123e-17."""
    X86_64_C = "x86_64_c"
    """What C computes on x86-64 Linux where the interpreter scales angles with ``M_PIl`` in ``long double``
    and stores the result in a double (LinuxCNC's ``rs274``): ``SIN[180]`` is -5.0166e-20 and ``COS[90]``
    -2.5083e-20 (``postproc.interp.long_double``); ``ROUND`` converts through a C ``int``."""


class Env(Protocol):
    """What ``evaluate`` needs from the interpreter: variable values and the dialect's rules."""

    @property
    def vacancy(self) -> Vacancy:
        """The vacancy regime of the program's dialect."""

    @property
    def arithmetic(self) -> Arithmetic:
        """How the program's controller computes (``Arithmetic``)."""

    @property
    def increment(self) -> float:
        """Least input increment of an address in the current units (0.001 mm, 0.0001 inch):
        Fanuc's ROUND inside an NC word rounds to it (``round_address``)."""

    def read(self, key: VarKey) -> Value:
        """The value of a variable; None if it has none (vacant, unset). Raises ``EvalError`` for a
        variable the program may not read or whose value only the machine knows (``#5021``)."""

    def exists(self, key: VarKey) -> bool:
        """Whether a variable exists (``exists``: LinuxCNC EXISTS, ISG EXIST), by the dialect family's
        rule; ``EvalError`` where the family has no such test or only the machine knows."""


register_computed_value_reader(expr_from_xml)
