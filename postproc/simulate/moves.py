"""The simulator's position and moves: programmed points to mm, straight and arc moves as events, and
the tool length and cutter radius compensation they pass through (``postproc.compensation``). The block
dispatch that drives them is ``postproc.simulate.simulator``; what the simulator assumes is in
``postproc.simulate.toolpath``'s docstring. Over 600 lines: the moves and the offsets that move their
controlled point (length, lathe and entry offsets, cutter radius) read and change one position state."""

from __future__ import annotations

from typing import Any, Callable, Final

from mypy_extensions import mypyc_attr

from ..block_rules import NO_FEED, ArcError, arc_centre
from ..compensation.cutter_radius import CutterRadius, Item, Segment
from ..compensation.nose import TIPS, mirrored
from ..compensation.geometry_for import cutter_for
from ..compensation.rules import CutterRules
from ..compensation.tool_length import AXIS as _AXIS, ToolLength
from ..compensation.tool_table import ToolTable
from ..context import Context
from ..errors import Location, PostprocError, ProgramError, UnsupportedError
from ..expr import Expr
from ..geometry import CENTRE_KEYS
from ..ir import Block, DataSetting, Motion
from ..ir.verbatim import STORED_WORK_OFFSET
from ..lowering.inverse_time import move_length
from ..lowering.program_end import EndTracker
from ..state import PLANE_AXES, ModalState
from .events import LATHE_TOOL_OFFSET, LINEAR_AXES as _LINEAR, TOUCH_OFF, UNEVALUATED, Event, num, start_position
from .move_record import Emitted, MoveRecord
from .travel import TravelCheck, TravelError
from .work_offsets import declared_offsets, offset_beyond_frame

LENGTH_AXIS: Final = _AXIS
LINEAR_AXES: Final = _LINEAR
# Final: compiled, a C constant, not a look-up in the module's dictionary (every move reads them)
PATH_CONTROL: Final = "path control"
"""The setting a path control mode is recorded as (``postproc.simulate.events.UNSIMULATED``)."""
_INITIAL_SETTINGS = {"cutter compensation": "off", "work offset": "1", LATHE_TOOL_OFFSET: "cancel"}
_CENTRE_LETTER = {"X": "I", "Y": "J", "Z": "K"}


def _nowhere(ev: Emitted) -> None:
    raise AssertionError("an event released outside a block")


@mypyc_attr(allow_interpreted_subclasses=True)
class Moves:
    """Position, units and compensation of one program run; its moves become events (``out``)."""

    def __init__(self, ctx: Context, travel_warn: bool = False, cutter_rules: CutterRules | None = None) -> None:
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
        self.pos = start_position(setup)
        self.index = {a: i for i, a in enumerate(self.axes)}
        """Machine axis -> its place in ``axes`` (and in the rounded points)."""
        self.length_index = self.index.get(LENGTH_AXIS, -1)
        """The place of the tool length's axis in ``axes`` (-1: the machine has none)."""
        self.rounded: list[float | int] = [num(self.pos[a]) for a in self.axes]
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
        self.factors: dict[str, float] = {}
        """Per machine axis, mm of the position per unit of its word (``scale``, a diameter's half): ``target``
        reads one number an axis word, and a letter not here is no axis of the machine."""
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
        self.cutter = None if cutter_rules is None else cutter_for(cutter_rules, self._release)
        """Cutter radius compensation, when the dialect's rules are known (else it stays a setting)."""
        self.cutter_started = False
        """A G41/G42 has started ``cutter`` (before that it is idle: ``_cutter_idle`` reads none of its state, three
        attributes of an interpreted object a move, ~640 instructions compiled)."""
        self.compensating = False
        """Moves go through ``postproc.compensation`` (an offset is in force, a move waits in the cutter
        queue, or the controlled point has not yet met the programmed one again)."""
        self.crounded = list(self.rounded)
        """The controlled point of the last move written, rounded (while ``compensating``), as ``rounded``."""
        self.out: Callable[[Emitted], None] = _nowhere
        """Where released events go (the ``emit`` of the block being run)."""
        self.queued: Callable[[Emitted], None] = self._event
        """``_event`` bound once: a block's events while compensating (a bound method made per block cost
        ~340 instructions)."""
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
        self.written_feed: float | None = None
        self.written_f: float | int = 0
        """The feed ``_feed_into`` last wrote and its ``num`` (the feed of a CAM program changes rarely)."""


    def target(self, block: Block, axes: dict[str, float | Expr], absolute: bool,
               machine: bool = False) -> dict[str, float]:
        """End point in mm of programmed axis words (absolute or incremental); an absolute point in work
        coordinates is shifted by the work offset a G10 set (``shift``), one in machine coordinates not."""
        pos = self.pos
        out = dict(pos)
        incremental = self.incremental and not absolute
        shift = self.shift if not machine and not incremental and self.shift else None  # (tested once, not a word)
        increments = self.increments if self.increments else None  # empty on a mill: tested once, not a word
        factors = self.factors
        for axis, value in axes.items():
            if not isinstance(value, float) and isinstance(value, Expr):  # a float first: one type test a word
                raise ProgramError(UNEVALUATED, self._at(block, axis))
            real = increments.get(axis) if increments is not None else None
            if real is not None:
                if real not in pos:
                    raise ProgramError(f"axis {real} is not on this machine (axes {''.join(self.axes)})",
                                       self._at(block, axis))
                v = value * self.scale * (0.5 if self.diameter and real == "X" else 1.0)
                out[real] = out[real] + v
                continue
            factor = factors.get(axis)
            if factor is None:
                raise ProgramError(f"axis {axis} is not on this machine (axes {''.join(self.axes)})",
                                   self._at(block, axis))
            v = value * factor
            out[axis] = pos[axis] + v if incremental else v + shift.get(axis, 0.0) if shift is not None else v
        return out


    def set_scale(self, scale: float) -> None:
        """mm per program unit (the units changed), and with it each axis word's factor (``factors``: a
        diameter's half times the scale is the scale's half, exactly)."""
        self.scale = scale
        diameter = self.diameter
        self.factors = {a: (scale if a in LINEAR_AXES else 1.0) * (0.5 if diameter and a == "X" else 1.0)
                        for a in self.axes}

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
            if axis not in self.pos:
                raise ProgramError(f"axis {axis} is not on this machine", self._at(block, axis))
            in_force = self.length.offset if axis == LENGTH_AXIS else self.lathe_shift.get(axis, 0.0)
            measured = self.pos[axis] + in_force - (value * self.scale + system.get(axis, 0.0))
            if axis == LENGTH_AXIS:
                self.tools.set("length", setting.index, measured)
            else:
                self.tools.set_sideways(setting.index, axis, measured)
        r = setting.values.get("R")
        if isinstance(r, (int, float)):
            self.tools.set("radius", setting.index, r * self.scale)

    def compensation(self, block: Block, emit: Callable[[Emitted], None]) -> None:
        """A block's cutter compensation and tool length changes (before its motion, as the controller
        runs them): compensation ends first, so the move it queued is written with the old setting."""
        get = block.sections.get
        cutter, cc = self.cutter, get("CutterCompensation")
        if cutter is not None and cc is not None:
            mode = cc.mode  # type: ignore[attr-defined]
            if mode == "off":
                cutter.cancel()
            elif mode in ("left", "right") and self.native_stretch:
                cutter.cancel()  # recorded as a setting (``record_settings``), as without rules
            elif mode in ("left", "right"):
                reads = self._cutter_register(block, cc.register)  # type: ignore[attr-defined]
                self.cutter_started = True
                try:
                    cutter.start(mode, self._cutter_radius(block, reads), self.modal.plane,
                                 self._nose_tip(block, reads))
                except PostprocError as err:
                    raise err.located(self._at(block)) from None
                self._begin()
            else:
                raise UnsupportedError(f"cutter compensation '{mode}' cannot be simulated", self._at(block))
        dynamic = get("DynamicCutterCompensation")
        if dynamic is not None:
            if cutter is None:
                raise UnsupportedError("cutter compensation by a diameter cannot be simulated under the rules of "
                                       f"{self.ctx.dialect}", self._at(block))
            lathe = self.modal.plane == "ZX" and self.lathe
            tip = TIPS[mirrored(dynamic.orientation or 0)] if lathe else (0, 0)  # type: ignore[attr-defined]
            self.cutter_started = True
            try:  # D/2, negative: the other side
                cutter.start(dynamic.mode, dynamic.radius(self.scale), self.modal.plane,  # type: ignore[attr-defined]
                             (float(tip[0]), float(tip[1])))
            except PostprocError as err:
                raise err.located(self._at(block)) from None
            self._begin()
        tl = get("ToolLengthOffset")
        if tl is not None and self.lathe and tl.mode in ("positive", "cancel"):  # type: ignore[attr-defined]
            register = tl.register if tl.register is not None else self.spindle_tool  # type: ignore[attr-defined]
            self.lathe_offset(block, 0 if tl.mode == "cancel" else register)  # type: ignore[attr-defined]
        elif tl is not None:
            before = self.length.offset
            try:
                self.length.change(tl.mode, tl.register, tl.length, self.scale)  # type: ignore[attr-defined]
            except PostprocError as err:
                raise err.located(self._at(block, "H")) from None
            if self.length_at_axis and self.length.offset != before:
                self._keep_machine_point(self.length.offset - before)
            elif self.length.offset:
                self._begin()
            register = tl.register  # type: ignore[attr-defined]
            across = self.tools.sideways(register) if tl.mode == "positive" and isinstance(register, int) else {}  # type: ignore[attr-defined]
            if across or self.lathe_shift:
                self._tool_shift(across)  # the entry's X and Y offsets (LinuxCNC ``G10 L1 X.. Y..``)

    def _keep_machine_point(self, change: float) -> None:
        """A length change on a controller that moves nothing until the length axis is programmed
        absolutely: the controlled point stays, the programmed point takes the change instead ([V] rs274:
        ``G43 H1`` then ``G1 X10`` keeps machine Z, the canonical Z reads ``old - length``; [V] grbl
        ``gcode.c``: an axis without a word keeps ``gc_state.position``, the machine position, and only an
        absolute word adds ``tool_length_offset``). A later incremental move moves the machine by its
        increment, an absolute one goes to the programmed point plus the new length."""
        if LENGTH_AXIS not in self.pos:
            return
        self._begin()  # the controlled point before the change is the one kept
        self.pos = dict(self.pos)  # the old dict may be a queued segment's end
        self.pos[LENGTH_AXIS] -= change
        self.rounded = list(self.rounded)
        self.rounded[self.index[LENGTH_AXIS]] = num(self.pos[LENGTH_AXIS])
        self._settle()

    def lathe_offset(self, block: Block, register: object) -> None:
        """A lathe's tool offset register selected (Fanuc T/GSK ``T0102``'s last digits, LinuxCNC's lathe
        ``G43 H2``; 0 cancels). Where the set-up gives the register's X and Z (``<Tool x z>``), they move
        the controlled point: from the next move on (Fanuc T, GSK: the simulation's model, as for a mill's
        length [?]: Fanuc's parameter LWM chooses the T block itself or the next move, the end point of
        that move is the same), or where the axis is next programmed absolutely on a controller that moves
        nothing at the change ([V] rs274: lathe ``G43 H2`` prints ``USE_TOOL_LENGTH_OFFSET`` with entry 2's
        X and Z and moves nothing). Where it gives none, the selection is a setting that moves the tool,
        compared between the programs (``verify``), never taken as zero silently."""
        self.offset_register = register if isinstance(register, int) else None
        values = self.tools.lathe(register, self.diameter) if isinstance(register, int) else None
        if values is None:
            self._lathe_shift(0.0, 0.0)
            value = "cancel" if register == 0 else f"offset {register}"
            if value != self.settings.get(LATHE_TOOL_OFFSET):
                self.settings[LATHE_TOOL_OFFSET] = value
                self.unsimulated.append((block.line, LATHE_TOOL_OFFSET, value))
            return
        if self.settings.get(LATHE_TOOL_OFFSET) != "cancel":
            self.settings[LATHE_TOOL_OFFSET] = "cancel"  # applied from here on: nothing left to compare
            self.unsimulated.append((block.line, LATHE_TOOL_OFFSET, "cancel"))
        self._lathe_shift(*values)

    def _lathe_shift(self, x: float, z: float) -> None:
        """Put the lathe offset (X radius, Z; mm) in force."""
        self._tool_shift({"X": x, "Z": z} if x or z else {})

    def _tool_shift(self, new: dict[str, float]) -> None:
        """Put a tool offset along the axes of ``new`` (mm) in force, beside the length along the spindle axis:
        a lathe tool's X and Z, a mill's entry X and Y (``ToolTable.sideways``); kept in ``lathe_shift``."""
        old = self.lathe_shift
        if new == old:
            return
        if self.length_at_axis:
            self._begin()
            self.pos, self.rounded = dict(self.pos), list(self.rounded)
            for axis in sorted(set(new) | set(old)):
                change = new.get(axis, 0.0) - old.get(axis, 0.0)
                if change and axis in self.pos:
                    self.pos[axis] -= change
                    self.rounded[self.index[axis]] = num(self.pos[axis])
        self.lathe_shift = new
        if new:
            self._begin()
        self._settle()

    def _cutter_register(self, block: Block, register: int | None) -> int:
        """The register a G41/G42 reads: its own, or by the rules the spindle tool's (LinuxCNC). The plane
        is checked by ``CutterRadius.start`` (``CutterRules.planes``)."""
        assert self.cutter is not None
        if register is None and self.cutter.rules.register_absent == "offset":
            if not self.offset_register:
                raise ProgramError("tool nose radius compensation takes the radius of the offset the T code "
                                   "selected, and none is (program T with its offset number, T0101)",
                                   self._at(block))
            register = self.offset_register
        if register is None and self.cutter.rules.register_absent == "modal":
            if self.cutter_register is None:
                raise ProgramError("cutter compensation without its register takes the register programmed "
                                   "last, and none was: program D", self._at(block))
            return self.cutter_register
        if register is None:
            if self.cutter.rules.register_absent != "tool":
                raise UnsupportedError("cutter compensation without its register cannot be simulated",
                                       self._at(block))
            if self.spindle_tool is None:
                raise ProgramError("cutter compensation without its register takes the tool in the spindle, which "
                                   "is not known here (no tool change before it): program its register",
                                   self._at(block))
            register = self.spindle_tool
        self.cutter_register = register
        return register

    def _cutter_radius(self, block: Block, register: int) -> float:
        """The radius register ``register`` holds (a lathe tool's nose radius)."""
        try:
            return self.tools.radius(register)
        except PostprocError as err:
            raise err.located(self._at(block, "D")) from None

    def _nose_tip(self, block: Block, register: int) -> tuple[float, float]:
        """On a lathe (the ZX plane), the direction from the tool's nose centre to its imaginary tip, by
        the register's ``<Tool tip>`` (``postproc.compensation.nose``); a mill's tool has none."""
        if self.modal.plane != "ZX" or not self.lathe:
            return (0.0, 0.0)
        direction = TIPS[self.tools.tip(register)]
        return float(direction[0]), float(direction[1])

    def _begin(self) -> None:
        """Moves from here on go through the compensation."""
        if not self.compensating:
            self.compensating = True
            self.crounded = list(self.rounded)

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
            self.pos[axis] += delta
            i = self.index[axis]
            self.rounded, self.crounded = list(self.rounded), list(self.crounded)  # (a record may hold them)
            self.rounded[i] = num(self.pos[axis])
            self.crounded[i] = num(self.crounded[i] + delta)
        self.beyond = new

    def _coordinate(self, block: Block, axis: str, value: float) -> None:
        """Coordinate setting: the tool's present point gets ``value`` on ``axis``; nothing moves."""
        if axis not in self.pos:
            raise ProgramError(f"axis {axis} is not on this machine (axes {''.join(self.axes)})", self._at(block, axis))
        v = value * self.scale * (0.5 if self.diameter and axis == "X" else 1.0)
        if self.travel is not None:
            self.travel.coordinate_set(axis, v)
        self.pos[axis] = v
        self.rounded = list(self.rounded)  # (a record may hold it)
        self.rounded[self.index[axis]] = num(v)

    def line_move(self, kind: str, target: dict[str, float], line: int, emit: Callable[[Emitted], None]) -> None:
        if self.compensating:
            if self._cutter_idle() and not self.diameter:
                self._offset_line(kind, target, line)
            else:
                self._compensated(kind, target, line, None, None)
            return
        pos = self.pos
        rounded = list(self.rounded)
        for i, axis in enumerate(self.axes):
            value = target[axis]
            if value != pos[axis]:
                rounded[i] = num(value)
        if rounded == self.rounded:
            self.pos = target
            if self.mark_held:  # ``verify --transform`` may move it to somewhere else (``mark_held``)
                still: Event = {"line": line, "move": kind, "still": True}
                for i, (axis, key) in enumerate(self.keys):
                    still[key] = rounded[i]
                if self.diameter and "x" in still:
                    still["x"] = num(target["X"] * 2.0)
                if kind != "rapid":
                    self._feed_into(still)
                emit(still)
            return
        point = rounded
        if self.diameter and "X" in self.index:  # written as a diameter, kept as a radius
            point = list(rounded)
            point[self.index["X"]] = num(target["X"] * 2.0)
        f: float | int | None = None
        mode: str | None = None
        if kind != "rapid":
            f = self._feed_value()
            mode = self._stated_mode()
        self.pos, self.rounded = target, rounded
        record = MoveRecord(line, kind, self.key_names, point, f, mode, None)
        emit(record if self.records else record.event())

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

    def arc_move(self, block: Block, m: Motion, target: dict[str, float], emit: Callable[[Emitted], None],
                 absolute: bool = False) -> None:
        plane = self.modal.plane
        a1, a2, normal = PLANE_AXES[plane]
        pos = self.pos
        for axis in (a1, a2):
            if axis not in pos:
                raise ProgramError(f"an arc in the {plane} plane needs axis {axis}, not on this machine",
                                   self._at(block))
        s = (pos[a1], pos[a2])
        e = (target[a1], target[a2])
        clockwise = m.mode == "cw"
        offsets: dict[str, float] = {}
        for axis, value in (m.center or {}).items():
            if axis not in (a1, a2):
                raise ProgramError(f"arc centre offset along {axis} is outside the {plane} plane",
                                   self._at(block, _CENTRE_LETTER.get(axis, "G")))
            if isinstance(value, Expr):
                raise ProgramError(UNEVALUATED, self._at(block, _CENTRE_LETTER.get(axis, "G")))
            offsets[axis] = value
        scale = self.scale
        if isinstance(m.radius, Expr):
            raise ProgramError(UNEVALUATED, self._at(block, "R"))
        radius = None if m.radius is None else m.radius * scale
        try:
            c = arc_centre(s, e, (a1, a2), radius, {a: v * scale for a, v in offsets.items()}, clockwise,
                           self.ctx.arc_end, scale != 1.0, scale)
        except ArcError as err:
            raise err.located(self._at(block, err.letter)) from None
        if self.travel is not None:
            programmed = self._programmed(m.axes)
            incremental = self.incremental and not absolute
            if c is None:
                self.travel.line(block, pos, target, programmed, incremental, False)
            else:
                self.travel.arc(block, pos, target, programmed, incremental, c, (a1, a2), clockwise)
        if c is None:
            self.line_move("feed", target, block.line, emit)  # zero radius, zero length: dropped
            return
        if self.compensating:
            if self._cutter_idle() and not self.diameter:
                self._offset_arc(m.mode or "cw", target, block.line, c, plane)
            else:
                self._compensated(m.mode or "cw", target, block.line, c, plane)
            return
        rounded = [num(target[a]) for a in self.axes]
        centre = {a1: c[0], a2: c[1], normal: pos.get(normal, 0.0)}
        point = rounded
        written: list[float | int] = []
        for axis in self.centre_axes:
            written.append(num(centre[axis] * 2.0) if self.diameter and axis == "X" else num(centre[axis]))
        if self.diameter and "X" in self.index:  # written as a diameter, kept as a radius
            point = list(rounded)
            point[self.index["X"]] = num(target["X"] * 2.0)
        f = self._feed_value()
        mode = self._stated_mode()
        self.pos, self.rounded = target, rounded
        record = MoveRecord(block.line, m.mode or "cw", self.key_names, point, f, mode, None, self.centre_keys,
                            written, plane)
        emit(record if self.records else record.event())

    # -- compensation -------------------------------------------------------------------------------
    def _compensated(self, kind: str, target: dict[str, float], line: int, centre: tuple[float, float] | None,
                     plane: str | None) -> None:
        """A move handed to the compensation: the cutter queue (when compensating the radius) or straight
        to ``_write``; the programmed point moves on at once."""
        fields: Event = {"line": line}
        if kind != "rapid":
            self._feed_into(fields)
            if self.modal.feed_mode == "inverse_time" and self.sync is None and not self._cutter_idle():
                self._programmed_rate(fields, kind, target, centre, plane)
        pos = self.pos
        cutter = self.cutter
        a1, a2, normal = cutter.axes if cutter is not None else PLANE_AXES["XY"]
        seg = Segment(kind, fields, target, pos.get(normal, 0.0), self.length.offset)
        if centre is not None:
            seg.centre = seg.ccentre = centre
            seg.turn = 1 if kind == "ccw" else -1
            seg.normal = pos.get(PLANE_AXES[plane or "XY"][2], 0.0)
        if not self._cutter_idle():
            assert cutter is not None
            if cutter.on and PLANE_AXES[self.modal.plane] != cutter.axes:
                raise ProgramError(f"the plane cannot change to {self.modal.plane} while cutter compensation is on "
                                   "(cancel it first)", self._at())
            if cutter.on and (a1 not in pos or a2 not in pos):
                raise ProgramError(f"cutter compensation in the {self.modal.plane} plane needs axes {a1} and {a2}",
                                   self._at())
            start = (pos.get(a1, 0.0), pos.get(a2, 0.0))
            if centre is None:
                cutter.line(seg, start)
            else:
                cutter.arc(seg, start)
        else:
            self._write(seg)
        self.pos = target
        self.rounded = [num(target[a]) for a in self.axes]
        self._settle()

    def _programmed_rate(self, fields: Event, kind: str, target: dict[str, float],
                         centre: tuple[float, float] | None, plane: str | None) -> None:
        """An inverse-time move under cutter compensation runs at F times the length of the *programmed*
        move per minute, along the compensated one (an outside corner's arc at the rate of the move after
        it, whose fields it takes): the feed is given per minute [V: rs274 2.9, LinuxCNC's
        tests/interp/inverse-time-with-comp: ``g93 g1 x1 f30`` compensated to X1 Y-.2 runs at
        ``SET_FEED_RATE(30)``; an exit move ``g40 x2 y2 f10`` from the programmed X1 Y1 at 14.1421]."""
        assert self.feed is not None  # _feed_into refused a move without it
        start = {a: self.pos.get(a, 0.0) for a in ("X", "Y", "Z")}
        end = {a: target.get(a, 0.0) for a in ("X", "Y", "Z")}
        mode = "linear" if kind == "feed" else kind
        fields["f"] = num(self.feed * move_length(start, end, plane or "XY", mode, centre))
        if self.header_mode == "per_min":
            fields.pop("feed_mode", None)
        else:
            fields["feed_mode"] = "per_min"

    def _offset_line(self, kind: str, target: dict[str, float], line: int) -> None:
        """A straight move under a tool length alone (a whole program after its G43): ``_write``'s result,
        the programmed point rounded only on the axes that move (as ``line_move``). One pass over the axes
        builds both points (the record's lists): the values stay the objects ``num`` made (an int stays an int
        in the JSON line), compared per axis rather than as dictionaries."""
        pos, rounded, before = self.pos, self.rounded, self.crounded
        offset = self.length.offset
        shifts = self.lathe_shift
        length_at = self.length_index
        axes = self.axes
        point: list[float | int] = []
        crounded: list[float | int] = []
        moved = apart = False
        f: float | int | None = None
        mode: str | None = None
        for i in range(len(axes)):
            axis = axes[i]
            value = target[axis]
            r: Any
            if value == pos[axis]:
                r = rounded[i]
            else:
                r = num(value)
            c: Any = r
            if i == length_at:
                c = num(value + offset)
            if shifts:
                shift = shifts.get(axis)
                if shift is not None:
                    c = num(value + shift + (offset if i == length_at else 0.0))
            point.append(r)
            crounded.append(c)
            if not moved:  # (identity first: an axis that stays keeps its number's object; never a nan)
                b = before[i]
                if c is not b and c != b:
                    moved = True
            if not apart and c is not r and c != r:
                apart = True
        if kind != "rapid":  # a move it drops fixes the header's feed mode too, as ``_compensated``'s
            f = self._feed_value()
            mode = self._stated_mode()
        if not moved:
            self.pos, self.rounded = target, point
            self._settle()
            return
        self.pos, self.rounded, self.crounded = target, point, crounded
        record = MoveRecord(line, kind, self.key_names, point, f, mode, crounded if apart else None)
        self.out(record if self.records else record.event())
        self._settle()

    def _offset_arc(self, kind: str, target: dict[str, float], line: int, c: tuple[float, float], plane: str) -> None:
        """An arc under a tool length (and a lathe's tool offset) alone: ``_compensated``'s and ``_write``'s event
        for it, without the cutter's segment (an interpreted object: ~25k instructions an arc)."""
        a1, a2, normal = PLANE_AXES[plane]
        pos = self.pos
        offset = self.length.offset
        shifts = self.lathe_shift
        centre = {a1: c[0], a2: c[1], normal: pos.get(normal, 0.0)}
        rounded: list[float | int] = []
        crounded: list[float | int] = []
        apart = False
        for axis in self.axes:
            value = target[axis]
            r = num(value)
            controlled = value
            if offset and axis == LENGTH_AXIS:
                controlled += offset
            shift = shifts.get(axis) if shifts else None
            if shift is not None:
                controlled += shift
            rounded.append(r)
            cr = num(controlled)
            crounded.append(cr)
            if cr != r:
                apart = True
        written: list[float | int] = []
        cwritten: list[float | int] = []
        for axis in self.centre_axes:
            at = centre[axis]
            r = num(at)
            written.append(r)
            if offset and axis == LENGTH_AXIS:
                at += offset
            shift = shifts.get(axis) if shifts else None
            if shift is not None:
                at += shift
            cr = num(at)
            cwritten.append(cr)
            if cr != r:
                apart = True
        f = self._feed_value()
        mode = self._stated_mode()
        self.pos, self.rounded, self.crounded = target, rounded, crounded
        record = MoveRecord(line, kind, self.key_names, rounded, f, mode, crounded if apart else None,
                            self.centre_keys, written, plane, cwritten if apart else None)
        self.out(record if self.records else record.event())
        self._settle()

    def _cutter_idle(self) -> bool:
        """No cutter compensation is on, queued or pending its exit move."""
        cutter = self.cutter
        return cutter is None or not self.cutter_started or (
            cutter.side is None and not cutter.queue and not cutter.arc_banned)

    def _event(self, ev: Emitted) -> None:
        """A non-motion event while compensating: behind a queued move, if any (a straight move emitted after the
        block's compensation ended, as its dictionary: the queue holds events)."""
        if self.cutter is not None:
            self.cutter.event(ev.event() if isinstance(ev, MoveRecord) else ev)
        else:
            self.out(ev)

    def _release(self, item: Item) -> None:
        if isinstance(item, Segment):
            self._write(item)
        else:
            self.out(item)

    def _write(self, seg: Segment) -> None:
        """A compensated move as its event: the programmed point in the usual keys, the controlled one in
        ``controlled`` when it differs; a straight move the controlled point does not make is dropped."""
        end = seg.end
        control = dict(end)
        if seg.xy is not None:
            a1, a2, _ = self.cutter.axes if self.cutter is not None else PLANE_AXES["XY"]
            control[a1], control[a2] = seg.xy
        if seg.dz and LENGTH_AXIS in control:
            control[LENGTH_AXIS] += seg.dz
        for axis, shift in self.lathe_shift.items():
            if axis in control:
                control[axis] += shift
        crounded = [num(control[a]) for a in self.axes]
        kind = seg.kind
        if kind in ("rapid", "feed") and crounded == self.crounded:
            return
        self.crounded = crounded
        ev: Event = {"line": seg.fields["line"], "move": kind}
        ctrl: Event = {}
        diameter = self.diameter
        for i, (axis, key) in enumerate(self.keys):
            ev[key] = num(end[axis] * 2.0) if diameter and axis == "X" else num(end[axis])
            ctrl[key] = num(control[axis] * 2.0) if diameter and axis == "X" else crounded[i]
        if seg.centre is not None:
            plane = self.modal.plane
            a1, a2, normal = PLANE_AXES[plane]
            centre = {a1: seg.centre[0], a2: seg.centre[1], normal: seg.normal}
            cc = seg.ccentre or seg.centre
            ccentre = {a1: cc[0], a2: cc[1], normal: seg.normal}
            if seg.dz and LENGTH_AXIS in ccentre:
                ccentre[LENGTH_AXIS] += seg.dz
            for axis, shift in self.lathe_shift.items():
                if axis in ccentre:
                    ccentre[axis] += shift
            for axis in ("X", "Y", "Z"):
                if axis in self.pos:
                    scale = 2.0 if diameter and axis == "X" else 1.0
                    ev[CENTRE_KEYS[axis]] = num(centre[axis] * scale)
                    ctrl[CENTRE_KEYS[axis]] = num(ccentre[axis] * scale)
            ev["plane"] = plane
        for key, value in seg.fields.items():
            if key != "line":
                ev[key] = value
        if any(ev[key] != value for key, value in ctrl.items()):
            ev["controlled"] = ctrl
        self.out(ev)

    def _settle(self) -> None:
        """Leave the compensation once nothing offsets the tool and it stands at the programmed point."""
        if not self.length.offset and not self.lathe_shift and self._cutter_idle() and self.rounded == self.crounded:
            self.compensating = False

    def finish(self) -> None:
        """The end of the input: a move still waiting in the cutter queue is written as it stands."""
        if self.cutter is not None:
            self.cutter.finish()

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
        if feed != self.written_feed:  # always for nan: ``num`` refuses it at each move, as it did
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

