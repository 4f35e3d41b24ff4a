"""The simple sections: one modal word or one action each (units, plane, feed, spindle, tool, coolant,
dwell, cycle call...), written as a dialect spells it and read into its neutral meaning."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import TYPE_CHECKING, Any

from .expr import Expr
from ..xmlio import XAttr, lxml_etree, where
from .section import Section

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


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
    """Tape start/end marker line; ``title``: what the program's first ``%`` line holds after the ``%``
    (its leader, which the control skips up to the end of the line), kept so that a translation does not
    drop it."""

    XNAME = "TapeMark"

    KEY = "TapeMark"
    __slots__ = ("title",)
    XATTRS = (XAttr("title", str, None),)
    title: str | None

    def __init__(self, title: str | None = None) -> None:
        self.title = title


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
    the neutral order (``postproc.ir.event_order``) makes it after."""

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
    """'exact_stop', 'exact_path' or 'cutting' path control. 'exact_stop': the machine stops at the end of each
    block (Fanuc G61 [K], LinuxCNC G61.1 [V]); 'exact_path': the path runs through every programmed point, the
    machine slowing at a corner as it must, not necessarily stopping (grbl's G61, its one mode [V: grbl ``gcode.h``
    ``CONTROL_MODE_EXACT_PATH // G61``, ``gcode.c`` refuses G61.1]; LinuxCNC's G61 [V: ``g-code.adoc``]): the two
    reach the same programmed points, so a target without an exact path writes its exact stop
    (``WordWriter.path_control_words``) and ``verify`` takes them as one; 'cutting' may blend (leave the points).
    ``tolerance`` and ``naive``: how far a blended path may
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
    __slots__ = ("texts", "semicolon")

    def __init__(self, texts: list[str], semicolon: bool = False) -> None:
        self.texts = texts
        self.semicolon = semicolon
        """The last text was a ``;`` comment (RS274/NGC reading): LinuxCNC acts on some ``( )`` comments and never
        on a ``;`` one, so its writer keeps that one inert (``postproc_linuxcnc.writer``). Not in the XML: a
        block rebuilt from it, or a section made anew, says False (written as before)."""

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
