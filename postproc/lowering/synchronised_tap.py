"""Rigid (spindle-synchronised) tapping: one IR section, and the lowering step that keeps it exact.

A rigid tap feeds the tap in step with the spindle, reverses the spindle at the bottom and feeds back out
in step: the thread is cut by the pitch, not by a feed rate. The same holes fed as plain moves (a floating
tap's motion, without the holder) break the tap, so a rigid tap is never written as feed moves:

* ``RigidTap`` is the neutral meaning, what LinuxCNC's ``G33.1 Z.. K..`` says [V: LinuxCNC
  ``docs/src/gcode/g-code.adoc`` "G33.1 Rigid Tapping"; ``interp_convert.cc`` ``convert_straight`` emits
  ``START_SPEED_FEED_SYNCH(spindle, K)``, ``RIGID_TAP(x, y, z)``, ``STOP_SPEED_FEED_SYNCH()`` and leaves
  the current point where it was]: from the current point to the end point synchronised at ``pitch`` per
  revolution, the spindle reversed there, synchronised back to the start, the spindle reversed again.
  A Fanuc rigid tap cycle (``M29 S..`` then ``G84``/``G74``) expands into positioning rapids, one
  ``RigidTap`` per hole from the R level to the bottom and back, and the G98 return
  (``postproc.cycles.rigid_tap``).
* ``resolve_rigid_taps`` (a generic lowering step, ``postproc.cycles.rigid_tap_lowering``): towards a target that writes the synchronised move
  (``Dialect.SYNCHRONISED_TAP``), the rigid-tapping code of another family (Fanuc ``M29``) is left out
  with a comment (the taps after it carry its meaning). Towards a target that taps rigidly with a tap
  cycle after a code (``Dialect.RIGID_TAP_CODE``: Fanuc's ``M29 S..`` then ``G84``/``G74``), a synchronised
  tap along the drilling axis becomes that code with the spindle speed in force, one ``G99`` tap cycle at
  the spot with R at the start level and the bottom at the end point (so the tool returns to the start,
  as G33.1 does), ``G84`` for a clockwise spindle and ``G74`` for a counter-clockwise one, F the pitch times
  S (feed per minute) or the pitch (per revolution), then the cycle cancel and the return level, feed and
  distance mode that were in force. Towards a target with neither, every rigid tap is a located error in
  either ``--on-unsupported`` mode.

The simulator writes a rigid tap as two moves of their own kind, ``"move": "tap"`` (in, then out), with
the pitch as ``"f"`` in mm per revolution (``docs/toolpath-format.md``): ``verify`` compares the kind, so
a tap written as a plain feed fails.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from mypy_extensions import mypyc_attr

from ..ir.expr import Expr
from ..ir import Block, CompoundMotion, Section, axes_from_xml, axes_to_xml
from ..xmlio import computed_value, lxml_etree

if TYPE_CHECKING:
    from lxml import etree


@mypyc_attr(allow_interpreted_subclasses=True)
class RigidTap(Section):
    """A spindle-synchronised tap from where the tool stands to ``axes`` and back (see the module).

    ``axes`` are program units and follow the block's distance mode (inside a ``CompoundMotion``: absolute,
    as every item there); ``pitch`` is the distance per spindle revolution in program units; ``dwell`` the
    seconds the tool waits at the end point before reversing (Fanuc's P; None: none); ``speedup`` the
    spindle speed factor of the way out (LinuxCNC's I; None: the same speed). Neither changes a point.
    ``stroke`` is None for the whole tap (in and back); "in" or "out" for one stroke of a controller that
    programs them apart (ISG's ``G331`` in, ``G332`` out with the spindle reversed: ``Dialect.TAP_STROKES``),
    a move to ``axes`` that does change the point; the sign of its ``pitch`` is then the thread's hand
    (negative: left-hand, [V] TF5200 "Tapping (G331/G332)").
    """

    XNAME = "RigidTap"
    KEY = "RigidTap"
    __slots__ = ("axes", "pitch", "dwell", "speedup", "stroke")

    def __init__(self, axes: dict[str, float | Expr], pitch: float | Expr, dwell: float | None = None,
                 speedup: float | None = None, stroke: str | None = None) -> None:
        self.axes = axes
        self.pitch = pitch
        self.dwell = dwell
        self.speedup = speedup
        self.stroke = stroke

    @classmethod
    def from_xml(cls, el: etree._Element) -> "RigidTap":
        axes: dict[str, float | Expr] = {}
        for child in el:
            if child.tag == "Axes":
                axes = axes_from_xml(child)
            elif isinstance(child.tag, str) and child.tag != "Value":
                raise ValueError(f"unexpected <{child.tag}>")
        raw = el.get("pitch")
        pitch = computed_value(el, "pitch") if raw is None else float(raw)
        if pitch is None:
            raise ValueError("<RigidTap> needs its pitch")
        dwell, speedup = el.get("dwell"), el.get("speedup")
        return cls(axes, pitch, None if dwell is None else float(dwell), None if speedup is None else float(speedup),
                   el.get("stroke"))

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        etree = lxml_etree()
        el = etree.Element(self.XNAME)
        if isinstance(self.pitch, Expr):
            etree.SubElement(el, "Value", of="pitch").append(self.pitch.make_xml_source())
        else:
            el.set("pitch", repr(float(self.pitch)))
        if self.dwell is not None:
            el.set("dwell", repr(float(self.dwell)))
        if self.speedup is not None:
            el.set("speedup", repr(float(self.speedup)))
        if self.stroke is not None:
            el.set("stroke", self.stroke)
        axes_to_xml(el, "Axes", self.axes)
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.axes, self.pitch, self.dwell, self.speedup, self.stroke)

    def __repr__(self) -> str:
        return (f"RigidTap({self.axes!r}, pitch={self.pitch!r}, dwell={self.dwell!r}, speedup={self.speedup!r}, "
                f"stroke={self.stroke!r})")


def rigid_taps(block: Block) -> list[RigidTap]:
    """The rigid taps a block makes: its own section, or the items of its expansion. (One list, appended: an
    expansion's items as a comprehension extending it cost two lists more an expanded hole, ~500 instructions
    compiled.)"""
    sections = block.sections
    own = sections.get("RigidTap")
    found: list[RigidTap] = []
    if isinstance(own, RigidTap):
        found.append(own)
    compound = sections.get("CompoundMotion")
    if isinstance(compound, CompoundMotion) and "CannedCycle" not in sections:  # an expansion to be written
        for item in compound.items:
            if isinstance(item, RigidTap):
                found.append(item)
    return found
