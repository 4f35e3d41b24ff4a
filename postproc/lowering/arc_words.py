"""One arc's words as numbers (``ArcWords``): the arc of a ``Motion`` in true plane geometry, from where the
program stands, and points written back in the arc's own words, for the arc passes of
``postproc.lowering.arcs`` (``--arcs`` and ``settle_arc_ends``), which decide what an arc becomes.

The words an arc is written in are the program's: each address absolute or incremental (the distance mode, or
an increment address such as a lathe's U/W, ``Context.increments``), X a diameter where the program writes
diameters (halved into geometry, doubled back). A start point that is not known (None in the position) is
taken as zero when every word of the arc is an increment (the arc is the same wherever it starts); else the
arc cannot be computed here (a ``ProgramError``, which the passes turn into their own answer).
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..context import Context
from ..errors import ProgramError, UnsupportedError
from ..ir import Motion
from ..ir.expr import Expr
from ..ir.state import MM_PER_INCH, ModalState
from .arc_geometry import Arc


@mypyc_attr(allow_interpreted_subclasses=True)
class ArcWords:
    """One arc's numbers: its plane points in true geometry (a diameter halved), and how to write a
    point back in the arc's own words (absolute or incremental per address, a diameter doubled)."""

    def __init__(self, state: ModalState, ctx: Context, diameter: bool, motion: Motion, incremental: bool,
                 plane: tuple[str, str]) -> None:
        """``state``: where the program stands (its position, units and plane: the start is read from it, and
        ``finish`` moves it to the end); ``diameter``: X words are diameters."""
        self.state = state
        self.ctx = ctx
        self.source = motion
        self.plane = plane
        self.quantum = 1e-7 if state.units == "inch" else 1e-6
        """Intermediate points are rounded to this (program units): finer than the writer's ``EXACT``."""
        increments = ctx.increments
        self.diameter = diameter
        if isinstance(motion.radius, Expr) or any(isinstance(v, Expr) for v in (motion.center or {}).values()):
            raise UnsupportedError("--arcs: a computed arc cannot be rewritten")
        self.forms: dict[str, tuple[bool, str]] = {}
        """Real axis -> (written as an increment, address)."""
        given: dict[str, float] = {}
        for address, value in motion.axes.items():
            if isinstance(value, Expr):
                raise UnsupportedError("--arcs: a computed arc cannot be rewritten")
            real = increments.get(address) if increments else None
            self.forms[real or address] = (incremental or real is not None, address)
            given[real or address] = value
        position = state.position
        axes = set(plane) | set(given)
        self.relative = any(position.get(a) is None for a in axes)
        """The start is not known: the arc is computed from its start taken as zero (all its words are increments)."""
        backwards = {real: address for address, real in increments.items()} if increments else {}
        for a in plane:
            if a in self.forms:
                continue
            if incremental:
                self.forms[a] = (True, a)
            elif not self.relative:
                self.forms[a] = (False, a)
            elif a in backwards:
                self.forms[a] = (True, backwards[a])
        if self.relative and (len(self.forms) < len(axes) or not all(inc for inc, _ in self.forms.values())):
            raise ProgramError("--arcs: the start point of this arc is not known here (program an absolute move on "
                               "its axes after the origin moved)")
        self.start = {a: 0.0 if self.relative else float(position[a]) for a in axes}  # type: ignore[arg-type]
        self.end = {a: self.start[a] + v if self.forms[a][0] else v for a, v in given.items()}
        for a in plane:
            self.end.setdefault(a, self.start[a])
        self.written = dict(self.start)
        """The point the previous piece ended at (an increment of the next piece is relative to it)."""

    def _geo(self, axis: str, value: float) -> float:
        return value * 0.5 if self.diameter and axis == "X" else value

    def _prog(self, axis: str, value: float) -> float:
        return value * 2.0 if self.diameter and axis == "X" else value

    def arc(self) -> Arc:
        from ..block_rules import ArcError, arc_centre  # (imported when an arc is first computed)
        a1, a2 = self.plane
        s = (self._geo(a1, self.start[a1]), self._geo(a2, self.start[a2]))
        e = self.end_geo()
        mm = MM_PER_INCH if self.state.units == "inch" else 1.0
        m = self.source
        offsets = {a: float(v) for a, v in (m.center or {}).items()}  # type: ignore[arg-type]
        for axis in offsets:
            if axis not in self.plane:
                raise ProgramError(f"arc centre offset along {axis} is outside the {self.state.plane} plane")
        radius = None if m.radius is None else float(m.radius) * mm  # type: ignore[arg-type]  # checked above
        try:
            c = arc_centre((s[0] * mm, s[1] * mm), (e[0] * mm, e[1] * mm), self.plane, radius,
                           {a: v * mm for a, v in offsets.items()}, m.mode == "cw", self.ctx.arc_end,
                           mm != 1.0, mm)
        except ArcError as err:
            raise ProgramError(err.message) from None
        if c is None:
            raise ProgramError("--arcs: a zero-radius arc cannot be rewritten")
        along = {a: (self.start[a], self.end[a]) for a in self.end if a not in self.plane}
        return Arc(s, e, (c[0] / mm, c[1] / mm), m.mode == "cw", along)

    def end_geo(self) -> tuple[float, float]:
        a1, a2 = self.plane
        return self._geo(a1, self.end[a1]), self._geo(a2, self.end[a2])

    def piece(self, mode: str, point: tuple[float, float], others: dict[str, float],
              centre: tuple[float, float] | None, radius: float | None) -> Motion:
        """A piece ending at ``point`` (true geometry) with the other axes at ``others``, in the arc's words;
        ``centre`` as offsets from the piece's start (true geometry: a lathe's I is a radius)."""
        a1, a2 = self.plane
        target = dict(others)
        if point == self.end_geo():
            target[a1], target[a2] = self.end[a1], self.end[a2]  # the programmed values themselves
        else:
            target[a1], target[a2] = self._prog(a1, point[0]), self._prog(a2, point[1])
        axes: dict[str, float | Expr] = {}
        for axis in sorted(target, key=_axis_order):
            increment, address = self.forms[axis]
            axes[address] = round(target[axis] - self.written[axis], 9) if increment else target[axis]
        self.written.update(target)
        centre_words: dict[str, float | Expr] | None = None if centre is None else {a1: centre[0], a2: centre[1]}
        return Motion(mode, axes, centre_words, radius)

    def finish(self) -> None:
        """The position after the arc: its end (absolute), or moved by its increments."""
        position = self.state.position
        for axis, value in self.end.items():
            if self.relative:
                known = position.get(axis)
                position[axis] = None if known is None else known + value
            else:
                position[axis] = value


def _axis_order(axis: str) -> int:
    order = "XYZUVWABC"
    return order.index(axis) if axis in order else len(order)
