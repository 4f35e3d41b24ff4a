"""HolePattern: a pattern of holes at which the active canned cycle is repeated (Fagor's multiple
machining, DIALECTS.md §2.3), in neutral terms.

The section says what the pattern is (a line, a parallelogram's perimeter, a grid, a full circle or an
arc of one), never how a dialect spells it: a dialect's reader maps its words to these fields, and a
writer whose controller runs patterns natively writes them back. All lengths are in program units, in
the plane of the pattern (``plane``: first and second plane axis, ``postproc.ir.state.PLANE_AXES``);
angles are in degrees, counter-clockwise from the first plane axis to the second.

Point 1 is the first point, where the tool stands when the pattern starts (the controller machined it
with the cycle's own block); the pattern block machines the others, except those in ``skip``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from postproc.cycles.section import CannedCycle
from postproc.ir import Section
from postproc.ir.state import PLANE_AXES
from postproc.xmlio import XAttr, lxml_etree

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

KINDS = ("line", "parallelogram", "grid", "circle", "arc")
"""The pattern kinds, each documented at ``HolePattern``."""
MOVES = ("rapid", "linear", "cw", "ccw")
"""How the tool travels between points: in rapid, at the feed ``feed``, or along the circle."""
SIDED = frozenset(("parallelogram", "grid"))
ROUND = frozenset(("circle", "arc"))


class HolePattern(Section):
    """Where a block repeats the active cycle, and how the tool travels between the points.

    ``line``: ``count`` points ``step`` apart, in the direction ``angle``.
    ``parallelogram``: the perimeter of a parallelogram whose first side has ``count`` points ``step``
    apart in the direction ``angle`` and whose second side, at ``angle2`` from the first, has ``count2``
    points ``step2`` apart; the points are numbered from point 1 along the first side, up the second,
    back along the third and down the fourth (counter-clockwise when ``angle2`` is between 0 and 180).
    ``grid``: the same sides, every point of the parallelogram they span, row by row along the first
    side, each row in the opposite direction to the one before (the tool zig-zags).
    ``circle``: ``count`` points on the circle around ``center`` (the offset from point 1 to the
    centre), ``step`` degrees apart (positive: counter-clockwise); ``count`` times ``step`` is a full
    turn. ``arc``: the same on an arc of ``count - 1`` steps.

    ``move`` says how the tool goes from each machined point to the next machined one ('rapid': the
    cycle's own positioning; 'linear' at ``feed``; 'cw'/'ccw' along the circle at ``feed``, only on a
    circle or an arc whose ``step`` turns the same way). The tool stays at the level where the cycle
    left it.

    Filled in when the pattern is resolved against the program (``postproc.patterns.resolve``):
    ``start`` (where the tool stood: point 1 and the level), ``cycle`` (the active cycle, the record
    repeated at every point), ``incremental`` (the distance mode in force, for a point-by-point
    translation) and ``split`` (how many items of the block's ``CompoundMotion`` belong to each
    machined point, in order, so a lowering can give each point a block of its own).
    """

    XNAME = KEY = "HolePattern"
    XATTRS = (
        XAttr("kind"), XAttr("plane", str, "XY"), XAttr("count", int), XAttr("step", float),
        XAttr("angle", float, 0.0), XAttr("count2", int, None), XAttr("step2", float, None),
        XAttr("angle2", float, 90.0), XAttr("move", str, "rapid"), XAttr("feed", float, None),
        XAttr("incremental", bool, False),
    )
    __slots__ = tuple(a.name for a in XATTRS) + ("center", "skip", "start", "cycle", "split")

    def __init__(self, kind: str, count: int, step: float, *, plane: str = "XY", angle: float = 0.0,
                 count2: int | None = None, step2: float | None = None, angle2: float = 90.0,
                 center: dict[str, float] | None = None, skip: tuple[int, ...] = (), move: str = "rapid",
                 feed: float | None = None, start: dict[str, float] | None = None,
                 cycle: CannedCycle | None = None, incremental: bool = False,
                 split: tuple[int, ...] = ()) -> None:
        self.kind = kind
        self.plane = plane
        self.count = count
        """Points along the first side (line, parallelogram, grid) or in all (circle, arc), point 1 included."""
        self.step = step
        """Distance between neighbouring points of the first side, or the angle between neighbouring
        points of a circle or arc (degrees, positive counter-clockwise)."""
        self.angle = angle
        """Direction of the first side from the first plane axis, in degrees."""
        self.count2 = count2
        self.step2 = step2
        """Points and their distance along the second side (parallelogram and grid only)."""
        self.angle2 = angle2
        """Angle between the first and the second side, in degrees."""
        self.center = center if center is not None else {}
        """Circle and arc: from point 1 to the centre, per plane axis letter."""
        self.skip = skip
        """Numbers of the points not machined (point 1 is the first point)."""
        self.move = move
        self.feed = feed
        """Feed of the moves between points ('linear', 'cw', 'ccw'); the cycle keeps its own feed."""
        self.start = start if start is not None else {}
        self.cycle = cycle
        self.incremental = incremental
        self.split = split
        check(self)

    @classmethod
    def from_xml(cls, el: etree._Element) -> "HolePattern":
        kwargs: dict[str, Any] = {a.name: a.parse(el) for a in cls.XATTRS}
        skip = el.get("skip")
        kwargs["skip"] = tuple(int(n) for n in skip.split()) if skip else ()
        split = el.get("split")
        kwargs["split"] = tuple(int(n) for n in split.split()) if split else ()
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag == "Center":
                kwargs["center"] = {k: float(v) for k, v in child.attrib.items()}
            elif child.tag == "Start":
                kwargs["start"] = {k: float(v) for k, v in child.attrib.items()}
            elif child.tag == CannedCycle.XNAME:
                kwargs["cycle"] = CannedCycle.from_xml(child)
            else:
                raise ValueError(f"unexpected <{child.tag}>")
        return cls(**kwargs)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        for attr in self.XATTRS:
            attr.emit(el, getattr(self, attr.name))
        if self.skip:
            el.set("skip", " ".join(str(n) for n in self.skip))
        if self.split:
            el.set("split", " ".join(str(n) for n in self.split))
        for tag, values in (("Center", self.center), ("Start", self.start)):
            if values:
                child = etree.SubElement(el, tag)
                for key, value in values.items():
                    child.set(key, repr(float(value)))
        if self.cycle is not None:
            el.append(self.cycle.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def _key(self) -> tuple[Any, ...]:
        return tuple(getattr(self, a.name) for a in self.XATTRS) + (
            tuple(self.center.items()), self.skip, tuple(self.start.items()), self.cycle, self.split)

    def __repr__(self) -> str:
        return (f"HolePattern({self.kind!r}, count={self.count}, step={self.step!r}, center={self.center!r}, "
                f"skip={self.skip!r}, move={self.move!r})")


def check(p: HolePattern) -> None:
    """The pattern's own consistency (a reader checks its words before; this guards XML and the API).
    Raises ValueError naming the field."""
    if p.kind not in KINDS:
        raise ValueError(f"unknown hole pattern kind {p.kind!r} (one of {', '.join(KINDS)})")
    _plane_axes(p.plane)
    if p.move not in MOVES:
        raise ValueError(f"unknown move between points {p.move!r} (one of {', '.join(MOVES)})")
    if p.count < 1:
        raise ValueError("a hole pattern has at least one point")
    if p.kind in SIDED:
        if p.count2 is None or p.step2 is None:
            raise ValueError(f"a {p.kind} needs count2 and step2 (its second side)")
        if p.count < 2 or p.count2 < 2:
            raise ValueError(f"each side of a {p.kind} has at least two points")
    elif p.count2 is not None or p.step2 is not None:
        raise ValueError(f"a {p.kind} has no second side")
    if p.kind in ROUND:
        if set(p.center) - set(_plane_axes(p.plane)):
            raise ValueError(f"the centre of a {p.kind} lies in the {p.plane} plane")
        if p.step == 0:
            raise ValueError(f"the angular step of a {p.kind} cannot be 0")
        if not any(p.center.values()):
            raise ValueError(f"the centre of a {p.kind} cannot be its first point")
    elif p.move in ("cw", "ccw"):
        raise ValueError(f"a {p.kind} has no circle to move along")
    if p.move == "cw" and p.step > 0 or p.move == "ccw" and p.step < 0:
        raise ValueError(f"a {p.move} move between points turns against the step {p.step!r}")
    if p.move != "rapid" and (p.feed is None or p.feed <= 0):
        raise ValueError(f"a {p.move} move between points needs a positive feed")
    if any(n < 2 for n in p.skip):
        raise ValueError("point 1 is machined by the cycle's own block and cannot be skipped")
    total = total_points(p)
    if any(n > total for n in p.skip):
        raise ValueError(f"the {p.kind} has {total} points: point {max(p.skip)} cannot be skipped")


def total_points(p: HolePattern) -> int:
    """How many points the pattern has, point 1 included."""
    if p.kind == "parallelogram":
        return 2 * (p.count + (p.count2 or 0)) - 4
    if p.kind == "grid":
        return p.count * (p.count2 or 0)
    return p.count


def _plane_axes(plane: str) -> tuple[str, str]:
    if plane not in PLANE_AXES:
        raise ValueError(f"unknown plane {plane!r}")
    first, second, _ = PLANE_AXES[plane]
    return first, second
