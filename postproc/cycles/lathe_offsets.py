"""A lathe program's tool offsets (``T0102``: offset 2) written into the coordinates, for a target that has
no lathe tool offsets (grbl and the other mill controls): the set-up's ``<Tool number="2" x=".." z=".."/>``
(geometry plus wear, X as the set-up's X) is added to every X and Z the program moves to while the offset
is in force, so the target's programmed point is the source's controlled point.

When it applies follows the simulation's model of Fanuc T and GSK (``Moves.lathe_offset``): from the
next move of any axis, which takes both X and Z to the new offset; so that move gets the axis it does not
program, at the point the program stands at (tracked by ``postproc.cycles.lathe_lowering``). Where that
point is not known, where the move is incremental or a reference return, or where the set-up gives the
register no X/Z, the translation is a located error that says what to add.
"""

from __future__ import annotations

from typing import Protocol

from postproc.compensation.tool_table import ToolTable
from postproc.context import Context
from postproc.errors import UnsupportedError
from postproc.ir.expr import Expr
from postproc.ir import Block, CompoundMotion, Motion, ToolSelect
from postproc.ir.lathe_sections import CoordinateSet
from postproc.lowering.units_and_distance import UnitsAndDistance

_PLAIN = frozenset(("rapid", "linear", "cw", "ccw"))
AXES = ("X", "Z")


class Where(Protocol):
    """The tracked programmed point (``lathe_lowering._Position``): X as the source writes it."""

    x: float | None
    z: float | None


class LatheOffsets:
    """The offset in force and the one waiting for its first move, in the target's words (X a radius)."""

    def __init__(self, ctx: Context, radius: bool) -> None:
        self.ctx = ctx
        self.table = ToolTable(ctx.setup)
        self.radius = radius
        """The target's X words are radii while the source's are diameters (the tracker halves them)."""
        self.shift: dict[str, float] = {"X": 0.0, "Z": 0.0}
        """mm: what the offset in force adds (X a radius)."""
        self.waiting = False
        """A new offset takes effect with the next move (both axes then)."""
        self.modes = UnitsAndDistance()
        """The units and the distance mode of the blocks so far (``block`` takes every block)."""

    def select(self, block: Block, select: object) -> None:
        """A turret index (``select``, as the source wrote it): its offset number's X and Z from the set-up,
        or a located error naming them."""
        if not isinstance(select, ToolSelect) or not isinstance(select.number, int):
            return
        register = select.number % 100
        values = self.table.lathe(register, self.ctx.diameter)
        if values is None:
            raise UnsupportedError(
                f"T{select.number:04d} selects lathe offset {register:02d}, which the target has no way to apply: "
                f"it is written into the coordinates from the set-up, which gives offset {register} no X and Z (add "
                f"<Tool number=\"{register}\" x=\"..\" z=\"..\"/> to its <Tools>)", self.ctx.at(block))
        new = {"X": values[0], "Z": values[1]}
        if new != self.shift:
            self.shift = new
            self.waiting = True

    def block(self, block: Block, where: Where) -> None:
        """Add the offset to the block's X and Z (after the tracker made them absolute and X a radius)."""
        sections = block.sections
        self.modes.follow(sections)
        coords = sections.get("CoordinateSet")
        if isinstance(coords, CoordinateSet) and self._active():
            sections["CoordinateSet"] = CoordinateSet(self._shifted(block, dict(coords.axes)))
            block.changed()
        motion = sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode is not None and motion.axes:
            if not self._active():
                return
            if motion.mode not in _PLAIN:
                raise UnsupportedError("a reference return with a lathe tool offset in force on a target that has "
                                       "none (cancel the offset first: T..00)", self.ctx.at(block))
            if not self.modes.absolute:
                if self.waiting:
                    raise UnsupportedError("an incremental move takes a new lathe tool offset here, which the target "
                                           "has no way to apply: program X and Z absolutely", self.ctx.at(block))
                return  # an increment is the same under a steady offset
            if self.waiting:
                self._complete(block, motion.axes, where)
            motion.axes = self._shifted(block, motion.axes)
            block.changed()
            self.waiting = False
        compound = sections.get("CompoundMotion")
        if isinstance(compound, CompoundMotion) and self._active():
            first = True
            for item in compound.items:
                if isinstance(item, Motion) and item.axes:
                    if first and self.waiting:
                        self._complete(block, item.axes, where)
                    item.axes = self._shifted(block, item.axes)
                    first = False
            block.changed()
            self.waiting = False

    def _active(self) -> bool:
        return self.waiting or any(self.shift.values())

    def _complete(self, block: Block, axes: dict[str, float | Expr], where: Where) -> None:
        """The first move under a new offset takes both axes there: the one it does not program is added
        at the point the program stands at."""
        for axis in AXES:
            if axis in axes:
                continue
            value = where.x if axis == "X" else where.z
            if value is None:
                raise UnsupportedError(f"the move that takes the new lathe tool offset programs no {axis}, and where "
                                       f"{axis} stands is not known here: program {axis} in it", self.ctx.at(block))
            axes[axis] = value / 2.0 if axis == "X" and self.radius else value

    def _shifted(self, block: Block, axes: dict[str, float | Expr]) -> dict[str, float | Expr]:
        scale = self.modes.scale
        out = dict(axes)
        for axis in AXES:
            value = out.get(axis)
            if value is None:
                continue
            if isinstance(value, Expr):
                raise UnsupportedError(f"a computed {axis} under a lathe tool offset the target has no way to apply",
                                       self.ctx.at(block))
            out[axis] = value + self.shift[axis] / scale
        return out

