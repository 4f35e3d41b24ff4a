"""The stock-removal algorithm G71 and G72 share, worked in the canonical frame (see ``profile.Frame``).

In the canonical frame the tool infeeds toward -x and cuts toward -z; the part lies below the
profile (smaller x) and the stock above it. Levels are horizontal lines Δd apart below A'; at each
level the tool cuts every span of z where the offset profile lies below the level (one span for a
type I profile, one more per pocket for type II), then one contour pass along the offset profile
removes what the levels left (never more than Δd deep) and the tool returns to A.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Literal, Sequence

from postproc.errors import ProgramError

from .profile import (EPS, Frame, Point, Seg, TurnMove, arc_contains, arc_level_points, arc_radius,
                      arc_sweep, check_chain, contour_moves, drop_still, finite, same, shifted, sign)

MONOTONIC_TOL = 1e-7
"""How far a profile may step back along an axis and still count as monotonic (float noise of /2)."""


@dataclass(frozen=True)
class Roughing:
    """The words of one stock-removal cycle, in the original frame (radius values)."""

    name: str
    """How messages name the cycle (no G code: the caller's wording)."""
    start: Point
    profile: Sequence[Seg]
    depth: float
    retract: float
    offset: Point
    """The finishing allowance as a vector (radius X, Z)."""
    feed: float | None
    type_ii: bool | None
    limit: int
    infeed_axis: str
    """'X' for turning (G71), 'Z' for facing (G72)."""


@dataclass(frozen=True)
class Span:
    """A stretch of a level the tool can cut: from z_hi down to z_lo; ``first`` when it starts at A'."""

    z_hi: float
    z_lo: float
    first: bool


def rough(words: Roughing) -> list[TurnMove]:
    """Validate the words, choose the frame, cut, and map the moves back (see the module docstring)."""
    name, start, profile = words.name, words.start, words.profile
    finite(name, x0=start[0], z0=start[1], depth=words.depth, retract=words.retract, u=words.offset[0],
           w=words.offset[1], feed=words.feed)
    check_chain(profile, start, name)
    if not words.depth > 0.0:
        raise ProgramError(f"{name}: the depth of cut must be positive, not {words.depth:g}")
    if words.retract < 0.0:
        raise ProgramError(f"{name}: the retract amount must not be negative, not {words.retract:g}")
    frame = _frame(words)
    canon = [frame.seg(s) for s in profile]
    ax, az = frame.point(*start)
    ox, oz = frame.point(*words.offset)
    _check_shape(words, canon)
    offset = [shifted(s, ox, oz) for s in canon]
    moves = _cut((ax, az), (ax + ox, az + oz), offset, words)
    return drop_still([frame.move(m) for m in moves], start)


def _frame(words: Roughing) -> Frame:
    """Swap for facing; reflect so the ns block infeeds toward -x and the profile runs toward -z."""
    swap = words.infeed_axis == "Z"
    ns, last = words.profile[0], words.profile[-1]
    probe = Frame(swap, 1.0, 1.0)
    ax, _ = probe.point(ns.x0, ns.z0)
    bx, bz = probe.point(ns.x1, ns.z1)
    _, cz = probe.point(last.x1, last.z1)
    infeed, along = sign(bx - ax), sign(cz - bz)
    other = "Z" if words.infeed_axis == "X" else "X"
    if infeed == 0:
        raise ProgramError(f"{words.name}: the first profile block (line {ns.line}) must move in "
                           f"{words.infeed_axis}: its direction is the direction of infeed")
    if along == 0:
        raise ProgramError(f"{words.name}: the profile does not move in {other} (it ends where it starts)")
    return Frame(swap, -infeed, -along)


def _check_shape(words: Roughing, canon: Sequence[Seg]) -> bool:
    """Type I (the ns block moves only along the infeed axis) or II, and the monotonic rules of each.

    Type I: along the profile after ns, x never decreases and z never increases (canonical frame).
    Type II: z never increases. Arcs must not pass an extreme of a checked axis. Returns type II.
    """
    name = words.name
    ns = canon[0]
    other = "Z" if words.infeed_axis == "X" else "X"
    if ns.kind != "line":
        raise ProgramError(f"{name}: the first profile block (line {ns.line}) must be a straight move")
    moves_along = not same(ns.z0, ns.z1, MONOTONIC_TOL)
    type_ii = moves_along if words.type_ii is None else words.type_ii
    if moves_along and not type_ii:
        raise ProgramError(f"{name}: the first profile block (line {ns.line}) moves in {other}, "
                           f"which makes the cycle type II")
    if ns.z1 > ns.z0 + MONOTONIC_TOL:
        raise ProgramError(f"{name}: the profile is not monotonic in {other} at line {ns.line}")
    for seg in canon[1:]:
        _monotonic(seg, "z", -1.0, name, other)
        if not type_ii:
            _monotonic(seg, "x", 1.0, name, words.infeed_axis)
    return type_ii


def _monotonic(seg: Seg, axis: str, direction: float, name: str, label: str) -> None:
    """Refuse a segment that moves against ``direction`` along ``axis`` anywhere."""
    a0, a1 = (seg.x0, seg.x1) if axis == "x" else (seg.z0, seg.z1)
    bad = direction * (a1 - a0) < -MONOTONIC_TOL
    if seg.kind != "line" and not bad:
        extremes = (math.pi / 2.0, -math.pi / 2.0) if axis == "x" else (0.0, math.pi)
        bad = any(arc_contains(seg, a, strict=True) for a in extremes)
    if bad:
        raise ProgramError(f"{name}: the profile is not monotonic in {label} at line {seg.line}")


def _lowest(segs: Sequence[Seg]) -> float:
    low = math.inf
    for seg in segs:
        low = min(low, seg.x0, seg.x1)
        if seg.kind != "line" and arc_contains(seg, -math.pi / 2.0, strict=False):
            assert seg.cx is not None
            low = min(low, seg.cx - arc_radius(seg))
    return low


def _highest(segs: Sequence[Seg]) -> float:
    high = -math.inf
    for seg in segs:
        high = max(high, seg.x0, seg.x1)
        if seg.kind != "line" and arc_contains(seg, math.pi / 2.0, strict=False):
            assert seg.cx is not None
            high = max(high, seg.cx + arc_radius(seg))
    return high


def _pieces(seg: Seg, level: float) -> list[tuple[bool, float, float]]:
    """The segment cut where it crosses the level: (below the level?, z at start, z at end) in order."""
    if seg.kind == "line":
        ts = [0.0, 1.0]
        dx = seg.x1 - seg.x0
        if abs(dx) > EPS:
            t = (level - seg.x0) / dx
            if EPS < t < 1.0 - EPS:
                ts = [0.0, t, 1.0]
        points = [(seg.x0 + t * dx, seg.z0 + t * (seg.z1 - seg.z0)) for t in ts]
    else:
        assert seg.cx is not None and seg.cz is not None
        r, sweep = arc_radius(seg), arc_sweep(seg)
        a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
        turn = -1.0 if seg.kind == "cw" else 1.0
        fractions = {0.0, 1.0}
        for angle in arc_level_points(seg, level):
            f = ((angle - a0) * turn) % (2.0 * math.pi) / sweep
            if EPS < f < 1.0 - EPS:
                fractions.add(f)
        ts = sorted(fractions)
        points = []
        for f in ts:
            a = a0 + turn * f * sweep
            points.append((seg.cx + r * math.sin(a), seg.cz + r * math.cos(a)))
        points[0], points[-1] = (seg.x0, seg.z0), (seg.x1, seg.z1)
    out = []
    for i in range(len(ts) - 1):
        mid = _x_at(seg, (ts[i] + ts[i + 1]) / 2.0)
        out.append((mid < level + EPS, points[i][1], points[i + 1][1]))
    return out


def _x_at(seg: Seg, t: float) -> float:
    if seg.kind == "line":
        return seg.x0 + t * (seg.x1 - seg.x0)
    assert seg.cx is not None and seg.cz is not None
    a0 = math.atan2(seg.x0 - seg.cx, seg.z0 - seg.cz)
    turn = -1.0 if seg.kind == "cw" else 1.0
    return seg.cx + arc_radius(seg) * math.sin(a0 + turn * t * arc_sweep(seg))


def spans(contour: Sequence[Seg], level: float, z_start: float) -> list[Span]:
    """Where a cut at ``level`` meets no part, in cutting order: runs of the contour (B'..C') below the
    level. A run from B' reaches back to ``z_start`` (A'); runs of no length in z (a slot as wide as
    nothing) are dropped; anything not below the level between two runs is a wall the tool stops at."""
    out: list[Span] = []
    run: list[float] | None = None  # [z_hi, z_lo] of the run being collected
    first = True
    for seg in contour:
        for below, z0, z1 in _pieces(seg, level):
            if below:
                if run is None:
                    run = [z_start if first else z0, z1]
                else:
                    run[1] = z1
            else:
                if run is not None:
                    out.append(Span(run[0], run[1], run[0] == z_start and not out))
                run = None
            first = False
    if run is not None:
        out.append(Span(run[0], run[1], run[0] == z_start and not out))
    return [s for s in out if s.z_hi - s.z_lo > EPS]


def _cut(start: Point, a1: Point, offset: Sequence[Seg], words: Roughing) -> list[TurnMove]:
    """The canonical toolpath: approach A', the levels, the contour pass B'..C', the return to A."""
    (ax, az), (a1x, a1z) = start, a1
    depth, e, feed = words.depth, words.retract, words.feed
    ns, contour = offset[0], offset[1:]
    infeed_kind: Literal["rapid", "feed"] = "rapid" if ns.rapid else "feed"
    infeed_feed = None if ns.rapid else feed
    top = max(ax, a1x, _highest(offset))
    bottom = min(ns.x1, _lowest(contour)) if contour else ns.x1
    count = max(0, math.ceil((a1x - bottom) / depth - 1e-9) - 1) if a1x > bottom else 0
    if count > words.limit:
        raise ProgramError(f"{words.name}: {count} levels of {depth:g} exceed the limit of {words.limit}")
    moves = [TurnMove("rapid", a1x, a1z, note="approach")]
    x, z = a1x, a1z
    previous = a1x  # the level cut last (A' before the first)
    clear = max(ax, a1x)

    def go(kind: Literal["rapid", "feed"], nx: float, nz: float, note: str, f: float | None = None) -> None:
        nonlocal x, z
        moves.append(TurnMove(kind, nx, nz, feed=f, note=note))
        x, z = nx, nz

    for k in range(1, count + 1):
        level = a1x - k * depth
        for span in spans(contour, level, a1z):
            if span.first:
                if not same(z, a1z):
                    go("rapid", x, a1z, "return")
                if x > previous + e:
                    go("rapid", previous + e, a1z, "return")
                go(infeed_kind, level, a1z, "infeed", infeed_feed)
                go("feed", level, span.z_lo, "rough", feed)
                go("rapid", level + e, span.z_lo + e, "retract")
            else:
                go("rapid", top, z, "clear")
                go("rapid", top, span.z_hi, "clear")
                go("rapid", previous if k > 1 else clear, span.z_hi, "approach")
                go("feed", level, span.z_hi, "plunge", feed)
                go("feed", level, span.z_lo, "rough", feed)
                go("rapid", top, span.z_lo, "retract")
        previous = level
    if not same(z, a1z):
        go("rapid", x, a1z, "return")
    if x > previous + e:
        go("rapid", previous + e, a1z, "return")
    go(infeed_kind, ns.x1, ns.z1, "infeed", infeed_feed)
    moves += contour_moves(contour, feed, "contour", rapid_as_rapid=False)
    end = contour[-1] if contour else ns
    moves += [TurnMove("rapid", top, end.z1, note="return"), TurnMove("rapid", top, az, note="return"),
              TurnMove("rapid", ax, az, note="return")]
    return moves
