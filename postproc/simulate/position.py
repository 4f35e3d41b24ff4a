"""The simulator's position: its state (programmed and controlled point, units, feed, offsets, tools), programmed
points to mm, the work offsets a program sets and selects, the feed a move writes, and where an error stands.
The offsets that move a controlled point and the moves themselves are its subclasses'
(``postproc.simulate.compensated_moves``, ``postproc.simulate.moves``); the block dispatch that drives them is
``postproc.simulate.simulator``; what the simulator assumes is in ``postproc.simulate.toolpath``'s docstring."""

from __future__ import annotations

import math
from typing import Any, Callable, Final

from mypy_extensions import mypyc_attr

from ..block_rules import NO_FEED
from ..compensation.cutter_radius import CutterRadius
from ..compensation.tool_length import AXIS as _AXIS, ToolLength
from ..compensation.tool_table import ToolTable
from ..context import Context
from ..errors import Location, ProgramError
from ..ir.expr import Expr
from ..geometry.arcs import CENTRE_KEYS
from ..ir import Block, DataSetting
from ..ir.move_words import X as _X, Y as _Y, Z as _Z
from ..ir.verbatim import STORED_WORK_OFFSET
from ..lowering.program_end import EndTracker
from ..ir.state import ModalState
from .events import LATHE_TOOL_OFFSET, LINEAR_AXES as _LINEAR, TOUCH_OFF, UNEVALUATED, Event, num, start_position
from .move_record import Emitted
from .travel import TravelCheck, TravelError
from .work_offsets import declared_offsets, offset_beyond_frame

LENGTH_AXIS: Final = _AXIS
LINEAR_AXES: Final = _LINEAR
# Final: compiled, a C constant, not a look-up in the module's dictionary (every move reads them)
_NAN: Final = math.nan
PATH_CONTROL: Final = "path control"
"""The setting a path control mode is recorded as (``postproc.simulate.events.UNSIMULATED``)."""
_INITIAL_SETTINGS = {"cutter compensation": "off", "work offset": "1", LATHE_TOOL_OFFSET: "cancel"}
CENTRE_LETTER = {"X": "I", "Y": "J", "Z": "K"}
"""An arc centre's letter by its axis (for an error's column: ``Moves.arc_move``)."""


def point_dict(axes: tuple[str, ...], point: list[float]) -> dict[str, float]:
    """A point in the order of ``axes`` as a dictionary (axis -> value)."""
    out: dict[str, float] = {}
    for i in range(len(axes)):
        out[axes[i]] = point[i]
    return out


def _nowhere(ev: Emitted) -> None:
    raise AssertionError("an event released outside a block")


@mypyc_attr(allow_interpreted_subclasses=True)
class Position:
    """Position, units, offsets and feed of one program run (the state its moves read and change)."""

    def __init__(self, ctx: Context, travel_warn: bool = False) -> None:
        setup = ctx.setup
        self.ctx = ctx
        self.axes = tuple(setup.machine.axes)
        self.keys = tuple((a, a.lower()) for a in self.axes)
        self.key_names = tuple(a.lower() for a in self.axes)
        """The events' axis keys in the order of ``axes`` (one tuple a run, held by every ``MoveRecord``)."""
        self.centre_axes = tuple(a for a in ("X", "Y", "Z") if a in self.axes)
        self.centre_keys = tuple(CENTRE_KEYS[a] for a in self.centre_axes)
        """An arc's centre keys (and their machine axes), held by every arc's ``MoveRecord``."""
        self.records = False
        """A straight move is emitted as its ``MoveRecord`` (``toolpath_stream``'s readers take them), else as the
        record's dictionary (``MoveRecord.event``)."""
        start = start_position(setup)
        self.at: list[float] = [start[a] for a in self.axes]
        """The programmed point, mm (degrees on a rotary axis), in the order of ``axes``: a list by place, where a
        dictionary by axis letter cost each move a copy, a look-up and a write an axis word, and a look-up an axis
        to compare (compiled, ~2.5k instructions a move; callgrind, branch simfast4). Never changed in place: a new
        list where it changes (a move's end is the list ``target`` made). ``pos`` gives it as a dictionary, for
        the readers that are not hot."""
        self.index = {a: i for i, a in enumerate(self.axes)}
        """Machine axis -> its place in ``axes`` (and in ``at`` and the rounded points)."""
        self.length_index = self.index.get(LENGTH_AXIS, -1)
        """The place of the tool length's axis in ``axes`` (-1: the machine has none)."""
        self.x_at = self.index.get("X", -1)
        self.y_at = self.index.get("Y", -1)
        self.z_at = self.index.get("Z", -1)
        """The places of X, Y and Z in ``axes`` (-1: not on the machine), for a move the run's ``MoveWords`` read."""
        self.xyz_bits = (_X if self.x_at >= 0 else 0) | (_Y if self.y_at >= 0 else 0) | (_Z if self.z_at >= 0 else 0)
        """The ``MoveWords`` bits of the machine's axes among X, Y and Z."""
        self.rounded: list[float | int] = [num(v) for v in self.at]
        """The programmed point as the events write it (``num``), in the order of ``axes``: a list, where a
        dictionary cost each move under a tool length ~1.5k instructions in look-ups and writes (compiled). Never
        changed in place (nor is ``crounded``): a ``MoveRecord`` holds it; a change makes a new list."""
        self.modal = ModalState()
        """The program's modal state (units, plane, distance and feed mode, tool...), in program terms."""
        self.home = {axis: t.home * setup.machine.mm() for axis, t in setup.travel.items()
                     if t.home is not None and axis in self.axes and axis in LINEAR_AXES}
        """Where a reference return goes on a mill, mm: the set-up's ``<Axis home>`` (machine coordinates,
        put in the work frame at the move: ``Simulator.machine_to_frame``), else machine zero."""
        self.scale = 1.0
        """mm per program unit (from ``modal.units``)."""
        self.incremental = False
        """``modal.distance`` is incremental (kept at hand: every move reads it)."""
        self.feed: float | None = None
        """The feed in force in mm/min (or the inverse-time value), None until programmed."""
        self.header_mode: str | None = None
        """Feed mode the header states, fixed by the first feed move (None until then)."""
        self.spindle: str | None = None
        """Spindle direction of the last spindle event (None before the first): a tool change stops a
        turning spindle first, as a tool changer does, and stopping a stopped spindle is no event."""
        self.tool_change_keeps_spindle = setup.controller.tool_change_with_spindle_on
        """The set-up's machine changes tools with the spindle turning (``<Controller toolChangeWithSpindleOn>``):
        a tool change stops nothing."""
        self.after_tap: str | None = None
        """The spindle direction before a tap's out stroke, until the next spindle code (``Simulator._restates``)."""
        self.oriented = False
        """An oriented spindle stop was emitted since ``simulate`` last looked (``prepared_taps``)."""
        self.lathe = ctx.lathe
        self.length_at_axis = ctx.length_at_axis
        """A length change keeps the machine point (``Dialect.LENGTH_AT_PROGRAMMED_AXIS``)."""
        self.increments = ctx.increments
        """Addresses that move an axis by an increment (a lathe's U and W: ``Dialect.INCREMENTAL_AXES``)."""
        self.diameter = ctx.diameter
        """X words are diameters: the position is kept as a radius (true geometry, arcs with radius I) and
        written as a diameter."""
        self.factors: list[float] = []
        """Per machine axis (in the order of ``axes``), mm of the position per unit of its word (``scale``, a
        diameter's half): ``target`` reads one number an axis word."""
        self.unit_factors = True
        """Every factor is 1.0 (mm, no diameter): ``target`` reads none (a factor of the list unboxed, ~30
        instructions a word)."""
        self.set_scale(1.0)
        if self.lathe:
            self.modal.plane = "ZX"
            self.modal.feed_mode = ctx.state.feed_mode  # the reading dialect's mode at the start
        self.ended = False
        self.end = EndTracker()
        self.live_after_end: list[int] = []
        """Lines of the live blocks after the program end (code a streamed controller would run)."""
        self.current: Block | None = None
        """The block being simulated (for error locations)."""
        self.unsimulated: list[tuple[int, str, str]] = []
        """(line, setting, value) each time a setting the simulation does not apply changes
        (``UNSIMULATED``): ``verify`` compares these between the two programs."""
        self.mark_held = False
        """For ``verify --transform`` (``postproc.transforms.events``): a reference return's move to the reference
        point carries ``"held"``, the axes it put at a machine position; a straight move that goes nowhere is
        kept, ``"still": True`` (moving the program may move it); ``simulator.simulate`` marks what a block
        programs absolutely (``"programmed"``)."""
        self.tool_data: list[tuple[int, str, str, float]] = []
        """(line, kind, what, mm) each time the tool data in force changes: ``TOOL_LENGTH`` (``positive 18``,
        ``negative 18``, ``dynamic``, ``off``; the length), ``CUTTER_RADIUS`` (``left D18``, ``off``; the radius, nan where the set-up gives
        none), ``TOOL_SELECTION`` (``T5``; the number): ``verify`` names what a translation lost from it
        (``postproc.simulate.lost_tool_data``). A block that changes tool data is rare: nothing a move."""
        self.settings: dict[str, str] = dict(_INITIAL_SETTINGS)
        self.path_pending = True
        """No move yet: a controller that starts in exact stop records it at the first move where the program
        has set no mode before (``Simulator.path_at_first_move``)."""
        self.undeclared: set[str] = set()
        """Machine-specific codes warned about as undeclared (once each)."""
        self.offsets: dict[int, dict[str, float]] = {}
        """Work offsets a G10 set, mm per axis, by work system (1 = G54; 0 the external offset)."""
        self.stored: dict[int, dict[str, float]] = {}
        """Offsets written into the table for the system active then (``STORED_WORK_OFFSET``), mm per axis, by
        work system: they apply at the next selection (``select``)."""
        self.shift: dict[str, float] = {}
        """What the active work system adds to an absolute point (empty until a G10 sets an offset)."""
        self.declared = declared_offsets(setup, self.axes, self.diameter)
        """The set-up's work offsets (``<WorkOffsets>``), simulator units, by work system: the frame does not
        hold them, so a machine position is put in it by subtracting them (``postproc.simulate.work_offsets``)."""
        self.beyond: dict[str, float | None] = self._beyond()
        """Per axis, machine minus frame position from the set-up's work offsets in force (all zero when the
        set-up gives none; None: it gives some, not the active system's on that axis)."""
        self.moved = False
        """A move has been programmed: until then the start (``<Machine startX>``...) is a point of the work
        system the program selects first, so selecting one moves no number (``reframe``)."""
        self.travel: TravelCheck | None = None
        """The travel-limit check, when the set-up declares limits (``postproc.simulate.travel``)."""
        self.travel_warn = travel_warn
        """A move beyond the travel is a warning (``--on-unsupported warn``), not an error."""
        if setup.travel_limited():
            self.travel = TravelCheck(self, self._travel_report)
        self.tools = ToolTable(setup)
        self.length = ToolLength(self.tools)
        self.lathe_shift: dict[str, float] = {}
        """The lathe tool offset in force (``lathe_offset``): mm added to the programmed X (a radius) and Z."""
        self.cutter: CutterRadius | None = None
        """Cutter radius compensation, when the dialect's rules are known (else it stays a setting): set by
        ``CompensatedMoves``."""
        self.cutter_started = False
        """A G41/G42 has started ``cutter`` (before that it is idle: ``_cutter_idle`` reads none of its state, three
        attributes of an interpreted object a move, ~640 instructions compiled)."""
        self.compensating = False
        """Moves go through ``postproc.compensation`` (an offset is in force, a move waits in the cutter
        queue, or the controlled point has not yet met the programmed one again)."""
        self.crounded = list(self.rounded)
        """The controlled point of the last move written, rounded (while ``compensating``), as ``rounded``."""
        self.out: list[Emitted] = []
        """Where released events go: the list the block being run emits into (set once a run by its loop,
        ``simulate``; a list, not its bound ``append``: compiled, an append to a typed list is a C call where calling
        a bound method went through Python's vector call, ~110 instructions a move)."""
        self.queued: Callable[[Emitted], None] = _nowhere
        """``CompensatedMoves._event`` bound once: a block's events while compensating (a bound method made per
        block cost ~340 instructions)."""
        self.spindle_tool: int | None = setup.machine.start_tool
        self.station: int | None = None
        """The turret station at the cutting position (a turret lathe's last index; None: not known, as at the
        start): a T naming it again indexes nothing (``Simulator``: no tool event, its offset applied)."""
        self.cutter_register: int | None = None
        """The cutter compensation register programmed last (a Fanuc G41 without D reads it)."""
        self.kept_native: Callable[[str], bool] | None = None
        """``verify``, where the program it compares with keeps some stretches of cutter compensation as a
        setting (under rules not modelled) and resolved the others into its path: given a G41/G42's
        setting ("left D4"), whether this stretch is one kept (compared as a setting, not compensated here)."""
        self.native_stretch = False
        """The compensation in force is a stretch ``kept_native`` chose: a setting, not simulated."""
        self.offset_register: int | None = None
        """The lathe offset register the T code selected last (a Fanuc T G41 reads it; 0: none)."""
        """The tool the last tool change put in the spindle (before any: the set-up's ``startTool``, None:
        the machine's, unknown)."""
        self.sync: float | None = None
        """While a rigid tap moves (``rigid_tap``): its pitch in mm per revolution, the ``f`` of its moves."""
        self.written_feed: float = _NAN
        self.written_f: float | int = 0
        """The feed ``_feed_into`` last wrote and its ``num`` (the feed of a CAM program changes rarely)."""

    @property
    def pos(self) -> dict[str, float]:
        """The programmed point as a dictionary (axis -> mm), made when read: changing it changes nothing."""
        return point_dict(self.axes, self.at)

    @pos.setter
    def pos(self, point: dict[str, float]) -> None:
        self.at = [point[a] for a in self.axes]

    def axis_value(self, point: list[float], axis: str) -> float:
        """``point``'s value on ``axis`` (a point in the order of ``axes``); 0.0 for an axis the machine lacks."""
        i = self.index.get(axis, -1)
        return point[i] if i >= 0 else 0.0

    def target(self, block: Block, axes: dict[str, float | Expr], absolute: bool,
               machine: bool = False) -> list[float]:
        """End point in mm of programmed axis words (absolute or incremental), in the order of ``axes``; an
        absolute point in work coordinates is shifted by the work offset a G10 set (``shift``), one in machine
        coordinates not."""
        at = self.at
        out = at[:]  # (a slice: compiled, one C call; ``list(at)`` went through the sequence protocol)
        incremental = self.incremental and not absolute
        shift = self.shift if not machine and not incremental and len(self.shift) else None  # (tested once)
        increments = self.increments if len(self.increments) else None  # empty on a mill: tested once, not a word
        factors = self.factors
        plain = self.unit_factors and not incremental and shift is None  # a word's float is the point's (``word * 1.0``)
        if plain and increments is None:
            # A move the reading's modal state read (``ModalStateSyntax._move``: the run's ``MoveWords``, keyed on
            # these words, which no step changes in place): its X, Y and Z floats are the point's, as the loop
            # below stores them, without its three look-ups (~400 instructions a move compiled).
            read = self.ctx.move_words
            bits = read.bits
            if axes is read.axes and bits >= 0 and len(axes) == read.size and bits & self.xyz_bits == bits:
                held_words: list[Any] = out  # (the words as objects, as the loop below stores them)
                if bits & _X:
                    held_words[self.x_at] = read.x_word
                if bits & _Y:
                    held_words[self.y_at] = read.y_word
                if bits & _Z:
                    held_words[self.z_at] = read.z_word
                return out
        held: list[Any] = out  # (its items as objects: compiled, a word's float stored as it is, not unboxed and boxed)
        names = self.axes
        found = 0
        for i in range(len(names)):  # the machine's axes first, each looked up (the words of a block are most
            # often all axes: a look-up ~130 instructions compiled, where taking an item of ``axes.items()`` and
            # finding its axis's place by its letter cost ~230; ``target`` 1,600 -> 1,307 a move of three words,
            # callgrind, branch simfast8)
            axis = names[i]
            word = axes.get(axis)
            kept: Any = word  # (the word's object as it is: compiled, a narrowed float is unboxed and boxed again)
            if word is None or increments is not None and axis in increments:
                continue  # (an address that is an increment is the second loop's)
            found += 1
            if isinstance(word, float):  # a float first: one type test a word
                if plain or factors[i] == 1.0 and not incremental and shift is None:
                    held[i] = kept  # the word's own float (``word * 1.0`` is it): none made, none freed at the next move
                    continue
            elif isinstance(word, Expr):
                raise ProgramError(UNEVALUATED, self._at(block, axis))
            v = word * factors[i]
            out[i] = at[i] + v if incremental else v + shift.get(axis, 0.0) if shift is not None else v
        if found == len(axes):
            return out
        index = self.index
        for axis, value in axes.items():  # the other words: a lathe's increments (U, W), or no axis of the machine
            real = increments.get(axis) if increments is not None else None
            if real is None:
                if axis in index:
                    continue  # (the first loop's)
                raise ProgramError(f"axis {axis} is not on this machine (axes {''.join(self.axes)})",
                                   self._at(block, axis))
            if not isinstance(value, float) and isinstance(value, Expr):
                raise ProgramError(UNEVALUATED, self._at(block, axis))
            r = index.get(real, -1)
            if r < 0:
                raise ProgramError(f"axis {real} is not on this machine (axes {''.join(self.axes)})",
                                   self._at(block, axis))
            v = value * self.scale * (0.5 if self.diameter and real == "X" else 1.0)
            out[r] = out[r] + v
        return out


    def set_scale(self, scale: float) -> None:
        """mm per program unit (the units changed), and with it each axis word's factor (``factors``: a
        diameter's half times the scale is the scale's half, exactly)."""
        self.scale = scale
        diameter = self.diameter
        self.factors = [(scale if a in LINEAR_AXES else 1.0) * (0.5 if diameter and a == "X" else 1.0)
                        for a in self.axes]
        self.unit_factors = all(factor == 1.0 for factor in self.factors)

    def note_tool_data(self, line: int, kind: str, what: str, value: float) -> None:
        """Record a change of the tool data in force (``tool_data``); the same value again is no change."""
        data = self.tool_data
        for k in range(len(data) - 1, -1, -1):
            if data[k][1] == kind:
                if data[k][2] == what and (data[k][3] == value or value != value and data[k][3] != data[k][3]):
                    return
                break
        data.append((line, kind, what, value))

    def data_setting(self, block: Block, setting: DataSetting) -> None:
        """G10: a work offset is kept (mm, per axis) and shifts later absolute points in its system; a tool
        register is kept for the offsets that read it; other data is recorded for ``verify``."""
        if setting.table in TOUCH_OFF:
            self.touch_off(block, setting)
            return
        if not setting.table.startswith("work_offset"):
            if not self.tools.write(setting, self.scale):
                self.unsimulated.append((block.line, "tool offset data", setting.text))
            return
        stored = setting.table == STORED_WORK_OFFSET
        key = setting.index if setting.table == "work_offset" or stored else 100 + setting.index
        if stored and key == self.modal.work_offset:
            entry = self.stored.setdefault(key, {})  # the table's entry: taken at the next selection (``select``)
        else:
            entry = self.offsets.setdefault(key, {})
        for axis, value in setting.values.items():
            if isinstance(value, Expr):
                raise ProgramError(UNEVALUATED, self._at(block, axis))
            v = value * self.scale if axis in LINEAR_AXES else value
            if setting.incremental:  # added to the offset in force: the program's, else the set-up's
                v += entry.get(axis, self.declared.get(key, {}).get(axis, 0.0))
            entry[axis] = v
        if stored and key == self.modal.work_offset:
            return
        self._shift()
        if self.declared:
            self.reframe(block)

    def select(self) -> None:
        """A work system selection: the offsets the program set, those written into the table for the active
        system (``STORED_WORK_OFFSET``) included, apply from here."""
        if self.stored:
            for key, values in self.stored.items():
                self.offsets.setdefault(key, {}).update(values)
            self.stored.clear()
        if self.offsets:
            self._shift()

    def touch_off(self, block: Block, setting: DataSetting) -> None:
        """A tool entry measured where the tool stands (LinuxCNC ``G10 L10``/``L11``): the offsets that make
        the current point read the given Z (and X, Y) in the active work system (its offset cancels) or in
        work system 9, with the offsets in force now; R sets the radius (``postproc_linuxcnc.tool_entry``).
        [V] LinuxCNC ``interp_convert.cc`` ``convert_setup_tool``: each axis word gives the entry's offset as
        the point without the tool offset in that system minus the word; X alone keeps the entry's Y, Y
        alone its X (their rotated components, no rotation being modelled here)."""
        for letter in setting.values:
            if isinstance(setting.values[letter], Expr):
                raise ProgramError(UNEVALUATED, self._at(block, letter))
        system = self.shift if setting.table == TOUCH_OFF[0] else self.offsets.get(9, {})
        for axis in ("X", "Y", LENGTH_AXIS):
            value = setting.values.get(axis)
            if not isinstance(value, (int, float)):
                continue
            if axis not in self.index:
                raise ProgramError(f"axis {axis} is not on this machine", self._at(block, axis))
            in_force = self.length.offset if axis == LENGTH_AXIS else self.lathe_shift.get(axis, 0.0)
            measured = self.at[self.index[axis]] + in_force - (value * self.scale + system.get(axis, 0.0))
            if axis == LENGTH_AXIS:
                self.tools.set("length", setting.index, measured)
            else:
                self.tools.set_sideways(setting.index, axis, measured)
        r = setting.values.get("R")
        if isinstance(r, (int, float)):
            self.tools.set("radius", setting.index, r * self.scale)

    def _shift(self) -> None:
        """The offset of the active work system plus the external one (P0), applied to absolute points."""
        active = self.offsets.get(self.modal.work_offset, {})
        common = self.offsets.get(0, {})
        self.shift = {a: active.get(a, 0.0) + common.get(a, 0.0) for a in set(active) | set(common)}

    def _beyond(self) -> dict[str, float | None]:
        if not self.declared:
            return {a: 0.0 for a in self.axes}
        return {a: offset_beyond_frame(a, self.modal.work_offset, self.offsets, self.declared)[0] for a in self.axes}

    def reframe(self, block: Block) -> None:
        """The work system or an offset changed while the set-up gives work offsets: the machine stays, so the
        present point is given in the new frame ([V] rs274: after ``G55`` an axis not programmed reads the
        machine position less G55's offset). Where the set-up lacks the old or the new system's offset on an
        axis, that point is unknown: a located error, never a point off by the missing offset."""
        new = self._beyond()
        if not self.moved:
            self.beyond = new
            return
        for axis, after in new.items():
            before = self.beyond[axis]
            if before == after:
                continue
            if before is None or after is None:
                system = self.modal.work_offset
                why = offset_beyond_frame(axis, system, self.offsets, self.declared)[1] if after is None else (
                    f"the set-up gives the work system left no offset for {axis} and the program set none")
                raise ProgramError(f"where the tool stands in the new work coordinates is unknown: {why}",
                                   self._at(block))
            if self.cutter is not None and self.cutter.side is not None:
                raise ProgramError("a change of work offset with cutter compensation on cannot be run",
                                   self._at(block))  # [V] LinuxCNC: "Cannot change coordinate systems with cutter radius compensation on"
            delta = before - after
            i = self.index[axis]
            self.at = list(self.at)
            self.at[i] += delta
            self.rounded, self.crounded = list(self.rounded), list(self.crounded)  # (a record may hold them)
            self.rounded[i] = num(self.at[i])
            self.crounded[i] = num(self.crounded[i] + delta)
        self.beyond = new

    def _coordinate(self, block: Block, axis: str, value: float) -> None:
        """Coordinate setting: the tool's present point gets ``value`` on ``axis``; nothing moves."""
        if axis not in self.index:
            raise ProgramError(f"axis {axis} is not on this machine (axes {''.join(self.axes)})", self._at(block, axis))
        v = value * self.scale * (0.5 if self.diameter and axis == "X" else 1.0)
        if self.travel is not None:
            self.travel.coordinate_set(axis, v)
        self.at = list(self.at)
        self.at[self.index[axis]] = v
        self.rounded = list(self.rounded)  # (a record may hold it)
        self.rounded[self.index[axis]] = num(v)

    def _programmed(self, axes: dict[str, float | Expr]) -> set[str]:
        """The machine axes a block's axis words name (a lathe's U and W are X and Z)."""
        increments = self.increments
        return {increments.get(a, a) for a in axes} if increments else set(axes)

    def _travel_report(self, err: TravelError) -> None:
        """A travel problem: an error, or a warning under ``--on-unsupported warn``; the block's events
        stay (the path is still drawn)."""
        if self.travel_warn:
            self.ctx.diagnostics.warn(err.message, err.location)
        else:
            self.ctx.diagnostics.error(err)

    # -- feed --------------------------------------------------------------------------------------
    def _set_feed(self, value: float) -> None:
        self.feed = value if self.modal.feed_mode == "inverse_time" else value * self.scale

    def _feed_into(self, ev: Event) -> None:
        """A feed move's ``f`` and, where it differs from the header's, its ``feed_mode``, into its event."""
        ev["f"] = self._feed_value()
        mode = self._stated_mode()
        if mode is not None:
            ev["feed_mode"] = mode

    def _feed_value(self) -> float | int:
        """A feed move's ``f`` as written; the first fixes the header's feed mode."""
        if self.sync is not None:  # a rigid tap: its pitch, per revolution whatever the feed mode
            return num(self.sync)
        feed = self.feed
        if feed is None:
            raise ProgramError(NO_FEED, self._at(), needs="F")
        if feed != self.written_feed:  # always for nan: ``num`` refuses it at each move, as it did (and before the
            # first feed: ``written_feed`` starts as nan; a float, compiled one unboxed comparison, not a boxed one)
            self.written_f = num(feed)
            self.written_feed = feed
        if self.header_mode is None:
            self.header_mode = self.modal.feed_mode
        return self.written_f

    def _stated_mode(self) -> str | None:
        """The ``feed_mode`` a feed move states after ``_feed_value``: its own where it is not the header's (a
        synchronised move's per revolution), else none."""
        if self.sync is not None:
            return None if self.header_mode == "per_rev" else "per_rev"
        mode = self.modal.feed_mode
        return None if mode == self.header_mode else mode

    # -- locations (computed only for errors) ------------------------------------------------------
    def _at(self, block: Block | None = None, word: str | None = None) -> Location:
        """Where ``word`` (a letter, or a code such as 'G68') stands in the block; column 1 if unknown."""
        block = block or self.current
        if block is None:
            return Location(self.ctx.file, 0, 1)
        if word is None:
            return self.ctx.at(block)
        if len(word) > 1:
            i = (block.text or "").upper().find(word.upper())
            return self.ctx.at(block, i + 1 if i >= 0 else 1)
        return self.ctx.at(block, self.ctx.column_of(block, word))

