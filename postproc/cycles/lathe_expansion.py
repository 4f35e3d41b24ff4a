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
from postproc.ir.expr import Expr
from postproc.errors import ProgramError
from postproc.ir import Block, Feed, Motion, Section
from postproc.ir.lathe_sections import LatheCycle

if TYPE_CHECKING:
    from postproc.compensation.rules import CutterRules

    from .turning.profile import Seg, TurnMove

PROFILE_SECTIONS = frozenset(("Sequence", "Motion", "Feed", "Comments"))
"""What a profile block may hold for the expansion to be exact (nose radius compensation, a spindle
speed or a dwell inside ns..nf are refused: the expansion would drop them)."""


def profile_segments(blocks: Sequence[Block], start: tuple[float, float], ctx: Context, code: str,
                     nose: bool = False) -> list[Seg]:
    """The profile blocks ns..nf as segments from ``start`` (radius, Z); each refusal names its block.
    ``nose``: the first block turns tool nose radius compensation on and the last turns it off (checked by
    the caller, whose controller runs that form: ``nose_shape``); compensation anywhere else is refused."""
    from .turning.profile import Seg
    x, z = start
    feed: float | None = None
    segs: list[Seg] = []
    half = 0.5 if ctx.diameter else 1.0
    incremental = ctx.state.distance == "incremental"
    increments = ctx.increments  # the reading dialect's U/W (``Dialect.INCREMENTAL_AXES``)
    last = len(blocks) - 1
    for i, block in enumerate(blocks):
        other = [k for k in block.sections if k not in PROFILE_SECTIONS
                 and not (nose and k == "CutterCompensation" and i in (0, last))]
        if other and other[0] == "CutterCompensation":
            raise ProgramError(f"{code}: the profile block at line {block.line} turns tool nose radius compensation on "
                               "or off: this controller's rules for compensation inside the cycle are not in our "
                               "sources (Fanuc T alarms on compensation inside the profile [K]; the Haas form, on in "
                               "the first block and off in the last, is read for a Haas set-up), so its moves are "
                               "not known; turn compensation on before the finishing cycle and off after it, "
                               "outside the profile", ctx.at(block))
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


def nose_shape(segs: Sequence[Seg], start: tuple[float, float], side: str, radius: float, tip: tuple[int, int],
               kind: str, rough_type: str, code: str, rules: CutterRules) -> list[Seg]:
    """The profile a roughing cycle roughs to when its first block turns nose compensation on and its last
    turns it off (``turning.nose_path``, under the controller's ``rules``): the approach from ``start`` to
    where the tip path begins, then the tip path of the blocks between (the departure block is no part of
    it). A type I cycle keeps its approach along the infeed axis and reaches the tip path's start along the
    other (monotonic, as type I must be) [?]."""
    from .turning.nose_path import nose_path
    from .turning.profile import Seg
    if len(segs) < 3:
        raise ProgramError(f"{code}: a profile that turns tool nose radius compensation on in its first block and "
                           "off in its last needs blocks between them that move")
    path = nose_path(segs, side, radius, tip, code, rules)
    ns, first = segs[0], path[0]
    x0, z0 = start
    if rough_type == "II":
        return [Seg("line", x0, z0, first.x0, first.z0, None, None, ns.feed, ns.line, ns.rapid), *path]
    corner = (first.x0, z0) if kind != "face_rough" else (x0, first.z0)
    approach = Seg("line", x0, z0, corner[0], corner[1], None, None, ns.feed, ns.line, ns.rapid)
    if abs(corner[0] - first.x0) <= 1e-12 and abs(corner[1] - first.z0) <= 1e-12:
        return [approach, *path]
    bridge = Seg("line", corner[0], corner[1], first.x0, first.z0, None, None, first.feed, first.line, False)
    return [approach, bridge, *path]


def finishing_split(start: tuple[float, float], profile: Sequence[Seg],
                    feed: float | None) -> tuple[list[TurnMove], list[TurnMove]]:
    """G70's moves (``turning.finishing``) in two parts: every block but the last, then the last block and the
    return to ``start``, for a profile whose last block turns nose compensation off as it moves."""
    from dataclasses import replace
    from .turning.profile import TurnMove, check_chain, contour_moves, drop_still
    check_chain(profile, start, "finishing cycle")
    own = [seg if seg.feed is not None else replace(seg, feed=feed) for seg in profile]
    head = drop_still(contour_moves(own[:-1], None, "finish"), start)
    end = (own[-2].x1, own[-2].z1) if len(own) > 1 else start
    tail = contour_moves(own[-1:], None, "finish")
    tail.append(TurnMove("rapid", start[0], start[1], note="return"))
    return head, drop_still(tail, end)


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
