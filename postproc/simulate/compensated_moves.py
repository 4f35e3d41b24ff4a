"""The simulator's tool length, tool offset and cutter radius compensation (``postproc.compensation``): the
settings a block makes, and the moves that pass through them, their controlled point beside the programmed one.
The position they change is ``postproc.simulate.position``'s; the plain moves are ``postproc.simulate.moves``'."""

from __future__ import annotations

from typing import Any, Callable

from mypy_extensions import mypyc_attr

from ..compensation.cutter_radius import CutterRadius, Item, Segment
from ..compensation.nose import TIPS, mirrored
from ..compensation.geometry_for import cutter_for
from ..compensation.rules import CutterRules
from ..context import Context
from ..errors import PostprocError, ProgramError, UnsupportedError
from ..geometry.arcs import CENTRE_KEYS
from ..ir import Block
from ..lowering.inverse_time import move_length
from ..ir.state import PLANE_AXES
from .events import CUTTER_RADIUS, LATHE_TOOL_OFFSET, TOOL_LENGTH, Event, all_as_written, differs, num
from .move_record import Emitted, MoveRecord
from .position import LENGTH_AXIS, Position, point_dict


@mypyc_attr(allow_interpreted_subclasses=True)
class CompensatedMoves(Position):
    """A run's position with the compensation its moves pass through (the moves that do are written here)."""

    def __init__(self, ctx: Context, travel_warn: bool = False, cutter_rules: CutterRules | None = None) -> None:
        super().__init__(ctx, travel_warn)
        self.cutter = None if cutter_rules is None else cutter_for(cutter_rules, self._release)
        self.queued = self._event

    def compensation(self, block: Block, emit: Callable[[Emitted], None]) -> None:
        """A block's cutter compensation and tool length changes (before its motion, as the controller
        runs them): compensation ends first, so the move it queued is written with the old setting."""
        get = block.sections.get
        cutter, cc = self.cutter, get("CutterCompensation")
        if cutter is not None and cc is not None:
            mode = cc.mode  # type: ignore[attr-defined]
            if mode == "off":
                cutter.cancel()
                self.note_tool_data(block.line, CUTTER_RADIUS, "off", 0.0)
            elif mode in ("left", "right") and self.native_stretch:
                cutter.cancel()  # recorded as a setting (``record_settings``), as without rules
            elif mode in ("left", "right"):
                reads = self._cutter_register(block, cc.register)  # type: ignore[attr-defined]
                self.cutter_started = True
                radius = self._cutter_radius(block, reads)
                try:
                    cutter.start(mode, radius, self.modal.plane, self._nose_tip(block, reads))
                except PostprocError as err:
                    raise err.located(self._at(block)) from None
                self.note_tool_data(block.line, CUTTER_RADIUS, f"{mode} D{reads}", radius)
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
            self.note_tool_data(block.line, CUTTER_RADIUS, f"{dynamic.mode} (its diameter in the block)",  # type: ignore[attr-defined]
                                abs(dynamic.radius(self.scale)))  # type: ignore[attr-defined]
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
            self.note_tool_data(block.line, TOOL_LENGTH, _length_name(tl.mode, register),  # type: ignore[attr-defined]
                                self.length.offset)
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
        i = self.length_index
        if i < 0:
            return
        self._begin()  # the controlled point before the change is the one kept
        self.at = list(self.at)  # (never changed in place)
        self.at[i] -= change
        self.rounded = list(self.rounded)
        self.rounded[i] = num(self.at[i])
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
            self.at, self.rounded = list(self.at), list(self.rounded)
            for axis in sorted(set(new) | set(old)):
                change = new.get(axis, 0.0) - old.get(axis, 0.0)
                if change and axis in self.index:
                    i = self.index[axis]
                    self.at[i] -= change
                    self.rounded[i] = num(self.at[i])
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

    # -- compensation -------------------------------------------------------------------------------
    def _compensated(self, kind: str, end: list[float], line: int, centre: tuple[float, float] | None,
                     plane: str | None) -> None:
        """A move handed to the compensation: the cutter queue (when compensating the radius) or straight
        to ``_write``; the programmed point moves on at once (the segment holds its end as a dictionary)."""
        target = point_dict(self.axes, end)
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
        self.at = end
        self.rounded = [num(v) for v in end]
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

    def _offset_line(self, kind: str, target: list[float], line: int) -> None:
        """A straight move under a tool length alone (a whole program after its G43): ``_write``'s result,
        the programmed point rounded only on the axes that move (as ``line_move``). One pass over the axes
        builds both points (the record's lists): the values stay the objects ``num`` made (an int stays an int
        in the JSON line), compared per axis rather than as dictionaries. Where every value of ``target`` is as
        ``num`` writes it (``all_as_written``: a CAM program's move), ``target`` itself is the programmed point:
        no list, no float an axis made and freed (~600 instructions a move, callgrind, branch simfast9)."""
        at, rounded, before = self.at, self.rounded, self.crounded
        offset = self.length.offset
        shifts = self.lathe_shift
        shifted = len(shifts) != 0  # (tested once, not an axis: a mill has none)
        length_at = self.length_index
        axes = self.axes
        kept = all_as_written(target)  # (a CAM program's move: ``target`` is the point as written, no list made)
        values: list[Any] = target  # (its items as the objects they are: compiled, not a float unboxed and boxed)
        point: list[Any] = target if kept else []
        crounded: list[Any] = target[:] if kept else []  # (kept: the point as written, its offset axes set in the loop;
        # a slice is one C call, where a new list grew at its first append: ~100 instructions a move, callgrind)
        moved = apart = False
        f: float | int | None = None
        mode: str | None = None
        if kept and not shifted:  # (a mill's CAM move: the loop below, but for the length's axis alone)
            if length_at >= 0:
                value = target[length_at]
                c0 = num(value + offset)
                crounded[length_at] = c0
                apart = not isinstance(c0, float) or c0 != value  # (``value`` is as ``num`` writes it: not integral)
            for i in range(len(axes)):
                c1: Any = crounded[i]
                b1: Any = before[i]
                if c1 is not b1 and differs(c1, b1):
                    moved = True
                    break
        for i in range(len(axes) if not kept or shifted else 0):
            r: Any
            if kept:
                r = values[i]
            else:
                value = target[i]
                r = rounded[i] if value == at[i] else num(value)
                point.append(r)  # (appended: compiled, ``[0] * n`` and a store by index cost ~600 instructions a
                # move more, a list repeated through Python; callgrind, branch simfast3)
            c: Any = r
            if i == length_at or shifted:  # (the controlled value is the programmed one but on an offset's axes)
                value = target[i]
                shift = shifts.get(axes[i]) if shifted else None
                if shift is not None:
                    c = num(value + shift + (offset if i == length_at else 0.0))
                elif i == length_at:
                    c = num(value + offset)
                if not apart and c is not r and differs(c, r):
                    apart = True
            if not kept:
                crounded.append(c)
            elif c is not r:
                crounded[i] = c
            if not moved:  # (identity first: an axis that stays keeps its number's object; never a nan)
                b = before[i]
                if c is not b and differs(c, b):
                    moved = True
        if kind != "rapid":  # a move it drops fixes the header's feed mode too, as ``_compensated``'s
            f = self._feed_value()
            mode = self._stated_mode()
        if not moved:
            self.at, self.rounded = target, point
            self._settle()
            return
        self.at, self.rounded, self.crounded = target, point, crounded
        record = MoveRecord(line, kind, self.key_names, point, f, mode, crounded if apart else None)
        self.out.append(record if self.records else record.event())
        self._settle()

    def _offset_arc(self, kind: str, target: list[float], line: int, c: tuple[float, float], plane: str) -> None:
        """An arc under a tool length (and a lathe's tool offset) alone: ``_compensated``'s and ``_write``'s event
        for it, without the cutter's segment (an interpreted object: ~25k instructions an arc)."""
        a1, a2, normal = PLANE_AXES[plane]
        offset = self.length.offset
        shifts = self.lathe_shift
        shifted = len(shifts) != 0
        length_at = self.length_index if offset else -1
        kept = all_as_written(target)  # ``target`` is the point as written (as ``_offset_line``'s)
        values: list[Any] = target
        rounded: list[Any] = target if kept else []
        crounded: list[float | int] = []
        apart = False
        axes = self.axes
        for k in range(len(axes)):  # (a value no offset moves is its programmed number: ``num`` once, not twice)
            value = target[k]
            r: Any
            if kept:
                r = values[k]
            else:
                r = num(value)
                rounded.append(r)
            cr = r
            shift = shifts.get(axes[k]) if shifted else None
            if k == length_at or shift is not None:
                controlled = value + offset if k == length_at else value
                cr = num(controlled + shift if shift is not None else controlled)
                if cr != r:
                    apart = True
            crounded.append(cr)
        normal_at = self.axis_value(self.at, normal)  # the centre on the axis normal to the plane: the start's
        written: list[float | int] = []
        cwritten: list[float | int] = []
        for axis in self.centre_axes:
            at = c[0] if axis == a1 else c[1] if axis == a2 else normal_at
            r = num(at)
            written.append(r)
            cr = r
            shift = shifts.get(axis) if shifted else None
            if offset and axis == LENGTH_AXIS or shift is not None:
                if offset and axis == LENGTH_AXIS:
                    at += offset
                cr = num(at + shift if shift is not None else at)
                if cr != r:
                    apart = True
            cwritten.append(cr)
        f = self._feed_value()
        mode = self._stated_mode()
        self.at, self.rounded, self.crounded = target, rounded, crounded
        record = MoveRecord(line, kind, self.key_names, rounded, f, mode, crounded if apart else None,
                            self.centre_keys, written, plane, cwritten if apart else None)
        self.out.append(record if self.records else record.event())
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
            self.out.append(ev)

    def _release(self, item: Item) -> None:
        if isinstance(item, Segment):
            self._write(item)
        else:
            self.out.append(item)

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
                if axis in self.index:
                    scale = 2.0 if diameter and axis == "X" else 1.0
                    ev[CENTRE_KEYS[axis]] = num(centre[axis] * scale)
                    ctrl[CENTRE_KEYS[axis]] = num(ccentre[axis] * scale)
            ev["plane"] = plane
        for key, value in seg.fields.items():
            if key != "line":
                ev[key] = value
        if any(ev[key] != value for key, value in ctrl.items()):
            ev["controlled"] = ctrl
        self.out.append(ev)

    def _settle(self) -> None:
        """Leave the compensation once nothing offsets the tool and it stands at the programmed point."""
        if not self.length.offset and not self.lathe_shift and self._cutter_idle() and self.rounded == self.crounded:
            self.compensating = False

    def finish(self) -> None:
        """The end of the input: a move still waiting in the cutter queue is written as it stands."""
        if self.cutter is not None:
            self.cutter.finish()


def _length_name(mode: str, register: object) -> str:
    """A tool length offset as ``Position.tool_data`` records it, in no dialect's spelling: ``positive 18``
    (added), ``negative 18`` (subtracted), ``dynamic`` (its length given in the block), ``off``
    (``postproc.simulate.lost_tool_data`` spells it for the report)."""
    if mode == "cancel":
        return "off"
    if mode == "dynamic":
        return "dynamic"
    return f"{mode} {register}" if register is not None else mode
