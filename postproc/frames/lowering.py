"""evaluate_frames: a target that runs the program's frame commands itself gets them as written; every other
target (and the simulation) gets every point evaluated into the work coordinates.

Kept native only back to the reading dialect itself (Fanuc to Fanuc, a Haas set-up included; LinuxCNC
to LinuxCNC): another dialect's G52 or G92 shares the number but not every rule (LinuxCNC's G52 and G92
share one offset, Fanuc's do not), and a target that runs some frames natively and gets others evaluated
would stack them wrongly.

Evaluated, each move is carried through the frame (``postproc.frames.frame``): an absolute point to its
absolute work point, on every axis the frame mixes into (a rotated ``X10`` moves X and Y); an
incremental move as its carried increment; an arc's centre offsets as vectors, its radius scaled, its
direction turned over by a mirror, and refused where the frame makes it an ellipse. A canned cycle under a
frame other than offsets is expanded (its holes carried like moves), and a mirror swaps the side of
cutter compensation. The frame commands themselves leave the block.

The rules of each command live in ``frame``; the commands' handling in the run (a command into the frame, the
axes it leaves to be programmed again, the rotations) in ``commands``; what offset changes and data settings
do to the program position in ``offset_changes``. This module carries the moves through the frame.

The program position is tracked in program coordinates (mm), None where unknown; a move that needs an
unknown coordinate (an axis it omits, that the frame mixes into the ones it programs) is a located error. On
a controller that keeps the machine point at a tool offset change the position takes the change
(``offset_changes.tool_change``), so it is the current point the controller reads: what a G92 sets its offset
from and what a program reads as its position (``postproc.frames.parameters``).

A program kept symbolically (its loops, jumps and calls written for a target that has them) runs in
another order than its text: there a frame command that may not run once where the text has it
(``run_order``: inside a construct, across a jump), or a move that needs the position the text order
would give, is an error, which the translation's dry run (``postproc.api``) takes as the reason to
flatten the program instead; a computed word under a frame set before is carried as an expression
(``X[#1*10.+100.]``). The dry run starts from the frame and position the real run has reached (kept in
``ctx.frame_run``, which the dry run's context starts from a copy of).
"""

from __future__ import annotations

import copy
import math
from typing import Final, Iterator

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..compensation.tool_length import ToolLength
from ..errors import PostprocError, ProgramError
from ..interp.control import ASSIGN, CONTROL
from ..ir.expr import Expr
from ..ir import Block, CompoundMotion, CutterCompensation, Motion, Section
from ..ir.keys import watches_none
from ..lowering.lower import BlockStep, LoweringStep, run_blocks, still_moving
from ..lowering.move_words import move_words, moving
from ..ir.state import MM_PER_INCH, ModalState, changes_nothing
from .affine import EXACT, INDEX, XYZ
from .carried_arc import carried_arc, combination as _combination
from .frame import PLANE_AXES, Frame, Position
from .run_order import RunOrder
from .run_state import FrameRun
from .section import FrameChange
from .offset_changes import current_point_reads, data_setting
from .commands import command, pending
from .words import COMPUTED, LAYERED_FORBIDDEN, LINEAR, SWAPPED, SYMBOLIC, note as _note



EVALUATE_KEY: Final = "frames.evaluate"
"""``ctx.run_data`` key: evaluate the frames back to the reading dialect too (a program transform,
``postproc.transforms``, moves the evaluated points)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class EvaluateFrames(LoweringStep):
    """Lowering step (see the module docstring): back to its own dialect the stream passes through."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if target.NAME == ctx.dialect and not ctx.run_data.get(EVALUATE_KEY) or ctx.lathe:
            return None
        return FrameEvaluator(ctx, target.WRITER is not None)


evaluate_frames = EvaluateFrames()


@mypyc_attr(allow_interpreted_subclasses=True)
class FrameEvaluator(BlockStep):
    """The frame and the program position of one run, and the rewriting of each block."""

    def __init__(self, ctx: Context, rewrite: bool = True) -> None:
        super().__init__()  # every move is its business: it follows the position
        self.ctx = ctx
        self.rewrite = rewrite
        """Mark a rewritten block changed (a writer regenerates it); the simulation, which writes nothing,
        keeps its text for the columns of its errors."""
        self.modal = ModalState()
        run = ctx.frame_run
        if not isinstance(run, FrameRun):
            m = ctx.setup.machine
            start = {"X": m.start_x, "Y": m.start_y, "Z": m.start_z}
            run = FrameRun({a: float(start.get(a, 0.0)) * (m.mm() if a in LINEAR else 1.0) for a in m.axes},
                           move_words(ctx))
            ctx.frame_run = run
        if ctx.run_data.get("dry_run"):
            run.symbolic = True  # a dry run sees the part of the program that would be kept symbolically
            self.modal.units = ctx.state.units
            self.modal.plane = ctx.state.plane
            self.modal.distance = ctx.state.distance
            self.modal.work_offset = ctx.state.work_offset
        self.reached = run
        self.frame = run.frame
        self.p = run.p
        self.g5x = run.g5x
        self.scale = run.scale = MM_PER_INCH if self.modal.units == "inch" else 1.0
        self.plain_mm = self.scale == 1.0 and self.modal.distance == "absolute"
        """Absolute millimetres: a move's words are its position (``run``'s common case)."""
        self.words = move_words(ctx)
        """A plain move's numbers, read once for the steps that follow the point (``take_move``)."""
        run.notes.words = self.words  # (a dry run's copy of the run reads with its own run's reader)
        self.follow()

    def run(self, blocks: Iterator[Block]) -> Iterator[Block]:
        """Every block, as the lowering step takes them (``take``)."""
        return run_blocks(blocks, [self])

    def follow(self) -> None:
        """``point`` (``BlockStep.point``) as the run stands: a straight move of X, Y and Z numbers is only noted
        (``take_move``) while no frame is set, in absolute millimetres, before any construct (no jump target to
        note), once the start no longer stands for X, Y and Z (nothing ``unsettled`` to take off)."""
        reached = self.reached
        unsettled = reached.unsettled
        self.point = reached.notes if (self.frame is None and self.plain_mm and not reached.symbolic
                                       and "X" not in unsettled and "Y" not in unsettled
                                       and "Z" not in unsettled) else None

    def take(self, block: Block) -> list[Block] | None:
        out = self._take(block)
        self.follow()
        return out

    def _take(self, block: Block) -> list[Block] | None:
        """The common block (a move and its feed, no frame yet, absolute millimetres) only updates the
        position (one ``dict.update``: this step runs for every translation to another dialect, frames or
        not)."""
        s = block.sections
        if not s:
            return None
        self.reached.settle()  # (the plain moves' noted numbers: ``take_move``)
        if self.frame is None and watches_none(s, _WATCHED):
            m = s.get("Motion")
            if m is None:
                if self.reached.symbolic:
                    self.targets(s)
                return None
            if isinstance(m, Motion) and self.plain_mm and m.mode in _MOVES and not self.ctx.state.symbolic:
                self.p.update(m.axes)  # type: ignore[arg-type]  # numbers: nothing is symbolic yet
                unsettled = self.reached.unsettled
                if unsettled:
                    unsettled.difference_update(m.axes)
                if self.reached.symbolic:
                    self.targets(s)
                return None
        try:
            self.block(block)
        except PostprocError as err:
            self.ctx.diagnostics.error(err.located(self.ctx.at(block)))
            return []
        return None

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block the loop found only a move (``plain_move``: not asked again here, ~450 instructions
        compiled): with no frame, in absolute millimetres, the position follows its words (a move of X, Y and Z
        numbers only noted, ``FrameRun.settle``: read once for the steps that follow the point, ``move_words``;
        a straight one the loop notes itself while ``point`` is set); else ``take``."""
        m = block.sections["Motion"]
        if self.frame is None and self.plain_mm:
            if isinstance(m, Motion) and moving(m.mode) and not self.ctx.state.symbolic:
                reached = self.reached
                words = self.words
                bits = words.read(m)
                if bits >= 0:
                    reached.notes.note(words, bits)
                else:
                    reached.settle()
                    self.p.update(m.axes)  # type: ignore[arg-type]  # numbers: nothing is symbolic yet
                unsettled = reached.unsettled
                if len(unsettled) != 0:
                    unsettled.difference_update(m.axes)
                if reached.symbolic:
                    self.targets(block.sections)
                self.follow()
                return None
        return still_moving(block, self.take(block), m, m.axes if isinstance(m, Motion) else None)  # (a frame carries it)

    # -- one block ---------------------------------------------------------------------------------
    def block(self, block: Block) -> None:
        s = block.sections
        if ASSIGN in s or CONTROL in s:
            self.reached.symbolic = True
        if self.reached.symbolic:
            self.targets(s)
            control = s.get(CONTROL)
            if control is not None:
                self.reached.order.control(control, SYMBOLIC, self.frame is None or self.frame.plain())
        changed = False
        if not changes_nothing(s):
            self.settings(block, s)  # first: a G10 in a block with G20 gives inches [V: rs274 order of execution]
        if "ToolLengthOffset" in s or "CutterCompensation" in s or "DynamicCutterCompensation" in s:
            self.current_point_reads(s)
        frame = self.frame
        if "DataSetting" in s:
            changed = self.data_setting(block, s)
            frame = self.frame
        change = s.get("FrameChange")
        if change is not None and isinstance(change, FrameChange):  # (an interpreted class: a generic test)
            if self.reached.symbolic:
                self.reached.order.command(SYMBOLIC)  # refused unless it runs where the text has it
            self.command(block, change)
            del s["FrameChange"]
            _trace(s, change)
            frame, changed = self.frame, True
        if frame is not None and frame.pending:
            self.pending(s, frame)
        if frame is None or frame.plain():
            self.track(s)
        else:
            changed = self.carry(block, s, frame) or changed
        if changed and self.rewrite:
            block.changed()

    def current_point_reads(self, s: dict[str, Section]) -> None:
        """A tool offset change, cutter compensation on or off (``offset_changes.current_point_reads``)."""
        current_point_reads(self, s)

    def targets(self, s: dict[str, Section]) -> None:
        """The jump targets a block of the symbolic part carries, and a subprogram's start (``RunOrder``)."""
        if "ProgramStart" in s:
            self.reached.order.subprogram()
        label = s.get("Label")
        sequence = s.get("Sequence")
        if label is not None or sequence is not None:
            names = [] if label is None else [str(getattr(label, "name"))]
            if sequence is not None:
                names.append(f"N{getattr(sequence, 'number')}")
            self.reached.order.target(names)

    def settings(self, block: Block, s: dict[str, Section]) -> None:
        """Units, plane, distance mode and work system, as the block leaves them."""
        modal = self.modal
        work, plane = modal.work_offset, modal.plane
        modal.apply(s)
        if "WorkOffset" in s:
            self.reached.work = modal.work_offset
        self.scale = self.reached.scale = MM_PER_INCH if modal.units == "inch" else 1.0
        self.plain_mm = self.scale == 1.0 and modal.distance == "absolute"
        frame = self.frame
        if modal.plane != plane and frame is not None and frame.rotation is not None:
            if frame.rules == "rotate_first":
                # [V] Beckhoff TF5200 programming manual, "Rotate the coordinate system in the plane (G68/G69)": a
                # change of plane deselects the contour rotation, with a warning
                frame.unrotate(self.p)
                self.ctx.diagnostics.warn("the plane change ends the coordinate rotation (as the control does)",
                                          self.ctx.at(block))
            else:
                # [V] Fanuc 15i/16i operator's manuals: no plane selection in the mode of coordinate rotation
                raise ProgramError("the plane cannot change while coordinate rotation is on")
        if modal.work_offset != work:
            if frame is not None and frame.rules == "layered" and frame.linear_active():
                raise ProgramError(LAYERED_FORBIDDEN.format(what="a work system change"))
            for axis in self.p:
                self.p[axis] = None  # the tool stays; its place in the new system is not known here
            if frame is not None:
                frame.select_work(modal.work_offset)
                if frame.rules == "chain":
                    frame.pending.update(XYZ)  # a settable offset's change as a frame change's (chain rules,
                    # ``FrameChange.increment_setting``: the family base gives the setting and its source)

    def data_setting(self, block: Block, s: dict[str, Section]) -> bool:
        """A G10 (``offset_changes.data_setting``): True where the block changed."""
        return data_setting(self, block, s)

    def frame_for(self, rules: str) -> Frame:
        """The frame, made with ``rules`` at the first frame command."""
        if self.frame is None:
            self.frame = self.reached.frame = Frame(rules)
            self.frame.work = self.modal.work_offset
        return self.frame

    # -- frame commands ----------------------------------------------------------------------------
    def command(self, block: Block, change: FrameChange) -> None:
        """A frame command into the frame (``commands.command``)."""
        command(self, block, change)

    def pending(self, s: dict[str, Section], frame: Frame) -> None:
        """The axes a command left to be programmed again (``commands.pending``)."""
        pending(self, s, frame)

    def track(self, s: dict[str, Section]) -> None:
        """No frame: only the program position follows the block."""
        cc = s.get("CutterCompensation")
        if cc is not None:
            self.modal.extra["frames.cutter"] = cc.mode  # type: ignore[attr-defined]
        if "CompoundMotion" in s:
            p = self.p  # a cycle's last point is not read here (its expansion may be lazy); X, Y and Z each named:
            p["X"] = None  # a loop over ``XYZ``, another module's constant, built and walked the tuple generically
            p["Y"] = None  # (~600 instructions an expanded hole compiled)
            p["Z"] = None
            return
        m = s.get("Motion")
        if not isinstance(m, Motion) or m.mode is None:
            return
        p = self.p
        if "MachineCoordinates" in s or m.mode in ("home", "home2"):
            for axis in m.axes:
                p[axis] = None
            return
        incremental = self.modal.distance == "incremental"
        scale = self.scale
        for axis, value in m.axes.items():
            if isinstance(value, Expr):
                p[axis] = None
                continue
            v = value * scale if axis in LINEAR else value
            if incremental:
                here = p.get(axis)
                p[axis] = None if here is None else here + v
            else:
                p[axis] = v
                self.reached.unsettled.discard(axis)

    def carry(self, block: Block, s: dict[str, Section], frame: Frame) -> bool:
        """Rewrite the block's points into work coordinates; True when anything changed."""
        changed = False
        cc = s.get("CutterCompensation")
        if isinstance(cc, CutterCompensation):
            self.modal.extra["frames.cutter"] = cc.mode
            found = frame.map.arc_factor(PLANE_AXES["XY"])
            if cc.mode in SWAPPED and found is not None and found[1]:
                s["CutterCompensation"] = CutterCompensation(SWAPPED[cc.mode], cc.register)
                changed = True
        compound = s.get("CompoundMotion")
        m = s.get("Motion")
        if isinstance(m, Motion) and m.mode is not None:
            s["Motion"] = self.move(s, m, self.modal.distance == "incremental")
            changed = True
        if isinstance(compound, CompoundMotion):
            self.cycle(s, compound, frame)
            changed = True
        return changed

    def cycle(self, s: dict[str, Section], compound: CompoundMotion, frame: Frame) -> None:
        """A canned cycle's moves, carried one by one; the cycle is expanded for the target."""
        if frame.scaling is not None:
            self.scaled_cycle(frame.scaling[1])
        if frame.linear_active() and getattr(s.get("CannedCycle"), "kind", None) in _SHIFTING:
            raise ProgramError("a boring cycle with a shift under coordinate rotation, scaling or a mirror is not "
                               "simulated: its shift follows the spindle's oriented stop, a machine setting (Fanuc "
                               "parameter 5101), and whether the frame turns it is not settled [?]")
        if frame.map.mixes(2, 0) or frame.map.mixes(2, 1) or frame.map.m[8] != 1.0:
            raise ProgramError("a canned cycle under a frame that moves the drilling axis is not simulated")
        items: list[Section] = []
        for item in compound.items:
            items.append(self.move(s, item, False) if isinstance(item, Motion) and item.mode is not None else item)
        s["CompoundMotion"] = CompoundMotion(compound.term, items)
        cycle = s.get("CannedCycle")
        if cycle is not None and hasattr(cycle, "expand"):
            cycle = copy.copy(cycle)
            cycle.expand = True  # the target's native cycle would drill at the unrotated points
            s["CannedCycle"] = cycle

    @staticmethod
    def scaled_cycle(factors: tuple[float, float, float]) -> None:
        """A hole cycle under scaling: its hole positions scale as any point (a negative factor mirrors
        them) [K: Fanuc 0i-MF operator's manual, scaling; Haas 96-8000 manual, G51]. What else scales
        differs: Haas scales none of a cycle's Z moves (levels, depths, increments) [K: Haas 96-8000, G51],
        Fanuc scales R and Z per its axis parameters (5401 SCLx) but never Q or the retract d [K: 0i-MF],
        and neither scales a boring shift Q [K: 0i-MF]. So a Z factor other than 1 is refused (a shifting
        boring cycle is, under any frame that turns, scales or mirrors: ``cycle``); with X and Y scaled alone
        the controllers agree."""
        if factors[2] != 1.0:
            raise ProgramError("a canned cycle under a scaling of Z is not simulated (which of its levels and depths "
                               "scale differs between controllers and machine parameters): scale X and Y only "
                               "(I, J) or cancel scaling first")

    def move(self, s: dict[str, Section], m: Motion, incremental: bool) -> Motion:
        """One move carried through the frame (see the module docstring)."""
        frame = self.frame
        assert frame is not None
        p, scale, mode = self.p, self.scale, m.mode
        if "MachineCoordinates" in s and mode not in ("home", "home2"):
            if frame.rules == "layered" and frame.linear_active():
                raise ProgramError(LAYERED_FORBIDDEN.format(what="a move in machine coordinates"))
            for axis in m.axes:
                p[axis] = None
            return m
        home = mode in ("home", "home2")
        if home and frame.linear_active():
            raise ProgramError(LAYERED_FORBIDDEN.format(what="a reference return") if frame.rules == "layered" else
                               "a reference return under a rotated work system is not simulated [?: where its "
                               "intermediate point lies]")
        if _computed(m):
            if frame.polar is not None or home:
                raise ProgramError(COMPUTED)
            return self.computed_move(m, incremental, frame)
        given: dict[str, float] = {}
        for axis, value in m.axes.items():
            assert not isinstance(value, Expr)
            given[axis] = value * scale if axis in LINEAR else value
        if frame.polar is not None and not home:
            self.polar(m, given, incremental, frame.polar)
        out: dict[str, float | Expr] = {}
        fmap = frame.map
        if incremental:
            d = [given.get(a, 0.0) for a in XYZ]
            dw = fmap.linear(d)
            for i, axis in enumerate(XYZ):
                if axis in given or abs(dw[i]) > EXACT:
                    out[axis] = dw[i] / scale
            for axis, value in given.items():
                if axis not in INDEX:
                    out[axis] = value / (scale if axis in LINEAR else 1.0)
                here = p.get(axis)
                p[axis] = None if here is None or home else here + value
        else:
            point: list[float | None] = [given.get(a, p.get(a)) for a in XYZ]
            columns = [INDEX[a] for a in given if a in INDEX]
            for i, axis in enumerate(XYZ):
                if not any(fmap.mixes(i, j) for j in columns):
                    continue
                for j in range(3):
                    if fmap.mixes(i, j) and j not in columns:
                        self._omitted(axis, XYZ[j], point[j])
                w = fmap.point([v if v is not None else 0.0 for v in point])
                out[axis] = w[i] / scale
            for axis, value in given.items():
                if axis not in INDEX:
                    out[axis] = (value + frame.shift(axis)) / (scale if axis in LINEAR else 1.0)
                if home:
                    p[axis] = None
                else:
                    p[axis] = value
                    self.reached.unsettled.discard(axis)
        if mode not in ("cw", "ccw"):
            return Motion(mode, out)
        return self.arc(m, out, mode)

    def _omitted(self, axis: str, needed: str, here: float | None) -> None:
        """A move's ``axis`` needs the program position on ``needed``, which the block omits."""
        if self.reached.symbolic:
            raise ProgramError(f"{SYMBOLIC}: this move's {axis} needs the program's {needed}, which the block omits")
        if here is None:
            raise ProgramError(f"this move's {axis} under the coordinate frame needs the program's {needed}, which "
                               f"is not known here: program {needed} absolutely")

    def computed_move(self, m: Motion, incremental: bool, frame: Frame) -> Motion:
        """A move with computed words under a frame set before (a program kept symbolically): each carried
        coordinate is written as the expression ``sum(m[i][j] * word_j) + t[i]`` in program units."""
        fmap, scale, p = frame.map, self.scale, self.p
        words: list[float | Expr | None] = [m.axes.get(a) for a in XYZ]
        columns = [j for j in range(3) if words[j] is not None]
        out: dict[str, float | Expr] = {}
        for i, axis in enumerate(XYZ):
            if not any(fmap.mixes(i, j) for j in columns):
                continue
            terms: list[tuple[float, float | Expr]] = []
            for j in range(3):
                if not fmap.mixes(i, j):
                    continue
                word = words[j]
                if word is None:
                    if incremental:
                        continue
                    here = p.get(XYZ[j])
                    self._omitted(axis, XYZ[j], here)
                    assert here is not None
                    word = here / scale
                terms.append((fmap.m[3 * i + j], word))
            out[axis] = _combination(terms, 0.0 if incremental else fmap.t[i] / scale)
        for axis, value in m.axes.items():
            if axis not in INDEX:
                shift = 0.0 if incremental else frame.shift(axis) / (scale if axis in LINEAR else 1.0)
                out[axis] = _combination([(1.0, value)], shift)
            p[axis] = None
        if m.mode not in ("cw", "ccw"):
            return Motion(m.mode, out)
        return self.arc(m, out, m.mode)

    def polar(self, m: Motion, given: dict[str, float], incremental: bool, plane: str) -> None:
        """G16: the plane's first axis word is a radius, its second an angle in degrees counter-clockwise
        from the first axis, about the program's zero (the local zero under G52) [V: Fanuc 16/18-MC
        operator's manual 9.2]; an omitted one is the current point's [K: Mitsubishi M700 manual 6.12].
        Rewritten in ``given`` as the Cartesian point (mm)."""
        a1, a2, _ = PLANE_AXES[plane]
        if a1 not in given and a2 not in given:
            return
        if incremental:
            # [V] Fanuc 16/18-MC 9.2: in incremental mode the current point is the origin of the radius; the
            # reference of an incremental angle there is not settled [?]
            raise ProgramError("an incremental move in polar coordinates is not simulated (the reference of its "
                               "angle is not settled)")
        if m.mode in ("cw", "ccw") and m.center is not None:
            raise ProgramError("an arc in polar coordinates takes its radius R, not I/J/K [K: Fanuc 16/18-MC "
                               "operator's manual 9.2, limitations]")
        here1, here2 = self.p.get(a1), self.p.get(a2)
        if (a1 not in given or a2 not in given) and (here1 is None or here2 is None):
            raise ProgramError(f"a polar move without {a1 if a1 not in given else a2} takes the current point's, "
                               "which is not known here: program both")
        radius = given[a1] if a1 in given else math.hypot(here1, here2)  # type: ignore[arg-type]
        angle = m.axes[a2] if a2 in given else math.degrees(math.atan2(here2, here1))  # type: ignore[arg-type]
        assert isinstance(angle, float | int)
        c, s = _cos_sin(float(angle))
        given[a1], given[a2] = radius * c, radius * s

    def arc(self, m: Motion, out: dict[str, float | Expr], mode: str) -> Motion:
        frame = self.frame
        assert frame is not None
        arc = carried_arc(frame.map, self.modal.plane, m, out, mode)
        if arc is None:
            raise ProgramError(f"an arc in the {self.modal.plane} plane under this frame is not an arc (unequal "
                               "scaling, or a rotation out of its plane): it cannot be evaluated")
        return arc


_WATCHED: Final = frozenset(("Units", "Plane", "DistanceMode", "WorkOffset", "DataSetting", "FrameChange", ASSIGN,
                             CONTROL, "CutterCompensation", "CompoundMotion", "MachineCoordinates",
                             "ToolLengthOffset", "DynamicCutterCompensation"))
"""Sections that make a block more than a move to follow, before any frame."""
_MOVES: Final = frozenset(("rapid", "linear", "cw", "ccw"))


_SHIFTING: Final = frozenset(("fine_bore", "back_bore"))
"""Hole cycles that shift the tool sideways by Q (fine and back boring): the shift is not scaled [K] and runs
along the spindle's oriented stop, fixed to the machine (Fanuc parameter 5101) [K]."""


def _computed(m: Motion) -> bool:
    return any(isinstance(v, Expr) for v in m.axes.values()) or isinstance(m.radius, Expr) or (
        m.center is not None and any(isinstance(v, Expr) for v in m.center.values()))


def _cos_sin(degrees: float) -> tuple[float, float]:
    """Exact at whole quarter turns (a bolt circle's 90 degrees must not leave 6e-17 behind)."""
    quarter = degrees / 90.0
    if quarter.is_integer():
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
    return math.cos(math.radians(degrees)), math.sin(math.radians(degrees))


def _trace(s: dict[str, Section], change: FrameChange) -> None:
    """The evaluated command stays in the output as a comment (no block vanishes without a trace)."""
    _note(s, f"{change.text} evaluated")
