"""Motion sections: a programmed move (``Motion``) and the explicit moves a construct stands for
(``CompoundMotion``, made when read)."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import TYPE_CHECKING, Any, Callable

from .expr import Expr
from ..xmlio import DEFAULT, computed_value, lxml_etree
from .section import Section, axes_from_xml, axes_to_xml

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


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
                axes = axes_from_xml(c)
            elif c.tag == "Center":
                center = axes_from_xml(c)
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
        axes_to_xml(el, "Axes", self.axes)
        if self.center is not None:
            axes_to_xml(el, "Center", self.center)
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.mode, self.axes, self.center, self.radius)

    def __repr__(self) -> str:
        return f"Motion({self.mode!r}, {self.axes!r}, center={self.center!r}, radius={self.radius!r})"




_NOTHING: list[Section] = []
"""The items a lazy motion is built with, replaced at once (never read, never changed)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class CompoundMotion(Section):
    """The explicit motion a construct stands for (a canned cycle's rapids, feeds, dwells, spindle
    actions), in execution order. Moves inside are absolute, in program units.

    ``end``/``ended``: where the moves leave the axes, as ``postproc.lowering.point_after.compound_end``
    found it the first time a step asked (every step that follows the point asks it of every expanded
    hole: walked once, not once a step). Setting ``items`` forgets it; the items are not changed in place
    after it is asked (the cycle expansion's own touches, ``expand_canned_cycles``, come before)."""

    XNAME = "CompoundMotion"

    KEY = "CompoundMotion"
    __slots__ = ("term", "_items", "_make", "end", "ended")

    def __init__(self, term: str, items: list[Section]) -> None:
        self.term = term
        self._items: list[Section] | None = items
        self._make: Callable[[], list[Section]] | None = None
        self.end: dict[str, float | None] | None = None
        """The moves' end (``point_after.compound_end``: read only), once ``ended``."""
        self.ended = False

    @staticmethod
    def lazy(term: str, make: Callable[[], list[Section]]) -> "CompoundMotion":
        """The motion made only when something reads it: a target that keeps the construct native (a
        Fanuc cycle written as a Fanuc cycle) never pays for its expansion. ``make`` raises the located
        error the expansion finds, at the first reading. (A static method: compiled, a class method's
        ``cls(...)`` is a generic call of the class, a constructor named is a native one.)"""
        motion = CompoundMotion(term, _NOTHING)
        motion._items = None
        motion._make = make
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
        self.end, self.ended = None, False  # other moves: their end is found again

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
