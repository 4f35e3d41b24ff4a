"""move_program: the user's ``--transform`` applied to every point of a program, in its work coordinates.

It runs after the target's lowering (``postproc.transforms.apply``), on the blocks the writer gets: the
program's own frames are evaluated by then (a target of another dialect), cycles the target cannot run
are expanded (their moves carried like any), compensation a target lacks is resolved. Each move goes
through the map as the frames lowering carries a move (``postproc.frames.lowering``): an absolute point
to its absolute image on every axis the map mixes into (``X10`` under a rotation writes X and Y: an omitted
coordinate it needs is the tracked program position, or a located error), an increment as its image
vector; an arc keeps its exact centre (its offsets turned as vectors), its radius is scaled, a mirror
turns its direction over, and a map that makes it an ellipse (unequal scaling in its plane, a rotation
out of it) is a located error. A mirror of the XY plane swaps cutter compensation left and right.

A hole cycle the target runs stays a cycle: its hole position is carried like a point, its levels (R, the
bottom) by the drilling axis's own scale and shift (an increment by the scale alone), a peck depth by the
scale; a map that tilts the drilling axis, turns it over or turns a shifting cycle's shift is refused.

A rigid tap's end point is carried like a point where the map keeps Z as it is (the tap runs along Z with
its own pitch); otherwise it is refused.

Machine positions stay where the machine has them: the start, and a reference return, whose intermediate
point (work coordinates) is carried and whose return is kept as written. An axis the map changes is *held*
there (``held``) until the program names it absolutely: an increment from a held position, an arc in a plane
with a held axis, a hole cycle along a held axis, an absolute move whose image needs a held coordinate, or
an intermediate point that moves a held axis by more than 0 is a located error (it would be no point of the
moved program); a move that leaves a held axis alone leaves it where the machine has it (``verify``
follows the same rule: ``postproc.transforms.events``).

What cannot be carried exactly is a located error: the program's frame commands kept as written, a work
system rotation, a move in machine coordinates on an axis the map changes, a reference return whose
intermediate point the map moves on an axis it does not return, a rotary or parallel axis under a map that
is more than a translation, a computed word.

A lathe program (``Context.lathe``) takes only a shift along Z (``lathe_refusal`` names what else a map
does and why the program would no longer be valid). Its moves are carried with their incremental addresses
(U, W: ``Context.increments``: an increment, held as any), thread moves like feed moves. A lathe cycle kept for
the target and a coordinate setting (which declares where the tool stands) are refused by name.
"""

from __future__ import annotations

import copy
import math
from typing import Final, Iterator

from ..context import Context
from ..cycles.section import CannedCycle
from ..cycles.semantics import PECK
from ..errors import PostprocError, ProgramError
from ..ir.expr import Expr
from ..geometry.arcs import centre_from_radius
from ..frames.affine import EXACT, INDEX, XYZ, Affine
from ..frames.carried_arc import carried_arc
from ..frames.frame import PLANE_AXES
from ..frames.section import FrameChange
from ..ir import Block, CompoundMotion, CutterCompensation, DataSetting, Motion, Section
from ..ir.lathe_sections import CoordinateSet, LatheCycle
from ..ir.state import MM_PER_INCH, ModalState
from ..lowering.synchronised_tap import RigidTap
from .spec import ProgramTransform
from .words import COMPUTED, COMPUTES, INERT, SYMBOLIC, cycle_roles, named

WHAT: Final = "transformed"
_MOVES: Final = frozenset(("rapid", "linear", "cw", "ccw", "thread"))
_SWAPPED: Final = {"left": "right", "right": "left"}
_OWN: Final = frozenset(("Units", "Feed", "ToolLengthOffset", "PathControl"))
"""Sections this step leaves alone although they hold lengths (a feed is a speed, a tool length is the
tool's); the units step converts them."""
_LATHE_INERT: Final = frozenset(("SpindleMode", "SpindleClamp", "ThreadLead", "InProfile", "XProgramming"))
"""A lathe's sections with no point in them (a surface speed, a speed clamp, a thread's lead, the mark of a
cycle's profile block, whose moves are carried where the cycle is expanded, a switch of how X reads: the IR's
X stays the set-up's mode)."""


def move_program(blocks: Iterator[Block], ctx: Context, transform: ProgramTransform) -> Iterator[Block]:
    """The lowering step (see the module docstring); each error is reported at its block."""
    mover = ProgramMover(ctx, transform.map)
    report = ctx.diagnostics.error
    for block in blocks:
        if block.sections:
            try:
                mover.block(block)
            except PostprocError as err:
                report(err.located(ctx.at(block)))
                continue
        yield block


class ProgramMover:
    """The map, the modal state the blocks leave, and the program position (work coordinates, mm)."""

    def __init__(self, ctx: Context, fmap: Affine) -> None:
        self.map = fmap
        self.modal = ModalState()
        machine = ctx.setup.machine
        start = {"X": machine.start_x, "Y": machine.start_y, "Z": machine.start_z}
        self.p: dict[str, float | None] = {a: float(start[a]) * machine.mm() for a in XYZ}
        self.linear = fmap.m != Affine().m
        self.cycle_words = ctx.cycle_words
        self.lathe = ctx.lathe
        self.increments = ctx.increments
        """A lathe's incremental addresses (U -> X, W -> Z)."""
        self.diameter = ctx.diameter
        self.touched = frozenset(a for a in XYZ if not untouched(fmap, INDEX[a]))
        self.held: set[str] = set(self.touched)
        """Axes the map changes whose position is a machine position (the start, a reference return) until
        programmed absolutely (the module docstring); their program position is not known."""
        for axis in self.held:
            self.p[axis] = None
        if self.lathe:
            self.modal.plane = "ZX"

    @property
    def scale(self) -> float:
        return MM_PER_INCH if self.modal.units == "inch" else 1.0

    def block(self, block: Block) -> None:
        s = block.sections
        for key, section in s.items():
            if key in COMPUTES:
                raise ProgramError(SYMBOLIC.format(what=WHAT))
            if isinstance(section, FrameChange):
                raise ProgramError(f"{section.describe()}: a coordinate frame kept for the program's own dialect "
                                   f"cannot be {WHAT} (a translation to another dialect evaluates it)")
            if isinstance(section, LatheCycle):
                raise ProgramError(f"a lathe cycle kept for the target ({section.kind.replace('_', ' ')}) cannot be "
                                   f"{WHAT}: its words are not carried (a target that lacks the cycle gets its moves)")
            if isinstance(section, CoordinateSet):
                raise ProgramError(f"a coordinate setting (the tool's point given new coordinates) cannot be "
                                   f"{WHAT}: it declares where the tool stands, which the transform does not move")
            if self.lathe and key in _LATHE_INERT:
                continue
            if key not in INERT and key not in _OWN and key not in _HANDLED:
                raise ProgramError(f"{named(key, section)} cannot be {WHAT} (it is not carried through a program "
                                   "transform)")
        work = self.modal.work_offset
        self.modal.apply(s)
        changed = False
        setting = s.get("DataSetting")
        if isinstance(setting, DataSetting) and setting.table == "work_offset" and "R" in setting.values:
            raise ProgramError(f"{setting.describe()}: a work system rotation kept for the target cannot be "
                               f"{WHAT} (the target would turn the transformed program again)")
        if self.modal.work_offset != work or isinstance(setting, DataSetting) and (
                setting.table != "work_offset" or setting.index in (0, work)) and setting.table.startswith("work"):
            self.p = dict.fromkeys(XYZ)  # the tool stays; where it stands in the new system is not known here
        cc = s.get("CutterCompensation")
        if isinstance(cc, CutterCompensation) and cc.mode in _SWAPPED and mirrors_xy(self.map):
            s["CutterCompensation"] = CutterCompensation(_SWAPPED[cc.mode], cc.register)
            changed = True
        cycle = s.get("CannedCycle")
        m = s.get("Motion")
        if isinstance(m, Motion) and m.mode is not None:
            s["Motion"] = self.move(m, self.modal.distance == "incremental", "MachineCoordinates" in s)
            changed = True
        if isinstance(cycle, CannedCycle):
            if isinstance(m, Motion) and m.mode is None and m.axes:
                raise ProgramError(f"a cycle repeat's own axis words cannot be {WHAT} here")
            s["CannedCycle"] = self.cycle(cycle)
            changed = True
        compound = s.get("CompoundMotion")
        if isinstance(compound, CompoundMotion):
            items = [self.item(item) for item in compound.items]  # (they track the position a cycle leaves)
            if native(s):
                del s["CompoundMotion"]
            else:
                s["CompoundMotion"] = CompoundMotion(compound.term, items)
            changed = True
        tap = s.get("RigidTap")
        if isinstance(tap, RigidTap):
            s["RigidTap"] = self.tap(tap, self.modal.distance == "incremental")
            changed = True
        if changed:
            block.changed()

    # -- moves ---------------------------------------------------------------------------------------
    def item(self, item: Section) -> Section:
        if isinstance(item, Motion) and item.mode is not None:
            return self.move(item, False, False)
        if isinstance(item, RigidTap):
            return self.tap(item, False)
        if type(item).__name__ not in INERT and type(item).__name__ not in _OWN:
            raise ProgramError(f"{type(item).__name__} in the expanded motion cannot be {WHAT}")
        return item

    def move(self, m: Motion, incremental: bool, machine: bool, via: bool = False) -> Motion:
        if m.mode not in _MOVES or machine:
            return self.fixed(m)
        fmap, scale, p = self.map, self.scale, self.p
        start = dict(p)
        given: dict[str, float] = {}
        stepped: dict[str, float] = {}
        """A lathe's increments (U, W) by the axis they move, mm."""
        for axis, value in m.axes.items():
            if isinstance(value, Expr):
                raise ProgramError(COMPUTED.format(what=WHAT))
            if axis in self.increments:
                stepped[self.increments[axis]] = value * scale
                continue
            if axis not in INDEX and self.linear:
                raise ProgramError(f"the {axis} axis under a transform that rotates, mirrors or scales cannot be "
                                   f"{WHAT} (only X, Y and Z are)")
            given[axis] = value * scale if axis in XYZ else value
        self._from_held(given, stepped, incremental, via)
        if m.mode in ("cw", "ccw"):
            for axis in PLANE_AXES[self.modal.plane][:2]:
                if axis in self.held and not (axis in given and not incremental):
                    raise ProgramError(f"an arc from a machine position on {axis} (the start or a reference return), "
                                       f"which the transform does not move: program {axis} absolutely before it")
        for axis, step in stepped.items():
            here = p[axis]
            p[axis] = None if here is None else here + step
        out: dict[str, float | Expr] = {}
        if incremental:
            dw = fmap.linear([given.get(a, 0.0) for a in XYZ])
            for i, axis in enumerate(XYZ):
                if axis in given or abs(dw[i]) > EXACT:
                    out[axis] = dw[i] / scale
                here = p[axis]
                p[axis] = None if here is None else here + given.get(axis, 0.0)
        else:
            point = [given.get(a, p[a]) for a in XYZ]
            columns = [INDEX[a] for a in given if a in INDEX]
            for i, axis in enumerate(XYZ):
                if not any(fmap.mixes(i, j) for j in columns):
                    continue
                for j in range(3):
                    if fmap.mixes(i, j) and point[j] is None:
                        raise ProgramError(f"this move's {axis} under the transform needs the program's {XYZ[j]}, "
                                           f"which is not known here: program {XYZ[j]} absolutely")
                out[axis] = fmap.point([v if v is not None else 0.0 for v in point])[i] / scale
            for axis in XYZ:
                if axis in given:
                    p[axis] = given[axis]
            if not via:
                self.held.difference_update(given)
        for axis, value in m.axes.items():
            if axis not in INDEX:
                out[axis] = value  # (a lathe's U and W: the map is a shift along Z, which an increment keeps)
        if m.mode in ("cw", "ccw"):
            return self.arc(_centred(m, start, p, self.modal.plane, scale, self.diameter), out)
        return Motion(m.mode, out)

    def _from_held(self, given: dict[str, float], stepped: dict[str, float], incremental: bool, via: bool) -> None:
        """A move from a machine position (``held``): an increment on a held axis, or one the map turns into it,
        is no point of the moved program. A reference return's intermediate point (``via``) names a held axis
        absolutely or with an increment of 0 (it stays where the tool is)."""
        if not self.held:
            return
        for axis in sorted(self.held):
            if via:
                if axis in stepped or axis in given and incremental:
                    if stepped.get(axis, given.get(axis)) != 0.0:
                        raise ProgramError(f"this reference return's intermediate point is an increment from a machine "
                                           f"position on {axis} (the start or a reference return), which the transform "
                                           f"does not move: program {axis} absolutely before it, or name it with 0")
                continue
            i = INDEX[axis]
            if axis in stepped or incremental and any(self.map.mixes(i, INDEX[a]) for a in given if a in INDEX):
                raise ProgramError(f"this move starts from a machine position on {axis} (the start or a reference "
                                   f"return), which the transform does not move: program {axis} absolutely before "
                                   f"an increment")

    def tap(self, tap: RigidTap, incremental: bool) -> RigidTap:
        """A rigid tap's end point carried like a move's; the tool comes back to where it stood, so the
        position stays. Only under a map that moves the part rigidly about Z (a translation, a rotation
        about Z, a mirror of X or Y: nothing scaled, Z neither turned over nor mixed with X or Y): the tap
        then runs the same length in the same sense, and its pitch (the tap's thread) is the same."""
        found = self.map.arc_factor(PLANE_AXES["XY"])
        if not _untouched_direction(self.map, INDEX["Z"]) or found is None or abs(found[0] - 1.0) > 1e-12:
            raise ProgramError(f"a rigid tap cannot be {WHAT} by a map that scales, or turns over or tilts Z (the "
                               "tap's pitch and direction are the tool's)")
        here, held = dict(self.p), set(self.held)
        carried = self.move(Motion("linear", tap.axes), incremental, False)
        self.p, self.held = here, held
        return RigidTap(carried.axes, tap.pitch, tap.dwell, tap.speedup)

    def arc(self, m: Motion, out: dict[str, float | Expr]) -> Motion:
        arc = carried_arc(self.map, self.modal.plane, m, out, str(m.mode))
        if arc is None:
            raise ProgramError(f"an arc in the {self.modal.plane} plane cannot be {WHAT} by this map: unequal "
                               "scaling, or a rotation out of its plane, makes it no arc")
        if any(isinstance(value, Expr) for value in (m.center or {}).values()) or isinstance(m.radius, Expr):
            raise ProgramError(COMPUTED.format(what=WHAT))
        return arc

    def fixed(self, m: Motion) -> Motion:
        """A reference return or a machine-coordinate move: it goes where the machine is, not where the
        program is, so it stays as written. A reference return's intermediate point is carried (a point of
        the program: ``reference_return``); a machine-coordinate move is allowed only on axes the map leaves
        alone."""
        if m.mode in ("home", "home2"):
            return self.reference_return(m)
        for axis in m.axes:
            axis = self.increments.get(axis, axis)
            if axis in INDEX and not untouched(self.map, INDEX[axis]):
                raise ProgramError(f"a move to machine coordinates or a reference point on {axis} cannot be {WHAT}: "
                                   f"the transform changes {axis}")
            self.p[axis] = None
        return m

    def reference_return(self, m: Motion) -> Motion:
        """The intermediate point carried like a move, on the axes the return names only (a map that moves
        it on another axis would send that one home too: refused); the returned axes the map changes are
        held at the reference point."""
        incremental = self.modal.distance == "incremental"
        via = self.move(Motion("rapid", dict(m.axes)), incremental, False, True)
        named = {self.increments.get(a, a) for a in m.axes}
        for axis in via.axes:
            if self.increments.get(axis, axis) not in named:
                raise ProgramError(f"this reference return's intermediate point moves {axis} under the transform, "
                                   f"which it does not return: it cannot be {WHAT}")
        for axis in named:
            self.p[axis] = None
            if axis in self.touched:
                self.held.add(axis)
        return Motion(m.mode, dict(via.axes), m.center, m.radius)

    # -- hole cycles -----------------------------------------------------------------------------------
    def cycle(self, cycle: CannedCycle) -> CannedCycle:
        if self.cycle_words is None:
            raise ProgramError(f"a hole cycle cannot be {WHAT} here (its reading dialect names no cycle words)")
        first, second, normal = PLANE_AXES[cycle.plane]
        i1, i2, n = INDEX[first], INDEX[second], INDEX[normal]
        fmap, scale = self.map, self.scale
        if any(fmap.mixes(n, j) or fmap.mixes(j, n) for j in (i1, i2)) or fmap.m[4 * n] <= 0.0:
            raise ProgramError(f"a hole cycle in the {cycle.plane} plane cannot be {WHAT} by a map that tilts or "
                               f"turns over its drilling axis {normal} (a rotation out of its plane, a mirror in "
                               f"{normal})")
        if normal in self.held:
            raise ProgramError(f"a hole cycle from a machine position on {normal} (the start or a reference return), "
                               f"which the transform does not move: its initial level would be that position: "
                               f"program {normal} absolutely before it")
        roles = cycle_roles(cycle, self.cycle_words)
        if cycle.kind in PECK and fmap.m[4 * n] != 1.0:
            raise ProgramError(f"a peck drilling cycle cannot be {WHAT} by a map that scales its drilling axis "
                               f"{normal}: its retract and clearance are machine settings that do not scale")
        incremental = self.modal.distance == "incremental"
        sz, tz = fmap.m[4 * n], fmap.t[n]
        new = copy.copy(cycle)
        words: dict[str, float | int] = dict(cycle.words)
        if "shift" in roles.values() and any(fmap.m[3 * a + b] != (1.0 if a == b else 0.0)
                                             for a in (i1, i2) for b in (i1, i2)):
            raise ProgramError(f"a shifting cycle ({cycle.kind.replace('_', ' ')}) cannot be {WHAT} by a map that "
                               "rotates, mirrors or scales its plane (its shift direction is the machine's)")
        hole = {a: words[a] for a in (first, second) if a in words}
        if hole:
            carried = self.move(Motion("linear", dict(hole)), incremental, False)
            for axis in (first, second):
                words.pop(axis, None)
            for axis in XYZ:
                if axis in carried.axes:
                    words[axis] = carried.axes[axis]  # type: ignore[assignment]
        for letter, role in roles.items():
            value = cycle.words[letter]
            if role in ("level", "bottom"):
                words[letter] = value * sz if incremental else (value * scale * sz + tz) / scale
            elif role == "peck":
                words[letter] = value * sz
        new.words = {k: words[k] for k in _ordered(words)}
        self.p[normal] = None  # where the cycle leaves the drilling axis depends on its return level
        if incremental and cycle.repeat != 1:
            self.p[first] = self.p[second] = None
        new.position = self._points(cycle.position)
        new.start = self._points(cycle.start)
        new.step = {k: v for k, v in zip(XYZ, fmap.linear([cycle.step.get(a, 0.0) for a in XYZ]))
                    if k in cycle.step or abs(v) > EXACT}
        for level in ("initial", "r", "bottom", "top"):
            value = getattr(cycle, level)
            if value is not None:
                setattr(new, level, (value * scale * sz + tz) / scale)
        if cycle.q is not None and cycle.kind not in ("fine_bore", "back_bore"):
            new.q = cycle.q * sz
        return new

    def _points(self, values: dict[str, float]) -> dict[str, float]:
        """A record's absolute point (program units): its carried image on the axes it has."""
        if not values:
            return values
        scale = self.scale
        point = self.map.point([values.get(a, 0.0) * scale for a in XYZ])
        return {a: (point[INDEX[a]] / scale if a in INDEX else v) for a, v in values.items()}


_HANDLED: Final = frozenset(("Motion", "CompoundMotion", "CannedCycle", "CutterCompensation", "MachineCoordinates",
                             "DataSetting", "RigidTap"))


NEAR_HALF: Final = 0.999
"""An R-form arc whose chord is more than this part of its diameter is written with its centre: moved end
points rounded to the output's places would move the centre of a half circle by the square root of that
rounding (a 1e-6 mm change of the chord moves it about 3e-3 mm on R20)."""


def _centred(m: Motion, start: dict[str, float | None], end: dict[str, float | None], plane: str,
             scale: float, diameter: bool = False) -> Motion:
    """``m`` with its centre offsets in place of a radius close to half its chord (``NEAR_HALF``), where
    both of its end points are known (mm, program coordinates; ``diameter``: X is a lathe's diameter, its
    centre offset a radius)."""
    a1, a2, _ = PLANE_AXES[plane]
    s1, s2, e1, e2 = start.get(a1), start.get(a2), end.get(a1), end.get(a2)
    if diameter:
        s1, s2, e1, e2 = (None if v is None else v / 2.0 if a == "X" else v
                          for a, v in ((a1, s1), (a2, s2), (a1, e1), (a2, e2)))
    if m.radius is None or isinstance(m.radius, Expr) or None in (s1, s2, e1, e2) or m.radius == 0.0:
        return m
    assert s1 is not None and s2 is not None and e1 is not None and e2 is not None
    radius = m.radius * scale
    if math.hypot(e1 - s1, e2 - s2) / 2.0 < NEAR_HALF * abs(radius):
        return m
    c1, c2 = centre_from_radius((s1, s2), (e1, e2), radius, m.mode == "cw")
    return Motion(m.mode, m.axes, {a1: (c1 - s1) / scale, a2: (c2 - s2) / scale})


def native(s: dict[str, Section]) -> bool:
    """A hole cycle the target runs itself: a changed block must not write its expansion too (a target of
    the reading dialect gets both sections, and a block copied unchanged writes neither)."""
    cycle = s.get("CannedCycle")
    return isinstance(cycle, CannedCycle) and not cycle.expand and "CompoundMotion" in s


def _ordered(words: dict[str, float | int]) -> list[str]:
    from ..cycles.section import WORD_ORDER
    order = {c: i for i, c in enumerate(WORD_ORDER)}
    return sorted(words, key=lambda k: order.get(k, 99))


def mirrors_xy(fmap: Affine) -> bool:
    """The map turns the XY plane over (cutter compensation changes sides; ``verify`` pairs them so)."""
    m = fmap.m
    return m[0] * m[4] - m[1] * m[3] < 0.0


def _untouched_direction(fmap: Affine, i: int) -> bool:
    """The map keeps axis ``i``'s direction and scale and mixes it into no other (a shift along it is
    allowed)."""
    return fmap.m[4 * i] == 1.0 and not any(fmap.mixes(i, j) or fmap.mixes(j, i) for j in range(3) if j != i)


def untouched(fmap: Affine, i: int) -> bool:
    """The map leaves coordinate ``i`` alone and mixes it into no other."""
    return fmap.t[i] == 0.0 and fmap.m[4 * i] == 1.0 and not any(
        fmap.mixes(i, j) or fmap.mixes(j, i) for j in range(3) if j != i)


def lathe_refusal(transform: ProgramTransform) -> str | None:
    """Why ``transform`` cannot move a lathe program, or None for a shift along Z (the spindle's axis), the
    one map that keeps an XZ lathe program valid: X is a diameter or radius about the spindle's centre line,
    so a shift or scale of X, a rotation, or a mirror of X moves the tool off it or past it; a mirror of Z
    turns the cut end for end, which the tools (handed, their nose's tip direction in the tool data) and the
    chucked stock do not follow; a scale changes what thread leads and tool noses do not."""
    m, t = transform.map.m, transform.map.t
    said = f"--transform {transform.text!r} on a lathe program"
    if any(abs(m[3 * i + j]) > EXACT for i in range(3) for j in range(3) if i != j):
        return f"{said}: it rotates the program, which turns it off the spindle's axis (only 'translate 0,0,DZ' " \
               "keeps a lathe program valid)"
    if m[0] < 0.0 and m[8] < 0.0:
        return f"{said}: it turns X and Z over (a half turn in the ZX plane), which puts the tool past the spindle's " \
               "centre line and turns the cut end for end (only 'translate 0,0,DZ' keeps a lathe program valid)"
    if m[0] < 0.0:
        return f"{said}: it mirrors X, which puts the tool past the spindle's centre line (only 'translate 0,0,DZ' " \
               "keeps a lathe program valid)"
    if m[8] < 0.0:
        return f"{said}: it mirrors Z, which turns the cut end for end: the tools are handed and their nose's tip " \
               "direction is tool data, the stock stays in the chuck (only 'translate 0,0,DZ' keeps a lathe " \
               "program valid)"
    if any(abs(m[4 * i] - 1.0) > EXACT for i in range(3)):
        return f"{said}: it scales the program, which thread leads, tool nose radii and cycle depths do not follow " \
               "(only 'translate 0,0,DZ' keeps a lathe program valid)"
    if t[0] != 0.0 or t[1] != 0.0:
        axis = "X" if t[0] != 0.0 else "Y"
        return f"{said}: it shifts {axis}, which moves the part off the spindle's centre line (X0) (only " \
               "'translate 0,0,DZ' keeps a lathe program valid)"
    return None
