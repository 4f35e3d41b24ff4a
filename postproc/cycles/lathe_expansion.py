"""A resolved lathe cycle -> its moves, through the turning geometry (``postproc.cycles.turning``).

The bridge between the IR and the geometry library: profile blocks become ``Seg``s and the library's
``TurnMove``s become the ``Motion``/``Feed`` items of a ``CompoundMotion``. The library works in radii
(true distance from the axis); the IR keeps X as the program does (a diameter on a machine that
programs diameters, ``Context.diameter``), so X is halved going in and doubled coming out. Arc centres in
a ``Motion`` are offsets from the arc's start (I is a radius on every lathe).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Sequence

from postproc.block_rules import ArcError, arc_centre
from postproc.context import Context
from postproc.expr import Expr
from postproc.errors import ProgramError
from postproc.ir import Block, Feed, Motion, Section
from postproc.lathe_sections import LatheCycle

if TYPE_CHECKING:
    from .turning.profile import Seg, TurnMove

PROFILE_SECTIONS = frozenset(("Sequence", "Motion", "Feed", "Comments"))
"""What a profile block may hold for the expansion to be exact (nose radius compensation, a spindle
speed or a dwell inside ns..nf are refused: the expansion would drop them)."""


def profile_segments(blocks: Sequence[Block], start: tuple[float, float], ctx: Context, code: str) -> list[Seg]:
    """The profile blocks ns..nf as segments from ``start`` (radius, Z); each refusal names its block."""
    from .turning.profile import Seg
    x, z = start
    feed: float | None = None
    segs: list[Seg] = []
    half = 0.5 if ctx.diameter else 1.0
    incremental = ctx.state.distance == "incremental"
    increments = ctx.increments  # the reading dialect's U/W (``Dialect.INCREMENTAL_AXES``)
    for block in blocks:
        other = [k for k in block.sections if k not in PROFILE_SECTIONS]
        if other and other[0] == "CutterCompensation":
            raise ProgramError(f"{code}: the profile block at line {block.line} turns tool nose radius compensation on "
                               "or off (as Haas programs do in a profile's first and last blocks): how the controller "
                               "compensates inside the cycle is not in our sources, so its moves are not known; "
                               "turn compensation on before the finishing cycle and off after it, outside the "
                               "profile", ctx.at(block))
        if other:
            raise ProgramError(f"{code}: the profile block at line {block.line} holds {_name(other[0])}, which "
                               "a profile may not (only rapid, straight and arc moves and feeds)", ctx.at(block))
        f = block.sections.get("Feed")
        if isinstance(f, Feed):
            if not isinstance(f.value, float):
                raise ProgramError(f"{code}: a computed F in the profile cannot be expanded", ctx.at(block))
            feed = f.value
        motion = block.sections.get("Motion")
        if not isinstance(motion, Motion):
            continue
        if motion.mode not in ("rapid", "linear", "cw", "ccw"):
            raise ProgramError(f"{code}: the profile block at line {block.line} is a {motion.mode} move, which a "
                               "profile may not hold", ctx.at(block))
        x1, z1 = x, z
        for axis, value in motion.axes.items():
            if not isinstance(value, float):
                raise ProgramError(f"{code}: a computed word in the profile cannot be expanded", ctx.at(block))
            step = increments.get(axis)
            if axis == "X":
                x1 = x + value * half if incremental else value * half
            elif axis == "Z":
                z1 = z + value if incremental else value
            elif step == "X":
                x1 = x + value * half
            elif step == "Z":
                z1 = z + value
            else:
                raise ProgramError(f"{code}: axis {axis} has no place in a lathe profile", ctx.at(block))
        cx = cz = None
        if motion.mode in ("cw", "ccw"):
            radius = motion.radius
            offsets: dict[str, float] = {}
            for a, v in (motion.center or {}).items():
                if isinstance(v, Expr):
                    radius = v  # refused below with the radius
                    break
                offsets[a] = v
            if isinstance(radius, Expr):
                raise ProgramError(f"{code}: a computed word in the profile cannot be expanded", ctx.at(block))
            try:
                centre = arc_centre((z, x), (z1, x1), ("Z", "X"), radius, offsets, motion.mode == "cw",
                                    ctx.arc_end, ctx.state.units == "inch")
            except ArcError as err:
                raise ProgramError(f"{code}: the profile arc at line {block.line}: {err.message}", ctx.at(block)) from None
            if centre is None:
                continue
            cz, cx = centre
        kind = "line" if motion.mode in ("rapid", "linear") else motion.mode
        segs.append(Seg(kind, x, z, x1, z1, cx, cz, feed, block.line, motion.mode == "rapid"))  # type: ignore[arg-type]
        x, z = x1, z1
    return segs


def expand(cycle: LatheCycle, start: tuple[float, float], profile: list[Seg] | None, feed: float | None,
           ctx: Context, rough_type: str = "I") -> list[TurnMove]:
    """The cycle's moves from ``start`` (radius, Z), by the turning library; radius parameters in.
    ``rough_type``: G71/G72 type I (the ns block moves one axis) or II (it names both)."""
    p = cycle.params
    half = 0.5 if ctx.diameter else 1.0
    kind = cycle.kind

    def x(name: str) -> float:
        return float(p[name]) * half

    def f(name: str) -> float:
        return float(p[name])

    limit = ctx.setup.limits.moves_per_block
    diameter_allowance = f("allow_x") * (1.0 if ctx.diameter else 2.0) if "allow_x" in p else 0.0
    moves: list[TurnMove]
    if kind == "turn_finish":
        from .turning.finishing import finishing
        moves = finishing(start, _need(profile), feed)
    elif kind == "turn_rough":
        from .turning.rough_turning import rough_turning
        moves = rough_turning(start, _need(profile), f("depth"), f("retract"), diameter_allowance, f("allow_z"), feed,
                             type_ii=rough_type == "II", limit=limit)
    elif kind == "face_rough":
        from .turning.rough_facing import rough_facing
        moves = rough_facing(start, _need(profile), f("depth"), f("retract"), diameter_allowance, f("allow_z"), feed,
                            type_ii=rough_type == "II", limit=limit)
    elif kind == "pattern_repeat":
        from .turning.pattern_repeat import pattern_repeat
        moves = pattern_repeat(start, _need(profile), f("relief_x"), f("relief_z"), int(p["passes"]),
                               diameter_allowance, f("allow_z"), feed)
    elif kind == "turn_single":
        from .turning.single_turning import single_turning
        moves = single_turning(start, x("x"), f("z"), f("taper"), feed)
    elif kind == "face_single":
        from .turning.single_facing import single_facing
        moves = single_facing(start, x("x"), f("z"), f("taper"), feed)
    elif kind == "thread_single":
        from .turning.single_threading import single_threading
        moves = single_threading(start, x("x"), f("z"), _lead(feed), f("taper"), int(p.get("chamfer", 0)))
    elif kind == "face_peck":
        from .turning.peck_face import peck_face
        moves = peck_face(start, x("x"), f("z"), f("step_z"), f("retract"), f("step_x"), f("relief"), feed, limit)
    elif kind == "groove":
        from .turning.groove import groove
        moves = groove(start, x("x"), f("z"), f("step_x"), f("retract"), f("step_z"), f("relief"), feed, limit)
    elif kind == "thread_multi":
        from .turning.threading import threading
        moves = threading(start, x("x"), f("z"), _lead(feed), f("height"), f("first_depth"), int(p["finish_passes"]),
                          int(p["chamfer"]), float(p["angle"]), f("min_depth"), f("allowance"), f("taper"), limit)
    else:
        raise ProgramError(f"no expansion for the lathe cycle {kind}")
    return moves


def to_sections(moves: Sequence[TurnMove], start: tuple[float, float], ctx: Context) -> list[Section]:
    """``TurnMove``s -> absolute ``Motion`` items in program units (X doubled on a diameter machine), a
    ``Feed`` item wherever the feed changes; a spindle-synchronised move is a ``thread`` motion."""
    scale = 2.0 if ctx.diameter else 1.0
    items: list[Section] = []
    x, z = start
    feed: float | None = None
    for move in moves:
        if move.kind != "rapid" and move.feed is not None and move.feed != feed:
            feed = move.feed
            items.append(Feed(feed))
        axes: dict[str, float | Expr] = {"X": move.x * scale, "Z": move.z}
        if move.kind == "rapid":
            items.append(Motion("rapid", axes))
        elif move.kind == "feed":
            items.append(Motion("thread" if move.note.startswith("thread") else "linear", axes))
        else:
            if move.cx is None or move.cz is None:
                raise ProgramError("a lathe cycle arc without its centre")
            centre: dict[str, float | Expr] = {"X": move.cx - x, "Z": move.cz - z}
            items.append(Motion(move.kind, axes, centre))
        x, z = move.x, move.z
    return items


def _need(profile: list[Seg] | None) -> list[Seg]:
    if profile is None:
        raise ProgramError("the cycle has no profile")
    return profile


def _lead(feed: float | None) -> float:
    if feed is None:
        raise ProgramError("a threading cycle needs its lead F")
    return feed


def _name(key: str) -> str:
    return {"CutterCompensation": "tool nose radius compensation", "SpindleSpeed": "a spindle speed",
            "Dwell": "a dwell", "SpindleMode": "a spindle speed mode", "FeedMode": "a feed mode"}.get(key, key)


def start_point(ctx: Context) -> tuple[float, float] | None:
    """Where the tool is (radius, Z), or None while unknown."""
    pos: dict[str, Any] = ctx.state.position
    x, z = pos.get("X"), pos.get("Z")
    if x is None or z is None:
        return None
    return (x * (0.5 if ctx.diameter else 1.0), z)
