"""Cutter radius compensation whose corners are straight: the offset vector rules of cutter compensation C
(``CutterRules`` ``outside_corner="extend"``), where no arc is ever inserted.

Every corner is decided from the programmed path alone, at the point ``E`` where two moves meet, with
``t1`` the direction the first move arrives in, ``t2`` the direction the second leaves in, and ``n(t)``
the unit normal to ``t`` on the tool's side (an arc's tangent and normal at ``E``). Seen from the
workpiece, a corner whose angle is 180 degrees or more is an *inner* corner, else an *outer* one:

- inner corner: both moves are cut short where their offset paths (lines, or circles about the arcs'
  centres) intersect, the intersection nearest the corner; none is an alarm ("no solution");
- outer corner at 90 degrees or more: the offset paths are extended to their intersection;
- outer corner under 90 degrees (acute): the first path is extended by the radius along ``t1`` to
  ``E + r n1 + r t1``, a straight move goes to ``E + r n2 - r t2``, and the second path starts there (an arc
  is left and reached at its own offset point, straight moves in between).

Start-up (the move that turns compensation on, then the move after it) and cancel (the last compensated
move, then the move that turns it off) follow ``CutterRules.entry``: ``"perpendicular"`` (start-up type
A) ends the start-up move at ``E + r n2``, beside the start of the next move, and ends the last compensated
move at ``E + r n1`` before the cancel move goes to its programmed end; ``"corner"`` (start-up type B)
ends the start-up move as an outer corner of offset mode would, and refuses what is not known (an inner
corner, and the cancel move, whose type B figures were not read).

The decision waits for the next move in the plane: at most ``CutterRules.look_ahead`` blocks without
motion in the plane may come between (their own position is the corner point); more is refused, as the
controller then stops looking and the corner it makes is not modelled here.

Sources of the rules and their tags are in ``cutter_rules.FANUC_A`` (and ``cutter_rules.HAAS_A``: a Haas runs them with
what its manual leaves out refused, ``CutterRules.startup_arc_known``, ``acute_corner_known``,
``exit_arc_known``). Angles in radians, lengths in mm.
"""

from __future__ import annotations

import math
from typing import Any, Callable

from ..errors import ProgramError, UnsupportedError
from .cutter_radius import CutterRadius, Item, Point, Segment, Suspended, find_turn
from .rules import CutterRules
from ..ir.state import PLANE_AXES

STRAIGHT = 1e-6
"""Radians within which two directions make no corner (the second move goes straight on)."""
ON_CURVE = 1e-7
"""mm: intersections closer than this are one (a tangent line and circle)."""


def _unit(v: Point) -> Point:
    length = math.hypot(v[0], v[1])
    return v[0] / length, v[1] / length


def _add(p: Point, *terms: tuple[float, Point]) -> Point:
    x, y = p
    for k, v in terms:
        x, y = x + k * v[0], y + k * v[1]
    return x, y


class ExtendedCorners(CutterRadius):
    """The compensation state of one run under rules with straight corners (see the module docstring)."""

    def __init__(self, rules: CutterRules, release: Callable[[Item], None]) -> None:
        CutterRadius.__init__(self, rules, release, checked=False)
        self.prev: Segment | None = None
        """The last move in the plane, queued (``queue[0]``) until the next move decides where it ends."""
        self.prev_start: Point = (0.0, 0.0)
        """Its programmed start in the plane."""
        self.prev_from: Point = (0.0, 0.0)
        """Its compensated start in the plane."""
        self.entering = False
        """The queued move is the start-up move (its start has no offset)."""

    # -- state -------------------------------------------------------------------------------------
    def start(self, side: str, radius: float, plane: str = "XY", tip: Point = (0.0, 0.0)) -> None:
        if self.side is not None:
            if radius < 0.0:
                side, radius = ("right" if side == "left" else "left"), -radius
            if (side, radius, PLANE_AXES[plane]) == (self.side, self.radius, self.axes):
                return  # [K] G41 in G41 mode with the same offset: the mode goes on
            raise UnsupportedError(f"a change of cutter compensation side or offset while it is on cannot be "
                                   f"simulated under the rules of {self.rules.name} (cancel it first)")
        if self.prev is not None:
            raise UnsupportedError(f"cutter compensation turned on again before the move after a cancel cannot be "
                                   f"simulated under the rules of {self.rules.name}")
        CutterRadius.start(self, side, radius, plane, tip)

    def cancel(self) -> None:
        """G40: the last compensated move ends beside its end point (start-up type A's cancel); the next
        move goes from there to its programmed end."""
        if self.prev is not None:
            if self.entering:
                raise UnsupportedError(f"cutter compensation cancelled right after its start-up move cannot be "
                                       f"simulated under the rules of {self.rules.name}")
            if self.rules.entry != "perpendicular":
                raise UnsupportedError(f"the cancel move of start-up type B cannot be simulated under the rules of "
                                       f"{self.rules.name} (its figures were not read: set start-up type A)")
            self._finish_prev(self._offset_end())
            self.arc_banned = not self.rules.arc_after_cancel
        else:
            self._flush()
        self.side, self.first = None, True

    def suspend(self) -> Suspended | None:
        """A roughing cycle under the mode (``CutterRules.roughing_cycles``): "the offset is temporarily canceled
        during movement to the start point" [K: ``cutter_rules.FANUC_T``], so the queued move (the move to the cycle's
        start point, compensated at its start as any move of the mode) ends with the imaginary tip on its
        programmed end, and the mode is held, not cancelled: ``resume`` makes the next move a start-up."""
        if self.side is None:
            return None
        saved: Suspended = (self.side, self.radius, self.tip, self.axes)
        prev = self.prev
        if prev is not None:
            if prev.turn != 0:
                raise UnsupportedError(f"an arc as the move to a roughing cycle's start point under cutter "
                                       f"compensation cannot be simulated under the rules of {self.rules.name} (its "
                                       "end cannot be both on the arc's offset and at the programmed point): reach "
                                       "the start point with a straight move")
            e = self.in_plane(prev.end)
            end = (e[0] - self.tip[0], e[1] - self.tip[1])  # the nose centre whose tip is at the programmed end
            self._finish_prev(end)
            self.entering = False
        else:
            self._flush()
        self.side, self.first = None, True
        return saved

    def stop(self) -> None:
        """A program stop or end: the queued move ends beside its end point (as before a cancel)."""
        if self.prev is not None:
            if self.entering:
                raise UnsupportedError(f"a stop right after the start-up move of cutter compensation cannot be "
                                       f"simulated under the rules of {self.rules.name}")
            if self.rules.entry != "perpendicular":
                raise UnsupportedError(f"a stop with cutter compensation on under start-up type B cannot be "
                                       f"simulated under the rules of {self.rules.name} (set start-up type A)")
            self._finish_prev(self._offset_end())
        elif self.queue:
            self._flush()

    # -- moves -------------------------------------------------------------------------------------
    def line(self, seg: Segment, start: Point) -> None:
        self.arc_banned = False
        if not self.on:
            self.release(seg)
            return
        p = self.in_plane(seg.end)
        if p == start:  # no motion in the plane: it waits at the corner the next move decides
            if self.first:
                self.release(seg)
                return
            self._wait_block(seg)
            return
        self._move(seg, start, p)

    def arc(self, seg: Segment, start: Point) -> None:
        if self.arc_banned:
            if not self.rules.exit_arc_known:
                raise UnsupportedError(f"an arc right after cutter compensation is cancelled cannot be simulated "
                                       f"under the rules of {self.rules.name} (how its control runs one is not in "
                                       "our sources)")
            raise ProgramError("the move after cutter compensation is cancelled must be straight, not an arc "
                               "(alarm: circular interpolation in the cancel block)")
        if not self.on:
            self.release(seg)
            return
        if self.first:
            if not self.rules.startup_arc_known:
                raise UnsupportedError(f"an arc as the start-up move of cutter compensation cannot be simulated "
                                       f"under the rules of {self.rules.name} (how its control runs one is not in "
                                       "our sources: start it with a straight move)")
            raise ProgramError("cutter compensation cannot start with an arc (start it with a straight move)")
        assert seg.centre is not None
        e = self.in_plane(seg.end)
        radius = math.hypot(e[0] - seg.centre[0], e[1] - seg.centre[1])
        if self._inside(seg.turn) and radius <= self.radius + ON_CURVE:  # equal within float noise: no circle left
            raise ProgramError("the tool radius is not less than the radius of an arc it cuts inside "
                               "(interference)")
        seg.sweep = find_turn(start, seg.centre, seg.turn, e)
        self._move(seg, start, e)

    def event(self, ev: dict[str, Any]) -> None:
        if self.prev is not None:
            self._wait_block(ev)
        else:
            self.release(ev)

    def finish(self) -> None:
        """The program's last block: the queued move ends beside its end point."""
        self.stop()
        self._flush()

    # -- the corner --------------------------------------------------------------------------------
    def _move(self, seg: Segment, op: Point, e: Point) -> None:
        r = self.radius
        if self.first:  # the start-up move: it ends where the next move decides
            self.first, self.entering = False, True
            self.prev, self.prev_start, self.prev_from = seg, op, op
            self.queue.insert(0, seg)
            return
        prev = self.prev
        assert prev is not None
        t1 = self._tangent(prev, self.prev_start, self.in_plane(prev.end), at_end=True)
        t2 = self._tangent(seg, op, e, at_end=False)
        n1, n2 = self._normal(t1), self._normal(t2)
        turn = math.atan2(t1[0] * t2[1] - t1[1] * t2[0], t1[0] * t2[0] + t1[1] * t2[1])
        left = self.side == "left"
        points: list[Point]
        if abs(turn) < STRAIGHT:
            points = [_add(op, (r, n1))]
        elif abs(abs(turn) - math.pi) < STRAIGHT:
            raise ProgramError("a move that turns back on itself under cutter compensation (interference)")
        elif (turn > 0) == left:  # inner corner
            if self.entering:
                if self.rules.entry != "perpendicular":
                    raise UnsupportedError(f"an inner corner after the start-up move of start-up type B cannot be "
                                           f"simulated under the rules of {self.rules.name} (set type A)")
                points = [_add(op, (r, n2))]
            else:
                points = [self._meet(prev, self.prev_start, seg, op, e, t1, t2, n1, n2)]
        elif self.entering and self.rules.entry == "perpendicular":  # start-up type A
            points = [_add(op, (r, n2))]
        elif t1[0] * t2[0] + t1[1] * t2[1] >= 0.0:  # outer corner of 90 degrees or more: intersection
            points = [self._meet(prev, self.prev_start, seg, op, e, t1, t2, n1, n2, outer=True)]
        else:  # acute outer corner: extended by the radius along both moves
            if not self.rules.acute_corner_known:
                raise UnsupportedError(f"an acute outer corner (over 270 degrees outside) cannot be simulated under "
                                       f"the rules of {self.rules.name} (its control joins it with an extra straight "
                                       "move whose ends are not in our sources)")
            points = [_add(op, (r, n1), (r, t1)), _add(op, (r, n2), (-r, t2))]
            if prev.turn != 0:
                points.insert(0, _add(op, (r, n1)))
            if seg.turn != 0:
                points.append(_add(op, (r, n2)))
        if any(isinstance(item, Segment) for item in self.queue[1:]) and len(points) > 1:
            raise UnsupportedError(f"a move off the plane at an acute outer corner cannot be simulated under the "
                                   f"rules of {self.rules.name} (its place among the corner's moves is not known)")
        self._finish_prev(points[0], points[1:], seg.fields)
        self.prev, self.prev_start, self.prev_from = seg, op, points[-1]
        self.entering = False
        seg.xy = _add(e, (r, self._normal(self._tangent(seg, op, e, at_end=True))))  # until the next corner
        self.current = seg.xy
        if seg.turn != 0:
            seg.ccentre = seg.centre
        seg.direction = (e[0] - op[0], e[1] - op[1])
        self.queue.append(seg)

    def _finish_prev(self, end: Point, corner: list[Point] | tuple[()] = (), fields: dict[str, Any] | None = None) -> None:
        """The queued move ends at ``end``, then straight moves through ``corner``; what waited behind it
        stands at the last point."""
        prev = self.prev
        assert prev is not None and self.queue and self.queue[0] is prev
        self._check(prev, self.prev_from, end)
        prev.xy = end
        waiting = self.queue[1:]
        last = corner[-1] if corner else end
        kind = "feed" if prev.kind != "rapid" else "rapid"
        a1, a2, normal = self.axes
        extra: list[Item] = []
        for point in corner:
            at = dict(prev.end)
            extra.append(Segment(kind, dict(prev.fields), at, at.get(normal, prev.normal), prev.dz, xy=point))
        for item in waiting:
            if isinstance(item, Segment):
                item.xy = last
        self.queue = [prev, *extra, *waiting]
        self.prev = None
        self._flush()
        self.current = last

    def _check(self, seg: Segment, start: Point, end: Point) -> None:
        """Interference: a straight move whose compensated direction is turned more than 90 degrees from
        the programmed one, or an arc whose compensated ends cross (it would run backwards)."""
        if seg.turn == 0:
            dx, dy = seg.direction if seg.direction != (0.0, 0.0) else (1.0, 0.0)
            if self.entering:
                return
            if dx * (end[0] - start[0]) + dy * (end[1] - start[1]) < 0.0:
                raise ProgramError("cutter compensation turns a straight move back against its programmed "
                                   "direction (interference: the move is too short for the tool radius)")
            return
        assert seg.centre is not None
        c, turn = seg.centre, seg.turn
        if self.entering or seg.sweep == 0.0:
            return
        programmed = self.prev_start, self.in_plane(seg.end)
        moved = [_signed(math.atan2(q[1] - c[1], q[0] - c[0]) - math.atan2(p[1] - c[1], p[0] - c[0])) * turn
                 for q, p in ((start, programmed[0]), (end, programmed[1]))]
        if abs(seg.sweep) - moved[0] + moved[1] < -self.sweep_slack:
            raise ProgramError("cutter compensation runs an arc backwards (interference: the arc is too short "
                               "for the tool radius)")

    def _wait_block(self, item: Item) -> None:
        """A block without motion in the plane between two moves in it: the controller looks past
        ``rules.look_ahead`` of them."""
        waiting = len(self.queue) - 1
        if waiting >= self.rules.look_ahead:
            raise UnsupportedError(f"more than {self.rules.look_ahead} block(s) without motion in the plane under "
                                   f"cutter compensation cannot be simulated under the rules of {self.rules.name} "
                                   "(the controller stops looking ahead there)")
        if isinstance(item, Segment):
            item.xy = self.current
        self.queue.append(item)

    # -- geometry ----------------------------------------------------------------------------------
    def _offset_end(self) -> Point:
        prev = self.prev
        assert prev is not None
        e = self.in_plane(prev.end)
        return _add(e, (self.radius, self._normal(self._tangent(prev, self.prev_start, e, at_end=True))))

    def _normal(self, t: Point) -> Point:
        return (-t[1], t[0]) if self.side == "left" else (t[1], -t[0])

    @staticmethod
    def _tangent(seg: Segment, start: Point, end: Point, at_end: bool) -> Point:
        if seg.turn == 0:
            return _unit((end[0] - start[0], end[1] - start[1]))
        assert seg.centre is not None
        q = end if at_end else start
        u = _unit((q[0] - seg.centre[0], q[1] - seg.centre[1]))
        return (-u[1] * seg.turn, u[0] * seg.turn)

    def _offset_curve(self, seg: Segment, through: Point, t: Point) -> tuple[Point, Point, float]:
        """A move's offset path: (point, direction, 0) for a line, (centre, (0, 0), radius) for an arc."""
        if seg.turn == 0:
            return through, t, 0.0
        assert seg.centre is not None
        c = seg.centre
        return c, (0.0, 0.0), math.hypot(through[0] - c[0], through[1] - c[1])

    def _meet(self, prev: Segment, prev_start: Point, seg: Segment, op: Point, e: Point, t1: Point, t2: Point,
              n1: Point, n2: Point, outer: bool = False) -> Point:
        """Where the two offset paths intersect, nearest the corner; an outer corner's lines beyond it."""
        r = self.radius
        a = self._offset_curve(prev, _add(op, (r, n1)), t1)
        b = self._offset_curve(seg, _add(op, (r, n2)), t2)
        found = _intersections(a, b)
        if not found:
            if outer:
                raise UnsupportedError(f"an outer corner whose offset paths do not meet cannot be simulated under "
                                       f"the rules of {self.rules.name}")
            raise ProgramError("the offset paths of an inner corner under cutter compensation do not intersect "
                               "(alarm: no solution of cutter compensation)")
        near = _add(op, (r / 2.0, n1), (r / 2.0, n2))
        return min(found, key=lambda p: math.hypot(p[0] - near[0], p[1] - near[1]))


def _signed(angle: float) -> float:
    """An angle in (-pi, pi]."""
    return angle - 2.0 * math.pi * math.ceil((angle - math.pi) / (2.0 * math.pi))


def _intersections(a: tuple[Point, Point, float], b: tuple[Point, Point, float]) -> list[Point]:
    """Points common to two offset paths (see ``_offset_curve``)."""
    (pa, da, ra), (pb, db, rb) = a, b
    if ra == 0.0 and rb == 0.0:
        cross = da[0] * db[1] - da[1] * db[0]
        if abs(cross) < 1e-12:
            return []
        s = ((pb[0] - pa[0]) * db[1] - (pb[1] - pa[1]) * db[0]) / cross
        return [_add(pa, (s, da))]
    if ra == 0.0 or rb == 0.0:
        (p, d), (c, radius) = ((pa, da), (pb, rb)) if ra == 0.0 else ((pb, db), (pa, ra))
        along = (c[0] - p[0]) * d[0] + (c[1] - p[1]) * d[1]
        foot = _add(p, (along, d))
        off = math.hypot(c[0] - foot[0], c[1] - foot[1])
        if off > radius + ON_CURVE:
            return []
        half = math.sqrt(max(radius * radius - off * off, 0.0))
        return [_add(foot, (-half, d)), _add(foot, (half, d))]
    between = math.hypot(pb[0] - pa[0], pb[1] - pa[1])
    if between == 0.0 or between > ra + rb + ON_CURVE or between < abs(ra - rb) - ON_CURVE:
        return []
    along = (ra * ra - rb * rb + between * between) / (2.0 * between)
    half = math.sqrt(max(ra * ra - along * along, 0.0))
    u = ((pb[0] - pa[0]) / between, (pb[1] - pa[1]) / between)
    mid = _add(pa, (along, u))
    return [_add(mid, (half, (-u[1], u[0]))), _add(mid, (-half, (-u[1], u[0])))]
