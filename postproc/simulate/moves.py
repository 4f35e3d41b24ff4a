"""The simulator's moves: straight and arc moves as events (``MoveRecord``), or handed to the compensation in
force (``postproc.simulate.compensated_moves``, on the position of ``postproc.simulate.position``). The block
dispatch that drives them is ``postproc.simulate.simulator``; what the simulator assumes is in
``postproc.simulate.toolpath``'s docstring."""

from __future__ import annotations

from typing import Callable, Union, cast

from mypy_extensions import mypyc_attr

from ..block_rules import ArcError, arc_centre
from ..errors import ProgramError
from ..ir.expr import Expr
from ..ir import Block, Motion
from ..ir.state import PLANE_AXES
from .events import UNEVALUATED, Event, all_as_written, num
from .compensated_moves import CompensatedMoves
from .move_record import Emitted, MoveRecord
from .position import CENTRE_LETTER, PATH_CONTROL as PATH_CONTROL, point_dict


@mypyc_attr(allow_interpreted_subclasses=True)
class Moves(CompensatedMoves):
    """Position, units and compensation of one program run; its moves become events (``out``)."""

    def line_move(self, kind: str, target: list[float], line: int, emit: Callable[[Emitted], None]) -> None:
        """A straight move to ``target`` (mm, in the order of ``axes``: a list ``target`` made, held from here on)."""
        if self.compensating:
            if self._cutter_idle() and not self.diameter:
                self._offset_line(kind, target, line)
            else:
                self._compensated(kind, target, line, None, None)
            return
        at = self.at
        rounded: list[float | int]
        if all_as_written(target):  # the point as written: ``target`` itself (``CompensatedMoves._offset_line``)
            rounded = cast(list[Union[float, int]], target)
        else:
            rounded = list(self.rounded)
            for i in range(len(at)):
                value = target[i]
                if value != at[i]:
                    rounded[i] = num(value)
        if rounded == self.rounded:
            self.at = target
            if self.mark_held:  # ``verify --transform`` may move it to somewhere else (``mark_held``)
                still: Event = {"line": line, "move": kind, "still": True}
                for i, (axis, key) in enumerate(self.keys):
                    still[key] = rounded[i]
                if self.diameter and "x" in still:
                    still["x"] = num(target[self.index["X"]] * 2.0)
                if kind != "rapid":
                    self._feed_into(still)
                emit(still)
            return
        point = rounded
        if self.diameter and "X" in self.index:  # written as a diameter, kept as a radius
            point = list(rounded)
            point[self.index["X"]] = num(target[self.index["X"]] * 2.0)
        f: float | int | None = None
        mode: str | None = None
        if kind != "rapid":
            f = self._feed_value()
            mode = self._stated_mode()
        self.at, self.rounded = target, rounded
        record = MoveRecord(line, kind, self.key_names, point, f, mode, None)
        emit(record if self.records else record.event())

    def arc_move(self, block: Block, m: Motion, target: list[float], emit: Callable[[Emitted], None],
                 absolute: bool = False) -> None:
        plane = self.modal.plane
        a1, a2, normal = PLANE_AXES[plane]
        at, index = self.at, self.index
        for axis in (a1, a2):
            if axis not in index:
                raise ProgramError(f"an arc in the {plane} plane needs axis {axis}, not on this machine",
                                   self._at(block))
        i1, i2 = index[a1], index[a2]
        s = (at[i1], at[i2])
        e = (target[i1], target[i2])
        clockwise = m.mode == "cw"
        scale = self.scale
        offsets: dict[str, float] = {}  # mm
        for axis, value in (m.center or {}).items():
            if axis not in (a1, a2):
                raise ProgramError(f"arc centre offset along {axis} is outside the {plane} plane",
                                   self._at(block, CENTRE_LETTER.get(axis, "G")))
            if not isinstance(value, float) and isinstance(value, Expr):  # (a float first: ``Expr`` is no native
                # class, its test a generic ``isinstance``, ~250 instructions compiled)
                raise ProgramError(UNEVALUATED, self._at(block, CENTRE_LETTER.get(axis, "G")))
            offsets[axis] = value * scale
        if m.radius is not None and not isinstance(m.radius, float) and isinstance(m.radius, Expr):
            raise ProgramError(UNEVALUATED, self._at(block, "R"))
        radius = None if m.radius is None else m.radius * scale
        try:
            c = arc_centre(s, e, (a1, a2), radius, offsets, clockwise,
                           self.ctx.arc_end, scale != 1.0, scale)
        except ArcError as err:
            raise err.located(self._at(block, err.letter)) from None
        if self.travel is not None:
            programmed = self._programmed(m.axes)
            incremental = self.incremental and not absolute
            pos, end = self.pos, point_dict(self.axes, target)
            if c is None:
                self.travel.line(block, pos, end, programmed, incremental, False)
            else:
                self.travel.arc(block, pos, end, programmed, incremental, c, (a1, a2), clockwise)
        if c is None:
            self.line_move("feed", target, block.line, emit)  # zero radius, zero length: dropped
            return
        if self.compensating:
            if self._cutter_idle() and not self.diameter:
                self._offset_arc(m.mode or "cw", target, block.line, c, plane)
            else:
                self._compensated(m.mode or "cw", target, block.line, c, plane)
            return
        rounded = [num(v) for v in target]
        centre = {a1: c[0], a2: c[1], normal: self.axis_value(at, normal)}
        point = rounded
        written: list[float | int] = []
        for axis in self.centre_axes:
            written.append(num(centre[axis] * 2.0) if self.diameter and axis == "X" else num(centre[axis]))
        if self.diameter and "X" in self.index:  # written as a diameter, kept as a radius
            point = list(rounded)
            point[self.index["X"]] = num(target[self.index["X"]] * 2.0)
        f = self._feed_value()
        mode = self._stated_mode()
        self.at, self.rounded = target, rounded
        record = MoveRecord(block.line, m.mode or "cw", self.key_names, point, f, mode, None, self.centre_keys,
                            written, plane)
        emit(record if self.records else record.event())
