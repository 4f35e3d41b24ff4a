"""Travel limits: every move of a simulated program, in machine coordinates, against the set-up's
``<Axes>`` (``min``/``max``), so a program that would drive an axis into its limit fails at its block.

The simulator (``postproc.simulate.toolpath``) moves in work coordinates; this module adds what lies between them
and the machine, and refuses to guess what it cannot know:
- the work offset of the active system (G54..G59): the value a G10 in the program set, else the set-up's
  ``<WorkOffsets>`` entry; an axis with neither is unknown. The external offset (0) counts as zero unless
  the set-up or a G10 gives it.
- the tool offset in force: G43 adds the length of its H register to Z, G44 subtracts it (a G10 L10/L11 in
  the program, else the set-up's ``<Tools>``); on a lathe the offset number of a ``T0101`` word adds the
  tool's ``x``/``z``. An unknown length or offset makes the axis unknown.
- G53: the programmed value is the machine position, under a tool offset too: the simulation moves the
  controlled point there without the offset (``Simulator._machine_coordinates``: Fanuc cancels the tool
  length offset vector of the axis for the move [K: Fanuc 0i-MB operator's manual B-63844EN/02 14.1.2];
  ISG's ``#SUPPRESS OFFSETS`` suppresses every offset; SINUMERIK writes ``SUPA`` only where none is in
  force, as ``$MN_G53_TOOLCORR`` decides).
- G28/G30 end at the axis's ``home``; without one the axis is unknown.
- G50 (lathe coordinate setting) keeps the machine where it is and moves the frame.
A move on a limited axis whose machine position is unknown is an error once per axis and reason (not
per block), at the first move that needs it. Lines are checked at their end points, arcs also at every
quadrant point they sweep through (an arc bulges past a limit its end points respect).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Callable, Protocol

from ..errors import Location, ProgramError


class TravelError(ProgramError):
    """A move beyond the machine's travel, or one whose machine position cannot be known."""
from ..ir import Block
from ..setup.machine import ROTARY_AXES, AxisTravel
from .work_offsets import offset_beyond_frame

if TYPE_CHECKING:
    from ..context import Context
    from ..ir.state import ModalState


class Simulated(Protocol):
    """What the check reads of the simulator running the program (``postproc.simulate.toolpath.Simulator``)."""

    ctx: "Context"
    axes: tuple[str, ...]
    pos: dict[str, float]
    modal: "ModalState"
    scale: float
    lathe: bool
    diameter: bool
    offsets: dict[int, dict[str, float]]
    declared: dict[int, dict[str, float]]

    def _at(self, block: Block | None = None, word: str | None = None) -> Location: ...

_FRAME_KEYS = frozenset(("WorkOffset", "ToolLengthOffset", "ToolSelect", "DataSetting"))
"""Sections that change what lies between the program's frame and the machine."""
EPSILON = 1e-6
"""mm (or degrees) a point may pass a limit by: the rounding of the toolpath's coordinates."""


class TravelCheck:
    """Tracks the machine position of one simulated run and reports moves beyond the travel."""

    def __init__(self, sim: Simulated, report: Callable[[TravelError], None]) -> None:
        setup = sim.ctx.setup
        self.sim = sim
        self.report = report
        self.setup = setup
        self.unit = setup.machine.units
        self.factor = {a: (1.0 if a in ROTARY_AXES else setup.machine.mm()) * (0.5 if sim.diameter and a == "X" else 1.0)
                       for a in sim.axes}
        """Set-up value -> simulator value (mm, lathe X as a radius), per axis."""
        self.travel: dict[str, AxisTravel] = {a: t for a, t in setup.travel.items() if a in self.factor}
        self.declared = sim.declared
        """The set-up's work offsets in simulator units, by system number (``work_offsets.declared_offsets``)."""
        self.checked = tuple(a for a in sim.axes if a in self.travel and self.travel[a].limited())
        self.length_mode = "cancel"
        self.length_register: int | None = None
        self.dynamic: float | None = None
        """The length (mm) a dynamic offset (G43.1 Z..) gave; None: not a number."""
        self.lathe_offset: int | None = 0
        """The offset number a lathe T word put in force (0: none; None: unknown)."""
        self.lengths: dict[int, float] = {}
        self.wear: dict[int, float] = {}
        """Tool lengths (and their wear) a G10 in the program set, mm, by register."""
        self.frame: dict[str, float] = {}
        """Axis -> machine minus simulator position that a coordinate setting (G50) fixed."""
        self.said: set[tuple[str, str]] = set()
        self.extra: dict[str, tuple[float | None, str]] = {}
        """Axis -> ``_extra`` while no work system, work or tool offset, or coordinate setting changes."""
        self.overrun_block: Block | None = None
        self.overrun: set[str] = set()
        """Axes of ``overrun_block`` already reported beyond their limits."""
        self.why: dict[str, str] = {}
        """Axis -> why its machine position became unknown."""
        self.pos: dict[str, float | None] = {a: self._machine(a, v) for a, v in sim.pos.items()}

    # -- settings ----------------------------------------------------------------------------------
    def settings(self, block: Block) -> None:
        """Tool offsets a block puts in force (before its motion, as the controller applies them)."""
        sections = block.sections
        if not sections.keys().isdisjoint(_FRAME_KEYS):
            self.extra.clear()
        s = sections.get("ToolLengthOffset")
        if s is not None:
            self.length_mode = s.mode  # type: ignore[attr-defined]
            self.length_register = s.register  # type: ignore[attr-defined]
            length = getattr(s, "length", None)
            self.dynamic = length * self.sim.scale if isinstance(length, (int, float)) else None
        s = sections.get("ToolSelect")
        if s is not None and self.sim.lathe:
            number = s.number  # type: ignore[attr-defined]
            self.lathe_offset = number % 100 if number >= 100 else 0 if number == 0 else None
        s = sections.get("DataSetting")
        if s is not None and s.table in ("tool_length", "tool_length_wear"):  # type: ignore[attr-defined]
            table = self.lengths if s.table == "tool_length" else self.wear  # type: ignore[attr-defined]
            value = s.values.get("R")  # type: ignore[attr-defined]
            if value is not None:
                v = value * self.sim.scale
                table[s.index] = table.get(s.index, 0.0) + v if s.incremental else v  # type: ignore[attr-defined]

    def coordinate_set(self, axis: str, value: float) -> None:
        """G50 on a lathe: the tool stays; the program's frame moves so the present point reads ``value``."""
        self.extra.clear()
        here = self.pos.get(axis)
        tool = self._tool(axis)
        if here is None or tool is None:
            self.frame[axis] = math.nan
        else:
            self.frame[axis] = here - value - tool

    # -- moves -------------------------------------------------------------------------------------
    def line(self, block: Block, start: dict[str, float], end: dict[str, float], programmed: set[str],
             incremental: bool, machine: bool) -> None:
        new = self._end(block, start, end, programmed, incremental, machine)
        for axis in self.checked:
            self._check(block, axis, new.get(axis), None)
        self.pos = new

    def home(self, block: Block, axes: set[str]) -> None:
        """The reference leg of G28/G30: each named axis goes to its home."""
        new = dict(self.pos)
        for axis in axes:
            if axis not in new:
                continue
            t = self.travel.get(axis)
            if t is None or t.home is None:
                new[axis] = None
                self._unknown(block, axis, f"the set-up gives axis {axis} no home (<Axis name=\"{axis}\" home=...>) "
                                           "for the reference return")
            else:
                new[axis] = t.home * self.factor[axis]
        self.pos = new

    def arc(self, block: Block, start: dict[str, float], end: dict[str, float], programmed: set[str],
            incremental: bool, centre: tuple[float, float], plane: tuple[str, str], clockwise: bool) -> None:
        new = self._end(block, start, end, programmed, incremental, False)
        extremes: dict[str, list[float]] = {}
        a1, a2 = plane
        shift = {a: None if new.get(a) is None else new[a] - end[a] for a in plane}  # type: ignore[operator]
        for index, point in _arc_extremes((start[a1], start[a2]), (end[a1], end[a2]), centre, clockwise):
            moved = shift[plane[index]]  # an axis whose machine position is known (the other's may not be)
            if moved is not None:
                extremes.setdefault(plane[index], []).append(point + moved)
        for name in self.checked:
            reached = new.get(name)
            if self._check(block, name, reached, None) or reached is None:
                continue
            for bulge in extremes.get(name, []):
                if self._check(block, name, bulge, " between the arc's end points"):
                    break
        self.pos = new

    # -- machine positions ------------------------------------------------------------------------
    def _end(self, block: Block, start: dict[str, float], end: dict[str, float], programmed: set[str],
             incremental: bool, machine: bool) -> dict[str, float | None]:
        new = dict(self.pos)
        for axis, value in end.items():
            if axis in programmed and machine:
                new[axis] = value  # the controlled point, without the tool offset (``_machine_coordinates``)
            elif axis in programmed and not incremental:
                new[axis] = self._machine(axis, value, block)
            else:
                here = self.pos.get(axis)
                if here is None and value != start[axis]:
                    self._unknown(block, axis, self.why.get(axis, "its machine position is unknown"))
                new[axis] = None if here is None else here + (value - start[axis])
        return new

    def _machine(self, axis: str, value: float, block: Block | None = None) -> float | None:
        """The machine position of a simulator position in the present frame, or None (unknown, said)."""
        extra = self.extra.get(axis)
        if extra is None:
            extra = self.extra[axis] = self._extra(axis)
        if extra[0] is None:
            self._unknown(block, axis, extra[1])
            return None
        return value + extra[0]

    def _extra(self, axis: str) -> tuple[float | None, str]:
        """Machine minus simulator position on ``axis`` in the present frame, or None and why not."""
        tool = self._tool(axis)
        frame = self.frame.get(axis)
        if frame is not None:
            base: float | None = None if math.isnan(frame) else frame
            reason = "a coordinate setting while the axis's machine position was unknown"
        else:
            base, reason = self._work_offset(axis)
        if tool is None:
            reason = self._tool_reason(axis)
        if base is None or tool is None:
            return None, reason
        return base + tool, ""

    def _work_offset(self, axis: str) -> tuple[float | None, str]:
        """What the active work system adds beyond what the simulator already added (a G10's values)."""
        return offset_beyond_frame(axis, self.sim.modal.work_offset, self.sim.offsets, self.declared)

    def _tool(self, axis: str) -> float | None:
        """What the tool offset in force adds on ``axis`` (simulator units), or None when unknown."""
        if self.sim.lathe:
            if axis not in ("X", "Z") or self.lathe_offset == 0:
                return 0.0
            if self.lathe_offset is None:
                return None
            tool = self.setup.tools.get(str(self.lathe_offset))
            value = None if tool is None else tool.x if axis == "X" else tool.z
            return None if value is None else value * self.factor[axis]
        if axis == "Z" and self.length_mode == "dynamic":
            return self.dynamic  # the program gave the length itself (G43.1 Z..)
        if axis != "Z" or self.length_mode not in ("positive", "negative") \
                or self.setup.machine.tool_lengths == "touched_off":
            return 0.0
        register = self.length_register
        if register is None:
            return None
        length = self.lengths.get(register)
        if length is None:
            tool = self.setup.tools.get(str(register))
            geometry = None if tool is None else tool.geometry("length")
            if geometry is None:
                return None
            length = geometry * self.factor[axis]
        wear = self.wear.get(register)
        if wear is None:  # the set-up's wear column (Fanuc memory B/C), unless the program wrote one
            tool = self.setup.tools.get(str(register))
            wear = 0.0 if tool is None else tool.wear("length") * self.factor[axis]
        length += wear
        return length if self.length_mode == "positive" else -length

    def _tool_reason(self, axis: str) -> str:
        if self.sim.lathe:
            if self.lathe_offset is None:
                return "a tool word of one or two digits (its offset number depends on the controller)"
            return (f"the set-up gives tool offset {self.lathe_offset} no {axis.lower()} (<Tools><Tool "
                    f"number=\"{self.lathe_offset}\" {axis.lower()}=...>)")
        if self.length_register is None:
            return "a tool length offset without its register"
        return (f"the set-up gives tool length {self.length_register} no value (<Tools><Tool "
                f"number=\"{self.length_register}\" length=...>) and the program sets none")

    # -- reporting ---------------------------------------------------------------------------------
    def _check(self, block: Block, axis: str, value: float | None, how: str | None) -> bool:
        if value is None:
            return False
        t = self.travel[axis]
        f = self.factor[axis]
        unit = "deg" if axis in ROTARY_AXES else self.unit
        for limit, sign in ((t.maximum, 1.0), (t.minimum, -1.0)):
            if limit is None:
                continue
            over = (value - limit * f) * sign
            if over > EPSILON:
                if self.overrun_block is not block:
                    self.overrun_block, self.overrun = block, set()
                if axis not in self.overrun:  # once per block and axis: a cycle's moves repeat it
                    self.overrun.add(axis)
                    self.report(TravelError(
                        f"{axis}{'+' if sign > 0 else '-'}{over / f:.3f} {unit} beyond the limit {limit:.3f}"
                        f"{how or ''} (machine {axis} {value / f:.3f})", self._at(block, axis)))
                return True
        return False

    def _unknown(self, block: Block | None, axis: str, reason: str) -> None:
        """The machine position of ``axis`` is unknown from here: said once per axis and reason, on a
        limited axis, at a block that moves it."""
        self.why[axis] = reason
        if block is None or axis not in self.checked or (axis, reason) in self.said:
            return
        self.said.add((axis, reason))
        self.report(TravelError(f"the travel of {axis} cannot be checked: {reason}", self._at(block, axis)))

    def _at(self, block: Block, axis: str) -> Location:
        return self.sim._at(block, axis if axis in (block.text or "").upper() else None)


def _arc_extremes(start: tuple[float, float], end: tuple[float, float], centre: tuple[float, float],
                  clockwise: bool) -> list[tuple[int, float]]:
    """(0 or 1 for the plane's first or second axis, value) at each quadrant point the arc sweeps through."""
    r = math.hypot(start[0] - centre[0], start[1] - centre[1])
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    sweep = (a0 - a1) if clockwise else (a1 - a0)
    sweep %= 2 * math.pi
    if sweep < 1e-12:
        sweep = 2 * math.pi  # a full circle
    out: list[tuple[int, float]] = []
    for k in range(4):
        angle = k * math.pi / 2
        delta = ((a0 - angle) if clockwise else (angle - a0)) % (2 * math.pi)
        if delta <= sweep:
            axis = k % 2
            value = centre[axis] + (r if k in (0, 1) else -r)
            out.append((axis, value))
    return out
