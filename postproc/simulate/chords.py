"""``verify --arcs lines:TOL``: an arc of the source against the run of straight feeds its translation
cut it into (``translate --arcs lines:TOL``), checked on its own terms rather than with the translator's
arithmetic: every chord end lies on the arc (the radius interpolated along it, as the simulator draws
an arc whose end radius differs), every chord's middle and its point nearest the centre lie within TOL of it
(along the rays from the centre: ``postproc.geometry.arc_paths``'s matching of two arcs), the axes outside the
plane move in proportion to the angle (a helix), each chord turns the arc's way by at most half a turn,
and together they end where the arc ends, at its feed.

verify merges OUT's straight feeds that continue one line (within half its tolerance) before they come
here, so a run may go on through the arc's end: where an arc turns into the next one the other way
(an S), or into a tangent line, the last chord and the next move are nearly in line, and the finer the
chords the more certainly they merge; so do a line and the first chord of an arc it runs into. Such a
run is cut where it passes the arc's end (or the line's); its rest goes back to OUT's stream for IN's
next move.
"""

from __future__ import annotations

import math
from itertools import zip_longest
from typing import Any, Callable, Iterable, Iterator, Protocol

from ..geometry.arcs import PLANE_INDEX
from .normal_move import Move, same_feed

Item = Any
"""A normalised move (``Move``) or a machine event (a dict)."""


class Report(Protocol):
    """What the pairing reads and fills of ``verify.Report``."""

    tolerance: float
    chord_tolerance: float | None
    chord_deviation: float
    chord_where: tuple[int, int] | None
    mismatch: str | None
    mismatch_at: tuple[int | None, int | None]


def pair_with_chords(ins: Iterable[Item], outs: Iterable[Item], report: Report) -> Iterator[tuple[Item, Item]]:
    """``zip_longest(ins, outs)``, except that an arc of IN met by a straight feed of OUT takes as many of
    OUT's feeds as make up the arc, paired as one arc move that stands for them. Their distance from the
    arc goes to ``report.chord_deviation``; chords that do not make up the arc are a mismatch. Without a
    chord tolerance it is ``zip_longest`` itself, not a generator around it: this module runs as Python,
    and passing every pair of a verify through a Python generator's frame cost about 2,000 instructions a
    pair (callgrind, ``benchmarks/callgrind.sh fanuc verify:linuxcnc 0``)."""
    if report.chord_tolerance is None:
        return zip_longest(ins, outs)
    return _pairs_with_chords(ins, outs, report)


def _pairs_with_chords(ins: Iterable[Item], outs: Iterable[Item], report: Report) -> Iterator[tuple[Item, Item]]:
    """``pair_with_chords`` under a chord tolerance."""
    rest = _Pushback(outs)
    for a in ins:
        b = next(rest, None)
        if report.mismatch is None and isinstance(a, Move) and isinstance(b, Move) and b.kind == "feed":
            if a.centre is not None:
                b = _chords(a, b, rest, report)
            elif a.kind == "feed":
                cut = _through(b.start, b.end, a.end, report.tolerance + 1e-9)
                if cut is not None:  # a line into an arc, merged with the arc's first chord
                    b, tail = _cut(b, cut)
                    rest.push(tail)
        yield a, b
    for b in rest:
        yield None, b


class _Pushback:
    """OUT's items, with room to put one back (the rest of a run cut at an arc's end)."""

    def __init__(self, items: Iterable[Item]) -> None:
        self.items = iter(items)
        self.back: list[Item] = []

    def __iter__(self) -> "_Pushback":
        return self

    def __next__(self) -> Item:
        return self.back.pop() if self.back else next(self.items)

    def push(self, item: Item) -> None:
        self.back.append(item)


def _through(s: dict[str, float], e: dict[str, float], point: dict[str, float], near: float) -> dict[str, float] | None:
    """The point of the straight move ``s``-``e`` nearest ``point``, when within ``near`` of it and more than
    ``near`` before ``e`` (a move that ends within ``near`` of ``point`` ends there, within the tolerance)."""
    keys = sorted(set(s) | set(e) | set(point))
    d = [e.get(k, 0.0) - s.get(k, 0.0) for k in keys]
    length2 = sum(v * v for v in d)
    if length2 == 0.0:
        return None
    u = sum((point.get(k, 0.0) - s.get(k, 0.0)) * v for k, v in zip(keys, d)) / length2
    if u <= 1e-9 or (1.0 - u) * math.sqrt(length2) <= near:
        return None
    cut = {k: s.get(k, 0.0) + u * v for k, v in zip(keys, d)}
    return cut if math.dist([cut[k] for k in keys], [point.get(k, 0.0) for k in keys]) <= near else None


def _cut(chord: Move, at: dict[str, float]) -> tuple[Move, Move]:
    """A straight run as two: up to ``at`` (a point on it) and from there on."""
    head = Move(chord.kind, chord.start, at, chord.f, chord.first_line, chord.last_line, chord.direction,
                length=math.dist([at.get(k, 0.0) for k in at], [chord.start.get(k, 0.0) for k in at]))
    tail = Move(chord.kind, at, chord.end, chord.f, chord.last_line, chord.last_line, chord.direction,
                length=math.dist([at.get(k, 0.0) for k in at], [chord.end.get(k, 0.0) for k in at]))
    return head, tail


def _inside(s: dict[str, float], e: dict[str, float], c: tuple[float, float], pi: str, pj: str, t0: float, t: float,
            step: float, angle: Callable[[dict[str, float]], float], turn: float,
            radius_at: Callable[[float], float]) -> float:
    """How far inside the arc the chord ``s``-``e`` (turning ``step`` of it, from the share ``t0`` to ``t``) comes at
    its point nearest the centre: a chord's distance from the centre is least there (its ends may lie off the
    circle unevenly, so that point is not always its middle), and the arc's radius is the one at that point's
    angle. Along the rays from the centre, as ``postproc.geometry.arc_paths`` matches two arcs."""
    sx, sy = s.get(pi, 0.0), s.get(pj, 0.0)
    dx, dy = e.get(pi, 0.0) - sx, e.get(pj, 0.0) - sy
    length2 = dx * dx + dy * dy
    if length2 == 0.0 or step <= 0.0:
        return 0.0
    u = min(1.0, max(0.0, ((c[0] - sx) * dx + (c[1] - sy) * dy) / length2))
    p = {pi: sx + u * dx, pj: sy + u * dy}
    turned = (turn * (angle(p) - angle(s))) % (2.0 * math.pi)
    share = t0 + (t - t0) * min(turned / step, 1.0)
    return abs(radius_at(share) - math.hypot(p[pi] - c[0], p[pj] - c[1]))


def _chords(arc: Move, first: Move, rest: _Pushback, report: Report) -> Move:
    i, j, _ = PLANE_INDEX[arc.plane or "XY"]
    pi, pj = "xyz"[i], "xyz"[j]
    c = arc.centre
    assert c is not None
    turn = -1.0 if arc.kind == "cw" else 1.0
    r0 = arc.radius
    r1 = math.hypot(arc.end.get(pi, 0.0) - c[0], arc.end.get(pj, 0.0) - c[1])
    along = [k for k in arc.end if k not in (pi, pj)]

    def angle(p: dict[str, float]) -> float:
        return math.atan2(p.get(pj, 0.0) - c[1], p.get(pi, 0.0) - c[0])

    def radius_at(t: float) -> float:
        return r0 + (r1 - r0) * t

    swept, worst, at = 0.0, 0.0, first.first_line
    chord: Move = first
    problem: str | None = None
    near = report.tolerance + 1e-9
    while True:
        if not same_feed(chord.f, arc.f):
            problem = f"IN's arc feeds at F{arc.f:g}, OUT's line at F{chord.f:g}"
            break
        s, e = chord.start, chord.end
        cut = _through(s, e, arc.end, near)
        if cut is not None:
            to_cut = (turn * (angle(cut) - angle(s))) % (2.0 * math.pi)
            if 0.0 < to_cut <= math.pi + 1e-12 and swept + to_cut >= arc.sweep - min(math.pi / 2.0, arc.sweep / 2.0):
                chord, tail = _cut(chord, cut)  # the run goes on past the arc's end: its rest is OUT's next move
                rest.push(tail)
                e = cut
        step = (turn * (angle(e) - angle(s))) % (2.0 * math.pi)
        if step == 0.0 or step > math.pi + 1e-12:
            problem = "OUT's straight move does not turn the arc's way"
            break
        t0, swept = swept / arc.sweep, swept + step
        t = swept / arc.sweep
        if t > 1.0 + 1e-9 + near / max(r0, 1e-9):
            problem = "OUT's straight moves run past the end of IN's arc"
            break
        mid = {k: (s.get(k, 0.0) + e.get(k, 0.0)) / 2.0 for k in (pi, pj)}
        deviation = max(abs(math.hypot(e.get(pi, 0.0) - c[0], e.get(pj, 0.0) - c[1]) - radius_at(t)),
                        abs(radius_at((t0 + t) / 2.0) - math.hypot(mid[pi] - c[0], mid[pj] - c[1])),
                        _inside(s, e, c, pi, pj, t0, t, step, angle, turn, radius_at))
        for k in along:
            expected = arc.start.get(k, 0.0) + (arc.end[k] - arc.start.get(k, 0.0)) * t
            deviation = max(deviation, abs(e.get(k, 0.0) - expected))
        if deviation > worst:
            worst, at = deviation, chord.last_line
        if swept >= arc.sweep - min(math.pi / 2.0, arc.sweep / 2.0) and \
                math.dist([e.get(k, 0.0) for k in arc.end], [arc.end[k] for k in arc.end]) <= near:
            break
        following = next(rest, None)
        if not isinstance(following, Move) or following.kind != "feed":
            problem = "OUT's straight moves end before IN's arc does"
            break
        chord = following
    if worst > report.chord_deviation or report.chord_where is None:
        report.chord_deviation = max(worst, report.chord_deviation)
        report.chord_where = (arc.first_line, at) if worst >= report.chord_deviation else report.chord_where
    if problem is not None and report.mismatch is None:
        report.mismatch = problem
        report.mismatch_at = (arc.first_line, chord.last_line)
    return Move(arc.kind, first.start, chord.end, chord.f, first.first_line, chord.last_line, None, arc.centre,
                arc.plane, arc.radius, swept)
