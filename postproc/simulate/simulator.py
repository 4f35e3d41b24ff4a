"""The simulator's block dispatch: a block's settings, machine events and motion in the order a
controller runs them (``Simulator.block``). ``postproc.simulate.stream.simulate`` is the loop that runs it over a
lowered block stream (``postproc.simulate.toolpath`` assembles the reading and lowering before it).
"""

from __future__ import annotations

import math
from typing import Any, Callable, Final

from mypy_extensions import mypyc_attr

from ..block_rules import NO_FEED, needs_feed
from ..compensation.cutter_radius import Suspended
from ..compensation.cycle_entry import finishing_entry
from ..compensation.tool_length import AXIS as _AXIS
from ..context import Context
from ..cycles.lathe_lowering import lathe_tool
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..ir.event_order import after_motion
from ..ir.expr import Expr
from ..ir import Block, MachineFunction, Motion, Section
from ..ir.state import MM_PER_INCH, MODAL_KEYS as _MODAL
from .events import (CUTTER_RADIUS, LATHE_TOOL_OFFSET, TOOL_SELECTION, UNEVALUATED, UNSIMULATED, Event, num,
                     _setting_text)
from .move_record import Emitted, MoveRecord
from .moves import PATH_CONTROL, Moves
from .position import point_dict
from .work_offsets import offset_beyond_frame

LENGTH_AXIS: Final = _AXIS
MODAL_KEYS: Final = _MODAL
# Final: compiled, a C constant, not a look-up in the module's dictionary (every block reads them)
_SETTING_KEYS: Final = frozenset((*UNSIMULATED, "DataSetting", "ToolLengthOffset", "DynamicCutterCompensation"))
_COMPENSATION_KEYS: Final = frozenset(("CutterCompensation", "ToolLengthOffset", "DynamicCutterCompensation"))
_EVENT_KEYS: Final = frozenset(("ToolSelect", "ToolChange", "SpindleControl", "Coolant", "Dwell", "SpindleOrientation",
                         "ProgramControl", "MachineFunction"))
_KIND_MODAL: Final = 1
_KIND_SETTING: Final = 2
_KIND_COMPENSATION: Final = 4
_KIND_EVENT: Final = 8
_KIND_RARE: Final = 16
_KIND_MACHINE: Final = 32
EXACT: Final = "exact stop"
"""How an exact stop mode reads as a setting (``postproc.simulate.events._setting_text``)."""
_EXACT_TEXTS: Final = frozenset((EXACT, "exact path"))
"""The settings of the modes that reach every programmed point (``PathControl``)."""
_RARE_KEYS: Final = frozenset(("TapeMark", "InProfile", "NativeCode", "CompoundMotion", "CoordinateSet", "RigidTap",
                               "CycleCall", "FrameChange"))
"""Sections a CAM block has none of, each looked up by ``Simulator.block`` only where the block has one of them
(a look-up ~130 instructions compiled, eight a block)."""
_KEY_KINDS: Final[dict[str, int]] = {
    key: (_KIND_MODAL if key in MODAL_KEYS else 0) | (_KIND_SETTING if key in _SETTING_KEYS else 0)
    | (_KIND_COMPENSATION if key in _COMPENSATION_KEYS else 0) | (_KIND_EVENT if key in _EVENT_KEYS else 0)
    | (_KIND_RARE if key in _RARE_KEYS else 0) | (_KIND_MACHINE if key == "MachineCoordinates" else 0)
    for key in MODAL_KEYS | _SETTING_KEYS | _COMPENSATION_KEYS | _EVENT_KEYS | _RARE_KEYS | {"MachineCoordinates"}}
"""Section key -> the kinds of work it asks of ``Simulator.block`` (bits above): one look-up a section, where
four ``keys().isdisjoint`` tests were four bound method calls a block (~2,700 instructions compiled). A block's
``Motion`` and ``Sequence`` are in none: ``Simulator.block`` takes the motion as it passes and looks up neither."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Simulator(Moves):
    """Modal state and position of one program run; ``block`` emits the block's events in order."""

    # -- one block ---------------------------------------------------------------------------------
    def lathe_frame(self, block: Block, frame: Any) -> None:
        """A frame command on a lathe, where no frame is evaluated (``postproc.frames.lowering``: the toolpath
        keeps the program's coordinates). An origin (``G92 X.. Z..``, the ``G50``/``G92`` coordinate setting of
        the family that reads it so) makes the tool's present point read the words, a ``CoordinateSet``: so a
        Fanuc T ``G50`` written as LinuxCNC's ``G92`` counts the same moves [V: rs274 2.9.0~pre1, lathe G7 at X40:
        ``G92 X20`` prints ``SET_G92_OFFSET(10, ..)`` and a following ``G0 X20`` stands still; ``G92`` a second
        time sets the offset again from the present point: ``NgcLatheWriting.coordinate_set_words``]. Any other
        frame command (``G92.1``-``G92.3``, ``G52``, a rotation) would move the program's coordinates by an
        offset this simulation does not keep: a located error, not a toolpath in the wrong coordinates."""
        if frame.kind != "origin":
            raise UnsupportedError(f"{frame.describe()} cannot be simulated on a lathe (its frame is not modelled "
                                   "there)", self._at(block))
        for axis, value in frame.words.items():
            if isinstance(value, Expr):
                raise UnsupportedError(f"{frame.describe()} with a computed {axis} cannot be simulated",
                                       self._at(block, axis))
            self._coordinate(block, axis, float(value))

    def block(self, block: Block, emit: Callable[[Emitted], None]) -> None:
        sections: dict[str, Any] = block.sections  # each section read by its key: Any
        if not sections:
            return
        kinds = 0
        motion: Motion | None = None  # typed: compiled, its fields are read directly
        for key, value in sections.items():  # (a string comparison a key: ~130 instructions less than a look-up)
            if key == "Motion":
                motion = value
            elif key != "Sequence":
                kinds |= _KEY_KINDS.get(key, 0)
        rare = kinds & _KIND_RARE != 0
        if self.ended or rare and "TapeMark" in sections:
            self._tape_or_after_end(block)
            return
        self.current = block
        if rare and "InProfile" in sections:
            return  # the controller runs a profile block only through its cycle
        if self.compensating:
            emit = self.queued
        native = sections.get("NativeCode") if rare else None
        if native is not None and not native.inert:
            code = native.what.split(" ", 1)[0]
            raise UnsupportedError(f"{native.what} cannot be simulated", self._at(block, code))
        if kinds & _KIND_MODAL:
            self.apply_modal(sections)
        if self.travel is not None:
            self.travel.settings(block)
        if kinds & _KIND_EVENT and self.cutter is not None and "ToolChange" in sections:
            try:  # before the block's own G40/G41/G42 (``CutterRadius.tool_change``)
                self.cutter.tool_change()
            except ProgramError as err:
                raise err.located(self._at(block)) from None
        if kinds & _KIND_SETTING:
            self.record_settings(block)
            setting = sections.get("DataSetting")
            if setting is not None:
                self.data_setting(block, setting)
            if kinds & _KIND_COMPENSATION:
                self.compensation(block, emit)
                if self.compensating:
                    emit = self.queued
        line = block.line
        before = kinds & _KIND_EVENT != 0
        spindle: Any = None
        coolant: Any = None
        machine: Any = None
        if before:
            spindle = sections.get("SpindleControl")
            coolant = sections.get("Coolant")
            machine = sections.get("MachineFunction")
            s = sections.get("ToolSelect")
            if s is not None:
                if isinstance(s.number, int):
                    self.note_tool_data(line, TOOL_SELECTION, f"T{s.number}", float(s.number))
                if self.lathe and self.ctx.lathe_turret and "ToolChange" not in sections:  # (an M6 lathe: only prepared)
                    if not isinstance(s.number, int):  # (T[1/0]: found by make fuzz, an internal error before)
                        raise UnsupportedError("a computed lathe T word cannot be simulated (the tool and offset it "
                                               "selects are known when the program runs)", self._at(block, "T"))
                    station = lathe_tool(s.number)
                    if station is None or station != self.station:  # T0200 after T0202: the offset alone
                        emit({"line": line, "event": "tool", "number": lathe_tool(s.number)})
                    self.station = station
                    if isinstance(s.number, int):
                        self.lathe_offset(block, s.number % 100)
            if "ToolChange" in sections:
                self.spindle_tool = self.modal.tool if isinstance(self.modal.tool, int) else None
                if self.spindle in ("cw", "ccw") and not self.tool_change_keeps_spindle:
                    self.spindle_event(line, "stop", emit)
                emit({"line": line, "event": "tool", "number": self.modal.tool})
            if spindle is not None and not after_motion("SpindleControl", spindle):
                self.spindle_event(line, spindle.direction, emit)
            if coolant is not None and not after_motion("Coolant", coolant):
                emit({"line": line, "event": "coolant", "on": coolant.mode != "off"})
            if machine is not None and not after_motion("MachineFunction", machine):
                self.machine_function(block, machine, emit)
            s = sections.get("Dwell")
            if s is not None:
                emit({"line": line, "event": "dwell", "seconds": num(s.seconds)})
        compound = sections.get("CompoundMotion") if rare else None
        machine_coordinates = kinds & _KIND_MACHINE != 0
        coords = sections.get("CoordinateSet") if rare else None
        if coords is not None:
            for axis, value in coords.axes.items():
                self._coordinate(block, axis, value)
        frame = sections.get("FrameChange") if rare and self.lathe else None
        if frame is not None:
            self.lathe_frame(block, frame)
        if compound is not None:
            cutter = self.cutter
            held: Suspended | None = None
            back: Section | None = None
            if cutter is not None and cutter.side is not None:
                if compound.term in cutter.rules.roughing_cycles and "CannedCycle" not in sections:
                    try:  # its moves are the tip's path to the offset shape (``CutterRules.roughing_cycles``)
                        held = cutter.suspend()
                    except PostprocError as err:
                        raise err.located(self._at(block)) from None
                elif compound.term not in cutter.rules.profile_cycles or "CannedCycle" in sections:
                    raise ProgramError("a canned cycle with cutter compensation on cannot be run (cancel it first)",
                                       self._at(block))  # [V] rs274 "Cannot use canned cycles with cutter compensation on"
                elif "CutterCompensation" not in sections:  # (the Haas form turns it on in the cycle's own block)
                    try:
                        held, back = finishing_entry(cutter, compound.items)
                    except PostprocError as err:
                        raise err.located(self._at(block)) from None
            if motion is not None and motion.mode is not None:
                self.motion(block, motion, False, emit, machine_coordinates)
            for item in compound.items:
                if item is back and cutter is not None:
                    try:
                        cutter.cancel()
                    except PostprocError as err:
                        raise err.located(self._at(block)) from None
                self.item(block, item, emit)
            if held is not None and cutter is not None:
                cutter.resume(held)
                self._begin()
        elif motion is not None:
            if motion.mode is None and "CannedCycle" not in sections:
                raise UnsupportedError("a canned-cycle repeat cannot be simulated: the cycle was not "
                                       "resolved to motion", self._at(block))
            if motion.mode is not None:
                self.motion(block, motion, False, emit, machine_coordinates)
        elif rare and "CycleCall" in sections and "CannedCycle" not in sections:
            raise UnsupportedError(f"canned cycle '{sections['CycleCall'].kind}' cannot be simulated: it was not "
                                   "resolved to motion", self._at(block))
        tap = sections.get("RigidTap") if rare else None
        if tap is not None:
            self.rigid_tap(block, tap, False, emit)
        if not before:
            return
        if spindle is not None and after_motion("SpindleControl", spindle):
            self.spindle_event(line, "stop", emit)
        s = sections.get("SpindleOrientation")
        if s is not None:
            self.oriented = True
            emit({"line": line, "event": "orient", "angle": num(s.angle)})
        if coolant is not None and after_motion("Coolant", coolant):
            emit({"line": line, "event": "coolant", "on": False})
        if machine is not None and after_motion("MachineFunction", machine):
            self.machine_function(block, machine, emit)
        s = sections.get("ProgramControl")
        if s is not None:
            self.program_control(line, s.kind, emit)

    def record_settings(self, block: Block) -> None:
        """Note a change of a setting the path does not show (work offset, path control, cutter compensation
        where its rules are not modelled...)."""
        for key, section in block.sections.items():
            kind = UNSIMULATED.get(key)
            if kind is None or (key == "CutterCompensation" and self.cutter is not None and self.kept_native is None):
                continue
            if key == "PathControl" and section.one_shot:  # type: ignore[attr-defined]
                self._stop_once(block.line, kind)
                continue
            value = _setting_text(key, section)
            if key == "CutterCompensation" and self.lathe and value in ("left", "right"):
                value = self._turret_register(value)
            if key == "CutterCompensation" and self.cutter is not None and not self._kept_native(kind, value):
                continue
            if value is not None and value != self.settings.get(kind):
                self.settings[kind] = value
                self.unsimulated.append((block.line, kind, value))
                if key == "CutterCompensation":
                    self._note_radius(block, value, section.register)  # type: ignore[attr-defined]

    def _note_radius(self, block: Block, value: str, register: object) -> None:
        """Cutter compensation kept as a setting (its rules not simulated): the radius it would put in force, for
        ``verify``'s account of lost tool data (``tool_data``); nan where the set-up gives the register none."""
        radius = 0.0
        if value != "off":
            radius = math.nan
            if isinstance(register, int):
                try:
                    radius = self.tools.radius(register)
                except PostprocError:
                    pass
        self.note_tool_data(block.line, CUTTER_RADIUS, value, radius)

    def path_at_first_move(self, line: int) -> None:
        """The first move (``line``): a program that has set no path control mode runs in its controller's
        power-on mode. A controller that starts in exact stop (``Dialect.PATH_CONTROL_AT_START``: a SINUMERIK's
        G60) records it here, as if the program had set it, so its translation for a controller that starts
        blending, which writes the mode first (``postproc.lowering.path_at_start``), compares alike; one that
        starts blending records nothing, as before (the changes recorded count from blending)."""
        self.path_pending = False
        start = self.ctx.path_at_start
        if self.settings.get(PATH_CONTROL) is None and start != "cutting":  # exact stop, or grbl's exact path
            text = start.replace("_", " ")
            self.settings[PATH_CONTROL] = text
            self.unsimulated.append((line, PATH_CONTROL, text))

    def _stop_once(self, line: int, kind: str) -> None:
        """A one-shot exact stop: exact stop for the block, then the mode before (where none was set, the
        controller's power-on mode: cutting on Fanuc and LinuxCNC [K], ``Dialect.PATH_CONTROL_AT_START``), so a target without one that writes the two modes
        (LinuxCNC's ``exact_stop`` lowering) compares alike; under an exact-stop mode it changes nothing."""
        before = self.settings.get(kind) or self.ctx.path_at_start.replace("_", " ")
        if before in _EXACT_TEXTS:  # (under the exact path, the stop changes no point reached either)
            return
        self.unsimulated += [(line, kind, "exact stop"), (line, kind, before)]
        self.settings[kind] = before

    def _kept_native(self, kind: str, value: str | None) -> bool:
        """Whether a compensation change is recorded as a setting while the rules are simulated (``verify``
        comparing with a program that keeps some stretches native): a start when ``kept_native`` chooses
        it, the cancel that ends such a stretch."""
        assert self.kept_native is not None
        if value == self.settings.get(kind):
            return self.native_stretch  # no change: the stretch goes on as it is
        if value is None or value == "off":
            native, self.native_stretch = self.native_stretch, False
            return native
        self.native_stretch = self.kept_native(value)
        return self.native_stretch

    def _turret_register(self, side: str) -> str:
        """A turret lathe's G41/G42 names no register: it compensates by the offset the last T selected
        [K: Fanuc T, GSK], so the setting reads as that register (as LinuxCNC's ``G42 D02`` does)."""
        offset = self.settings.get(LATHE_TOOL_OFFSET, "")
        return f"{side} D{offset.split()[1]}" if offset.startswith("offset ") else side

    def machine_function(self, block: Block, code: MachineFunction, emit: Callable[[Emitted], None]) -> None:
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
            if direction == "stop" and self.spindle == "stop" or self._restates(direction):
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
        scale = MM_PER_INCH if modal.units == "inch" else 1.0
        if scale != self.scale:
            self.set_scale(scale)
        self.incremental = modal.distance == "incremental"
        if self.cutter is not None:
            self.cutter.sweep_slack = 0.001 if modal.units == "inch" else 0.0254
        s = sections.get("Feed")
        if s is not None:
            self._set_feed(s.value)  # type: ignore[attr-defined]
        if "WorkOffset" in sections:
            self.select()
            if self.declared and self.current is not None:
                self.reframe(self.current)

    def spindle_event(self, line: int, direction: str, emit: Callable[[Emitted], None]) -> None:
        """A spindle change; stopping a stopped spindle is no event (two programs that differ only
        there move the machine alike), nor is the direction said again after a tap's out stroke."""
        if direction == "stop" and self.spindle == "stop" or self._restates(direction):
            return
        self.spindle = direction
        emit({"line": line, "event": "spindle", "dir": direction})

    def _restates(self, direction: str) -> bool:
        """The first spindle code after a tap's out stroke (ISG ``G332``), in the direction it turned before
        the tap: it puts the spindle back to turning as it did (the stroke reversed it; a program says the
        direction again, ``postproc.cycles.rigid_tap_lowering.as_strokes``), so it is no change against a
        tap that reverses back by itself (LinuxCNC ``G33.1``)."""
        after, self.after_tap = self.after_tap, None
        return after is not None and direction == after == self.spindle

    def item(self, block: Block, item: Section, emit: Callable[[Emitted], None]) -> None:
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
            self.oriented = True
            emit({"line": line, "event": "orient", "angle": num(item.angle)})  # type: ignore[attr-defined]
        elif key == "ProgramControl":
            self.program_control(line, item.kind, emit)  # type: ignore[attr-defined]
        elif key == "RigidTap":
            self.rigid_tap(block, item, True, emit)
        else:
            raise UnsupportedError(f"{key} inside a compound motion cannot be simulated", self._at(block))

    def program_control(self, line: int, kind: str, emit: Callable[[Emitted], None]) -> None:
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
    def motion(self, block: Block, m: Motion, absolute: bool, emit: Callable[[Emitted], None],
               machine_coordinates: bool | None = None) -> None:
        """One motion of ``block`` (its own, or an item of its compound motion: ``absolute``). ``machine_coordinates``:
        whether the block has a ``MachineCoordinates`` section (``block`` knows it from its keys; None: looked up)."""
        mode, line = m.mode, block.line
        travel = self.travel
        if m.axes:
            self.moved = True
        if mode in ("home", "home2"):
            if not m.axes:
                return
            if self.cutter is not None and self.cutter.side is not None:
                raise ProgramError("a reference return with cutter compensation on cannot be run", self._at(block))
            via = self.target(block, m.axes, absolute)
            if travel is not None:
                travel.line(block, self.pos, point_dict(self.axes, via), self._programmed(m.axes),
                            self.incremental and not absolute, False)
            self.line_move("rapid", via, line, emit)
            ref = list(self.at)
            index = self.index
            for axis in m.axes:
                key = self.increments.get(axis, axis)
                ref[index[key]] = self.home.get(key, 0.0) if mode == "home" and not self.lathe else 0.0
            self.machine_to_frame(block, ref, self._programmed(m.axes))
            if self.length.offset and LENGTH_AXIS in m.axes:
                ref[index[LENGTH_AXIS]] -= self.length.offset  # the reference point is a machine position
            for axis, shift in self.lathe_shift.items():
                if axis in self._programmed(m.axes):
                    ref[index[axis]] -= shift
            if travel is not None:
                travel.home(block, self._programmed(m.axes))
            if self.mark_held:
                legs: list[Emitted] = []
                out = self.out
                self.out = legs  # a compensated leg (a tool length in force) comes through ``out``
                try:
                    self.line_move("rapid", ref, line, legs.append)
                finally:
                    self.out = out
                held = "".join(sorted(self._programmed(m.axes))).lower()
                for leg in legs:
                    ev = leg.event() if isinstance(leg, MoveRecord) else leg  # (a ``mark_held`` run makes none)
                    if ev.get("line") == line:  # (not a move of an earlier block the cutter queue lets go now)
                        ev["held"] = held
                    out.append(ev)
            else:
                self.line_move("rapid", ref, line, emit)
            return
        if not m.axes and mode in ("rapid", "linear") and (self.cutter is None or self.cutter.side is None):
            return  # a motion code alone (``G00 T0101``) sets the mode and moves nothing, so a tool offset
            # changed in its block applies at the next move, as after a T code alone [K: a block moves only
            # the axes it names]; under cutter compensation the block still goes to the compensation's queue
        if self.feed is None and needs_feed(m):
            raise ProgramError(NO_FEED, self._at(block), needs="F")
        machine = ("MachineCoordinates" in block.sections if machine_coordinates is None else machine_coordinates)
        target = self.target(block, m.axes, absolute or machine, machine)
        if travel is not None and mode not in ("cw", "ccw"):  # (a machine move's values: machine positions)
            travel.line(block, self.pos, point_dict(self.axes, target), self._programmed(m.axes),
                        self.incremental and not (absolute or machine), machine)
        if machine and self.compensating:
            self._machine_coordinates(block, m, target)
        if machine:
            self.machine_to_frame(block, target, self._programmed(m.axes))
        if mode == "rapid":
            self.line_move("rapid", target, line, emit)
        elif mode == "linear":
            self.line_move("feed", target, line, emit)
        elif mode == "thread":
            self.thread_move(block, target, emit)
        elif mode in ("cw", "ccw"):
            self.arc_move(block, m, target, emit, absolute or machine)
        else:
            raise UnsupportedError(f"motion '{mode}' cannot be simulated", self._at(block))

    def thread_move(self, block: Block, target: list[float], emit: Callable[[Emitted], None]) -> None:
        """A spindle-synchronised thread move: ``f`` is its lead per revolution whatever the feed mode (Fanuc
        ``G32 F``: F is the lead [K]; LinuxCNC ``G33 K``: the block's ``ThreadLead``)."""
        lead = block.sections.get("ThreadLead")
        value = self.feed if lead is None else lead.lead * self.scale  # type: ignore[attr-defined]
        if value is None:
            raise ProgramError(NO_FEED, self._at(block), needs="F")
        if self.header_mode is None:
            self.header_mode = self.modal.feed_mode  # as a first feed move would set it
        self.sync = value
        try:
            self.line_move("feed", target, block.line, emit)
        finally:
            self.sync = None

    def rigid_tap(self, block: Block, tap: Any, absolute: bool, emit: Callable[[Emitted], None]) -> None:
        """A spindle-synchronised tap (``postproc.lowering.synchronised_tap``): a ``tap`` move to the end point and
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
        start = list(self.at)
        self.moved = True
        end = self.target(block, tap.axes, absolute)
        if self.travel is not None:
            self.travel.line(block, point_dict(self.axes, start), point_dict(self.axes, end),
                             self._programmed(tap.axes), self.incremental and not absolute, False)
        if tap.stroke is not None:  # one stroke (ISG G331/G332): its pitch's sign is the thread's hand
            hand = "cw" if pitch > 0 else "ccw"
            if hand != self.spindle:
                raise ProgramError(f"a {'right' if pitch > 0 else 'left'}-hand tap stroke (K{pitch:g}) with the spindle "
                                   f"turning {'counter-' if self.spindle == 'cw' else ''}clockwise: which way the "
                                   "spindle then turns is not modelled [?]", self._at(block, "K"))
            self.sync = abs(pitch) * self.scale
            try:
                self.line_move("tap", end, block.line, emit)
            finally:
                self.sync = None
            self.after_tap = self.spindle if tap.stroke == "out" else None
            return
        self.sync = pitch * self.scale
        try:
            self.line_move("tap", end, block.line, emit)
            if tap.dwell:
                emit({"line": block.line, "event": "dwell", "seconds": num(tap.dwell)})
            self.line_move("tap", start, block.line, emit)
        finally:
            self.sync = None

    def machine_to_frame(self, block: Block, point: list[float], axes: set[str]) -> None:
        """Machine positions on ``axes`` of ``point`` (a move in machine coordinates, a reference point) put in
        the work frame: less the work offset the frame does not hold (the set-up's, where the program set
        none; ``postproc.simulate.work_offsets``), as LinuxCNC gives such a move in program coordinates [V
        rs274: ``G10 L2 P1 Z10`` then ``G53 G0 Z0`` prints ``STRAIGHT_TRAVERSE(.., -10.0000, ..)``]. A set-up
        with no ``<WorkOffsets>`` at all takes every offset as zero (documented); one that gives some but not
        the active system's on an axis is a located error, never a point off by the missing offset."""
        for axis in axes:
            i = self.index.get(axis, -1)
            if i < 0:
                continue
            beyond = self.beyond[axis]
            if beyond is None:
                why = offset_beyond_frame(axis, self.modal.work_offset, self.offsets, self.declared)[1]
                raise ProgramError(f"a machine position cannot be put in work coordinates: {why}",
                                   self._at(block, axis if axis in (block.text or "").upper() else None))
            point[i] -= beyond

    def _machine_coordinates(self, block: Block, m: Motion, target: list[float]) -> None:
        """A move in machine coordinates: its value is where the machine's controlled point goes, without
        the tool length ([K] Fanuc, Haas: ``G53 Z0`` retracts the spindle to the top whatever the tool;
        [?] LinuxCNC), so the programmed point is what lies the offset below it. Cutter compensation
        refuses it ([V] LinuxCNC "Cannot use g53 with cutter radius comp")."""
        if self.cutter is not None and self.cutter.side is not None:
            raise ProgramError("a move in machine coordinates with cutter compensation on cannot be run",
                               self._at(block))
        if self.length.offset and LENGTH_AXIS in self._programmed(m.axes):
            target[self.index[LENGTH_AXIS]] -= self.length.offset
        for axis, shift in self.lathe_shift.items():
            if axis in self._programmed(m.axes):
                target[self.index[axis]] -= shift
