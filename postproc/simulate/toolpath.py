"""Toolpath simulation: a block stream becomes a stream of motion and machine events (DESIGN.md,
"Toolpath JSON lines"), so two dialects' programs can be compared and drawn in one neutral frame.

Streaming: the simulator keeps the modal state and one position, never the program. It is a reading
"target" without native canned cycles: the blocks pass through the registered lowering transforms for
such a controller first, so cycles arrive expanded as ``CompoundMotion``.

Assumptions (a simulator knows no machine data):
- Positions are absolute coordinates in mm from the set-up's start position (``Machine startX``...).
  Every work offset (G54...) is zero until the program sets one (G10 L2: ``DataSetting``), and then
  shifts the absolute points programmed in that work system.
- Tool length (G43/G44/G49) and, for a dialect with ``CUTTER_RULES``, cutter radius compensation move the
  controlled point (``postproc.compensation``); a move's event keeps the programmed point and carries the
  controlled one beside it (``controlled``) when they differ. Register values come from the program's own
  data settings, else the set-up's ``<Tools>``; a register with neither is a located error.
- Machine coordinates (G53) are therefore work coordinates until a G10 sets an offset; they are
  always absolute.
- A reference return (G28/G30) rapids to the intermediate point, then to the reference point, taken as
  machine zero = work zero on the axes named in the block; on a mill, G28 goes to the set-up's
  ``<Axis home>`` where it gives one (machine coordinates, which are work coordinates here).
- Arc centres ``cx, cy, cz`` are absolute; on the axis normal to the plane the centre carries the arc's
  start value. ``plane`` is the IR's name of the plane: "XY", "ZX" or "YZ".
- Optional-skip blocks (``/``) are executed, as with the block-delete switch off.
- After the program end (M02/M30, or a closing ``%``) no more events are emitted; the rest is still
  read and checked, and the lines of live blocks there (``postproc.lowering.program_end``) are recorded in
  ``Simulator.live_after_end`` for ``verify``.
- A T word alone is a preselection on a mill (the ``tool`` event comes with the tool change, M06);
  on a lathe set-up T indexes the turret and emits the event itself.
- Zero-length moves (after rounding to 6 decimals) are dropped; a full circle is not zero-length.
"""

from __future__ import annotations

import math
from typing import Any, Callable, Iterable, Iterator, Mapping

from ..reading import gc_paused, macro_arguments, read_blocks
from ..block_rules import NO_FEED, ArcError, arc_centre, check_blocks, needs_feed
from ..lowering.machine_functions import drop_foreign_machine_functions
from ..lowering.program_end import EndTracker, comment_after_end
from ..dialect import Dialect
from ..errors import Diagnostics, Location, PostprocError, ProgramError, UnsupportedError
from ..expr import Expr
from ..cycles.lathe_lowering import lathe_tool
from ..compensation.cutter_radius import CutterRadius, Item, Segment
from ..compensation.rules import CutterRules
from ..compensation.tool_length import AXIS as LENGTH_AXIS, ToolLength
from ..compensation.tool_table import ToolTable
from ..event_order import after_motion
from ..geometry import CENTRE_KEYS, PLACES
from ..ir import Block, DataSetting, MachineFunction, Motion, Section
from ..lowering.lower import lower_for
from ..plugins import Registry, default_registry
from ..setup.machine_setup import MachineSetup
from .travel import TravelCheck, TravelError
from ..state import MM_PER_INCH, MODAL_KEYS, PLANE_AXES, ModalState
from ..cycles.rigid_tap_lowering import resolve_rigid_taps
from ..context import Context

UNEVALUATED = "a computed word reaches the simulation unevaluated"
"""The interpreter evaluates every expression first: an ``Expr`` here is a defect, reported where it is."""

Event = dict[str, Any]

HEADER_LOOKAHEAD = 1000
"""Events held back at most while waiting for the first feed move to fix the header's feed mode."""
LINEAR_AXES = frozenset("XYZUVW")
"""Axes converted from inches; rotary axes (A, B, C) are in degrees whatever the length unit."""


TRANSLATE_ONLY = (check_blocks, comment_after_end, drop_foreign_machine_functions, resolve_rigid_taps)
"""Generic lowering steps a simulation skips: it checks the feed itself, it must see the blocks after
the program end as they are written (to record the live ones), and it runs machine-specific codes and
rigid taps."""


class ToolpathTarget(Dialect):
    """The simulator as a lowering target: it runs no canned cycle natively, everything else it reads.
    Never registered as a dialect; it only selects the lowering transforms the simulation needs."""

    NAME = "toolpath"
    DESCRIPTION = "toolpath simulation (not a dialect)"
    NATIVE_CYCLES = frozenset()
    MACHINE_TYPES = frozenset({"mill", "lathe"})
    INVERSE_TIME_FEED = True
    """It reports an inverse-time F as it is (``feed_mode`` says so); ``verify`` compares it per minute."""
    DIAMETER_PROGRAMMING = True
    """It reads the program's own X (a diameter stays a diameter: the simulator halves it itself)."""


def num(value: float) -> float | int:
    """A number as written to a toolpath: rounded, integral values as int, never -0, always finite
    (a value beyond the float range fails at its block, rather than as JSON's invalid ``Infinity``).
    Rounding keeps an infinity or a nan as it is, so finiteness is tested only on what is not integral
    (five calls a move: the test costs less there)."""
    r = round(value, PLACES)
    if r == 0:
        return 0
    if r.is_integer():
        return int(r)
    if r - r != 0.0:  # inf - inf and nan - nan are nan
        raise ProgramError(f"a value beyond the range of a float ({value!r}) cannot be simulated"
                           if value == value else "a value that is not a number (nan) cannot be simulated")
    return r


def start_position(setup: MachineSetup) -> dict[str, float]:
    """Where a program starts, per machine axis, in mm (rotary axes at 0)."""
    m = setup.machine
    start = {"X": m.start_x, "Y": m.start_y, "Z": m.start_z}
    return {a: float(start.get(a, 0.0)) * (m.mm() if a in LINEAR_AXES else 1.0) for a in m.axes}


# -- the simulator -------------------------------------------------------------------------------------

class Simulator:
    """Modal state and position of one program run; ``block`` emits the block's events in order."""

    def __init__(self, ctx: Context, travel_warn: bool = False, cutter_rules: CutterRules | None = None) -> None:
        setup = ctx.setup
        self.ctx = ctx
        self.axes = tuple(setup.machine.axes)
        self.keys = tuple((a, a.lower()) for a in self.axes)
        self.pos = start_position(setup)
        self.rounded = {a: num(v) for a, v in self.pos.items()}
        self.modal = ModalState()
        """The program's modal state (units, plane, distance and feed mode, tool...), in program terms."""
        self.home = {axis: t.home * setup.machine.mm() for axis, t in setup.travel.items()
                     if t.home is not None and axis in self.axes and axis in LINEAR_AXES}
        """Where a reference return goes on a mill, mm: the set-up's ``<Axis home>`` (machine coordinates,
        which are the work coordinates here), else machine zero."""
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
        self.lathe = ctx.lathe
        self.increments = ctx.increments
        """Addresses that move an axis by an increment (a lathe's U and W: ``Dialect.INCREMENTAL_AXES``)."""
        self.diameter = ctx.diameter
        """X words are diameters: the position is kept as a radius (true geometry, arcs with radius I) and
        written as a diameter."""
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
        self.settings: dict[str, str] = dict(_INITIAL_SETTINGS)
        self.undeclared: set[str] = set()
        """Machine-specific codes warned about as undeclared (once each)."""
        self.offsets: dict[int, dict[str, float]] = {}
        """Work offsets a G10 set, mm per axis, by work system (1 = G54; 0 the external offset)."""
        self.shift: dict[str, float] = {}
        """What the active work system adds to an absolute point (empty until a G10 sets an offset)."""
        self.travel: TravelCheck | None = None
        """The travel-limit check, when the set-up declares limits (``postproc.simulate.travel``)."""
        self.travel_warn = travel_warn
        """A move beyond the travel is a warning (``--on-unsupported warn``), not an error."""
        if setup.travel_limited():
            self.travel = TravelCheck(self, self._travel_report)
        self.tools = ToolTable(setup)
        self.length = ToolLength(self.tools)
        self.cutter = None if cutter_rules is None else CutterRadius(cutter_rules, self._release)
        """Cutter radius compensation, when the dialect's rules are known (else it stays a setting)."""
        self.compensating = False
        """Moves go through ``postproc.compensation`` (an offset is in force, a move waits in the cutter
        queue, or the controlled point has not yet met the programmed one again)."""
        self.crounded = dict(self.rounded)
        """The controlled point of the last move written, rounded (while ``compensating``)."""
        self.out: Callable[[Event], None] = _nowhere
        """Where released events go (the ``emit`` of the block being run)."""
        self.spindle_tool: int | None = setup.machine.start_tool
        """The tool the last tool change put in the spindle (before any: the set-up's ``startTool``, None:
        the machine's, unknown)."""
        self.sync: float | None = None
        """While a rigid tap moves (``rigid_tap``): its pitch in mm per revolution, the ``f`` of its moves."""

    # -- one block ---------------------------------------------------------------------------------
    def block(self, block: Block, emit: Callable[[Event], None]) -> None:
        sections = block.sections
        if not sections:
            return
        if self.ended or "TapeMark" in sections:
            self._tape_or_after_end(block)
            return
        self.current = block
        if "InProfile" in sections:
            return  # the controller runs a profile block only through its cycle
        self.out = emit
        if self.compensating:
            emit = self._event
        get: Callable[[str], Any] = sections.get
        native = get("NativeCode")
        if native is not None and not native.inert:
            code = native.what.split(" ", 1)[0]
            raise UnsupportedError(f"{native.what} cannot be simulated", self._at(block, code))
        keys = sections.keys()
        if not keys.isdisjoint(MODAL_KEYS):
            self.apply_modal(sections)
        if self.travel is not None:
            self.travel.settings(block)
        if not keys.isdisjoint(_SETTING_KEYS):
            self.record_settings(block)
            setting = get("DataSetting")
            if setting is not None:
                self.data_setting(block, setting)
            if not keys.isdisjoint(_COMPENSATION_KEYS):
                self.compensation(block, emit)
                if self.compensating:
                    emit = self._event
        line = block.line
        before = not keys.isdisjoint(_EVENT_KEYS)
        spindle = get("SpindleControl")
        coolant = get("Coolant")
        machine = get("MachineFunction")
        if before:
            s = get("ToolSelect")
            if s is not None:
                if self.lathe and "ToolChange" not in sections:
                    emit({"line": line, "event": "tool", "number": lathe_tool(s.number)})
            if "ToolChange" in sections:
                if self.cutter is not None and self.cutter.side is not None:
                    raise ProgramError("a tool change with cutter compensation on cannot be run (cancel it "
                                       "first)", self._at(block))
                self.spindle_tool = self.modal.tool if isinstance(self.modal.tool, int) else None
                if self.spindle in ("cw", "ccw"):
                    self.spindle_event(line, "stop", emit)
                emit({"line": line, "event": "tool", "number": self.modal.tool})
            if spindle is not None and not after_motion("SpindleControl", spindle):
                self.spindle_event(line, spindle.direction, emit)
            if coolant is not None and not after_motion("Coolant", coolant):
                emit({"line": line, "event": "coolant", "on": coolant.mode != "off"})
            if machine is not None and not after_motion("MachineFunction", machine):
                self.machine_function(block, machine, emit)
            s = get("Dwell")
            if s is not None:
                emit({"line": line, "event": "dwell", "seconds": num(s.seconds)})
        compound = get("CompoundMotion")
        motion = get("Motion")
        coords = get("CoordinateSet")
        if coords is not None:
            for axis, value in coords.axes.items():
                self._coordinate(block, axis, value)
        if compound is not None:
            if self.cutter is not None and self.cutter.side is not None:
                raise ProgramError("a canned cycle with cutter compensation on cannot be run (cancel it first)",
                                   self._at(block))  # [V] rs274 "Cannot use canned cycles with cutter compensation on"
            if motion is not None and motion.mode is not None:
                self.motion(block, motion, False, emit)
            for item in compound.items:
                self.item(block, item, emit)
        elif motion is not None:
            if motion.mode is None and "CannedCycle" not in sections:
                raise UnsupportedError("a canned-cycle repeat cannot be simulated: the cycle was not "
                                       "resolved to motion", self._at(block))
            if motion.mode is not None:
                self.motion(block, motion, False, emit)
        elif "CycleCall" in sections and "CannedCycle" not in sections:
            raise UnsupportedError(f"canned cycle '{get('CycleCall').kind}' cannot be simulated: it was not "
                                   "resolved to motion", self._at(block))
        tap = get("RigidTap")
        if tap is not None:
            self.rigid_tap(block, tap, False, emit)
        if not before:
            return
        if spindle is not None and after_motion("SpindleControl", spindle):
            self.spindle_event(line, "stop", emit)
        s = get("SpindleOrientation")
        if s is not None:
            emit({"line": line, "event": "orient", "angle": num(s.angle)})
        if coolant is not None and after_motion("Coolant", coolant):
            emit({"line": line, "event": "coolant", "on": False})
        if machine is not None and after_motion("MachineFunction", machine):
            self.machine_function(block, machine, emit)
        s = get("ProgramControl")
        if s is not None:
            self.program_control(line, s.kind, emit)

    def record_settings(self, block: Block) -> None:
        """Note a change of a setting the path does not show (work offset, path control, cutter compensation
        where its rules are not modelled...)."""
        for key, section in block.sections.items():
            kind = UNSIMULATED.get(key)
            if kind is None or (key == "CutterCompensation" and self.cutter is not None):
                continue
            value = _setting_text(key, section)
            if value is not None and value != self.settings.get(kind):
                self.settings[kind] = value
                self.unsimulated.append((block.line, kind, value))

    def machine_function(self, block: Block, code: MachineFunction, emit: Callable[[Event], None]) -> None:
        """A machine-specific code: the event of its declared action, carrying the code (``verify`` lists
        these rather than comparing them: another family has no such code). An undeclared code is
        warned about once and moves nothing."""
        line, action = block.line, code.action
        if not code.declared and code.code not in self.undeclared:
            self.undeclared.add(code.code)
            self.ctx.diagnostics.warn(
                f"{code.code} is not declared for this machine (the set-up's <MachineCodes> or the "
                f"{code.family} family's defaults): simulated as a code that moves nothing",
                self._at(block, code.code))
        ev: Event
        if action in ("spindle-cw", "spindle-ccw", "spindle-stop"):
            direction = action[len("spindle-"):]
            if direction == "stop" and self.spindle == "stop":
                return
            self.spindle = direction
            ev = {"line": line, "event": "spindle", "dir": direction}
        elif action in ("coolant-on", "coolant-off"):
            ev = {"line": line, "event": "coolant", "on": action == "coolant-on"}
        elif action in ("stop", "optional-stop"):
            ev = {"line": line, "event": "stop", "optional": action == "optional-stop"}
        elif action == "tool-change":
            ev = {"line": line, "event": "tool", "number": self.modal.tool}
        else:
            ev = {"line": line, "event": "machine"}
            if action != "none":
                ev["action"] = action
        ev["code"] = code.code
        if code.name:
            ev["name"] = code.name
        emit(ev)

    def _tape_or_after_end(self, block: Block) -> None:
        """A ``%`` closes the program once it has content; after the end, live blocks are recorded."""
        end = self.end
        if not self.ended:
            end.started = self.current is not None
            end.before_end(block.sections)
            self.ended = end.ended
        elif end.after_end(block.sections) == "live":
            self.live_after_end.append(block.line)

    def apply_modal(self, sections: dict[str, Section]) -> None:
        """Apply the block's modal settings (before its motion, as a controller does); its feed is
        converted with the units and feed mode the block leaves in force."""
        modal = self.modal
        modal.apply(sections)
        self.scale = MM_PER_INCH if modal.units == "inch" else 1.0
        self.incremental = modal.distance == "incremental"
        if self.cutter is not None:
            self.cutter.sweep_slack = 0.001 if modal.units == "inch" else 0.0254
        s = sections.get("Feed")
        if s is not None:
            self._set_feed(s.value)  # type: ignore[attr-defined]
        if self.offsets and "WorkOffset" in sections:
            self._shift()

    def spindle_event(self, line: int, direction: str, emit: Callable[[Event], None]) -> None:
        """A spindle change; stopping a stopped spindle is no event (two programs that differ only
        there move the machine alike)."""
        if direction == "stop" and self.spindle == "stop":
            return
        self.spindle = direction
        emit({"line": line, "event": "spindle", "dir": direction})

    def item(self, block: Block, item: Section, emit: Callable[[Event], None]) -> None:
        """One item of a compound motion (absolute, program units)."""
        key, line = item.KEY, block.line
        if key == "Motion":
            self.motion(block, item, True, emit)  # type: ignore[arg-type]
        elif key == "Feed":
            self.modal.feed = item.value  # type: ignore[attr-defined]
            self._set_feed(item.value)  # type: ignore[attr-defined]
        elif key == "Dwell":
            emit({"line": line, "event": "dwell", "seconds": num(item.seconds)})  # type: ignore[attr-defined]
        elif key == "SpindleControl":
            self.spindle_event(line, item.direction, emit)  # type: ignore[attr-defined]
        elif key == "SpindleOrientation":
            emit({"line": line, "event": "orient", "angle": num(item.angle)})  # type: ignore[attr-defined]
        elif key == "ProgramControl":
            self.program_control(line, item.kind, emit)  # type: ignore[attr-defined]
        elif key == "RigidTap":
            self.rigid_tap(block, item, True, emit)
        else:
            raise UnsupportedError(f"{key} inside a compound motion cannot be simulated", self._at(block))

    def program_control(self, line: int, kind: str, emit: Callable[[Event], None]) -> None:
        if kind in ("stop", "optional_stop"):
            if self.cutter is not None:
                self.cutter.stop()  # a stop writes the queued move at its compensated end [V]
            emit({"line": line, "event": "stop", "optional": kind == "optional_stop"})
        elif kind in ("end", "end_rewind"):
            if self.cutter is not None:
                self.cutter.stop()
                self.cutter.cancel()  # the program end cancels compensation (LinuxCNC, Fanuc)
            emit({"line": line, "event": "end"})
            self.ended = self.end.ended = True
        else:
            raise UnsupportedError(f"program control '{kind}' cannot be simulated")

    # -- motion ------------------------------------------------------------------------------------
    def motion(self, block: Block, m: Motion, absolute: bool, emit: Callable[[Event], None]) -> None:
        mode, line = m.mode, block.line
        travel = self.travel
        if mode in ("home", "home2"):
            if not m.axes:
                return
            if self.cutter is not None and self.cutter.side is not None:
                raise ProgramError("a reference return with cutter compensation on cannot be run", self._at(block))
            via = self.target(block, m.axes, absolute)
            if travel is not None:
                travel.line(block, self.pos, via, self._programmed(m.axes), self.incremental and not absolute, False)
            self.line_move("rapid", via, line, emit)
            ref = dict(self.pos)
            for axis in m.axes:
                key = self.increments.get(axis, axis)
                ref[key] = self.home.get(key, 0.0) if mode == "home" and not self.lathe else 0.0
            if self.length.offset and LENGTH_AXIS in m.axes:
                ref[LENGTH_AXIS] -= self.length.offset  # the reference point is a machine position
            if travel is not None:
                travel.home(block, self._programmed(m.axes))
            self.line_move("rapid", ref, line, emit)
            return
        if self.feed is None and needs_feed(m):
            raise ProgramError(NO_FEED, self._at(block), needs="F")
        machine = "MachineCoordinates" in block.sections
        target = self.target(block, m.axes, absolute or machine, machine)
        if machine and self.compensating:
            self._machine_coordinates(block, m, target)
        if travel is not None and mode not in ("cw", "ccw"):
            travel.line(block, self.pos, target, self._programmed(m.axes),
                        self.incremental and not (absolute or machine), machine)
        if mode == "rapid":
            self.line_move("rapid", target, line, emit)
        elif mode == "linear" or mode == "thread":
            self.line_move("feed", target, line, emit)
        elif mode in ("cw", "ccw"):
            self.arc_move(block, m, target, emit, absolute or machine)
        else:
            raise UnsupportedError(f"motion '{mode}' cannot be simulated", self._at(block))

    def rigid_tap(self, block: Block, tap: Any, absolute: bool, emit: Callable[[Event], None]) -> None:
        """A spindle-synchronised tap (``postproc.synchronised_tap``): a ``tap`` move to the end point and
        one back to the start, ``f`` the pitch in mm/rev; a dwell between them if the tap has one."""
        if self.cutter is not None and self.cutter.side is not None:
            raise ProgramError("a rigid tap with cutter compensation on cannot be run (cancel it first)",
                               self._at(block))
        if self.spindle not in ("cw", "ccw"):
            raise ProgramError("a rigid tap with the spindle stopped cannot be run (start it first)",
                               self._at(block))  # [V] rs274: "Spindle not turning in G33.1"
        pitch = tap.pitch
        if isinstance(pitch, Expr):
            raise ProgramError(UNEVALUATED, self._at(block, "K"))
        start = dict(self.pos)
        end = self.target(block, tap.axes, absolute)
        if self.travel is not None:
            self.travel.line(block, start, end, self._programmed(tap.axes), self.incremental and not absolute, False)
        self.sync = pitch * self.scale
        try:
            self.line_move("tap", end, block.line, emit)
            if tap.dwell:
                emit({"line": block.line, "event": "dwell", "seconds": num(tap.dwell)})
            self.line_move("tap", start, block.line, emit)
        finally:
            self.sync = None

    def _machine_coordinates(self, block: Block, m: Motion, target: dict[str, float]) -> None:
        """A move in machine coordinates: its value is where the machine's controlled point goes, without
        the tool length ([K] Fanuc, Haas: ``G53 Z0`` retracts the spindle to the top whatever the tool;
        [?] LinuxCNC), so the programmed point is what lies the offset below it. Cutter compensation
        refuses it ([V] LinuxCNC "Cannot use g53 with cutter radius comp")."""
        if self.cutter is not None and self.cutter.side is not None:
            raise ProgramError("a move in machine coordinates with cutter compensation on cannot be run",
                               self._at(block))
        if self.length.offset and LENGTH_AXIS in self._programmed(m.axes):
            target[LENGTH_AXIS] -= self.length.offset

    def target(self, block: Block, axes: dict[str, float | Expr], absolute: bool,
               machine: bool = False) -> dict[str, float]:
        """End point in mm of programmed axis words (absolute or incremental); an absolute point in work
        coordinates is shifted by the work offset a G10 set (``shift``), one in machine coordinates not."""
        pos = self.pos
        out = dict(pos)
        incremental = self.incremental and not absolute
        shift = self.shift if not machine and not incremental else None
        increments = self.increments  # empty on a mill: one test of an empty dict per word
        for axis, value in axes.items():
            if isinstance(value, Expr):
                raise ProgramError(UNEVALUATED, self._at(block, axis))
            real = increments.get(axis) if increments else None
            if real is not None:
                if real not in pos:
                    raise ProgramError(f"axis {real} is not on this machine (axes {''.join(self.axes)})",
                                       self._at(block, axis))
                v = value * self.scale * (0.5 if self.diameter and real == "X" else 1.0)
                out[real] = out[real] + v
                continue
            if axis not in pos:
                raise ProgramError(f"axis {axis} is not on this machine (axes {''.join(self.axes)})",
                                   self._at(block, axis))
            v = value * self.scale if axis in LINEAR_AXES else value
            if self.diameter and axis == "X":
                v *= 0.5
            out[axis] = pos[axis] + v if incremental else v + shift.get(axis, 0.0) if shift else v
        return out

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
        key = setting.index if setting.table == "work_offset" else 100 + setting.index
        entry = self.offsets.setdefault(key, {})
        for axis, value in setting.values.items():
            if isinstance(value, Expr):
                raise ProgramError(UNEVALUATED, self._at(block, axis))
            v = value * self.scale if axis in LINEAR_AXES else value
            entry[axis] = entry.get(axis, 0.0) + v if setting.incremental else v
        self._shift()

    def touch_off(self, block: Block, setting: DataSetting) -> None:
        """A tool entry measured where the tool stands (LinuxCNC ``G10 L10``/``L11``): the length that makes
        the current point read Z in the active work system (its offset cancels) or in work system 9, with
        the length in force now; R sets the radius (``postproc_linuxcnc.tool_entry``)."""
        for letter in setting.values:
            if isinstance(setting.values[letter], Expr):
                raise ProgramError(UNEVALUATED, self._at(block, letter))
        z = setting.values.get("Z")
        if isinstance(z, (int, float)):
            if LENGTH_AXIS not in self.pos:
                raise ProgramError(f"axis {LENGTH_AXIS} is not on this machine", self._at(block, "Z"))
            machine = self.pos[LENGTH_AXIS] + self.length.offset
            system = self.shift.get(LENGTH_AXIS, 0.0) if setting.table == TOUCH_OFF[0] \
                else self.offsets.get(9, {}).get(LENGTH_AXIS, 0.0)
            self.tools.set("length", setting.index, machine - (z * self.scale + system))
        r = setting.values.get("R")
        if isinstance(r, (int, float)):
            self.tools.set("radius", setting.index, r * self.scale)

    def compensation(self, block: Block, emit: Callable[[Event], None]) -> None:
        """A block's cutter compensation and tool length changes (before its motion, as the controller
        runs them): compensation ends first, so the move it queued is written with the old setting."""
        get = block.sections.get
        cutter, cc = self.cutter, get("CutterCompensation")
        if cutter is not None and cc is not None:
            mode = cc.mode  # type: ignore[attr-defined]
            if mode == "off":
                cutter.cancel()
            elif mode in ("left", "right"):
                if self.modal.plane != "XY":
                    raise UnsupportedError(f"cutter compensation in the {self.modal.plane} plane cannot be "
                                           "simulated", self._at(block))
                cutter.start(mode, self._cutter_radius(block, cc.register))  # type: ignore[attr-defined]
                self._begin()
            else:
                raise UnsupportedError(f"cutter compensation '{mode}' cannot be simulated", self._at(block))
        dynamic = get("DynamicCutterCompensation")
        if dynamic is not None:
            if cutter is None or self.modal.plane != "XY":
                raise UnsupportedError(f"cutter compensation by a diameter in the {self.modal.plane} plane cannot be "
                                       "simulated", self._at(block))
            cutter.start(dynamic.mode, dynamic.radius(self.scale))  # type: ignore[attr-defined]  # D/2, negative: other side
            self._begin()
        tl = get("ToolLengthOffset")
        if tl is not None:
            try:
                self.length.change(tl.mode, tl.register, tl.length, self.scale)  # type: ignore[attr-defined]
            except PostprocError as err:
                raise err.located(self._at(block, "H")) from None
            if self.length.offset:
                self._begin()

    def _cutter_radius(self, block: Block, register: int | None) -> float:
        """The radius a G41/G42 takes: its register's, or by the rules the spindle tool's (LinuxCNC)."""
        if register is None:
            assert self.cutter is not None
            if self.cutter.rules.register_absent != "tool":
                raise UnsupportedError("cutter compensation without its register cannot be simulated",
                                       self._at(block))
            if self.spindle_tool is None:
                raise ProgramError("cutter compensation without its register takes the tool in the spindle, which "
                                   "is not known here (no tool change before it): program its register",
                                   self._at(block))
            register = self.spindle_tool
        try:
            return self.tools.radius(register)
        except PostprocError as err:
            raise err.located(self._at(block, "D")) from None

    def _begin(self) -> None:
        """Moves from here on go through the compensation."""
        if not self.compensating:
            self.compensating = True
            self.crounded = dict(self.rounded)

    def _shift(self) -> None:
        """The offset of the active work system plus the external one (P0), applied to absolute points."""
        active = self.offsets.get(self.modal.work_offset, {})
        common = self.offsets.get(0, {})
        self.shift = {a: active.get(a, 0.0) + common.get(a, 0.0) for a in set(active) | set(common)}

    def _coordinate(self, block: Block, axis: str, value: float) -> None:
        """Coordinate setting: the tool's present point gets ``value`` on ``axis``; nothing moves."""
        if axis not in self.pos:
            raise ProgramError(f"axis {axis} is not on this machine (axes {''.join(self.axes)})", self._at(block, axis))
        v = value * self.scale * (0.5 if self.diameter and axis == "X" else 1.0)
        if self.travel is not None:
            self.travel.coordinate_set(axis, v)
        self.pos[axis] = v
        self.rounded[axis] = num(v)

    def line_move(self, kind: str, target: dict[str, float], line: int, emit: Callable[[Event], None]) -> None:
        if self.compensating:
            if self._cutter_idle() and not self.diameter:
                self._offset_line(kind, target, line)
            else:
                self._compensated(kind, target, line, None, None)
            return
        pos = self.pos
        rounded = self.rounded.copy()
        for axis, value in target.items():
            if value != pos[axis]:
                rounded[axis] = num(value)
        if rounded == self.rounded:
            self.pos = target
            return
        ev: Event = {"line": line, "move": kind}
        for axis, key in self.keys:
            ev[key] = rounded[axis]
        if self.diameter and "x" in ev:
            ev["x"] = num(target["X"] * 2.0)
        if kind != "rapid":
            self._feed_into(ev)
        self.pos, self.rounded = target, rounded
        emit(ev)

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

    def arc_move(self, block: Block, m: Motion, target: dict[str, float], emit: Callable[[Event], None],
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
            c = arc_centre(s, e, (a1, a2), radius, {a: v * scale for a, v in offsets.items()}, clockwise)
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
            self._compensated(m.mode or "cw", target, block.line, c, plane)
            return
        rounded = {a: num(v) for a, v in target.items()}
        ev: Event = {"line": block.line, "move": m.mode}
        for axis, key in self.keys:
            ev[key] = rounded[axis]
        centre = {a1: c[0], a2: c[1], normal: pos.get(normal, 0.0)}
        for axis in ("X", "Y", "Z"):
            if axis in pos:
                ev[CENTRE_KEYS[axis]] = num(centre[axis])
        if self.diameter and "x" in ev:
            ev["x"] = num(target["X"] * 2.0)
            ev[CENTRE_KEYS["X"]] = num(centre["X"] * 2.0)
        ev["plane"] = plane
        self._feed_into(ev)
        self.pos, self.rounded = target, rounded
        emit(ev)

    # -- compensation -------------------------------------------------------------------------------
    def _compensated(self, kind: str, target: dict[str, float], line: int, centre: tuple[float, float] | None,
                     plane: str | None) -> None:
        """A move handed to the compensation: the cutter queue (when compensating the radius) or straight
        to ``_write``; the programmed point moves on at once."""
        fields: Event = {"line": line}
        if kind != "rapid":
            self._feed_into(fields)
        pos = self.pos
        seg = Segment(kind, fields, target, pos.get(LENGTH_AXIS, 0.0), self.length.offset)
        cutter = self.cutter
        if centre is not None:
            seg.centre = seg.ccentre = centre
            seg.turn = 1 if kind == "ccw" else -1
            seg.normal = pos.get(PLANE_AXES[plane or "XY"][2], 0.0)
        if not self._cutter_idle():
            assert cutter is not None
            if cutter.on and (self.modal.plane != "XY" or "X" not in pos or "Y" not in pos):
                raise UnsupportedError(f"cutter compensation in the {self.modal.plane} plane cannot be simulated")
            start = (pos.get("X", 0.0), pos.get("Y", 0.0))
            if centre is None:
                cutter.line(seg, start)
            else:
                cutter.arc(seg, start)
        else:
            self._write(seg)
        self.pos = target
        self.rounded = {a: num(v) for a, v in target.items()}
        self._settle()

    def _offset_line(self, kind: str, target: dict[str, float], line: int) -> None:
        """A straight move under a tool length alone (a whole program after its G43): ``_write``'s result,
        the programmed point rounded only on the axes that move (as ``line_move``)."""
        pos = self.pos
        rounded = self.rounded.copy()
        for axis, value in target.items():
            if value != pos[axis]:
                rounded[axis] = num(value)
        crounded = rounded.copy()
        if LENGTH_AXIS in crounded:
            crounded[LENGTH_AXIS] = num(target[LENGTH_AXIS] + self.length.offset)
        if crounded == self.crounded:
            self.pos, self.rounded = target, rounded
            self._settle()
            return
        ev: Event = {"line": line, "move": kind}
        ctrl: Event = {}
        for axis, key in self.keys:
            ev[key] = rounded[axis]
            ctrl[key] = crounded[axis]
        if kind != "rapid":
            self._feed_into(ev)
        if crounded != rounded:
            ev["controlled"] = ctrl
        self.pos, self.rounded, self.crounded = target, rounded, crounded
        self.out(ev)
        self._settle()

    def _cutter_idle(self) -> bool:
        """No cutter compensation is on, queued or pending its exit move."""
        cutter = self.cutter
        return cutter is None or (cutter.side is None and not cutter.queue and not cutter.arc_banned)

    def _event(self, ev: Event) -> None:
        """A non-motion event while compensating: behind a queued move, if any."""
        if self.cutter is not None:
            self.cutter.event(ev)
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
            control["X"], control["Y"] = seg.xy
        if seg.dz and LENGTH_AXIS in control:
            control[LENGTH_AXIS] += seg.dz
        crounded = {a: num(v) for a, v in control.items()}
        kind = seg.kind
        if kind in ("rapid", "feed") and crounded == self.crounded:
            return
        self.crounded = crounded
        ev: Event = {"line": seg.fields["line"], "move": kind}
        ctrl: Event = {}
        diameter = self.diameter
        for axis, key in self.keys:
            ev[key] = num(end[axis] * 2.0) if diameter and axis == "X" else num(end[axis])
            ctrl[key] = num(control[axis] * 2.0) if diameter and axis == "X" else crounded[axis]
        if seg.centre is not None:
            plane = self.modal.plane
            a1, a2, normal = PLANE_AXES[plane]
            centre = {a1: seg.centre[0], a2: seg.centre[1], normal: seg.normal}
            cc = seg.ccentre or seg.centre
            ccentre = {a1: cc[0], a2: cc[1], normal: seg.normal}
            if seg.dz and LENGTH_AXIS in ccentre:
                ccentre[LENGTH_AXIS] += seg.dz
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
        if not self.length.offset and self._cutter_idle() and self.rounded == self.crounded:
            self.compensating = False

    def finish(self) -> None:
        """The end of the input: a move still waiting in the cutter queue is written as it stands."""
        if self.cutter is not None:
            self.cutter.finish()

    # -- feed --------------------------------------------------------------------------------------
    def _set_feed(self, value: float) -> None:
        self.feed = value if self.modal.feed_mode == "inverse_time" else value * self.scale

    def _feed_into(self, ev: Event) -> None:
        if self.sync is not None:  # a rigid tap: its pitch, per revolution whatever the feed mode
            ev["f"] = num(self.sync)
            if self.header_mode != "per_rev":
                ev["feed_mode"] = "per_rev"
            return
        if self.feed is None:
            raise ProgramError(NO_FEED, self._at(), needs="F")
        ev["f"] = num(self.feed)
        if self.header_mode is None:
            self.header_mode = self.modal.feed_mode
        elif self.modal.feed_mode != self.header_mode:
            ev["feed_mode"] = self.modal.feed_mode

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


_CENTRE_LETTER = {"X": "I", "Y": "J", "Z": "K"}
TOUCH_OFF = ("tool_entry_at_point", "tool_entry_at_point_9")
"""Tool tables whose length the tool's position decides: in the active work system, in work system 9."""

UNSIMULATED = {"CutterCompensation": "cutter compensation", "WorkOffset": "work offset",
               "PathControl": "path control", "SpindleSpeed": "spindle speed"}
"""Settings the simulation does not apply, by section key: ``verify`` compares their changes instead.
Cutter compensation is among them only for a dialect without ``CUTTER_RULES``; the work offset is
recorded although a G10's values are applied (the set-up's are not: the path stays in work
coordinates)."""
MOVES_THE_TOOL = frozenset(("cutter compensation", "work offset", "path control", "tool offset data"))
"""Of those, the ones that move the tool when they differ."""
_SETTING_KEYS = frozenset((*UNSIMULATED, "DataSetting", "ToolLengthOffset", "DynamicCutterCompensation"))
_COMPENSATION_KEYS = frozenset(("CutterCompensation", "ToolLengthOffset", "DynamicCutterCompensation"))
_INITIAL_SETTINGS = {"cutter compensation": "off", "work offset": "1"}


def _nowhere(ev: Event) -> None:
    raise AssertionError("an event released outside a block")


def _setting_text(key: str, section: Any) -> str | None:
    """How a setting reads in a verify report (None: it changes nothing, e.g. a one-shot exact stop)."""
    if key == "CutterCompensation":
        return section.mode if section.register is None else f"{section.mode} D{section.register}"
    if key == "ToolLengthOffset":
        return section.mode if section.register is None else f"{section.mode} H{section.register}"
    if key == "WorkOffset":
        return str(section.index)
    if key == "PathControl":
        return None if section.one_shot else section.mode.replace("_", " ")
    return f"S{section.rpm:g}" if isinstance(section.rpm, (int, float)) else None
_EVENT_KEYS = frozenset(("ToolSelect", "ToolChange", "SpindleControl", "Coolant", "Dwell", "SpindleOrientation",
                         "ProgramControl", "MachineFunction"))


def header(ctx: Context, feed_mode: str | None, program_units: str = "mm") -> Event:
    """The first line of a toolpath; keys beyond the fixed three only when they apply. ``program_units``:
    the units of the program's first move (lengths here are mm whatever they are; a backplot labels its
    drawing in the program's own)."""
    head: Event = {"toolpath": 1, "units": "mm", "dialect": ctx.dialect}
    if ctx.diameter:
        head["x_mode"] = "diameter"
    if feed_mode is not None and feed_mode != "per_min":
        head["feed_mode"] = feed_mode
    if program_units == "inch":
        head["program_units"] = "inch"
    return head


def simulate(blocks: Iterable[Block], ctx: Context, live_after_end: list[int] | None = None,
             unsimulated: list[tuple[int, str, str]] | None = None, travel_warn: bool = False,
             cutter_rules: CutterRules | None = None) -> Iterator[Event]:
    """Blocks (already lowered for ``ToolpathTarget``) -> the header, then events in execution order.

    Errors are reported to ``ctx.diagnostics`` with the block's location and the block is skipped;
    the caller raises them at the end (``Diagnostics.check``). Events are held back only until the
    first feed move fixes the header's feed mode (at most ``HEADER_LOOKAHEAD`` of them).
    """
    sim = Simulator(ctx, travel_warn, cutter_rules)
    if live_after_end is not None:
        sim.live_after_end = live_after_end  # the caller reads the lines recorded there
    if unsimulated is not None:
        sim.unsimulated = unsimulated  # so does verify the settings the path does not show
    report = ctx.diagnostics.error
    held: list[Event] = []
    holding = True
    units: str | None = None  # the program's units at its first move, for the header
    out: list[Event] = []
    for block in blocks:
        try:
            sim.block(block, out.append)
        except PostprocError as err:
            report(err.located(ctx.at(block)))
            out.clear()
            continue
        if not out:
            continue
        if holding:
            if units is None and any("move" in ev for ev in out):
                units = sim.modal.units
            held.extend(out)
            out.clear()
            if sim.header_mode is None and len(held) < HEADER_LOOKAHEAD:
                continue
            if sim.header_mode is None:
                sim.header_mode = "per_min"
            yield header(ctx, sim.header_mode, units or sim.modal.units)
            yield from held
            held, holding = [], False
        else:
            yield from out
            out.clear()
    try:
        sim.out = out.append
        sim.finish()
    except PostprocError as err:
        report(err.located(ctx.at(sim.current)) if sim.current is not None else err)
        out.clear()
    if out and not holding:
        yield from out
    elif out:
        held.extend(out)
    if holding:
        yield header(ctx, sim.header_mode, units or sim.modal.units)
        yield from held


def toolpath_events(lines: Iterable[str], *, file: str, dialect: str | type[Dialect],
                    setup: MachineSetup | None = None, registry: Registry | None = None,
                    diagnostics: Diagnostics | None = None, check: bool = True,
                    live_after_end: list[int] | None = None,
                    unsimulated: list[tuple[int, str, str]] | None = None,
                    on_unsupported: str = "error", compensate: bool = True,
                    arguments: Mapping[str, float] | None = None) -> Iterator[Event]:
    """Read a program in ``dialect`` and yield its toolpath (header first). Raises ``ErrorList`` at the
    end when the program had errors (unless ``check`` is False: the caller then checks
    ``diagnostics``); events already yielded then belong to a failed run. ``live_after_end``, if given,
    receives the lines of live blocks after the program end; ``unsimulated`` the changes of settings
    the simulation does not apply (``Simulator.unsimulated``). ``on_unsupported="warn"`` makes a move
    beyond the travel a warning. ``compensate=False`` leaves cutter radius compensation unsimulated even
    where the dialect has rules for it (``verify`` against a dialect that has none). ``arguments``
    (``{"A": 30.0}``): the program is a macro file run on its own, as called with these arguments
    (``postproc.reading.macro_arguments``)."""
    setup = setup or MachineSetup()
    diagnostics = diagnostics or Diagnostics()
    registry = registry or default_registry()
    if isinstance(dialect, str):
        dialect = registry.dialect(dialect)
    prepare = macro_arguments(dialect, arguments) if arguments else None
    with gc_paused():
        # a simulation runs the program's loops, jumps and calls
        from ..fast.reading import install_reading  # the reading lanes (postproc.fast), as a translation has
        ctx, blocks = read_blocks(lines, file, dialect, setup, diagnostics, program_mode="execute",
                                  prepare=prepare, lanes=install_reading)
        steps = [step for step in registry.lowerings if step not in TRANSLATE_ONLY]
        lowered = lower_for(blocks, ctx, ToolpathTarget, "error", steps)
        yield from simulate(lowered, ctx, live_after_end, unsimulated, on_unsupported == "warn",
                            dialect.CUTTER_RULES if compensate else None)
    if check:
        diagnostics.check()


def check_travel(lines: Iterable[str], *, file: str, dialect: type[Dialect], setup: MachineSetup,
                 diagnostics: Diagnostics, on_unsupported: str, registry: Registry | None = None) -> None:
    """A translation's travel check: the source program simulated against the set-up's limits; each
    problem goes to ``diagnostics`` (a warning under ``on_unsupported="warn"``). Where the simulation
    itself fails (a construct it cannot run), the travel from there on cannot be known: one error says
    so, and nothing after it is checked."""
    import io
    private = Diagnostics(max_errors=1_000_000, warn_stream=io.StringIO())
    for _ in toolpath_events(lines, file=file, dialect=dialect, setup=setup, registry=registry,
                             diagnostics=private, check=False):
        pass
    for err in private.errors:
        stopped = not isinstance(err, TravelError)
        if stopped:
            err = TravelError(f"the travel cannot be checked from here on: {err.message}", err.location)
        if on_unsupported == "warn":
            diagnostics.warn(err.message, err.location)
        else:
            diagnostics.error(err)
        if stopped:
            return
