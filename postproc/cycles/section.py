"""CannedCycle: one hole cycle block, resolved to absolute levels and positions (DIALECTS.md §3.5).

The record is what every dialect's hole cycle normalises to: the expansion syntaxes read it to make
the exact motion, and a writer whose controller runs the cycle natively writes it back from ``words``.
All lengths are in program units; levels are values on the drilling axis of ``plane``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar, Final

from mypy_extensions import mypyc_attr

from postproc.ir import Section
from postproc.xmlio import XAttr, decode, encode, lxml_etree

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

WORD_ORDER = "XYZABCUVWRQPIJKL"
"""Order in which the programmed cycle words are kept and written."""


@mypyc_attr(allow_interpreted_subclasses=True)
class CannedCycle(Section):
    """A hole cycle programmed or repeated in this block.

    ``repeat`` is the number of holes this block makes (K/L; 0 when the block only changes the cycle
    data, as with K0 or a block without hole position). ``position`` is the first hole in the plane,
    ``step`` the increment to each further hole (G91 rows; empty in G90, where a repeat drills the same
    spot). ``start`` is where the tool was before the block. ``semantics`` names how the controller moves
    through the cycle (a family's registered rules, ``postproc.cycles.semantics``: always said, the core has no
    default family), ``call`` whether the block programs the cycle code itself.
    """

    XNAME = "CannedCycle"
    KEY = "CannedCycle"
    XATTRS = (
        XAttr("kind"), XAttr("call", bool, False), XAttr("semantics"),
        XAttr("return_level", str, "initial"), XAttr("plane", str, "XY"),
        XAttr("initial", float, None), XAttr("r", float, None), XAttr("bottom", float, None),
        XAttr("top", float, None), XAttr("q", float, None), XAttr("clearance", float, None),
        XAttr("dwell", float, None), XAttr("orient", float, None), XAttr("feed", float, None),
        XAttr("repeat", int, 1), XAttr("spindle", str, None), XAttr("motion", str, None),
        XAttr("expand", bool, False), XAttr("pitch", float, None),
    )
    DICTS: ClassVar[tuple[str, ...]] = ("start", "position", "step", "shift", "words")
    """Child elements, one per axis dictionary; ``shift`` is None unless the cycle shifts the tool."""
    __slots__ = ("kind", "call", "semantics", "return_level", "plane", "initial", "r", "bottom", "top", "q",
                 "clearance", "dwell", "orient", "feed", "repeat", "spindle", "motion", "expand",
                 "pitch", "start", "position", "step", "shift", "words")
    """Every attribute of ``XATTRS`` and ``DICTS`` (written out: a compiled class body names them)."""

    def __init__(self, kind: str, *, semantics: str, call: bool = False,
                 return_level: str = "initial", plane: str = "XY", initial: float | None = None,
                 r: float | None = None, bottom: float | None = None, top: float | None = None,
                 q: float | None = None, clearance: float | None = None, dwell: float | None = None,
                 orient: float | None = None, feed: float | None = None, repeat: int = 1,
                 spindle: str | None = None, motion: str | None = None, start: dict[str, float] | None = None,
                 position: dict[str, float] | None = None, step: dict[str, float] | None = None,
                 shift: dict[str, float] | None = None, words: dict[str, float | int] | None = None,
                 expand: bool = False, pitch: float | None = None) -> None:
        self.kind = kind
        self.call = call
        self.semantics = semantics
        self.return_level = return_level
        self.plane = plane
        self.initial = initial
        """Initial level: the drilling-axis level when the cycle was first commanded after a cancel."""
        self.r = r
        self.bottom = bottom
        """Lowest level of the cut (for back boring: where the cut starts)."""
        self.top = top
        """Back boring only: the top of the counterbore, where the upward cut ends."""
        self.q = q
        """Peck depth (G73/G83)."""
        self.clearance = clearance
        """G73 retract or G83 re-approach clearance d, in program units."""
        self.dwell = dwell
        """Dwell at the bottom in seconds, None when none was programmed."""
        self.orient = orient
        """Oriented spindle stop angle in degrees (shifting cycles)."""
        self.feed = feed
        self.repeat = repeat
        self.spindle = spindle
        """Spindle direction before the cycle (RS274 restarts the spindle in it)."""
        self.motion = motion
        """The group-01 mode in force around the cycle (a plain move after G80 uses it again)."""
        self.start = start if start is not None else {}
        self.position = position if position is not None else {}
        self.step = step if step is not None else {}
        self.shift = shift
        """Tool shift vector of G76/G87 (direction from the set-up or from I/J)."""
        self.words = words if words is not None else {}
        """The cycle words as programmed in this block (F travels as the block's Feed section)."""
        self.expand = expand
        """Written as its motion whatever the target runs: the block's motion reaches the hole by a move
        that cancels the cycle on the target (a hole pattern's feed move or arc between points)."""
        self.pitch = pitch
        """A rigid tap (``postproc.cycles.rigid_tap``): the thread pitch per spindle revolution, program units;
        None for every other cycle, a floating tap included."""

    @classmethod
    def from_xml(cls, el: etree._Element) -> "CannedCycle":
        kwargs: dict[str, Any] = {a.name: a.parse(el) for a in cls.XATTRS}
        for child in el:
            if not isinstance(child.tag, str):
                continue
            name = _DICT_OF_TAG.get(child.tag)
            if name is None:
                raise ValueError(f"unexpected <{child.tag}>")
            if name == "words":
                kwargs[name] = {k: decode(float if _is_float(v) else int, v) for k, v in child.attrib.items()}
            else:
                kwargs[name] = {k: float(v) for k, v in child.attrib.items()}
        return cls(**kwargs)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        for attr in self.XATTRS:
            attr.emit(el, getattr(self, attr.name))
        for name in self.DICTS:
            values = getattr(self, name)
            if values is None or (not values and name != "shift"):
                continue
            child = etree.SubElement(el, _TAG_OF_DICT[name])
            for key, value in values.items():
                child.set(key, encode(value))
        return el

    def _key(self) -> tuple[Any, ...]:
        return tuple(getattr(self, a.name) for a in self.XATTRS) + tuple(
            None if getattr(self, d) is None else tuple(getattr(self, d).items()) for d in self.DICTS)

    def __repr__(self) -> str:
        return (f"CannedCycle({self.kind!r}, repeat={self.repeat}, position={self.position!r}, "
                f"r={self.r!r}, bottom={self.bottom!r})")


_TAG_OF_DICT: Final = {"start": "Start", "position": "Position", "step": "Step", "shift": "Shift", "words": "Words"}
_DICT_OF_TAG: Final = {v: k for k, v in _TAG_OF_DICT.items()}


def _is_float(text: str) -> bool:
    """Words keep their kind: integers (K, L, Fanuc's P) are written without a point."""
    return any(c in text for c in ".eEna")
