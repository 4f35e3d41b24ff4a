"""The intermediate representation: a program is a stream of ``Block``s.

A block keeps its source line, its raw text and words (so unchanged blocks are written back byte for
byte) and a dict of typed, dialect-neutral sections. No dialect's spelling lives here: a section says
"rapid motion" or "return to the initial level", never "G00" or "G98". Dialect-specific constructs with
no neutral meaning travel as ``NativeCode`` tagged with their dialect.

Blocks are plain ``__slots__`` objects without reference cycles and sections are created only for what a
block actually programs: a million-block program must stream without pressure on the garbage collector.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import TYPE_CHECKING, Any, Callable, ClassVar, Iterator, Final

from .expr import Expr, expr_from_xml
from .xmlio import (DEFAULT, XAttr, XFactory, XmlNode, computed_value, decode, encode, lxml_etree,
                    restore_slots, slot_state, where)

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

AXES = ("X", "Y", "Z", "A", "B", "C", "U", "V", "W")
"""Axis letters a neutral motion may carry, in output order."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Section(XmlNode):
    """A typed part of a block. ``KEY`` is its slot in ``Block.sections`` (one of each per block)."""

    __slots__ = ()
    KEY: ClassVar[str] = ""


@mypyc_attr(allow_interpreted_subclasses=True)
class BlockDelete(Section):
    """Optional block skip; level 1 is the plain '/'."""

    XNAME = "BlockDelete"

    KEY = "BlockDelete"
    __slots__ = ("level",)
    XATTRS = (XAttr("level", int, 1),)
    level: int

    def __init__(self, level: int = 1) -> None:
        self.level = level


@mypyc_attr(allow_interpreted_subclasses=True)
class ProgramStart(Section):
    """Program number or name (O-number, %name)."""

    XNAME = "ProgramStart"

    KEY = "ProgramStart"
    __slots__ = ("number", "name")
    XATTRS = (XAttr("number", int, None), XAttr("name", str, None))
    number: int | None
    name: str | None

    def __init__(self, number: int | None = None, name: str | None = None) -> None:
        self.number = number
        self.name = name


@mypyc_attr(allow_interpreted_subclasses=True)
class TapeMark(Section):
    """Tape start/end marker line."""

    XNAME = "TapeMark"

    KEY = "TapeMark"
    __slots__ = ()


@mypyc_attr(allow_interpreted_subclasses=True)
class Units(Section):
    """Length unit of the program: 'mm' or 'inch'."""

    XNAME = "Units"

    KEY = "Units"
    __slots__ = ("system",)
    XATTRS = (XAttr("system", str),)
    system: str

    def __init__(self, system: str) -> None:
        self.system = system


@mypyc_attr(allow_interpreted_subclasses=True)
class Plane(Section):
    """Working plane: 'XY', 'ZX' or 'YZ'."""

    XNAME = "Plane"

    KEY = "Plane"
    __slots__ = ("plane",)
    XATTRS = (XAttr("plane", str),)
    plane: str

    def __init__(self, plane: str) -> None:
        self.plane = plane


@mypyc_attr(allow_interpreted_subclasses=True)
class DistanceMode(Section):
    """'absolute' or 'incremental' coordinates."""

    XNAME = "DistanceMode"

    KEY = "DistanceMode"
    __slots__ = ("mode",)
    XATTRS = (XAttr("mode", str),)
    mode: str

    def __init__(self, mode: str) -> None:
        self.mode = mode


@mypyc_attr(allow_interpreted_subclasses=True)
class WorkOffset(Section):
    """Work coordinate system, 1 = first (G54 on Fanuc)."""

    XNAME = "WorkOffset"

    KEY = "WorkOffset"
    __slots__ = ("index",)
    XATTRS = (XAttr("index", int),)
    index: int

    def __init__(self, index: int) -> None:
        self.index = index


@mypyc_attr(allow_interpreted_subclasses=True)
class FeedMode(Section):
    """'per_min', 'per_rev' or 'inverse_time'."""

    XNAME = "FeedMode"

    KEY = "FeedMode"
    __slots__ = ("mode",)
    XATTRS = (XAttr("mode", str),)
    mode: str

    def __init__(self, mode: str) -> None:
        self.mode = mode


@mypyc_attr(allow_interpreted_subclasses=True)
class SpindleSpeed(Section):
    """Spindle speed."""

    XNAME = "SpindleSpeed"

    KEY = "SpindleSpeed"
    __slots__ = ("rpm",)
    XATTRS = (XAttr("rpm", float),)
    rpm: float | Expr

    def __init__(self, rpm: float | Expr) -> None:
        self.rpm = rpm


@mypyc_attr(allow_interpreted_subclasses=True)
class SpindleControl(Section):
    """Spindle on clockwise ('cw'), counter-clockwise ('ccw') or 'stop'. ``before_motion``: a stop that
    the reading controller makes before its block's motion (the RS274/NGC order of execution), where
    the neutral order (``postproc.event_order``) makes it after."""

    XNAME = "SpindleControl"

    KEY = "SpindleControl"
    __slots__ = ("direction", "before_motion")
    XATTRS = (XAttr("direction", str), XAttr("before_motion", bool, False))
    direction: str
    before_motion: bool

    def __init__(self, direction: str, before_motion: bool = False) -> None:
        self.direction = direction
        self.before_motion = before_motion


@mypyc_attr(allow_interpreted_subclasses=True)
class SpindleOrientation(Section):
    """Oriented spindle stop at an angle in degrees (or the expression a program kept symbolically
    computes it with: LinuxCNC's ``M19 R#1``)."""

    XNAME = "SpindleOrientation"

    KEY = "SpindleOrientation"
    __slots__ = ("angle",)
    XATTRS = (XAttr("angle", float, 0.0),)
    angle: float | Expr

    def __init__(self, angle: float | Expr = 0.0) -> None:
        self.angle = angle


@mypyc_attr(allow_interpreted_subclasses=True)
class ToolSelect(Section):
    """Tool number prepared or selected."""

    XNAME = "ToolSelect"

    KEY = "ToolSelect"
    __slots__ = ("number",)
    XATTRS = (XAttr("number", int),)
    number: int | Expr

    def __init__(self, number: int | Expr) -> None:
        self.number = number


@mypyc_attr(allow_interpreted_subclasses=True)
class ToolChange(Section):
    """Change to the selected tool."""

    XNAME = "ToolChange"

    KEY = "ToolChange"
    __slots__ = ()


@mypyc_attr(allow_interpreted_subclasses=True)
class ToolLengthOffset(Section):
    """'positive', 'negative' or 'cancel', with the offset register: a number, or the expression a
    program kept symbolically computes it with (``H#1``); or 'dynamic' with the ``length`` itself in
    program units (grbl's and LinuxCNC's ``G43.1 Z<length>``: no table, the program gives the value)."""

    XNAME = "ToolLengthOffset"

    KEY = "ToolLengthOffset"
    __slots__ = ("mode", "register", "length")
    XATTRS = (XAttr("mode", str), XAttr("register", int, None), XAttr("length", float, None))
    mode: str
    register: int | Expr | None
    length: float | Expr | None

    def __init__(self, mode: str, register: int | Expr | None = None, length: float | Expr | None = None) -> None:
        self.mode = mode
        self.register = register
        self.length = length


@mypyc_attr(allow_interpreted_subclasses=True)
class CutterCompensation(Section):
    """'off', 'left' or 'right', with the offset register: a number, or the expression a program kept
    symbolically computes it with (``D#517``)."""

    XNAME = "CutterCompensation"

    KEY = "CutterCompensation"
    __slots__ = ("mode", "register")
    XATTRS = (XAttr("mode", str), XAttr("register", int, None))
    mode: str
    register: int | Expr | None

    def __init__(self, mode: str, register: int | Expr | None = None) -> None:
        self.mode = mode
        self.register = register


@mypyc_attr(allow_interpreted_subclasses=True)
class Coolant(Section):
    """'flood', 'mist' or 'off'. ``before_motion``: coolant off that the reading controller makes before
    its block's motion (as ``SpindleControl.before_motion``)."""

    XNAME = "Coolant"

    KEY = "Coolant"
    __slots__ = ("mode", "before_motion")
    XATTRS = (XAttr("mode", str), XAttr("before_motion", bool, False))
    mode: str
    before_motion: bool

    def __init__(self, mode: str, before_motion: bool = False) -> None:
        self.mode = mode
        self.before_motion = before_motion


@mypyc_attr(allow_interpreted_subclasses=True)
class Dwell(Section):
    """Dwell for a time in seconds."""

    XNAME = "Dwell"

    KEY = "Dwell"
    __slots__ = ("seconds",)
    XATTRS = (XAttr("seconds", float),)
    seconds: float | Expr

    def __init__(self, seconds: float | Expr) -> None:
        self.seconds = seconds


@mypyc_attr(allow_interpreted_subclasses=True)
class ProgramControl(Section):
    """'stop', 'optional_stop', 'end' or 'end_rewind'."""

    XNAME = "ProgramControl"

    KEY = "ProgramControl"
    __slots__ = ("kind",)
    XATTRS = (XAttr("kind", str),)
    kind: str

    def __init__(self, kind: str) -> None:
        self.kind = kind


@mypyc_attr(allow_interpreted_subclasses=True)
class PathControl(Section):
    """'exact_stop' or 'cutting' path control. ``tolerance`` and ``naive``: how far a blended path may
    leave the programmed one, and how far a run of short moves may be merged (LinuxCNC ``G64 P Q``, program
    units; None: not given). They change no controlled point."""

    XNAME = "PathControl"

    KEY = "PathControl"
    __slots__ = ("mode", "one_shot", "tolerance", "naive")
    XATTRS = (XAttr("mode", str), XAttr("one_shot", bool, False), XAttr("tolerance", float, None),
              XAttr("naive", float, None))
    mode: str
    one_shot: bool
    tolerance: float | None
    naive: float | None

    def __init__(self, mode: str, one_shot: bool = False, tolerance: float | None = None,
                 naive: float | None = None) -> None:
        self.mode = mode
        self.one_shot = one_shot
        self.tolerance = tolerance
        self.naive = naive


@mypyc_attr(allow_interpreted_subclasses=True)
class ReturnLevel(Section):
    """Canned-cycle return: 'initial' level or 'r' level."""

    XNAME = "ReturnLevel"

    KEY = "ReturnLevel"
    __slots__ = ("level",)
    XATTRS = (XAttr("level", str),)
    level: str

    def __init__(self, level: str) -> None:
        self.level = level


@mypyc_attr(allow_interpreted_subclasses=True)
class CycleCancel(Section):
    """Cancel the active canned cycle."""

    XNAME = "CycleCancel"

    KEY = "CycleCancel"
    __slots__ = ()


@mypyc_attr(allow_interpreted_subclasses=True)
class MachineCoordinates(Section):
    """One-shot: this block's motion is in machine coordinates."""

    XNAME = "MachineCoordinates"

    KEY = "MachineCoordinates"
    __slots__ = ()


@mypyc_attr(allow_interpreted_subclasses=True)
class CycleCall(Section):
    """A canned cycle programmed in this block, by neutral name (e.g. 'drill', 'back_bore')."""

    XNAME = "CycleCall"

    KEY = "CycleCall"
    __slots__ = ("kind",)
    XATTRS = (XAttr("kind", str),)
    kind: str

    def __init__(self, kind: str) -> None:
        self.kind = kind


@mypyc_attr(allow_interpreted_subclasses=True)
class Sequence(Section):
    """Block (sequence) number, N on most controllers. Written out by hand: it is on most blocks."""

    XNAME = "Sequence"

    KEY = "Sequence"
    __slots__ = ("number",)
    XATTRS = (XAttr("number", int),)

    def __init__(self, number: int) -> None:
        self.number = number


@mypyc_attr(allow_interpreted_subclasses=True)
class Feed(Section):
    """Feed rate in program units per minute (or per rev). Written out by hand: it is frequent."""

    XNAME = "Feed"

    KEY = "Feed"
    __slots__ = ("value",)
    XATTRS = (XAttr("value", float),)

    def __init__(self, value: float | Expr) -> None:
        self.value = value


@mypyc_attr(allow_interpreted_subclasses=True)
class Comments(Section):
    """The comments written in a block, in order (without delimiters)."""

    XNAME = "Comments"

    KEY = "Comments"
    __slots__ = ("texts",)

    def __init__(self, texts: list[str]) -> None:
        self.texts = texts

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Comments":
        return cls([c.text or "" for c in el if c.tag == "Text"])

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        for t in self.texts:
            etree.SubElement(el, "Text").text = t
        return el

    def _key(self) -> tuple[Any, ...]:
        return (tuple(self.texts),)


def _axes_from_xml(el: etree._Element) -> dict[str, Any]:
    axes: dict[str, Any] = {k: float(v) for k, v in el.attrib.items()}
    for child in el:
        if child.tag == "Value":
            axis = child.get("of", "")
            axes[axis] = computed_value(el, axis)
        elif isinstance(child.tag, str):
            raise ValueError(f"unexpected <{child.tag}>")
    return axes


def _axes_to_xml(parent: etree._Element, tag: str, axes: dict[str, Any]) -> None:
    """Numbers as attributes (``X="1.0"``), computed values as ``<Value of="X">expr</Value>``."""
    etree = lxml_etree()
    child = etree.SubElement(parent, tag)
    for k, v in axes.items():
        if isinstance(v, Expr):
            etree.SubElement(child, "Value", of=k).append(v.make_xml_source())
        else:
            child.set(k, repr(float(v)))


@mypyc_attr(allow_interpreted_subclasses=True)
class Motion(Section):
    """A programmed move: mode 'rapid', 'linear', 'cw', 'ccw', or 'home'/'home2' (return to the first or
    second reference point through the programmed intermediate point), axis words as programmed.
    ``mode`` is None only for a block that repeats the active canned cycle at a new position.

    ``axes`` are in program units and follow the block's distance mode; ``center`` holds the arc
    centre offsets from the start point (per plane axis letter X/Y/Z) and ``radius`` the R form.
    """

    XNAME = "Motion"

    KEY = "Motion"
    __slots__ = ("mode", "axes", "center", "radius")

    def __init__(self, mode: str | None, axes: dict[str, float | Expr],
                 center: dict[str, float | Expr] | None = None, radius: float | Expr | None = None) -> None:
        self.mode = mode
        self.axes = axes
        self.center = center
        self.radius = radius

    @classmethod
    def from_xml(cls, el: etree._Element) -> "Motion":
        axes, center = {}, None
        for c in el:
            if c.tag == "Axes":
                axes = _axes_from_xml(c)
            elif c.tag == "Center":
                center = _axes_from_xml(c)
            elif isinstance(c.tag, str) and c.tag != "Value":
                raise ValueError(f"unexpected <{c.tag}>")
        r = el.get("radius")
        radius = computed_value(el, "radius") if r is None else float(r)
        return cls(el.get("mode"), axes, center, radius)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        if self.mode is not None:
            el.set("mode", self.mode)
        if isinstance(self.radius, Expr):
            etree.SubElement(el, "Value", of="radius").append(self.radius.make_xml_source())
        elif self.radius is not None:
            el.set("radius", repr(self.radius))
        _axes_to_xml(el, "Axes", self.axes)
        if self.center is not None:
            _axes_to_xml(el, "Center", self.center)
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.mode, self.axes, self.center, self.radius)

    def __repr__(self) -> str:
        return f"Motion({self.mode!r}, {self.axes!r}, center={self.center!r}, radius={self.radius!r})"


@mypyc_attr(allow_interpreted_subclasses=True)
class NativeCode(Section):
    """A construct with no neutral meaning, kept verbatim for its own dialect (e.g. ISG ``#CYL``).

    It round-trips unchanged within ``dialect`` and is an unsupported construct everywhere else. An
    ``inert`` one does nothing a tool path shows (an ISG STRING variable's declaration): the simulation
    passes it; every other one stops the simulation, naming it.
    """

    XNAME = "NativeCode"

    KEY = "NativeCode"
    __slots__ = ("dialect", "what", "text", "inert")
    XATTRS = (XAttr("dialect"), XAttr("what"), XAttr("text"), XAttr("inert", bool, False))

    def __init__(self, dialect: str, what: str, text: str, inert: bool = False) -> None:
        self.dialect = dialect
        self.what = what
        self.text = text
        self.inert = inert


@mypyc_attr(allow_interpreted_subclasses=True)
class MachineFunction(Section):
    """A machine-specific code (an M code of the machine builder, a machine G code such as a smoothing
    setting) with the words it takes, as written (``text``). It passes verbatim between controllers of
    ``family`` and has no equivalent anywhere else; the simulation runs its ``action`` (one of
    ``postproc.setup.machine_setup.MachineCode``'s). ``declared``: the set-up or the family's defaults know it."""

    XNAME = "MachineFunction"

    KEY = "MachineFunction"
    __slots__ = ("family", "code", "action", "name", "text", "declared")
    XATTRS = (XAttr("family"), XAttr("code"), XAttr("action", str, "none"), XAttr("name", str, ""),
              XAttr("text"), XAttr("declared", bool, True))
    family: str
    code: str
    action: str
    name: str
    text: str
    declared: bool

    def __init__(self, family: str, code: str, text: str, action: str = "none", name: str = "",
                 declared: bool = True) -> None:
        self.family = family
        self.code = code
        self.text = text
        self.action = action
        self.name = name
        self.declared = declared

    def describe(self) -> str:
        """``M31 (part counter)``, for messages."""
        return f"{self.code} ({self.name})" if self.name else self.code


@mypyc_attr(allow_interpreted_subclasses=True)
class DataSetting(Section):
    """Programmable data input (Fanuc ``G10 L2 P1 X.. Y..``): write ``values`` (axis letter or 'R' ->
    value in program units) into entry ``index`` of a controller table. ``table`` is neutral:
    'work_offset' (index 1 = the first work system, 0 = the offset common to all), 'work_offset_extended',
    'tool_length', 'tool_length_wear', 'cutter_offset', 'cutter_offset_wear'. ``incremental``: the values
    are added to the entry. ``text`` is the block's setting as written, passed verbatim within ``family``.
    A value may be an expression (``X[#1+1]``, a program kept symbolically); the table and the entry are
    numbers (a computed ``L`` or ``P`` keeps the block verbatim)."""

    XNAME = "DataSetting"

    KEY = "DataSetting"
    __slots__ = ("family", "table", "index", "values", "incremental", "text")

    def __init__(self, family: str, table: str, index: int, values: dict[str, float | Expr], incremental: bool,
                 text: str) -> None:
        self.family = family
        self.table = table
        self.index = index
        self.values = values
        self.incremental = incremental
        self.text = text

    def describe(self) -> str:
        return f"{self.text} (setting {self.table.replace('_', ' ')} {self.index})"

    @classmethod
    def from_xml(cls, el: etree._Element) -> "DataSetting":
        values: dict[str, float | Expr] = {}
        for c in el:
            if c.tag == "Values":
                values = _axes_from_xml(c)
            elif isinstance(c.tag, str):
                raise ValueError(f"unexpected <{c.tag}>")
        return cls(el.get("family", ""), el.get("table", ""), int(el.get("index", "0")), values,
                   el.get("incremental") == "true", el.get("text", ""))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, family=self.family, table=self.table, index=str(self.index))
        if self.incremental:
            el.set("incremental", "true")
        el.set("text", self.text)
        _axes_to_xml(el, "Values", self.values)
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.family, self.table, self.index, self.values, self.incremental, self.text)


SIMPLE_SECTIONS: Final[tuple[type[Section], ...]] = (
    Sequence, BlockDelete, ProgramStart, TapeMark, Units, Plane, DistanceMode, WorkOffset, FeedMode, Feed,
    SpindleSpeed, SpindleControl, SpindleOrientation, ToolSelect, ToolChange, ToolLengthOffset,
    CutterCompensation, Coolant, Dwell, ProgramControl, PathControl, ReturnLevel, CycleCancel,
    MachineCoordinates, CycleCall, MachineFunction,
)


@mypyc_attr(allow_interpreted_subclasses=True)
class Block:
    """One block of a program. Not an ``XmlNode`` subclass only to stay lean; it serialises the same way.

    ``text`` is the source line without its end-of-line (``eol``), or None once the block was changed
    and must be generated from its sections. ``words`` are (letter, number text) pairs as written;
    ``values`` the numbers they mean once the reading dialect applied its rules (e.g. Fanuc's decimal
    point rule), keyed by upper-case letter for every address but G and M; a computed word's value is
    its expression (``Expr``, G and M included), serialised as ``<Word kind="expr">`` holding the tree.
    """

    XNAME: ClassVar[str] = "Block"
    __slots__ = ("line", "text", "eol", "words", "values", "sections", "canonical")

    def __init__(self, line: int, text: str | None, eol: str = "\n",
                 words: list[tuple[str, str]] | None = None) -> None:
        self.line = line
        self.text = text
        self.eol = eol
        self.words = words if words is not None else []
        self.values: dict[str, float | int | Expr] = {}
        """Address -> what its word reads as (the reader's and block syntax's; no later step changes it,
        so a writer that copies a canonical word checks the section's value against it)."""
        self.sections: dict[str, Section] = {}
        self.canonical = False
        """A reader's hint: ``text`` is its ``words`` joined by single spaces, already in canonical
        spelling (``postproc.numbers``), so a writer may copy it (``WordWriter.straight_move``); whatever
        takes words out of such a block (a call's words into its section) clears it. Not part of the
        block's value (equality, XML)."""

    def add(self, section: Section) -> Section:
        self.sections[section.KEY] = section
        return section

    def get(self, key: str) -> Any:
        return self.sections.get(key)

    def changed(self) -> None:
        """Mark the block as rewritten: writers must generate it from its sections."""
        self.text = None

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Block):
            return NotImplemented
        return (self.line, self.text, self.eol, self.words, self.values, self.sections) == (
            other.line, other.text, other.eol, other.words, other.values, other.sections)

    def __getstate__(self) -> dict[str, Any]:
        return slot_state(self)

    def __setstate__(self, state: dict[str, Any]) -> None:
        restore_slots(self, state)

    def __repr__(self) -> str:
        return f"Block(line={self.line}, text={self.text!r}, sections={list(self.sections.values())!r})"

    @classmethod
    def from_xml(cls, el: etree._Element, factory: XFactory | None = None) -> "Block":
        factory = factory or DEFAULT
        text = el.get("text")
        block = cls(int(el.get("line", "0")), text, decode_eol(el.get("eol", "LF")))
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag == "Word":
                letter, num = child.get("letter", ""), child.get("text", "")
                block.words.append((letter, num))
                if child.get("kind") == "expr":
                    kids = [c for c in child if isinstance(c.tag, str)]
                    if len(kids) != 1:
                        from .errors import ConfigError
                        raise ConfigError("<Word kind=\"expr\"> holds exactly one expression", where(child))
                    block.values[letter.upper()] = expr_from_xml(kids[0])
                elif "value" in child.attrib:
                    block.values[letter.upper()] = decode(float if child.get("kind") == "float" else int,
                                                          child.get("value", ""))
            else:
                section = factory.create(child)
                if not isinstance(section, Section):
                    from .errors import ConfigError
                    raise ConfigError(f"<{child.tag}> is not a block section", where(child))
                block.add(section)
        return block

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, line=str(self.line))
        if self.text is not None:
            el.set("text", self.text)
        if self.eol != "\n":
            el.set("eol", encode_eol(self.eol))
        seen: set[str] = set()
        for letter, num in self.words:
            w = etree.SubElement(el, "Word", letter=letter, text=num)
            key = letter.upper()
            if key in self.values and key not in seen:
                seen.add(key)
                v = self.values[key]
                if isinstance(v, Expr):
                    w.set("kind", "expr")
                    w.append(v.make_xml_source(base_dir, rel_file, exhibition_only))
                    continue
                w.set("kind", "float" if isinstance(v, float) else "int")
                w.set("value", encode(v))
        for section in self.sections.values():
            el.append(section.make_xml_source(base_dir, rel_file, exhibition_only))
        return el


_EOLS: Final = {"\n": "LF", "\r\n": "CRLF", "\r": "CR", "": "none"}
_EOLS_BACK: Final = {v: k for k, v in _EOLS.items()}


def encode_eol(eol: str) -> str:
    return _EOLS[eol]


def decode_eol(name: str) -> str:
    if name not in _EOLS_BACK:
        raise ValueError(f"unknown end of line {name!r}")
    return _EOLS_BACK[name]


def one_line(text: str) -> str:
    """A block's text on one line (a block continued over several lines, ISG's ``\\``, keeps its line
    ends in ``text``), for a comment or a message that quotes it."""
    if "\n" in text or "\r" in text:
        return text.replace("\r\n", " ").replace("\n", " ").replace("\r", " ")
    return text


def register_sections(factory: XFactory | None = None) -> None:
    """Register every core section with ``factory``; idempotent."""
    for cls in iter_sections():
        cls.reg(factory)


def iter_sections() -> Iterator[type[Section]]:
    yield from (*SIMPLE_SECTIONS, Comments, Motion, NativeCode, CompoundMotion, DataSetting)


@mypyc_attr(allow_interpreted_subclasses=True)
class CompoundMotion(Section):
    """The explicit motion a construct stands for (a canned cycle's rapids, feeds, dwells, spindle
    actions), in execution order. Moves inside are absolute, in program units."""

    XNAME = "CompoundMotion"

    KEY = "CompoundMotion"
    __slots__ = ("term", "_items", "_make")

    def __init__(self, term: str, items: list[Section]) -> None:
        self.term = term
        self._items: list[Section] | None = items
        self._make: Callable[[], list[Section]] | None = None

    @classmethod
    def lazy(cls, term: str, make: Callable[[], list[Section]]) -> "CompoundMotion":
        """The motion made only when something reads it: a target that keeps the construct native (a
        Fanuc cycle written as a Fanuc cycle) never pays for its expansion. ``make`` raises the located
        error the expansion finds, at the first reading."""
        motion = cls(term, [])
        motion._items, motion._make = None, make
        return motion

    @property
    def items(self) -> list[Section]:
        items = self._items
        if items is None:
            make, self._make = self._make, None
            self._items = items = []  # a failed expansion is reported once; the run has failed then
            if make is not None:
                self._items = items = make()
        return items

    @items.setter
    def items(self, items: list[Section]) -> None:
        self._items, self._make = items, None

    @classmethod
    def from_xml(cls, el: etree._Element) -> "CompoundMotion":
        items = []
        for child in el:
            if isinstance(child.tag, str):
                item = DEFAULT.create(child)
                if not isinstance(item, Section):
                    raise ValueError(f"<{child.tag}> is not a section")
                items.append(item)
        return cls(el.get("term", ""), items)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME, term=self.term)
        for item in self.items:
            el.append(item.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.term, tuple(self.items))

    def __repr__(self) -> str:
        return f"CompoundMotion({self.term!r}, {self.items!r})"
