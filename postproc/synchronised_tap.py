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
* ``resolve_rigid_taps`` (a generic lowering step): towards a target that writes the synchronised move
  (``Dialect.SYNCHRONISED_TAP``), the rigid-tapping code of another family (Fanuc ``M29``) is left out
  with a comment (the taps after it carry its meaning); towards a target without it, every rigid tap is
  a located error in either ``--on-unsupported`` mode.

The simulator writes a rigid tap as two moves of their own kind, ``"move": "tap"`` (in, then out), with
the pitch as ``"f"`` in mm per revolution (``docs/toolpath-format.md``): ``verify`` compares the kind, so
a tap written as a plain feed fails.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Iterator

from .context import Context
from .dialect import Dialect
from .errors import UnsupportedError
from .expr import Expr
from .ir import Block, Comments, CompoundMotion, MachineFunction, Section, _axes_from_xml, _axes_to_xml
from .machine_functions import RIGID_TAP
from .xmlio import computed_value, lxml_etree

if TYPE_CHECKING:
    from lxml import etree


class RigidTap(Section):
    """A spindle-synchronised tap from where the tool stands to ``axes`` and back (see the module).

    ``axes`` are program units and follow the block's distance mode (inside a ``CompoundMotion``: absolute,
    as every item there); ``pitch`` is the distance per spindle revolution in program units; ``dwell`` the
    seconds the tool waits at the end point before reversing (Fanuc's P; None: none); ``speedup`` the
    spindle speed factor of the way out (LinuxCNC's I; None: the same speed). Neither changes a point.
    """

    XNAME = "RigidTap"
    KEY = "RigidTap"
    __slots__ = ("axes", "pitch", "dwell", "speedup")

    def __init__(self, axes: dict[str, float | Expr], pitch: float | Expr, dwell: float | None = None,
                 speedup: float | None = None) -> None:
        self.axes = axes
        self.pitch = pitch
        self.dwell = dwell
        self.speedup = speedup

    @classmethod
    def from_xml(cls, el: etree._Element) -> "RigidTap":
        axes: dict[str, float | Expr] = {}
        for child in el:
            if child.tag == "Axes":
                axes = _axes_from_xml(child)
            elif isinstance(child.tag, str) and child.tag != "Value":
                raise ValueError(f"unexpected <{child.tag}>")
        raw = el.get("pitch")
        pitch = computed_value(el, "pitch") if raw is None else float(raw)
        if pitch is None:
            raise ValueError("<RigidTap> needs its pitch")
        dwell, speedup = el.get("dwell"), el.get("speedup")
        return cls(axes, pitch, None if dwell is None else float(dwell), None if speedup is None else float(speedup))

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
        _axes_to_xml(el, "Axes", self.axes)
        return el

    def _key(self) -> tuple[Any, ...]:
        return (self.axes, self.pitch, self.dwell, self.speedup)

    def __repr__(self) -> str:
        return f"RigidTap({self.axes!r}, pitch={self.pitch!r}, dwell={self.dwell!r}, speedup={self.speedup!r})"


def rigid_taps(block: Block) -> list[RigidTap]:
    """The rigid taps a block makes: its own section, or the items of its expansion."""
    sections = block.sections
    own = sections.get("RigidTap")
    found = [own] if isinstance(own, RigidTap) else []
    compound = sections.get("CompoundMotion")
    if isinstance(compound, CompoundMotion) and "CannedCycle" not in sections:  # an expansion to be written
        found.extend(item for item in compound.items if isinstance(item, RigidTap))
    return found


def resolve_rigid_taps(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step (the module docstring): after ``expand_canned_cycles``, so an expanded rigid tap cycle
    shows its taps. A refused block is reported and not written, whatever ``--on-unsupported`` says."""
    synchronises = target.SYNCHRONISED_TAP
    family = target.family()
    for block in blocks:
        sections = block.sections
        if "MachineFunction" not in sections and "RigidTap" not in sections and "CompoundMotion" not in sections:
            yield block  # the common block
            continue
        code = sections.get("MachineFunction")
        if synchronises and isinstance(code, MachineFunction) and code.action == RIGID_TAP and code.family != family:
            _leave_out(block, code)
        taps = rigid_taps(block)
        if not taps:
            yield block
            continue
        why = _refusal(taps, target)
        if why is not None:
            ctx.diagnostics.error(UnsupportedError(why, ctx.at(block)))
            continue
        yield block


def _leave_out(block: Block, code: MachineFunction) -> None:
    """The rigid-tapping code goes; a comment says where its meaning went."""
    del block.sections["MachineFunction"]
    comments = block.sections.get("Comments")
    texts = list(comments.texts) if isinstance(comments, Comments) else []
    block.sections["Comments"] = Comments([*texts, f"{code.describe()}: the taps after it are written "
                                                  "spindle-synchronised"])
    block.changed()


def _refusal(taps: list[RigidTap], target: type[Dialect]) -> str | None:
    """Why ``target`` cannot run these taps exactly, or None."""
    if not target.SYNCHRONISED_TAP:
        return (f"a rigid (spindle-synchronised) tap: this translation writes no synchronised tap for {target.NAME}, "
                "and a tap fed without the spindle in step breaks: refused, even with --on-unsupported warn")
    if any(tap.dwell for tap in taps):
        return (f"a rigid tap with a dwell at the bottom (P): {target.NAME}'s synchronised tap reverses at once "
                "and has no dwell there: refused, even with --on-unsupported warn")
    return None
