"""Control-flow sections: the jumps, conditions, loops, subprograms and assignments of a program.

They are block sections like ``Motion``: a reader puts at most one control statement in a block, under
the key ``"Control"`` (``block.get("Control")``); assignments go under ``"Assign"``, because a block may
hold assignments and words together (LinuxCNC ``#1=2 G0 X#1``). The interpreter (``postproc.interp``)
executes them; a writer whose dialect has them spells them back.

Names and labels are kept as the program wrote them, lower-cased where the dialect is case-insensitive:
- a loop or block label is the text of its number or name (``"1"`` for Fanuc ``DO1``/``END1``, ``"100"``
  or ``"<name>"`` for LinuxCNC o-words);
- a subprogram name is the key the store finds it by: the program number as decimal text for numbered
  programs (Fanuc ``O2000`` and ``M98 P2000`` -> ``"2000"``, LinuxCNC ``o100 sub`` -> ``"100"``) and
  ``"<name>"`` for named ones (LinuxCNC ``o<probe> sub`` -> ``"<probe>"``). A call's name may also be
  an expression (``M98 P#1``, ``o[#2] call``); its value, an integer, is then the number.

XML: every expression sits in an element naming its role, so the nodes read the same whatever the
expression: ``<Goto><Target>E</Target><Cond>E</Cond></Goto>``, ``<While label="1"><Cond>E</Cond></While>``,
``<Call kind="macro" name="2000"><Arg n="1">E</Arg><Repeat>E</Repeat></Call>``,
``<Assign><Set><Var>..</Var>E</Set></Assign>``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Final, Iterator

from ..errors import ConfigError
from ..ir.expr import Expr, Var, expr_from_xml
from ..ir import Section
from ..xmlio import XAttr, XFactory, lxml_etree, where

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

CONTROL: Final = "Control"
"""Section key of a block's control statement (one per block)."""
ASSIGN: Final = "Assign"
"""Section key of a block's assignments."""
LABEL: Final = "Label"
"""Section key of a block's named jump label."""
CALL_KINDS = frozenset({"sub", "macro"})
"""``sub``: the subprogram shares the caller's local variables (Fanuc M98); ``macro``: it gets a new
level of locals, set from the arguments (Fanuc G65, LinuxCNC ``o.. call``)."""


def _role(el: etree._Element, tag: str, required: bool = True) -> Expr | None:
    """The one expression inside the child ``<tag>`` of ``el`` (None if absent and not required)."""
    found = [c for c in el if c.tag == tag]
    if not found:
        if required:
            raise ConfigError(f"<{el.tag}> needs a <{tag}> expression", where(el))
        return None
    if len(found) > 1:
        raise ConfigError(f"<{el.tag}> has more than one <{tag}>", where(found[1]))
    kids = [c for c in found[0] if isinstance(c.tag, str)]
    if len(kids) != 1:
        raise ConfigError(f"<{tag}> holds exactly one expression", where(found[0]))
    return expr_from_xml(kids[0])


def _required(el: etree._Element, tag: str) -> Expr:
    expr = _role(el, tag)
    if expr is None:  # _role raises for a missing required role; this only narrows the type
        raise ConfigError(f"<{el.tag}> needs a <{tag}> expression", where(el))
    return expr


def _check_children(el: etree._Element, allowed: frozenset[str]) -> None:
    for child in el:
        if isinstance(child.tag, str) and child.tag not in allowed:
            raise ConfigError(f"unknown element <{child.tag}> in <{el.tag}>", where(child))


def _put(el: etree._Element, tag: str, expr: Expr | None, base_dir: str, rel_file: str,
         exhibition_only: bool) -> None:
    etree = lxml_etree()
    if expr is not None:
        etree.SubElement(el, tag).append(expr.make_xml_source(base_dir, rel_file, exhibition_only))


class ControlSection(Section):
    """Base of the control statements: one per block, under ``"Control"``."""

    __slots__ = ()
    KEY: ClassVar[str] = CONTROL
    ROLES: ClassVar[tuple[str, ...]] = ()
    """Expression attributes written as role elements (``cond`` -> ``<Cond>``), in XML order."""
    OPTIONAL: ClassVar[frozenset[str]] = frozenset()
    """Roles that may be absent (None)."""

    @classmethod
    def from_xml(cls, el: etree._Element) -> Any:
        _check_children(el, frozenset(r.title() for r in cls.ROLES))
        kwargs: dict[str, Any] = {a.name: a.parse(el) for a in cls.XATTRS}
        for role in cls.ROLES:
            kwargs[role] = _role(el, role.title(), role not in cls.OPTIONAL)
        return cls(**kwargs)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        el = super().make_xml_source(base_dir, rel_file, exhibition_only)
        for role in self.ROLES:
            _put(el, role.title(), getattr(self, role), base_dir, rel_file, exhibition_only)
        return el

    def _key(self) -> tuple[Any, ...]:
        return tuple(getattr(self, a.name) for a in self.XATTRS) + tuple(getattr(self, r) for r in self.ROLES)

    def __repr__(self) -> str:
        names = [a.name for a in self.XATTRS] + list(self.ROLES)
        return f"{type(self).__name__}({', '.join(f'{n}={getattr(self, n)!r}' for n in names)})"


class Assign(Section):
    """``#i = expr`` statements of one block. Every right-hand side (and every word value of the block)
    is read first, then the variables are set in order (LinuxCNC's rule; Fanuc has one per block)."""

    XNAME = KEY = ASSIGN
    __slots__ = ("items",)

    def __init__(self, items: list[tuple[Var, Expr]]) -> None:
        self.items = items

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Assign":
        _check_children(el, frozenset({"Set"}))
        items: list[tuple[Var, Expr]] = []
        for child in el:
            if child.tag != "Set":
                continue
            kids = [c for c in child if isinstance(c.tag, str)]
            if len(kids) != 2:
                raise ConfigError("<Set> holds a variable and an expression", where(child))
            var = expr_from_xml(kids[0])
            if not isinstance(var, Var):
                raise ConfigError(f"<Set> assigns to a variable, not <{kids[0].tag}>", where(kids[0]))
            items.append((var, expr_from_xml(kids[1])))
        if not items:
            raise ConfigError("<Assign> needs at least one <Set>", where(el))
        return cls(items)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        for var, value in self.items:
            item = etree.SubElement(el, "Set")
            item.append(var.make_xml_source(base_dir, rel_file, exhibition_only))
            item.append(value.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (tuple(self.items),)

    def __repr__(self) -> str:
        return f"Assign({self.items!r})"


class Goto(ControlSection):
    """``GOTO n`` / ``IF [c] GOTO n``: jump to the block with sequence number ``target`` when ``cond``
    (if any) is true. Fanuc searches forward from the jump, then from the program start. ``fallthrough``:
    a missing target is no error, the run goes on with the next block (SINUMERIK's ``GOTOC``)."""

    XNAME = "Goto"
    __slots__ = ("target", "cond", "fallthrough")
    XATTRS = (XAttr("fallthrough", bool, False),)
    ROLES = ("target", "cond")
    OPTIONAL = frozenset({"cond"})

    def __init__(self, target: Expr, cond: Expr | None = None, fallthrough: bool = False) -> None:
        self.target = target
        self.cond = cond
        self.fallthrough = fallthrough


class GotoLabel(ControlSection):
    """Jump to the block carrying the named ``Label`` ``label`` when ``cond`` (if any) is true (ISG
    ``$GOTO [NAME]``); the search runs forward from the jump, then from the program's start.
    ``fallthrough``: a missing label is no error, the run goes on with the next block (SINUMERIK's ``GOTOC``)."""

    XNAME = "GotoLabel"
    __slots__ = ("label", "cond", "fallthrough")
    XATTRS = (XAttr("label"), XAttr("fallthrough", bool, False))
    ROLES = ("cond",)
    OPTIONAL = frozenset({"cond"})

    def __init__(self, label: str, cond: Expr | None = None, fallthrough: bool = False) -> None:
        self.label = label
        self.cond = cond
        self.fallthrough = fallthrough


class Label(Section):
    """A named jump target on a block (ISG ``[NAME]``), under its own key: the block's words run as
    usual; only ``GotoLabel`` looks at it, and a dialect without named labels cannot write it."""

    XNAME = KEY = "Label"
    __slots__ = ("name",)
    XATTRS = (XAttr("name"),)

    def __init__(self, name: str) -> None:
        self.name = name


class IfThen(ControlSection):
    """Fanuc ``IF [c] THEN #1=..``: a conditional assignment."""

    XNAME = "IfThen"
    __slots__ = ("cond", "assign")
    ROLES = ("cond",)

    def __init__(self, cond: Expr, assign: Assign) -> None:
        self.cond = cond
        self.assign = assign

    @classmethod
    def from_xml(cls, el: etree._Element) -> "IfThen":
        _check_children(el, frozenset({"Cond", ASSIGN}))
        found = [c for c in el if c.tag == ASSIGN]
        if len(found) != 1:
            raise ConfigError("<IfThen> needs exactly one <Assign>", where(el))
        return cls(_required(el, "Cond"), Assign.from_xml(found[0]))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        el = super().make_xml_source(base_dir, rel_file, exhibition_only)
        el.append(self.assign.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.cond, self.assign)


class _Labelled(ControlSection):
    """A structured statement: ``label`` pairs it with the rest of its construct."""

    __slots__ = ("label",)
    XATTRS: ClassVar[tuple[XAttr, ...]] = (XAttr("label"),)
    label: str

    def __init__(self, label: str) -> None:
        self.label = label


class _LabelledCond(_Labelled):
    __slots__ = ("cond",)
    ROLES = ("cond",)

    def __init__(self, label: str, cond: Expr) -> None:
        self.label = label
        self.cond = cond


class If(_LabelledCond):
    """Start of an if/elseif/else/endif construct (LinuxCNC ``o1 if [c]``)."""

    XNAME = "If"
    __slots__ = ()


class ElseIf(_LabelledCond):
    XNAME = "ElseIf"
    __slots__ = ()


class Else(_Labelled):
    XNAME = "Else"
    __slots__ = ()


class EndIf(_Labelled):
    XNAME = "EndIf"
    __slots__ = ()


class While(_LabelledCond):
    """Loop head: the body runs while ``cond`` is true (Fanuc ``WHILE [c] DO1``, LinuxCNC ``o1 while``)."""

    XNAME = "While"
    __slots__ = ()


class EndWhile(_Labelled):
    """Loop end (Fanuc ``END1``, LinuxCNC ``o1 endwhile``)."""

    XNAME = "EndWhile"
    __slots__ = ()


class Do(_Labelled):
    """Head of a loop tested at its end (LinuxCNC ``o1 do``; the end is ``DoWhile``)."""

    XNAME = "Do"
    __slots__ = ()


class DoWhile(_LabelledCond):
    """End of a do loop: back to its ``Do`` while ``cond`` is true (LinuxCNC ``o1 while [c]``)."""

    XNAME = "DoWhile"
    __slots__ = ()


class Repeat(_Labelled):
    """Run the body ``count`` times (LinuxCNC ``o1 repeat [n]``)."""

    XNAME = "Repeat"
    __slots__ = ("count",)
    ROLES = ("count",)

    def __init__(self, label: str, count: Expr) -> None:
        self.label = label
        self.count = count


class EndRepeat(_Labelled):
    XNAME = "EndRepeat"
    __slots__ = ()


class For(_Labelled):
    """A counted loop (ISG ``$FOR P1 = start, end, step``): ``start``, ``end`` and ``step`` are evaluated
    once, when the loop is entered; the counter is set to ``start`` and the body runs while the counter is
    at most ``end`` (``step`` > 0) or at least ``end`` (``step`` < 0); the counter grows by ``step`` after
    each pass, so it holds the first value past ``end`` afterwards. ``step`` 0 never ends by itself (the
    set-up's loop bound stops it). Ended by ``EndFor``."""

    XNAME = "For"
    __slots__ = ("counter", "start", "end", "step")
    ROLES = ("counter", "start", "end", "step")

    def __init__(self, label: str, counter: Expr, start: Expr, end: Expr, step: Expr) -> None:
        if not isinstance(counter, Var):
            raise ConfigError("a counted loop's counter must be a variable")
        self.label = label
        self.counter = counter
        self.start = start
        self.end = end
        self.step = step


class EndFor(_Labelled):
    """End of a counted loop: the counter grows by the step and the test runs again."""

    XNAME = "EndFor"
    __slots__ = ()


class Until(_LabelledCond):
    """End of a loop started by ``Do`` and tested at its end (ISG ``$REPEAT`` .. ``$UNTIL c``): back to
    the body while ``cond`` is false."""

    XNAME = "Until"
    __slots__ = ()


class Switch(_Labelled):
    """A multiple branch (ISG ``$SWITCH v``): the first ``Case`` whose value is within ``tolerance`` of
    ``value`` (``|v - c| < tolerance``), else the ``Default``, else nothing runs. A branch is left with
    ``Break`` (same label); running from one branch into the next ``Case``/``Default`` is an error (the
    fall-through of a controller is not modelled). Ended by ``EndSwitch``."""

    XNAME = "Switch"
    __slots__ = ("value", "tolerance")
    XATTRS = (XAttr("label"), XAttr("tolerance", float, 0.0))
    ROLES = ("value",)

    def __init__(self, label: str, value: Expr, tolerance: float = 0.0) -> None:
        self.label = label
        self.value = value
        self.tolerance = tolerance


class Case(_Labelled):
    """A branch of the switch labelled ``label``, taken when the switch value equals ``value``."""

    XNAME = "Case"
    __slots__ = ("value",)
    ROLES = ("value",)

    def __init__(self, label: str, value: Expr) -> None:
        self.label = label
        self.value = value


class Default(_Labelled):
    """The branch of the switch labelled ``label`` taken when no case matches."""

    XNAME = "Default"
    __slots__ = ()


class EndSwitch(_Labelled):
    XNAME = "EndSwitch"
    __slots__ = ()


class Break(_Labelled):
    """Leave the innermost loop (or switch) labelled ``label``."""

    XNAME = "Break"
    __slots__ = ()


class Continue(_Labelled):
    """Go to the test of the loop labelled ``label``."""

    XNAME = "Continue"
    __slots__ = ()


class SubStart(ControlSection):
    """Start of a subprogram definition (LinuxCNC ``o<x> sub``). A Fanuc ``O2000`` after the main
    program is a ``ProgramStart`` section instead, and starts a subprogram too."""

    XNAME = "SubStart"
    __slots__ = ("name",)
    XATTRS = (XAttr("name"),)

    def __init__(self, name: str) -> None:
        self.name = name


class SubEnd(ControlSection):
    """End of a subprogram definition, returning ``value`` if given (LinuxCNC ``o<x> endsub [v]``)."""

    XNAME = "SubEnd"
    __slots__ = ("name", "value")
    XATTRS = (XAttr("name"),)
    ROLES = ("value",)
    OPTIONAL = frozenset({"value"})

    def __init__(self, name: str, value: Expr | None = None) -> None:
        self.name = name
        self.value = value


class Return(ControlSection):
    """Return from a subprogram: Fanuc ``M99`` (no name), ``M99 P<seq>`` (``target``: continue at that
    sequence number in the caller), LinuxCNC ``o<x> return [v]`` (``value``, readable as ``#<_value>``).
    ``M99`` in a main program goes back to its start."""

    XNAME = "Return"
    __slots__ = ("name", "value", "target")
    XATTRS = (XAttr("name", str, None),)
    ROLES = ("value", "target")
    OPTIONAL = frozenset({"value", "target"})

    def __init__(self, name: str | None = None, value: Expr | None = None, target: Expr | None = None) -> None:
        self.name = name
        self.value = value
        self.target = target


def _args_from_xml(el: etree._Element) -> dict[int, Expr]:
    args: dict[int, Expr] = {}
    for child in el:
        if child.tag != "Arg":
            continue
        raw = child.get("n")
        if raw is None or not raw.isdigit() or int(raw) < 1:
            raise ConfigError("<Arg> needs a local variable number n (1 or more)", where(child))
        if int(raw) in args:
            raise ConfigError(f"<Arg n=\"{raw}\"> appears twice", where(child))
        kids = [c for c in child if isinstance(c.tag, str)]
        if len(kids) != 1:
            raise ConfigError("<Arg> holds exactly one expression", where(child))
        args[int(raw)] = expr_from_xml(kids[0])
    return args


class _CallLike(ControlSection):
    """What a call and a modal call share: a program name (text or expression), arguments, a repeat."""

    __slots__ = ("name", "args", "repeat")
    name: str | Expr
    args: dict[int, Expr]
    repeat: Expr | None

    @classmethod
    def _common(cls, el: etree._Element) -> dict[str, Any]:
        _check_children(el, frozenset({"Name", "Arg", "Repeat"}))
        raw = el.get("name")
        expr = _role(el, "Name", required=False)
        if (raw is None) == (expr is None):
            raise ConfigError(f"<{el.tag}> needs a name attribute or a <Name> expression (one of them)", where(el))
        return {"name": raw if raw is not None else expr, "args": _args_from_xml(el),
                "repeat": _role(el, "Repeat", required=False)}

    def _write(self, el: etree._Element, base_dir: str, rel_file: str, exhibition_only: bool) -> etree._Element:
        etree = lxml_etree()
        if isinstance(self.name, str):
            el.set("name", self.name)
        else:
            _put(el, "Name", self.name, base_dir, rel_file, exhibition_only)
        for n, value in self.args.items():
            etree.SubElement(el, "Arg", n=str(n)).append(value.make_xml_source(base_dir, rel_file, exhibition_only))
        _put(el, "Repeat", self.repeat, base_dir, rel_file, exhibition_only)
        return el


class Call(_CallLike):
    """Call a subprogram ``repeat`` times (None: once). ``args`` maps a local variable number to its value
    (Fanuc G65 letters already mapped, A -> 1 ...; LinuxCNC positional ``[a] [b]`` -> 1, 2). ``kind`` is
    ``"sub"`` (shares the caller's locals: M98) or ``"macro"`` (a new level: G65, LinuxCNC ``call``)."""

    XNAME = "Call"
    __slots__ = ("kind",)

    def __init__(self, name: str | Expr, args: dict[int, Expr] | None = None, repeat: Expr | None = None,
                 kind: str = "sub") -> None:
        if kind not in CALL_KINDS:
            raise ValueError(f"unknown call kind {kind!r} (sub or macro)")
        self.name = name
        self.args = args if args is not None else {}
        self.repeat = repeat
        self.kind = kind

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Call":
        return cls(kind=el.get("kind", "sub"), **cls._common(el))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, kind=self.kind)
        return self._write(el, base_dir, rel_file, exhibition_only)

    def _key(self) -> tuple[Any, ...]:
        return (self.name, tuple(self.args.items()), self.repeat, self.kind)

    def __repr__(self) -> str:
        return f"Call({self.name!r}, {self.args!r}, repeat={self.repeat!r}, kind={self.kind!r})"


class ModalCall(_CallLike):
    """Fanuc ``G66 P.. L.. args``: call the macro after every later block that moves an axis, until a
    ``ModalCallCancel`` (G67). Each such call is a new level of locals (as G65)."""

    XNAME = "ModalCall"
    __slots__ = ()

    def __init__(self, name: str | Expr, args: dict[int, Expr] | None = None, repeat: Expr | None = None) -> None:
        self.name = name
        self.args = args if args is not None else {}
        self.repeat = repeat

    @classmethod
    def from_xml(cls, el: etree._Element) -> "ModalCall":
        return cls(**cls._common(el))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        return self._write(etree.Element(self.XNAME), base_dir, rel_file, exhibition_only)

    def _key(self) -> tuple[Any, ...]:
        return (self.name, tuple(self.args.items()), self.repeat)

    def __repr__(self) -> str:
        return f"ModalCall({self.name!r}, {self.args!r}, repeat={self.repeat!r})"


class ModalCallCancel(ControlSection):
    """Fanuc ``G67``: no more modal calls."""

    XNAME = "ModalCallCancel"
    __slots__ = ()


CONTROL_SECTIONS: tuple[type[Section], ...] = (
    Assign, Goto, IfThen, If, ElseIf, Else, EndIf, While, EndWhile, Do, DoWhile, Repeat, EndRepeat, Break,
    Continue, SubStart, SubEnd, Return, Call, ModalCall, ModalCallCancel, For, EndFor, Until, Switch, Case,
    Default, EndSwitch, GotoLabel, Label,
)
"""Every control-flow section class, for registration."""

LOOP_HEADS: tuple[type[Section], ...] = (While, Do, Repeat, For)


def iter_control_sections() -> Iterator[type[Section]]:
    yield from CONTROL_SECTIONS


def register_control(factory: XFactory | None = None) -> None:
    """Register every control-flow section with ``factory`` (the default one if None); idempotent."""
    for cls in CONTROL_SECTIONS:
        cls.reg(factory)
