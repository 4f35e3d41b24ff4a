"""Inverse-time feed (G93) where the target has none: each move's feed per minute, exactly.

In inverse time a feed move's F says the move takes 1/F minutes, whatever its length ([V] LinuxCNC
src/emc/rs274ngc/interp_convert.cc and the G-code manual: "the move should be completed in one divided by
the F number minutes", arcs included, an F on every G1/G2/G3; [K] grbl: the same, from the NIST RS274/NGC
it follows). So the same move at ``length x F`` per minute takes the same time: the length of a line, the
length of an arc (radius x swept angle, with a helix's rise: sqrt(arc^2 + dz^2)). A target without G93
(``Dialect.INVERSE_TIME_FEED`` False: Fanuc, where G93 is an option [?]; ISG, where no inverse-time code is
confirmed [?]; Fagor 8070, whose inverse-time code is G32 [?] and whose G93 means a polar origin [K]; Mach3,
whose G93 is not confirmed in a manual at hand [?]) gets G94 and those feeds (``convert_inverse_time``);
``per_minute`` turns a toolpath's inverse-time feeds into the same per-minute ones, so ``verify`` compares
the two programs' feeds.

The conversion needs where each move starts: it follows the moves (absolute, incremental, units: the lowering's
one tracker, ``postproc.lowering.units_and_distance``; plane) from the reading's state at the program start (the
step starts before the first block is read: a lathe's ZX plane, a start in another feed mode or in the machine's
power-on units hold there) and forgets the position at anything else that could move the tool or its frame (a
reference return, a machine-coordinate move, a work offset or coordinate setting, an expanded cycle, a verbatim
code); an inverse-time move from an unknown point, and one that turns a rotary axis (its per-minute feed means
another speed on each controller), are located errors.
"""

from __future__ import annotations

import math
from typing import Any, Final, Iterable, Iterator

from ..block_rules import ArcError, arc_centre
from ..context import Context
from ..dialect import INVERSE_TIME_KEY, Dialect
from ..errors import UnsupportedError
from ..ir.expr import Expr
from ..geometry.arcs import arc_sweep
from ..ir import Block, Feed, FeedMode, Motion
from ..ir.state import PLANE_AXES
from .units_and_distance import UnitsAndDistance

LINEAR: Final = ("X", "Y", "Z")
ROTARY: Final = frozenset("ABCUVW")
FEED_MOVES: Final = frozenset(("linear", "cw", "ccw"))
_KEEPS_POSITION: Final = frozenset((
    "Feed", "FeedMode", "Units", "DistanceMode", "Plane", "Comments", "Sequence", "SpindleControl",
    "SpindleSpeed", "SpindleMode", "Coolant", "Dwell", "ToolSelect", "ToolChange", "ProgramControl", "PathControl",
    "ReturnLevel", "CycleCancel", "TapeMark", "ProgramStart", "BlockDelete", "CutterCompensation",
    "ToolLengthOffset", "DynamicCutterCompensation", "Motion", "Assign", "Control", "Label", "Generated",
    "XProgramming",
))
"""Sections after which the programmed point is where the moves left it."""


def move_length(start: dict[str, float], end: dict[str, float], plane: str, mode: str,
                centre: tuple[float, float] | None) -> float:
    """The length of a move from ``start`` to ``end`` (X, Y, Z in one unit); an arc needs its ``centre``
    in the plane."""
    if mode not in ("cw", "ccw") or centre is None:
        return math.dist([start[a] for a in LINEAR], [end[a] for a in LINEAR])
    a1, a2, normal = PLANE_AXES[plane]
    s, e = (start[a1], start[a2]), (end[a1], end[a2])
    radius = math.hypot(s[0] - centre[0], s[1] - centre[1])
    arc = radius * arc_sweep(s, e, centre, mode == "cw")
    return math.hypot(arc, end[normal] - start[normal])


def convert_inverse_time(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step (module docstring); a target with G93, and any program read by a dialect without it
    (no block can be in inverse time: a dialect reads and writes by one code table), get the blocks as they
    are, so the common translations pay nothing for the step."""
    if target.INVERSE_TIME_FEED or INVERSE_TIME_KEY not in ctx.run_data:
        return blocks
    return _convert(blocks, ctx, target)


def _convert(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    state = ctx.state  # (the program's start: no block is read yet)
    modes = UnitsAndDistance(state.units == "inch", state.distance != "incremental")
    plane = state.plane
    inverse = state.feed_mode == "inverse_time"
    position: dict[str, float] | None = None  # mm, X Y Z; None: not known
    for block in blocks:
        sections = block.sections
        if not sections:
            yield block
            continue
        get = sections.get
        modes.follow(sections)
        s = get("Plane")
        if s is not None:
            plane = s.plane  # type: ignore[attr-defined]
        mode = get("FeedMode")
        if mode is not None:
            inverse = mode.mode == "inverse_time"  # type: ignore[attr-defined]
            if inverse:
                sections["FeedMode"] = FeedMode("per_min")
                block.changed()
        scale = modes.scale
        motion = get("Motion")
        if any(key not in _KEEPS_POSITION and not _inert(sections, key) for key in sections) or (
                isinstance(motion, Motion) and (motion.mode not in ("rapid", "linear", "cw", "ccw")
                                                or "MachineCoordinates" in sections)):
            position = None
            if inverse and isinstance(motion, Motion) and motion.mode in FEED_MOVES:
                ctx.diagnostics.error(_error(ctx, block, "an inverse-time move whose start the translation cannot "
                                             "follow (after a reference return, a frame change or a verbatim "
                                             "code): program its start absolutely first"))
                continue
            yield block
            continue
        if not isinstance(motion, Motion) or motion.mode is None:
            yield block
            continue
        end = _end(motion, position, not modes.absolute, scale)
        if inverse and motion.mode in FEED_MOVES:
            try:
                feed = _feed(ctx, block, target, motion, position, end, plane, scale)
            except UnsupportedError as err:
                ctx.diagnostics.error(err)
                continue
            if feed is not None:
                sections["Feed"] = feed
                block.changed()
        position = end
        yield block


def _feed(ctx: Context, block: Block, target: type[Dialect], motion: Motion, start: dict[str, float] | None,
          end: dict[str, float] | None, plane: str, scale: float) -> Feed | None:
    """The per-minute feed of an inverse-time move (None: it does not move, its F stays)."""
    if any(axis in ROTARY for axis in motion.axes):
        raise _error(ctx, block, "an inverse-time move of a rotary axis has no exact feed per minute on the "
                                 f"{target.NAME} dialect (it has no inverse-time feed)")
    if start is None or end is None:
        raise _error(ctx, block, "an inverse-time move from a point the translation does not know: program X, "
                                 "Y and Z absolutely before it")
    feed = block.sections.get("Feed")
    if not isinstance(feed, Feed) or isinstance(feed.value, Expr):
        raise _error(ctx, block, "an inverse-time move needs its own F (1/minutes)")
    length = move_length(start, end, plane, motion.mode or "", _centre(ctx, block, motion, start, end, plane,
                                                                       scale))
    return Feed(length * feed.value / scale) if length > 0.0 else None


def _inert(sections: dict[str, Any], key: str) -> bool:
    """A verbatim code that does nothing a tool path shows (``NativeCode.inert``) leaves the point as it is."""
    return key == "NativeCode" and bool(getattr(sections[key], "inert", False))


def _end(motion: Motion, position: dict[str, float] | None, incremental: bool,
         scale: float) -> dict[str, float] | None:
    """Where a move ends (mm), or None when its start is needed and unknown."""
    end = dict(position) if position is not None else {}
    for axis in LINEAR:
        value = motion.axes.get(axis)
        if value is None:
            continue
        if isinstance(value, Expr):
            return None
        if incremental:
            if position is None:
                return None
            end[axis] = position[axis] + value * scale
        else:
            end[axis] = value * scale
    return end if all(axis in end for axis in LINEAR) else None


def _centre(ctx: Context, block: Block, motion: Motion, start: dict[str, float], end: dict[str, float],
            plane: str, scale: float) -> tuple[float, float] | None:
    if motion.mode not in ("cw", "ccw"):
        return None
    a1, a2, _ = PLANE_AXES[plane]
    offsets = {a: v * scale for a, v in (motion.center or {}).items() if not isinstance(v, Expr)}
    radius = motion.radius
    if isinstance(radius, Expr):
        raise _error(ctx, block, "an inverse-time arc with a computed radius")
    try:
        return arc_centre((start[a1], start[a2]), (end[a1], end[a2]), (a1, a2),
                          None if radius is None else float(radius) * scale, offsets, motion.mode == "cw",
                          ctx.arc_end, scale != 1.0, scale)
    except ArcError as err:
        raise UnsupportedError(err.message, ctx.at(block)) from None


def _error(ctx: Context, block: Block, message: str) -> UnsupportedError:
    return UnsupportedError(message, ctx.at(block))


def per_minute(events: Iterable[dict[str, Any]], start: dict[str, float] | None = None) -> Iterator[dict[str, Any]]:
    """A toolpath (header first) with every inverse-time feed given as the feed per minute (mm/min) that
    moves the same way: the header and the events then say ``per_min``. The points are the controlled
    ones when the toolpath has them (``verify`` hands this its controlled points); ``start``: where the
    program starts (mm, by axis)."""
    it = iter(events)
    head = next(it, None)
    if head is None:
        return
    default = head.get("feed_mode", "per_min")
    if default == "inverse_time":
        head = {k: v for k, v in head.items() if k != "feed_mode"}
    yield head
    where = None if start is None else {a: float(start.get(a, start.get(a.lower(), 0.0))) for a in LINEAR}
    for ev in it:
        if "move" not in ev:
            yield ev
            continue
        end = {a: float(ev.get(a.lower(), 0.0)) for a in LINEAR}
        mode = ev.get("feed_mode", default)
        if mode == "inverse_time" and "f" in ev and where is not None:
            plane = ev.get("plane", "XY")
            a1, a2, _ = PLANE_AXES[plane]
            centre = None
            if ev["move"] in ("cw", "ccw"):
                centre = (float(ev["c" + a1.lower()]), float(ev["c" + a2.lower()]))
            kind = {"feed": "linear"}.get(ev["move"], ev["move"])
            ev = dict(ev)
            ev["f"] = round(move_length(where, end, plane, kind, centre) * float(ev["f"]), 6)
            ev.pop("feed_mode", None)
        elif ev.get("feed_mode") == "per_min" and default == "inverse_time":
            ev = {k: v for k, v in ev.items() if k != "feed_mode"}
        where = end
        yield ev
