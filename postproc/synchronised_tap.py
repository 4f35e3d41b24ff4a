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

from typing import TYPE_CHECKING, Any, Iterator

from mypy_extensions import mypyc_attr

from .context import Context
from .dialect import Dialect
from .errors import PostprocError, ProgramError, UnsupportedError
from .expr import Expr
from .ir import (Block, Comments, CompoundMotion, CycleCancel, DistanceMode, Feed, MachineFunction, ReturnLevel,
                 Section, SpindleSpeed, _axes_from_xml, _axes_to_xml)
from .state import PLANE_AXES
from .machine_functions import RIGID_TAP
from .xmlio import computed_value, lxml_etree

if TYPE_CHECKING:
    from lxml import etree


@mypyc_attr(allow_interpreted_subclasses=True)
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
    shows its taps. A refused block is reported and not written, whatever ``--on-unsupported`` says. Back to
    its own dialect with no cycle expanded by force, every tap stays as written: the stream passes through."""
    if target.NAME == ctx.dialect and not ctx.setup.cycles.expanded():
        return blocks
    return _resolve(blocks, ctx, target)


def _resolve(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    synchronises = target.SYNCHRONISED_TAP
    family = target.family()
    cycle_code = target.RIGID_TAP_CODE
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
        if cycle_code and not synchronises and "RigidTap" in sections:
            try:
                yield from as_tap_cycle(block, ctx, target, sections["RigidTap"])  # type: ignore[arg-type]
            except PostprocError as err:
                ctx.diagnostics.error(err)
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


def as_tap_cycle(block: Block, ctx: Context, target: type[Dialect], tap: RigidTap) -> Iterator[Block]:
    """A synchronised tap as the target's rigid tap cycle (the module docstring): three blocks."""
    from .cycles.section import CannedCycle  # (here: the cycles package imports this module's RigidTap)
    state = ctx.state
    at = ctx.at(block)
    normal = PLANE_AXES[state.plane][2]
    if tap.dwell or isinstance(tap.pitch, Expr) or any(isinstance(v, Expr) for v in tap.axes.values()):
        raise UnsupportedError("a rigid tap with a computed word or a dwell: no tap cycle is written for it", at)
    incremental = state.distance == "incremental"
    start = state.position.get(normal)
    if start is None:
        raise ProgramError(f"a rigid tap where the tool's {normal} position is unknown: {target.NAME}'s tap cycle "
                           "needs its start as the R level (program a move to a known point first)", at)
    for axis, value in tap.axes.items():
        if axis != normal and (value != 0.0 if incremental else value != state.position.get(axis)):
            raise UnsupportedError(f"a rigid tap that moves {axis} (an oblique tap): {target.NAME}'s tap cycle "
                                   f"taps along {normal} only", at)
    if normal not in tap.axes:
        raise UnsupportedError(f"a rigid tap that does not move {normal}: {target.NAME}'s tap cycle taps along "
                               f"{normal} only", at)
    end = tap.axes[normal]
    assert not isinstance(end, Expr)  # (refused above)
    bottom = float(end) + (start if incremental else 0.0)
    rpm, direction, mode = state.spindle_rpm, state.spindle, state.feed_mode
    if direction not in ("cw", "ccw") or not rpm:
        raise ProgramError("a rigid tap with the spindle stopped or at no speed cannot be run", at)
    if mode not in ("per_min", "per_rev"):
        raise UnsupportedError(f"a rigid tap in {mode.replace('_', ' ')} feed: no tap cycle feed says its pitch", at)
    pitch = tap.pitch
    assert not isinstance(pitch, Expr)
    code = MachineFunction(target.family(), target.RIGID_TAP_CODE, target.RIGID_TAP_CODE, RIGID_TAP,
                           "rigid tapping")
    head = Block(block.line, None, block.eol or "\n")
    head.sections = {"MachineFunction": code, "SpindleSpeed": SpindleSpeed(float(rpm))}
    yield head
    del block.sections["RigidTap"]
    block.changed()
    sections = block.sections
    if incremental:
        sections["DistanceMode"] = DistanceMode("absolute")
    sections["ReturnLevel"] = ReturnLevel("r")
    sections["CannedCycle"] = CannedCycle(
        "tap" if direction == "cw" else "tap_left", call=True, semantics="fanuc", return_level="r",
        plane=state.plane, r=start, bottom=bottom, spindle=direction, pitch=pitch,
        words={normal: bottom, ctx.cycle_words.level if ctx.cycle_words is not None else "R": start},
        feed=pitch * float(rpm) if mode == "per_min" else pitch)
    sections["Feed"] = Feed(pitch * float(rpm) if mode == "per_min" else pitch)
    yield block
    tail = Block(block.line, None, block.eol or "\n")
    tail.sections = {"CycleCancel": CycleCancel()}
    if state.return_level != "r":
        tail.sections["ReturnLevel"] = ReturnLevel(state.return_level)
    if isinstance(state.feed, (int, float)):
        tail.sections["Feed"] = Feed(float(state.feed))
    if incremental:
        tail.sections["DistanceMode"] = DistanceMode("incremental")
    yield tail
