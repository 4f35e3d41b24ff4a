"""Resolve a hole pattern against the program: the active cycle at every machined point, with the
moves between the points, as the block's ``CompoundMotion`` (what the simulator runs and a target
without patterns writes).

A dialect's reader builds the ``HolePattern`` from its words (the geometry) and calls
``resolve_hole_pattern`` from its block syntax, before ``CannedCycleResolveSyntax`` runs on the block
(which then leaves the block's words alone: they are the pattern's, not cycle data).
"""

from __future__ import annotations

from postproc.ir.expr import Expr

from postproc.context import Context
from postproc.cycles.expansion import CycleExpansion, TooManyMoves
from postproc.cycles.resolve import active_cycle
from postproc.cycles.section import CannedCycle
from postproc.errors import Location, ProgramError
from postproc.ir import Block, CompoundMotion, Feed, Motion, Section
from postproc.ir.state import PLANE_AXES

from .geometry import Hop, first_point, pattern_hops
from .section import HolePattern, total_points


def resolve_hole_pattern(block: Block, pattern: HolePattern, ctx: Context, name: str, at: Location) -> None:
    """Give ``block`` the resolved ``pattern`` and its motion, and move the tracked position to the last
    machined point. ``name`` is how the dialect spells the pattern (for messages), ``at`` where the
    block programs it. Raises a located ``ProgramError`` when the pattern cannot run here."""
    state = ctx.state
    active = active_cycle(state)
    if active is None:
        what = "a canned cycle with computed words" if state.cycle is not None else "no canned cycle"
        raise ProgramError(f"{name} repeats the active canned cycle, and {what} is active", at)
    cycle, expansion = active
    if cycle.plane != pattern.plane:
        raise ProgramError(f"{name} lies in the {pattern.plane} plane, the active cycle in the {cycle.plane} "
                           "plane", at)
    start: dict[str, float] = {}
    for axis in PLANE_AXES[pattern.plane]:
        value = state.position.get(axis)
        if value is None:
            raise ProgramError(f"the first point of {name} is unknown: {axis} was never positioned absolutely", at)
        start[axis] = value
    pattern.start = start
    pattern.cycle = cycle
    pattern.incremental = state.distance == "incremental"
    try:
        items, split, end = expand_pattern(pattern, cycle, expansion, ctx.setup.limits.moves_per_block)
    except TooManyMoves as err:
        raise ProgramError(f"{name}: {err.message}", at) from None
    except ValueError as err:
        raise ProgramError(f"{name}: {err}", at) from None
    pattern.split = tuple(split)
    ctx.moves_made += len(items)
    block.add(pattern)
    block.add(CompoundMotion(cycle.kind, items))
    for axis, value in end.items():
        state.position[axis] = value


def expand_pattern(pattern: HolePattern, cycle: CannedCycle, expansion: CycleExpansion,
                   limit: int) -> tuple[list[Section], list[int], dict[str, float]]:
    """(items, items per machined point, where the tool ends): for each machined point after point 1,
    the move that reaches it (none for 'rapid': the cycle's own positioning is that rapid) and the
    cycle there. ``TooManyMoves`` beyond ``limit`` items: before any point is made when the points alone
    need more (a count of a hundred million makes neither a list of its points nor a move), else at the
    point that passes it."""
    points = total_points(pattern)
    machined = points - 1 - len(frozenset(pattern.skip))
    if machined * expansion.least_moves_per_hole(cycle) > limit:
        raise TooManyMoves(f"the pattern machines {machined} points, which make more than {limit} moves in one "
                           "block (the set-up's <Limits movesPerBlock>)", "repeat")
    first, second, normal = PLANE_AXES[pattern.plane]
    pos = dict(pattern.start)
    feed = cycle.feed
    items: list[Section] = []
    split: list[int] = []
    previous = first_point(pattern)
    for hop in pattern_hops(pattern):
        mine: list[Section] = []
        if hop.mode != "rapid":
            if pattern.feed != feed:
                mine.append(Feed(pattern.feed))  # type: ignore[arg-type]
                feed = pattern.feed
            mine.append(_move(hop, pos, first, second, normal))
            pos[first], pos[second] = hop.point
            if feed != cycle.feed:
                mine.append(Feed(cycle.feed))  # type: ignore[arg-type]
                feed = cycle.feed
        here = cycle_at(pattern, cycle, pos, hop.point, previous)
        previous = hop.point
        left = limit - len(items) - len(mine)
        try:
            holes, end = expansion.expand(here, max(left, 0))
        except TooManyMoves:  # its message would count only this point's moves against what is left
            holes = None
        if holes is None or len(holes) > left:
            raise TooManyMoves(f"the pattern makes more than {limit} moves in one block by its point {hop.number} "
                               f"of {points} (the set-up's <Limits movesPerBlock>)", "repeat")
        mine.extend(holes)
        items.extend(mine)
        split.append(len(mine))
        pos = dict(end)
    return items, split, pos


def cycle_at(pattern: HolePattern, cycle: CannedCycle, start: dict[str, float], point: tuple[float, float],
             previous: tuple[float, float]) -> CannedCycle:
    """The active cycle made once at ``point`` from ``start`` (a repeat of it, not a new call); its words
    are the point, absolute or (``pattern.incremental``) from ``previous``, as a point-by-point program
    writes them."""
    first, second, _ = PLANE_AXES[pattern.plane]
    a, b = point
    words: dict[str, float | int] = (
        {first: a - previous[0], second: b - previous[1]} if pattern.incremental else {first: a, second: b})
    return CannedCycle(
        cycle.kind, call=False, semantics=cycle.semantics, return_level=cycle.return_level, plane=cycle.plane,
        initial=cycle.initial, r=cycle.r, bottom=cycle.bottom, top=cycle.top, q=cycle.q,
        clearance=cycle.clearance, dwell=cycle.dwell, orient=cycle.orient, feed=cycle.feed, repeat=1,
        spindle=cycle.spindle, motion=cycle.motion, start=dict(start), position={first: a, second: b},
        step={first: words[first], second: words[second]} if pattern.incremental else {},
        shift=None if cycle.shift is None else dict(cycle.shift), words=words,
        pitch=cycle.pitch)  # a rigid tap stays rigid at every point (as ``postproc.fast.holes`` has it)


def _move(hop: Hop, pos: dict[str, float], first: str, second: str, normal: str) -> Motion:
    """The feed move or arc to the hop's point, at the level where the tool is (absolute axes)."""
    a, b = hop.point
    target: dict[str, float | Expr] = {axis: pos[axis] for axis in "XYZ" if axis in pos}
    target[first], target[second] = a, b
    if hop.centre is None:
        return Motion(hop.mode, target)
    ca, cb = hop.centre
    centre: dict[str, float | Expr] = {first: ca - pos[first], second: cb - pos[second]}
    return Motion(hop.mode, target, center=centre)
