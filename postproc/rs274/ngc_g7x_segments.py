"""The profile pieces of LinuxCNC's lathe cycles G70-G72 (``ngc_g7x``): lines, arcs and the fillets and
chamfers that round a corner, each able to offset itself, meet its neighbour and say how a roughing pass
crosses it.

A point is a complex number, Z the real part and X (a radius) the imaginary one, as the controller's own
code computes them [V: LinuxCNC ``src/emc/rs274ngc/interp_g7x.cc`` (stored commit 5c41560e), classes
``segment``, ``straight_segment``, ``round_segment``, ``fillet_segment``, ``chamfer_segment``]. The cycle
works in a frame turned so that the profile runs towards -Z and -X, where the roughing passes go to -Z; the
arithmetic here is that code's, step by step and with its tolerances, because a roughing cycle's passes are
decided by exact comparisons: another formula that is equal on paper would end a pass elsewhere. Every
rule was checked against rs274 2.9 by ``tests/test_ngc_g7x.py`` (a seeded random differential).
"""

from __future__ import annotations

import abc
import math
from typing import Callable, Final

TOLERANCE: Final = 1e-6
"""The cycle's length tolerance [V: ``interp_g7x.cc`` ``tolerance``]."""

Move = tuple[str, complex, complex | None]
"""One move in the cycle's frame: ("rapid" | "feed" | "cw" | "ccw", end, arc centre or None)."""
Output = Callable[[str, complex, "complex | None"], None]
"""Where a piece writes a move: ``out(kind, end, centre)``."""


def _arc(out: Output, ccw: bool, centre: complex, end: complex) -> None:
    out("ccw" if ccw else "cw", end, centre)


class Piece(abc.ABC):
    """A piece of the profile from ``start`` to ``end``; ``finish`` is a corner's size (fillet radius or
    chamfer length) until the corner is made."""

    __slots__ = ("start", "end", "finish")

    def __init__(self, start: complex, end: complex) -> None:
        self.start = start
        self.end = end
        self.finish = 0.0

    @abc.abstractmethod
    def copy(self) -> "Piece":
        """Each kind of piece answers for itself."""

    @abc.abstractmethod
    def length(self) -> float:
        """The size below which the cycle drops a piece (``radius`` there)."""

    def monotonic(self) -> bool:
        """The piece never runs towards +Z (with the cycle's tolerance)."""
        return (self.end - self.start).real <= 1e-3

    def mirror_x(self) -> None:
        self.start, self.end = self.start.conjugate(), self.end.conjugate()

    def mirror_z(self) -> None:
        self.start, self.end = -self.start.conjugate(), -self.end.conjugate()

    def turn(self) -> None:
        """A quarter turn, clockwise: a facing profile becomes a turning one."""
        self.start, self.end = -self.start * 1j, -self.end * 1j

    def shift(self, by: complex) -> None:
        self.start += by
        self.end += by

    def make_corner(self, prev: "Piece", nxt: "Piece") -> None:
        """A fillet or chamfer takes its place between ``prev`` and ``nxt`` (others do nothing)."""

    def _corner(self, prev: "Piece", nxt: "Piece") -> complex:
        """Cut the corner between ``prev`` and ``nxt`` by ``finish``: both end where the rounding arc
        touches them, which spans from the one to the other; the arc's centre is returned."""
        p, n = prev.copy(), nxt.copy()
        p.offset(self.finish)
        n.offset(self.finish)
        if (p.end - n.start).real > 1e-2:
            self.finish = -self.finish
            p, n = prev.copy(), nxt.copy()
            p.offset(self.finish)
            n.offset(self.finish)
        if (p.end - n.start).real > 1e-2:
            raise NgcCycleError(f"the corner finish failed at Z{prev.end.real:g} X{prev.end.imag:g}")
        meet(p, n)
        centre = (p.end + n.start) / 2.0
        p.offset(-self.finish)
        n.offset(-self.finish)
        self.start = prev.end = p.end
        self.end = nxt.start = n.start
        return centre

    # -- what each kind answers ----------------------------------------------------------------------
    @abc.abstractmethod
    def offset(self, distance: float) -> None:
        """Each kind of piece answers for itself."""

    @abc.abstractmethod
    def crossings(self, x: float) -> list[float]:
        """The Z where the piece crosses the height ``x``, in the controller's order."""

    @abc.abstractmethod
    def climb(self, at: list[complex], out: Output) -> bool:
        """Follow the piece up from ``at[0]``; True when it does not climb (a pocket may start)."""

    @abc.abstractmethod
    def climb_only(self, at: list[complex], out: Output) -> None:
        """Each kind of piece answers for itself."""

    @abc.abstractmethod
    def dive(self, at: list[complex], x: float, out: Output, fast: bool) -> bool:
        """Follow the piece down from ``at[0]`` to the height ``x``; True when it does not go down."""

    @abc.abstractmethod
    def draw(self, out: Output) -> None:
        """Each kind of piece answers for itself."""


class NgcCycleError(Exception):
    """The controller refuses the profile (its message, ``G7X error: ...``)."""


class Line(Piece):
    __slots__ = ()

    def copy(self) -> "Line":
        twin = Line(self.start, self.end)
        twin.finish = self.finish
        return twin

    def length(self) -> float:
        return abs(self.start - self.end)

    def offset(self, distance: float) -> None:
        d = 1j * distance * (self.start - self.end) / abs(self.start - self.end)
        self.start += d
        self.end += d

    def crossings(self, x: float) -> list[float]:
        s, e = self.start, self.end
        if min(s.imag, e.imag) > x + TOLERANCE or max(s.imag, e.imag) < x - TOLERANCE:
            return []
        if abs((s - e).imag) < TOLERANCE:
            return [s.real, e.real]
        return [(x - s.imag) / (e.imag - s.imag) * (e.real - s.real) + s.real]

    def climb(self, at: list[complex], out: Output) -> bool:
        if self.end.imag + TOLERANCE < self.start.imag:
            return True
        if abs(at[0] - self.start) > TOLERANCE:
            raise NgcCycleError("How did we get here?")
        out("feed", self.end, None)
        at[0] = self.end
        return False

    def climb_only(self, at: list[complex], out: Output) -> None:
        if self.end.imag < self.start.imag:
            return
        found = self.crossings(at[0].imag)
        if not found:
            return
        at[0] = complex(found[0], at[0].imag)
        out("feed", at[0], None)
        out("feed", self.end, None)
        at[0] = self.end

    def dive(self, at: list[complex], x: float, out: Output, fast: bool) -> bool:
        if self.start.imag <= self.end.imag + TOLERANCE:
            return True
        kind = "rapid" if fast else "feed"
        if x < self.end.imag:
            out(kind, self.end, None)
            at[0] = self.end
            return False
        found = self.crossings(x)
        if not found:
            raise NgcCycleError("x too large in straight dive")
        at[0] = complex(found[0], x)
        out(kind, at[0], None)
        return False

    def draw(self, out: Output) -> None:
        out("feed", self.end, None)


class Arc(Piece):
    __slots__ = ("ccw", "centre")

    def __init__(self, ccw: bool, start: complex, centre: complex, end: complex) -> None:
        super().__init__(start, end)
        self.ccw = ccw
        self.centre = centre

    def copy(self) -> "Arc":
        twin = Arc(self.ccw, self.start, self.centre, self.end)  # a fillet copies as a plain arc (as there)
        twin.finish = self.finish
        return twin

    def length(self) -> float:
        return min(abs(self.start - self.end), abs(self.start - self.centre))

    def mirror_x(self) -> None:
        self.ccw = not self.ccw
        super().mirror_x()
        self.centre = self.centre.conjugate()

    def mirror_z(self) -> None:
        self.ccw = not self.ccw
        super().mirror_z()
        self.centre = -self.centre.conjugate()

    def turn(self) -> None:
        super().turn()
        self.centre = -self.centre * 1j

    def shift(self, by: complex) -> None:
        super().shift(by)
        self.centre += by

    def monotonic(self) -> bool:
        if self.finish != 0:
            return True
        entry = (self.start - self.centre).imag
        exit_ = (self.end - self.centre).imag
        dz = (self.end - self.start).real
        if self.ccw:
            return entry >= -1e-3 and exit_ >= -1e-3 and dz <= -1e-3
        return entry <= 1e-3 and exit_ <= 1e-3 and dz <= -1e-3

    def offset(self, distance: float) -> None:
        r = abs(self.start - self.centre)
        factor = (r + (1 if self.ccw else -1) * distance) / r
        self.start = factor * (self.start - self.centre) + self.centre
        self.end = factor * (self.end - self.centre) + self.centre

    def _on(self, p: complex) -> bool:
        c = self.centre
        a = ((self.start - c).conjugate() * (p - c)).imag
        b = ((self.end - c).conjugate() * (p - c)).imag
        if self.ccw:
            return a >= -TOLERANCE and b <= TOLERANCE
        return a <= TOLERANCE and b >= -TOLERANCE

    def crossings(self, x: float) -> list[float]:
        c = self.centre
        r = abs(self.start - c)
        s = -(x - r - c.imag) * (x + r - c.imag)
        if s < -TOLERANCE:
            return []
        s = math.sqrt(max(s, 0.0))
        found = []
        for z in (c.real + s, c.real - s):
            if self._on(complex(z, x)):
                found.append(z)
        return found

    def _top(self) -> complex:
        """Where a counter-clockwise climb stops: the end, or the arc's top when the end is past it."""
        if self.end.real < self.centre.real:
            return complex(self.centre.real, self.centre.imag + abs(self.start - self.centre))
        return self.end

    def climb(self, at: list[complex], out: Output) -> bool:
        if not self.ccw:
            if at[0].real > self.centre.real:
                return True
            if abs(at[0] - self.end) > 1e-3:
                _arc(out, False, self.centre, self.end)
            at[0] = self.end
            return False
        if at[0].real < self.centre.real:
            return True
        top = self._top()
        if abs(at[0] - top) > 1e-3:
            _arc(out, True, self.centre, top)
        at[0] = top
        return True

    def dive(self, at: list[complex], x: float, out: Output, fast: bool) -> bool:
        here = at[0]
        if abs(here - self.end) < TOLERANCE or (here - self.end).real <= TOLERANCE:
            at[0] = self.end
            return False
        found = self.crossings(x) or self.crossings(x - TOLERANCE)
        c = self.centre
        if self.ccw:
            if here.real - TOLERANCE > c.real:
                return True
            if not found or found[-1] > c.real:
                _arc(out, True, c, self.end)
                at[0] = self.end
            else:
                at[0] = complex(found[-1], x)
                _arc(out, True, c, at[0])
            return False
        if here.real <= c.real:
            return True  # climbing already
        if not found:
            _arc(out, False, c, self.end)
            at[0] = self.end
        elif found[0] < c.real:
            pass  # met on the far side only: the pocket steps down
        else:
            at[0] = complex(found[0], x)
            _arc(out, False, c, at[0])
        return False

    def climb_only(self, at: list[complex], out: Output) -> None:
        found = self.crossings(at[0].imag)
        if not found:
            return
        c = self.centre
        if not self.ccw:
            if found[-1] > c.real:
                return
            at[0] = complex(found[-1], at[0].imag)
            out("feed", at[0], None)
            if abs(at[0] - self.end) > 1e-3:
                _arc(out, False, c, self.end)
            at[0] = self.end
            return
        if found[0] < c.real:
            return
        at[0] = complex(found[0], at[0].imag)
        out("feed", at[0], None)
        top = self._top()
        if abs(at[0] - top) > 1e-3:
            _arc(out, True, c, top)
        at[0] = top

    def draw(self, out: Output) -> None:
        _arc(out, self.ccw, self.centre, self.end)


class Fillet(Arc):
    """A rounding of radius ``A`` at the corner where it stands (made by ``make_corner``)."""

    __slots__ = ()

    def __init__(self, radius: float, at: complex) -> None:
        super().__init__(False, at, at, at)
        self.finish = radius

    def make_corner(self, prev: Piece, nxt: Piece) -> None:
        self.centre = self._corner(prev, nxt)
        self.ccw = (self.start - self.centre).imag > 0 or (self.end - self.centre).imag > 0
        self.finish = 0.0


class Chamfer(Line):
    """A chamfer at the corner where it stands: the chord of the fillet of radius ``C``."""

    __slots__ = ()

    def __init__(self, size: float, at: complex) -> None:
        super().__init__(at, at)
        self.finish = size

    def make_corner(self, prev: Piece, nxt: Piece) -> None:
        self._corner(prev, nxt)


def meet(a: Piece, b: Piece) -> None:
    """Move ``a``'s end and ``b``'s start to where the two meet (``b.intersect_end(a)`` there)."""
    if isinstance(b, Arc):
        if isinstance(a, Arc):
            ra, rb = abs(b.start - b.centre), abs(a.start - a.centre)
            d = abs(b.centre - a.centre)
            cos_b = (d * d + ra * ra - rb * rb) / 2.0 / ra / d
            turn = complex(cos_b, math.sqrt(1 - min(cos_b * cos_b, 1.0)))
            a.end = b.start = turn * (a.centre - b.centre) / d * ra + b.centre
            return
        if abs(b.start - a.end) < TOLERANCE:
            return
        a.end = b.start = _line_circle(a, b.end, b.centre, b.start)
        return
    if isinstance(a, Arc):
        if abs(b.start - a.end) < TOLERANCE:
            return
        a.end = b.start = _line_circle(b, a.end, a.centre, b.start)
        return
    rot = (b.start - b.end).conjugate() / abs(b.start - b.end)
    ps = (a.start - b.end) * rot
    pe = (a.end - b.end) * rot
    if (ps - pe).imag == 0:
        raise NgcCycleError("Cannot intersect parallel lines")
    f = ps.imag / (ps - pe).imag
    a.end = b.start = (ps + f * (pe - ps)) / rot + b.end


def _line_circle(line: Piece, point: complex, centre: complex, near: complex) -> complex:
    """Where ``line`` (extended) crosses the circle about ``centre`` through ``point``: of the two
    crossings the one nearer ``near`` (tangent or missing: the foot of the centre on the line)."""
    rot = (line.start - line.end).conjugate() / abs(line.start - line.end)
    base = line.end
    pe = (point - base) * rot
    pc = (centre - base) * rot
    gap = pc - pe
    h = gap.real * gap.real + gap.imag * gap.imag - pc.imag * pc.imag  # (``norm``, not abs() squared)
    h = math.sqrt(h) if h >= 0 else 0.0
    s1 = (pc.real + h) / rot + base
    s2 = (pc.real - h) / rot + base
    return s1 if abs(near - s1) < abs(near - s2) else s2
