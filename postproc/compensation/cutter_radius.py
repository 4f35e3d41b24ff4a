"""Cutter radius compensation in the XY or ZX plane: the tool's centre runs one radius beside the
programmed path, on the left (G41) or the right (G42) looking along the motion.

A plane's points are (first axis, second axis) as ``state.PLANE_AXES`` gives them: (X, Y) for G17, (Z, X)
for G18, so left and right are seen from the normal's positive end (+Z, +Y) [V: LinuxCNC
``interp_convert.cc`` ``comp_get_current``: in the XZ plane x is Z and y is X; ``convert_set_plane``:
compensation runs in XY or XZ only, and the plane cannot change while it is on]. Which planes a
controller compensates in is its rules' ``planes``.

Where a move ends depends on the move after it (an inside corner shortens it, an outside corner adds an
arc), so the last move waits in a small queue until the next move in the plane decides its end; what
comes between (moves along Z only, spindle, coolant, dwell) waits behind it, in order. The queue holds
one move in the plane and what followed it, at most ``QUEUE_LIMIT`` items: a program that runs longer
than that without a move in the plane is refused rather than held in memory.

The plane is the one compensation starts in (``start``): XY on a mill, ZX on a lathe, where the point
written is the nose centre moved to the imaginary tool tip (``postproc.compensation.nose``) for every
move the compensation made, as LinuxCNC offsets each queued move when it leaves the queue ([V]
``interp_queue.cc`` ``dequeue_canons``, ``latheorigin_x``/``latheorigin_z``); the exit move after G40 is
not offset.

The geometry follows LinuxCNC's interpreter (``CutterRules`` ``ARC_CORNERS``; [V] ``interp_convert.cc``
``convert_straight_comp1/2``, ``convert_arc_comp1/2``, ``convert_cutter_compensation_off``, and
``interp_queue.cc`` ``move_endpoint_and_flush``), checked move by move against ``rs274``
(``tests/test_cutter_compensation_rs274.py``). The NIST version 3 rules (``NIST_V3``, Mach3's) differ in
three places, each a rule field: the entry move (``entry="touching"``), inside corners (an error, no
look-ahead) and a rapid around an outside corner (straight to its end). Angles in radians, lengths in mm.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, Union

from ..errors import ProgramError, UnsupportedError
from ..ir.state import PLANE_AXES
from .rules import CutterRules

Point = tuple[float, float]
Event = dict[str, Any]
Suspended = tuple[str, float, Point, tuple[str, str, str]]
"""Compensation held over a roughing cycle: side, radius, tip offset, plane axes (``CutterRadius.suspend``)."""
TAU = 2.0 * math.pi
HALF_PI = math.pi / 2.0
SAME_ANGLE = 1e-9
"""Radians within which an arc's end is at its start (a full turn): LinuxCNC compares exactly in program
units, the simulation works in mm, whose conversion leaves a few ulps."""
QUEUE_LIMIT = 10_000
"""Most moves and events waiting behind a compensated move for the next move in the plane."""
RADIUS_MISMATCH = 0.01
"""mm by which a corrected arc's radius may change before it is an internal error (LinuxCNC's bound)."""


@dataclass(eq=False)
class Segment:
    """One move of the controlled path, waiting to be written by the simulator."""

    kind: str
    """"rapid", "feed", "cw" or "ccw"."""
    fields: Event
    """The event's keys other than its position (line, f, feed_mode)."""
    end: dict[str, float]
    """The programmed end, mm, every machine axis (a corner arc: the programmed corner)."""
    normal: float = 0.0
    """An arc's programmed start on the plane's normal axis (its centre carries it)."""
    dz: float = 0.0
    """The tool length the move is made with (added to the controlled Z)."""
    xy: Point | None = None
    """The controlled end in the plane (first, second axis); None: the programmed one."""
    centre: Point | None = None
    """An arc's programmed centre (a corner arc: the corner)."""
    ccentre: Point | None = None
    """An arc's controlled centre (an entry arc's differs from the programmed one)."""
    turn: int = 0
    """1 counter-clockwise, -1 clockwise, 0 a straight move."""
    sweep: float = 0.0
    """The angle the programmed arc sweeps (0 for a corner arc: its end is never checked)."""
    direction: Point = field(default=(0.0, 0.0))
    """The programmed direction of a straight move in the plane: its end moving back past its start is a
    gouge."""


Item = Union[Segment, Event]


def find_turn(start: Point, centre: Point, turn: int, end: Point) -> float:
    """The angle an arc sweeps from ``start`` to ``end`` (positive counter-clockwise); the same end as
    the start is a full turn."""
    if turn == 0:
        return 0.0
    a = math.atan2(start[1] - centre[1], start[0] - centre[0])
    b = math.atan2(end[1] - centre[1], end[0] - centre[0])
    if abs(b - a) < SAME_ANGLE:
        b = a
    if turn > 0:
        if b <= a:
            b += TAU
        return b - a
    if a <= b:
        a += TAU
    return b - a


def _towards(p: Point, length: float, angle: float) -> Point:
    return p[0] + length * math.cos(angle), p[1] + length * math.sin(angle)


class CutterRadius:
    """The compensation state of one run and its queue; ``release`` writes a segment or an event."""

    def __init__(self, rules: CutterRules, release: Callable[[Item], None], checked: bool = True) -> None:
        if checked and (rules.entry not in ("tangent", "touching") or rules.outside_corner != "arc"):
            raise UnsupportedError(f"cutter compensation rules of {rules.name} cannot be simulated yet")
        self.rules = rules
        self.write = release
        self.side: str | None = None
        """"left", "right", or None (off)."""
        self.radius = 0.0
        self.tip: Point = (0.0, 0.0)
        """From the nose centre to the imaginary tool tip, mm in the plane (a lathe tool's; zero: a mill's)."""
        self.first = True
        """The next move in the plane is the entry move."""
        self.current: Point = (0.0, 0.0)
        """The controlled point in the plane (while compensating)."""
        self.axes: tuple[str, str, str] = PLANE_AXES["XY"]
        """The plane compensation runs in: its first and second axis, then its normal (set by ``start``)."""
        self.queue: list[Item] = []
        self.endpoint: Point | None = None
        """Where the first queued move starts (None: unknown, its end is not checked when moved)."""
        self.arc_banned = False
        """The move after a cancel must be straight (``rules.arc_after_cancel``)."""
        self.sweep_slack = 0.0254
        """How much farther (radians) a corrected arc may sweep than programmed before it gouges: [V]
        LinuxCNC's ``move_endpoint_and_flush`` compares the sweep with a length in program units, 0.001 in
        an inch program and 0.0254 in a metric one (the simulator sets it with the units)."""

    # -- state -------------------------------------------------------------------------------------
    @property
    def on(self) -> bool:
        """Compensation moves the tool (it is on with a radius above zero)."""
        return self.side is not None and self.radius > 0.0

    def start(self, side: str, radius: float, plane: str = "XY", tip: Point = (0.0, 0.0)) -> None:
        """G41/G42 with the register's radius (a negative radius swaps the side [V][K]) in ``plane``;
        ``tip``: the direction (signs) from the nose centre to a lathe tool's imaginary tip."""
        if self.side is not None:
            raise ProgramError("cutter compensation is turned on while it is on (cancel it first)")
        if plane not in self.rules.planes:
            raise ProgramError(f"{self.rules.name} runs cutter compensation only in the "
                               f"{' or '.join(self.rules.planes)} plane, not in {plane}")
        if radius < 0.0:
            side, radius = ("right" if side == "left" else "left"), -radius
        self.side, self.radius, self.first = side, radius, True
        self.axes = PLANE_AXES[plane]
        self.tip = (tip[0] * radius, tip[1] * radius)

    def tool_change(self) -> None:
        """A tool change (M6) is refused while compensation is on, checked against the compensation in force
        before the block's own G40/G41/G42: [V] rs274 2.9 changes the tool of ``G41 M6 T1`` and then turns
        compensation on, and refuses ``G40 M6 T1`` under G41 ("Cannot change tools with cutter radius
        compensation on": the tool change comes before the compensation in its order of execution). One check
        for the simulation and for the lowering that resolves compensation into moves."""
        if self.side is not None:
            raise ProgramError("a tool change with cutter compensation on cannot be run (cancel it first)")

    def release(self, item: Item) -> None:
        """Write a move or an event; a move the compensation made is moved to the imaginary tool tip."""
        tip = self.tip
        if isinstance(item, Segment) and item.xy is not None and tip != (0.0, 0.0):
            item.xy = (item.xy[0] + tip[0], item.xy[1] + tip[1])
            if item.ccentre is not None:
                item.ccentre = (item.ccentre[0] + tip[0], item.ccentre[1] + tip[1])
        self.write(item)

    def in_plane(self, end: dict[str, float]) -> Point:
        """A point's coordinates in the compensation's plane."""
        a1, a2, _ = self.axes
        return end[a1], end[a2]

    def cancel(self) -> None:
        """G40: the last move keeps its compensated end; the next move (the exit move) goes from there to
        its programmed end."""
        if self.on and not self.first:
            self._move_end_and_flush(self.current)
            self.arc_banned = not self.rules.arc_after_cancel
        self._flush()
        self.side, self.first = None, True

    def suspend(self) -> Suspended | None:
        """A roughing cycle under compensation (``CutterRules.roughing_cycles``): the move to the cycle's start
        point ends there uncompensated, the cycle's own moves run as programmed (the imaginary tip's path:
        ``postproc.rs274.lathe_cycles``); returns what ``resume`` takes up after the cycle (None: compensation
        is off). Only the straight-corner rules know it (``ExtendedCorners``)."""
        if self.side is None:
            return None
        raise UnsupportedError(f"a roughing cycle under cutter compensation cannot be simulated under the rules of "
                               f"{self.rules.name}")

    def resume(self, saved: Suspended) -> None:
        """After the cycle: compensation is on again as before it, and the next move in the plane starts it up."""
        self.side, self.radius, self.tip, self.axes = saved
        self.first, self.arc_banned = True, False

    def stop(self) -> None:
        """A program stop or end: everything queued is written, the last move at its compensated end."""
        if self.queue:
            self._move_end_and_flush(self.current)

    def finish(self) -> None:
        """The program's last block: nothing may stay queued."""
        self._flush()

    def event(self, ev: Event) -> None:
        """A non-motion event keeps its place behind a queued move."""
        if self.queue:
            self._wait(ev)
        else:
            self.release(ev)

    # -- moves -------------------------------------------------------------------------------------
    def line(self, seg: Segment, start: Point) -> None:
        """A straight move from the programmed ``start`` (rapid or feed)."""
        self.arc_banned = False
        if not self.on:
            self.release(seg)
            return
        p = self.in_plane(seg.end)
        if self.first:
            self._line_entry(seg, start, p)
        else:
            self._line_next(seg, start, p)

    def arc(self, seg: Segment, start: Point) -> None:
        """An arc from the programmed ``start`` about ``seg.centre``."""
        if self.arc_banned:
            if not self.rules.exit_arc_known:
                raise UnsupportedError(f"an arc right after cutter compensation is cancelled cannot be simulated "
                                       f"under the rules of {self.rules.name}")
            raise ProgramError("the move after cutter compensation is cancelled must be straight, not an arc")
        if not self.on:
            self.release(seg)
            return
        if self.first:
            self._arc_entry(seg, start)
        else:
            self._arc_next(seg, start)

    def _line_entry(self, seg: Segment, c: Point, p: Point) -> None:
        """The tool ends beside ``p``, perpendicular to the line from the start point to ``p``."""
        r = self.radius
        distance = math.hypot(p[0] - c[0], p[1] - c[1])
        if distance <= r:
            raise ProgramError("the entry move of cutter compensation is not longer than the tool radius")
        if self.rules.entry == "touching":  # beside p, square to the line from p touching the circle about c
            theta = math.acos(r / distance)
            back = math.atan2(c[1] - p[1], c[0] - p[0])
            alpha = back - theta if self.side == "left" else back + theta
        else:
            alpha = math.atan2(p[1] - c[1], p[0] - c[0]) + (HALF_PI if self.side == "left" else -HALF_PI)
        seg.xy = _towards(p, r, alpha)
        seg.direction = (math.cos(alpha), math.sin(alpha))
        if self.rules.entry == "touching":  # the move's own way (its end is never moved back: no look-ahead)
            seg.direction = (seg.xy[0] - c[0], seg.xy[1] - c[1])
        self.endpoint = c
        self._enter(seg)

    def _arc_entry(self, seg: Segment, c: Point) -> None:
        """The tool ends on the arc's radius through its end; the arc it runs passes through the start
        point, about a centre on the line from the end through the programmed centre."""
        assert seg.centre is not None
        if self.rules.entry != "tangent":
            raise UnsupportedError(f"an entry arc of cutter compensation cannot be simulated under the rules of "
                                   f"{self.rules.name} (start it with a straight move)")
        r, centre, turn = self.radius, seg.centre, seg.turn
        e = self.in_plane(seg.end)
        if math.hypot(e[0] - c[0], e[1] - c[1]) <= r:
            raise ProgramError("the entry arc of cutter compensation does not end farther than the tool "
                               "radius from its start")
        inside = self._inside(turn)
        if inside and math.hypot(centre[0] - c[0], centre[1] - c[1]) <= r:
            raise ProgramError("the tool radius is not less than the radius of an arc it cuts inside")
        gamma = (math.atan2(centre[1] - e[1], centre[0] - e[0]) if inside
                 else math.atan2(e[1] - centre[1], e[0] - centre[0]))
        end = _towards(e, r, gamma)
        half_chord = math.hypot(c[0] - end[0], c[1] - end[1]) / 2.0
        to_centre = math.atan2(centre[1] - end[1], centre[0] - end[0])
        cos_a = math.cos(math.atan2(c[1] - end[1], c[0] - end[0]) - to_centre)
        if abs(cos_a) < 1e-6:
            raise ProgramError("the tool radius is not less than the radius of an arc it cuts inside")
        seg.xy = end
        seg.ccentre = _towards(end, half_chord / cos_a, to_centre)
        seg.sweep = find_turn(c, seg.ccentre, turn, end)
        self.endpoint = None
        if self.tip != (0.0, 0.0):
            # a lathe tool's origin moves to the tip first, or the arc would not start on its circle; that
            # move is queued, and moved with the arc's end by a corner after it [V] convert_arc_comp1
            a1, a2, normal = self.axes
            to_start = dict(seg.end)
            to_start[a1], to_start[a2] = c
            if normal in to_start:
                to_start[normal] = seg.normal
            self.queue.append(Segment("feed", dict(seg.fields), to_start, seg.normal, seg.dz, xy=c))
            self.endpoint = c
        self._enter(seg)

    def _enter(self, seg: Segment) -> None:
        assert seg.xy is not None
        self.queue.append(seg)
        self.first = False
        self.current = seg.xy

    def _line_next(self, seg: Segment, op: Point, p: Point) -> None:
        if p == op:  # no motion in the plane: the tool stays where it is (moved with the corner later)
            seg.xy = self.current
            self._wait(seg)
            return
        r, small, left = self.radius, self.rules.corner_tolerance, self.side == "left"
        c = self.current
        theta = math.atan2(c[1] - op[1], c[0] - op[0])
        alpha = math.atan2(p[1] - op[1], p[0] - op[0])
        if left:
            if theta < alpha:
                theta += TAU
            beta, gamma = theta - alpha - HALF_PI, HALF_PI
        else:
            if alpha < theta:
                alpha += TAU
            beta, gamma = alpha - theta - HALF_PI, -HALF_PI
        end = _towards(p, r, alpha + gamma)
        mid = _towards(op, r, alpha + gamma)
        front = self.queue[0] if self.queue else None
        after_arc = isinstance(front, Segment) and front.turn != 0
        meet = self.rules.inside_corner == "meet"
        concave = (beta < -small or beta > math.pi + small
                   or (meet and beta > math.pi - small and after_arc and (front.turn > 0) != left))  # type: ignore[union-attr]
        if concave and not meet:
            raise ProgramError(f"an inside corner under cutter compensation: {self.rules.name} stops there "
                               "(concave corner with cutter radius compensation)")
        if not concave and beta > small and seg.kind != "feed" and self.rules.rapid_corner == "direct":
            self._move_end_and_flush(c)  # a rapid around an outside corner: one traverse to its end
            self.endpoint = c
        elif not concave and beta > small:  # outside corner: an arc about it (a rapid goes straight)
            self._move_end_and_flush(c)
            self.release(self._corner(seg, op, mid, arc=seg.kind == "feed"))
            self.endpoint = mid
        elif concave and not after_arc:  # inside corner after a line: both lines meet
            self._front()
            half = (beta + math.pi) / 2.0
            if half == 0.0:
                raise ProgramError("a zero-degree inside corner cannot be compensated")
            self._move_end_and_flush(_towards(c, r / math.tan(half), theta + gamma))
        elif concave:  # inside corner after an arc: the line meets the compensated arc
            self._move_end_and_flush(self._arc_meets_line(self._front(), op, p))
        else:  # straight on, or a tangent arc before
            self._flush()
            self.endpoint = c
        seg.xy = end
        seg.direction = (p[0] - op[0], p[1] - op[1])
        self.queue.append(seg)
        self.current = end

    def _arc_meets_line(self, prev: Segment, op: Point, p: Point) -> Point:
        assert prev.ccentre is not None and prev.xy is not None
        r, pc = self.radius, prev.ccentre
        oldrad = math.hypot(pc[1] - prev.xy[1], pc[0] - prev.xy[0])
        base = math.atan2(p[1] - op[1], p[0] - op[0])
        theta = base + HALF_PI if prev.turn > 0 else base - HALF_PI
        phi = math.atan2(pc[1] - op[1], pc[0] - op[0])
        inside = self._inside(prev.turn)
        d = (oldrad + r if inside else oldrad - r) * math.cos(theta - phi)
        ratio = (d - r if inside else d + r) / oldrad
        if ratio > 1.0 or ratio < -1.0:
            raise ProgramError("an arc followed by a line makes a corner the compensated tool cannot fit in "
                               "without gouging")
        turn_back = (prev.turn > 0) == inside
        angle = theta + math.pi + (-math.acos(ratio) if turn_back else math.acos(ratio))
        return _towards(pc, oldrad, angle)

    def _arc_next(self, seg: Segment, op: Point) -> None:
        assert seg.centre is not None
        r, small, left, turn = self.radius, self.rules.corner_tolerance, self.side == "left", seg.turn
        centre, c = seg.centre, self.current
        e = self.in_plane(seg.end)
        arc_radius = math.hypot(centre[0] - e[0], centre[1] - e[1])
        theta = math.atan2(c[1] - op[1], c[0] - op[0])
        theta = theta - HALF_PI if left else theta + HALF_PI
        delta = math.atan2(centre[1] - op[1], centre[0] - op[0])
        alpha = delta - HALF_PI if turn > 0 else delta + HALF_PI
        beta = theta - alpha if left else alpha - theta
        if beta > 1.5 * math.pi:
            beta -= TAU
        elif beta < -HALF_PI:
            beta += TAU
        inside = self._inside(turn)
        if inside:
            gamma = math.atan2(centre[1] - e[1], centre[0] - e[0])
            if arc_radius <= r:
                raise ProgramError("the tool radius is not less than the radius of an arc it cuts inside")
        else:
            gamma = math.atan2(e[1] - centre[1], e[0] - centre[0])
            delta += math.pi
        end = _towards(e, r, gamma)
        meet = self.rules.inside_corner == "meet"
        if beta < -small or beta > math.pi + small or (meet and abs(beta - math.pi) < small and not inside):
            if not meet:
                raise ProgramError(f"an inside corner under cutter compensation: {self.rules.name} stops there "
                                   "(concave corner with cutter radius compensation)")
            front = self._front()
            if front.turn == 0:
                mid = self._line_meets_arc(centre, arc_radius, beta, theta, inside, turn)
            else:
                mid = self._arc_meets_arc(front, centre, arc_radius, inside, turn)
            self._move_end_and_flush(mid)
        elif beta > small:  # outside corner: an arc about it first
            mid = _towards(op, r, delta)
            self._flush()
            self.release(self._corner(seg, op, mid, arc=True))
            self.endpoint = mid
        else:
            self._flush()
            self.endpoint = c
        seg.xy, seg.ccentre = end, centre
        seg.sweep = find_turn(op, centre, turn, e)
        self.queue.append(seg)
        self.current = end

    def _line_meets_arc(self, centre: Point, arc_radius: float, beta: float, theta: float, inside: bool,
                        turn: int) -> Point:
        r = self.radius
        across = arc_radius * math.sin(beta - HALF_PI)
        dist = arc_radius - r if inside else arc_radius + r
        ratio = (across + r if inside else across - r) / dist
        if ratio > 1.0 or ratio < -1.0:
            raise ProgramError("an arc in an inside corner cannot be reached by the tool without gouging")
        if inside:
            angle = theta + math.asin(ratio) if turn > 0 else theta - math.asin(ratio)
        else:
            angle = theta + math.pi - math.asin(ratio) if turn > 0 else theta + math.pi + math.asin(ratio)
        return _towards(centre, dist, angle)

    def _arc_meets_arc(self, prev: Segment, centre: Point, arc_radius: float, inside: bool, turn: int) -> Point:
        assert prev.ccentre is not None and prev.xy is not None
        r, pc = self.radius, prev.ccentre
        oldrad = math.hypot(pc[1] - prev.xy[1], pc[0] - prev.xy[0])
        newrad = arc_radius - r if inside else arc_radius + r
        between = math.hypot(pc[1] - centre[1], pc[0] - centre[0])
        if oldrad == 0.0 or between == 0.0:
            raise ProgramError("two arcs about the same centre meet in a corner compensation cannot resolve")
        a = (oldrad * oldrad + between * between - newrad * newrad) / (2.0 * oldrad * between)
        if a > 1.0 or a < -1.0:
            raise ProgramError("two arcs make a corner the compensated tool cannot fit in without gouging")
        pullback = math.acos(a)
        towards = math.atan2(centre[1] - pc[1], centre[0] - pc[0])
        ahead = (turn > 0) == self._inside(prev.turn)
        return _towards(pc, oldrad, towards + pullback if ahead else towards - pullback)

    # -- the queue ---------------------------------------------------------------------------------
    def _inside(self, turn: int) -> bool:
        """The tool runs inside an arc of this direction (left of a counter-clockwise one)."""
        return (self.side == "left") == (turn > 0)

    def _front(self) -> Segment:
        """The queued move an inside corner shortens (none after a program stop: LinuxCNC reads an empty
        queue there, so the corner cannot be known)."""
        front = self.queue[0] if self.queue else None
        if not isinstance(front, Segment):
            raise UnsupportedError("an inside corner right after a program stop under cutter compensation "
                                   "cannot be simulated")
        return front

    def _corner(self, seg: Segment, op: Point, mid: Point, arc: bool) -> Segment:
        """The move around an outside corner: an arc about the programmed corner (its programmed point),
        made at the height the tool stands at; a rapid goes straight to the arc's end."""
        a1, a2, normal = self.axes
        corner = dict(seg.end)
        corner[a1], corner[a2] = op
        if normal in corner:
            corner[normal] = seg.normal  # the block's start height
        turn = -1 if self.side == "left" else 1
        if not arc:
            return Segment("rapid", dict(seg.fields), corner, seg.normal, seg.dz, xy=mid)
        return Segment("cw" if turn < 0 else "ccw", dict(seg.fields), corner, seg.normal, seg.dz, xy=mid,
                       centre=op, ccentre=op, turn=turn)

    def _move_end_and_flush(self, p: Point) -> None:
        """Every queued move ends at ``p`` (the corner the next move found); a move that would end up
        running backwards, or an arc that would sweep farther than programmed, gouges."""
        if not self.queue:
            return
        start = self.endpoint
        for item in self.queue:
            if not isinstance(item, Segment):
                continue
            if item.turn != 0 and item.ccentre is not None and item.xy is not None:
                pc = item.ccentre
                was = math.hypot(item.xy[0] - pc[0], item.xy[1] - pc[1])
                now = math.hypot(p[0] - pc[0], p[1] - pc[1])
                if abs(was - now) > RADIUS_MISMATCH:
                    raise ProgramError("internal error: cutter compensation made an arc whose radii differ")
                if item.sweep != 0.0 and start is not None and (
                        abs(find_turn(start, pc, item.turn, p)) > abs(item.sweep) + self.sweep_slack):
                    raise ProgramError("an arc in an inside corner cannot be reached by the tool without gouging")
            elif start is not None:
                dx, dy = item.direction
                if dx * (p[0] - start[0]) + dy * (p[1] - start[1]) < 0.0:
                    raise ProgramError(f"a straight {'traverse' if item.kind == 'rapid' else 'feed'} in an "
                                       "inside corner cannot be reached by the tool without gouging")
            item.xy = p
        self._flush()
        self.endpoint = p

    def _wait(self, item: Item) -> None:
        if len(self.queue) >= QUEUE_LIMIT:
            raise ProgramError(f"cutter compensation waits for a move in the plane for more than {QUEUE_LIMIT} "
                               "moves and events (move in the plane, or cancel compensation, sooner)")
        self.queue.append(item)

    def _flush(self) -> None:
        queue, self.queue = self.queue, []
        self.endpoint = None
        for item in queue:
            self.release(item)
