"""The compensated stretch written as moves (``cutter_compensation``): each programmed move goes into the
compensation (``CompensatedMoves._move``), and what the compensation releases is written (``_release``,
``_rewrite``): a move at its compensated end (an arc about its compensated centre, in I/J from the compensated
start), an outside corner in a block of its own at the feed of the move after it, the stretch in absolute
positions (or by increments in a frame of its own). Under G93 a compensated move is written per minute
(``_per_minute``); an exit move in machine coordinates takes the plane's axes back to the programmed point
(``_exit_in_machine``). The rules behind each are in ``cutter_compensation``'s docstring.
"""

from __future__ import annotations

import math
from typing import Final

from mypy_extensions import mypyc_attr

from ..block_rules import ArcError, arc_centre
from ..context import Context
from ..errors import ProgramError
from ..ir.expr import Expr
from ..ir import Block, DistanceMode, Feed, FeedMode, Motion
from ..compensation.cutter_radius import Item, Segment
from ..compensation.rules import CutterRules
from ..setup.work_offsets import declared_offsets, offset_beyond_frame
from .cutter_point import ProgrammedPoint, Unresolvable, UnknownHere
from .inverse_time import move_length

ARC_OFF_MM = 0.005
ARC_OFF_RATIO = 0.001
"""How far an arc's end may lie off the circle through its start before a controller refuses it: [V] grbl
``gcode.c`` (error 33 beyond 0.005 mm and 0.1 % of the radius). LinuxCNC joins an arc to a move within
its corner tolerance (0.05 rad) without moving the start onto the compensated circle, so its compensated
arc may start off the circle; such an arc is refused here rather than written one grbl rejects."""
_SEGMENT_KIND: Final = {"rapid": "rapid", "linear": "feed", "cw": "cw", "ccw": "ccw"}
_MOTION_MODE: Final = {"rapid": "rapid", "feed": "linear", "cw": "cw", "ccw": "ccw"}


def _noise_free(value: float | Expr) -> float | Expr:
    """A computed coordinate rounded to 1e-9 program units: the conversions leave float noise (0.1 in as
    2.54 mm and back is 0.10000000000000002), which a writer that keeps every digit a value needs (Mach3's)
    would write; 1e-9 is far below any controller's resolution."""
    return round(value, 9) if isinstance(value, float) else value


@mypyc_attr(allow_interpreted_subclasses=True)
class CompensatedMoves(ProgrammedPoint):
    """The moves of a compensated stretch in, the compensated blocks out."""

    def __init__(self, ctx: Context, rules: CutterRules, diameters: bool, checking: bool) -> None:
        super().__init__(ctx, rules, self._release, diameters, checking)

    def _move(self, block: Block, motion: Motion) -> None:
        if "MachineCoordinates" in block.sections or motion.mode in ("home", "home2"):
            if self.cutter.side is not None or self.cutter.queue:
                raise ProgramError("a move in machine coordinates or a reference return with cutter compensation "
                                   "on cannot be run")
            # the first move after G40 (the exit move) in machine coordinates: [V] rs274 (LinuxCNC's
            # mmount.ngc, G40 then G53 G0 Z0) runs it straight from the compensated end to the programmed
            # point, X and Y included; written as it is, it keeps the compensated X and Y, so each plane axis
            # the block does not name is written as the programmed point's machine position (``_exit_in_machine``)
            self._exit_in_machine(block, motion)
            self.cutter.arc_banned = False
            self._track(block)
            self.out.append(block)
            return
        kind = _SEGMENT_KIND.get(motion.mode or "")
        if kind is None:
            raise Unresolvable(f"motion '{motion.mode}' with cutter compensation on cannot be resolved")
        a1, a2, normal = self.cutter.axes
        start_1, start_2 = self._in_plane(self.pos)
        target = self._target(motion)
        end_1, end_2 = self._in_plane(target)
        if start_1 is None or start_2 is None or end_1 is None or end_2 is None:
            raise UnknownHere(f"the start point of a compensated move is not known (program {a1} and {a2} "
                               "absolutely after the origin moved)")
        end = {axis: value for axis, value in target.items() if value is not None}
        seg = Segment(kind, {"line": block.line}, end, self.pos.get(normal) or 0.0)
        seg.fields["source"] = id(seg)
        start = (start_1, start_2)
        self.held[id(seg)] = (block, not self.modes.absolute)
        if kind in ("cw", "ccw"):
            offsets = {a: v * self.modes.scale for a, v in (motion.center or {}).items() if isinstance(v, (int, float))}
            if isinstance(motion.radius, Expr) or any(isinstance(v, Expr) for v in (motion.center or {}).values()):
                raise Unresolvable("a computed arc under cutter compensation cannot be resolved")
            radius = None if motion.radius is None else motion.radius * self.modes.scale
            try:
                c = arc_centre(start, (end_1, end_2), (a1, a2), radius, offsets, kind == "cw",
                               self.ctx.arc_end, self.modes.scale != 1.0, self.modes.scale)
            except ArcError as err:
                raise UnknownHere(err.message) from None
            if c is None:
                raise UnknownHere("a zero-length arc under cutter compensation cannot be resolved")
            seg.centre = seg.ccentre = c
            seg.turn = 1 if kind == "ccw" else -1
            self._per_minute(block, kind, target, c)
            if self.trial is not None:
                self.trial.move(seg, start)
            self.cutter.arc(seg, start)
        else:
            self._per_minute(block, kind, target, None)
            if self.trial is not None:
                self.trial.move(seg, start)
            self.cutter.line(seg, start)
        self.pos = target

    def _exit_in_machine(self, block: Block, motion: Motion) -> None:
        """The exit move in machine coordinates (``G53 G0 Z0`` after G40): a plane axis the block does not name
        must still go from the compensated end to the programmed point, so it is written as that point's
        machine position: the programmed point plus the set-up's offset of the active work system (and the
        external one), the function the simulation puts machine positions in its frame by
        (``setup.work_offsets``). Where that is not known (the program set the offset, the set-up gives
        none, a reference return's intermediate point, a tool offset across the plane), a located error names
        what is missing."""
        names = motion.axes
        u, v = self._in_plane(self.pos)
        a1, a2, _ = self.cutter.axes
        missing = [(axis, programmed) for axis, programmed, at in ((a1, u, self.at[0]), (a2, v, self.at[1]))
                   if axis not in names and (programmed is None or abs(programmed - at) > 1e-9)]
        if not missing:
            return
        needs = (f"a move in machine coordinates or a reference return as the first move after compensation is "
                 f"cancelled cannot be resolved: it also takes {' and '.join(a for a, _ in missing)} from the "
                 "compensated point back to the programmed one")
        if motion.mode not in ("rapid", "linear") or self.diameters:
            raise Unresolvable(f"{needs} (program a move in work coordinates after the cancel first)")
        if any(programmed is None for _, programmed in missing):
            raise Unresolvable(f"{needs}, which is not known here (program a move in work coordinates after the "
                               "cancel first)")
        register = self.length_register
        if register is not None and (not isinstance(register, int) or self.table.sideways(register)):
            raise Unresolvable(f"{needs}, in machine coordinates under a tool offset across the plane (program a "
                               "move in work coordinates after the cancel first)")
        if self.shifted:
            raise Unresolvable(f"{needs}, in machine coordinates after a coordinate setting the frame holds "
                               "(program a move in work coordinates after the cancel first)")
        declared = declared_offsets(self.ctx.setup, ("X", "Y", "Z"), False)
        axes = dict(names)
        for axis, programmed in missing:
            offset, why = offset_beyond_frame(axis, self.work_offset, self.programmed_offsets, declared)
            if offset is None or axis in self.programmed_offsets.get(self.work_offset, {}) \
                    or axis in self.programmed_offsets.get(0, {}):
                raise Unresolvable(f"{needs}, which needs the work offset: {why or 'the program sets it'} (or "
                                   "program a move in work coordinates after the cancel first)")
            assert programmed is not None
            axes[axis] = _noise_free((programmed + offset) / self.modes.scale)
        order = sorted(axes, key=lambda a: "XYZABCUVW".find(a) % 10)
        block.sections["Motion"] = Motion(motion.mode, {a: axes[a] for a in order}, None, None)
        block.changed()

    def _per_minute(self, block: Block, kind: str, target: dict[str, float | None],
                    centre: tuple[float, float] | None) -> None:
        """Under G93, the block's feed per minute: F times its programmed length (see the module docstring)."""
        if not self.inverse_time or kind == "rapid":
            return
        feed = block.sections.get("Feed")
        if not isinstance(feed, Feed) or isinstance(feed.value, Expr):
            raise UnknownHere("an inverse-time move without its F under cutter compensation")
        start = {a: v for a in "XYZ" if (v := self.pos.get(a)) is not None}
        end = {a: v for a in "XYZ" if (v := target.get(a)) is not None}
        if len(start) < 3 or len(end) < 3:
            raise UnknownHere("the start point of a compensated inverse-time move is not known (program X, Y and "
                               "Z absolutely first)")
        length = move_length(start, end, self.plane, "linear" if kind == "feed" else kind, centre)
        block.sections["Feed"] = Feed(feed.value * length / self.modes.scale)
        if not self.per_minute or "FeedMode" in block.sections:  # the first of the stretch, or its own G93
            block.sections["FeedMode"] = FeedMode("per_min")
        block.changed()
        self.per_minute = True

    def _back_to_inverse_time(self, block: Block) -> None:
        """The first block after a stretch written per minute brings G93 back (unless it sets a mode)."""
        if self.per_minute and self.inverse_time and self._idle():
            self.per_minute = False
            if "FeedMode" not in block.sections:
                block.sections["FeedMode"] = FeedMode("inverse_time")
                block.changed()

    def _release(self, item: Item) -> None:
        if self.trial is not None:
            self.trial.record(item)
        if not isinstance(item, Segment):
            self.out.append(item["block"])
            return
        own = self.held.pop(id(item), None)
        if own is not None:
            block, incremental = own
            self._rewrite(block, item, incremental)
            return
        source = self.held.get(item.fields.get("source", 0))  # an outside corner, before the move that makes it
        corner = Block(item.fields["line"], None, "\n")
        if source is not None:
            feed = source[0].sections.get("Feed")
            if isinstance(feed, Feed):
                corner.sections["Feed"] = feed  # the corner runs at the feed of the move after it
                mode = source[0].sections.get("FeedMode")
                if isinstance(mode, FeedMode) and mode.mode == "per_min":
                    corner.sections["FeedMode"] = mode  # that feed per minute (G93 resolved)
        self._rewrite(corner, item, source is not None and source[1])

    def _rewrite(self, block: Block, seg: Segment, incremental: bool) -> None:
        """The block's move as the compensated one, in absolute program units."""
        sections = block.sections
        scale = self.modes.scale
        a1, a2, normal = self.cutter.axes
        xy = seg.xy if seg.xy is not None else (seg.end[a1], seg.end[a2])
        old = sections.get("Motion")
        by_increments = self.by_increments
        origin = self.at if by_increments else (0.0, 0.0)
        axes: dict[str, float | Expr] = {a1: (xy[0] - origin[0]) / scale, a2: (xy[1] - origin[1]) / scale}
        if isinstance(old, Motion) and normal in old.axes and normal in seg.end:
            axes[normal] = (seg.end[normal] - (self.at_normal if by_increments else 0.0)) / scale
        center: dict[str, float | Expr] | None = None
        if seg.turn != 0 and seg.ccentre is not None:
            cc = seg.ccentre
            off = abs(math.hypot(self.at[0] - cc[0], self.at[1] - cc[1]) - math.hypot(xy[0] - cc[0], xy[1] - cc[1]))
            if off > ARC_OFF_MM and off > ARC_OFF_RATIO * math.hypot(xy[0] - cc[0], xy[1] - cc[1]):
                raise Unresolvable(f"the compensated arc starts {off:.4f} mm off its circle (the source controller "
                                       "joins it to a nearly tangent move without a corner and runs it so; written as "
                                       "an arc, the target refuses it)", self.ctx.at(block))
            center = {a1: (cc[0] - self.at[0]) / scale, a2: (cc[1] - self.at[1]) / scale}
        x = axes.get("X")
        if self.diameters and isinstance(x, float):
            axes["X"] = x * 2.0  # a diameter (an arc's I stays a radius)
        axes = {a: _noise_free(axes[a]) for a in "XYZ" if a in axes}  # written X, Y, Z
        if center is not None:
            center = {a: _noise_free(center[a]) for a in "XYZ" if a in center}
        sections["Motion"] = Motion(_MOTION_MODE[seg.kind], axes, center, None)
        self.at = xy
        self.at_normal = seg.end.get(normal, self.at_normal)
        switched = incremental != by_increments  # the block's own mode is not the one it is written in
        if switched:
            sections["DistanceMode"] = DistanceMode("incremental" if by_increments else "absolute")
        block.changed()
        self.out.append(block)
        if switched:
            back = Block(block.line, None, "\n")
            back.sections = {"DistanceMode": DistanceMode("incremental" if incremental else "absolute")}
            self.out.append(back)
