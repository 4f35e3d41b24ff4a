"""convert_units: a whole program rewritten in millimetres or inches, the same path cut.

Every length is multiplied by the factor from the units it is programmed in (the program's own ``Units``
as it goes; millimetres before any, as the simulation reads it) to the target's: coordinates absolute
and incremental (a lathe's X diameter too), arc centre offsets and radii, feeds per minute and per revolution
(an inverse-time feed is a time and stays), a surface speed under G96 (metres to feet per minute), a lathe's
coordinate setting and thread lead, hole cycle words by their role (the hole position, the R level, the bottom, a peck
depth or a shift; a dwell and a repeat count stay) with the cycle's resolved levels, tool data and work
offsets a ``G10`` writes (a work system rotation is an angle and stays), a dynamic tool length, blending
tolerances, the lengths of a frame command kept as written, a rigid tap's end point and pitch. Each
``Units`` becomes the target's, and a program that names none gets one before its first block that does
anything (the target's own spelling, from its writer).

A computed word is refused at its line: its variables may hold a position or an offset read from the
machine in the old units, which nothing here can decide. In a translation that can flatten, the dry run
(``postproc.api``) takes that error as the reason to flatten the program instead, so a macro program
arrives as numbers; where flattening is impossible the error stands.
"""

from __future__ import annotations

import copy
from typing import Final, Iterator

from ..context import Context
from ..cycles.section import CannedCycle
from ..errors import PostprocError, ProgramError
from ..ir.expr import Expr
from ..frames.frame import PLANE_AXES
from ..frames.section import FrameChange
from ..ir.lathe_sections import CoordinateSet, InProfile, LatheCycle, SpindleMode, ThreadLead, XProgramming
from ..ir import (Block, CompoundMotion, DataSetting, Feed, Motion, NativeCode, PathControl, Section, SpindleSpeed,
                  ToolLengthOffset, Units)
from ..ir.state import MM_PER_INCH
from ..lowering.synchronised_tap import RigidTap
from .carry import native
from .words import COMPUTED, COMPUTES, INERT, SYMBOLIC, cycle_roles, named, respell

WHAT: Final = "converted to other units"
LINEAR: Final = frozenset("XYZUVW")
_LENGTH_ROLES: Final = frozenset(("first", "second", "level", "bottom", "peck", "shift"))
SURFACE_SPEED: Final = {"inch": 1.0 / 0.3048, "mm": 0.3048}
"""A surface speed (G96 S) into the target's units: metres per minute under mm, feet per minute under inch
[V: LinuxCNC G-code reference, G96; K: Fanuc 0i-TF operator's manual, constant surface speed control]."""
_TOOL_TABLES: Final = frozenset(("tool_length", "tool_length_wear", "cutter_offset", "cutter_offset_wear"))
_OPENING: Final = frozenset(("TapeMark", "ProgramStart", "Comments", "Sequence", "BlockDelete"))
"""Sections of the blocks a program opens with before it does anything (the unit code goes after them)."""


def convert_units(blocks: Iterator[Block], ctx: Context, target: str) -> Iterator[Block]:
    """The lowering step (see the module docstring); each error is reported at its block."""
    converter = UnitConverter(ctx, target)
    report = ctx.diagnostics.error
    opened = False
    for block in blocks:
        s = block.sections
        if not opened and not _OPENING.issuperset(s):
            opened = True
            if "Units" not in s:
                first = Block(block.line, None)
                first.add(Units(target))
                yield first
        if s:
            try:
                converter.block(block)
            except PostprocError as err:
                report(err.located(ctx.at(block)))
                continue
        yield block


class UnitConverter:
    """The units the program is in where it stands, and the rewriting of each block into ``target``."""

    def __init__(self, ctx: Context, target: str) -> None:
        if target not in ("mm", "inch"):
            raise ValueError(f"units are 'mm' or 'inch', not {target!r}")
        self.target = target
        self.source = "mm"
        self.per_time = True
        """The feed is a speed (per minute or per revolution), not inverse time."""
        self.cycle_words = ctx.cycle_words
        self.plane = "XY"
        self.angle: str | None = None
        """Polar coordinates (G16) are on: this axis word is an angle in degrees, not a length."""
        self.css = False
        """Constant surface speed (G96) is on: S is metres or feet per minute, converted with the lengths."""

    def block(self, block: Block) -> None:
        s = block.sections
        units = s.get("Units")
        changed = False
        if isinstance(units, Units):
            self.source = units.system
            if units.system != self.target:
                s["Units"] = Units(self.target)
                changed = True
        plane = s.get("Plane")
        if plane is not None:
            self.plane = getattr(plane, "plane", "XY")
        frame = s.get("FrameChange")
        if isinstance(frame, FrameChange) and frame.kind in ("polar", "polar_off"):
            # [V] Fanuc 16/18-MC operator's manual 9.2: under G16 the plane's second axis word is an angle
            self.angle = PLANE_AXES[self.plane][1] if frame.kind == "polar" else None
        mode = s.get("FeedMode")
        if mode is not None:
            self.per_time = getattr(mode, "mode", "") != "inverse_time"
        spindle = s.get("SpindleMode")
        if isinstance(spindle, SpindleMode):
            self.css = spindle.mode == "css"
        k = 1.0 if self.source == self.target else MM_PER_INCH if self.target == "mm" else 1.0 / MM_PER_INCH
        speed = s.get("SpindleSpeed")
        if self.css and k != 1.0 and isinstance(speed, SpindleSpeed):
            s["SpindleSpeed"] = SpindleSpeed(_times(speed.rpm, SURFACE_SPEED[self.target]))
            changed = True
        for key, section in list(s.items()):
            if key in COMPUTES and k != 1.0:  # (in the target's units already, a computed word stays right)
                raise ProgramError(SYMBOLIC.format(what=WHAT))
            if key in INERT or key in ("Units", "CutterCompensation", "MachineCoordinates"):
                continue
            converted = self.section(section, k)
            if converted is not section:
                s[key] = converted
                changed = True
        if changed:
            if native(s):
                del s["CompoundMotion"]  # a changed cycle block would write its expansion too
            block.changed()

    def section(self, section: Section, k: float) -> Section:
        """``section`` with its lengths times ``k`` (the same object when it has none to change)."""
        if isinstance(section, NativeCode):
            if section.inert:
                return section
            raise ProgramError(f"{section.what} is kept as written and cannot be {WHAT}")
        if isinstance(section, LatheCycle):
            raise ProgramError(f"a lathe cycle kept for the target ({section.kind.replace('_', ' ')}) cannot be {WHAT}: "
                               "its parameters are not converted (a target that lacks the cycle gets its moves)")
        if isinstance(section, (SpindleMode, InProfile, XProgramming)):
            return section
        if k == 1.0:
            return section
        if isinstance(section, CoordinateSet):
            return CoordinateSet(_lengths(section.axes, k, None))
        if isinstance(section, ThreadLead):
            return ThreadLead(section.lead * k)
        if isinstance(section, Motion):
            return Motion(section.mode, _lengths(section.axes, k, self.angle), None if section.center is None else
                          _lengths(section.center, k), None if section.radius is None else _times(section.radius, k))
        if isinstance(section, Feed):
            return Feed(_times(section.value, k)) if self.per_time else section
        if isinstance(section, CannedCycle):
            return self.cycle(section, k)
        if isinstance(section, CompoundMotion):
            return CompoundMotion(section.term, [self.section(item, k) for item in section.items])
        if isinstance(section, DataSetting):
            return _setting(section, k)
        if isinstance(section, ToolLengthOffset):
            return section if section.length is None else ToolLengthOffset(
                section.mode, section.register, _times(section.length, k))
        if isinstance(section, PathControl):
            return PathControl(section.mode, section.one_shot, _maybe(section.tolerance, k), _maybe(section.naive, k))
        if isinstance(section, FrameChange):
            # (a length of 0 stays 0: ISG's #ROTATION centred at the origin has no X/Y/Z words to respell)
            changed = {a: _times(v, k) for a, v in section.words.items() if a in LINEAR
                       and not (isinstance(v, float) and v == 0.0)}
            words = {**section.words, **changed}
            return FrameChange(section.kind, words, section.rules, section.family, respell(section.text, changed),
                               section.omitted, section.increment_setting)
        if isinstance(section, RigidTap):
            return RigidTap(_lengths(section.axes, k), _times(section.pitch, k), section.dwell, section.speedup)
        if type(section).__name__ in INERT:
            return section
        raise ProgramError(f"{named(section.KEY or type(section).__name__, section)} cannot be {WHAT} (its lengths "
                           "are not known here)")

    def cycle(self, cycle: CannedCycle, k: float) -> CannedCycle:
        if self.cycle_words is None:
            raise ProgramError(f"a hole cycle cannot be {WHAT} here (its reading dialect names no cycle words)")
        roles = cycle_roles(cycle, self.cycle_words)
        new = copy.copy(cycle)
        new.words = {letter: value * k if roles[letter] in _LENGTH_ROLES and letter != self.angle else value
                     for letter, value in cycle.words.items()}
        for name in ("initial", "r", "bottom", "top", "q", "clearance", "pitch"):
            setattr(new, name, _maybe(getattr(cycle, name), k))
        if self.per_time:
            new.feed = _maybe(cycle.feed, k)
        for name in ("start", "position", "step"):
            setattr(new, name, {a: v * k if a in LINEAR else v for a, v in getattr(cycle, name).items()})
        if cycle.shift is not None:
            new.shift = {a: v * k for a, v in cycle.shift.items()}
        return new


def _setting(setting: DataSetting, k: float) -> DataSetting:
    """A G10's values: lengths on a work system's linear axes, every value of a tool table."""
    if setting.table.startswith("work_offset"):
        lengths = {a for a in setting.values if a in LINEAR}
    elif setting.table in _TOOL_TABLES:
        lengths = set(setting.values)
    else:
        raise ProgramError(f"{setting.describe()}: what its values measure is not known here; it cannot be {WHAT}")
    changed = {a: _times(v, k) for a, v in setting.values.items() if a in lengths}
    values = {**setting.values, **changed}
    text = respell(setting.text, changed)
    return DataSetting(setting.family, setting.table, setting.index, values, setting.incremental, text)


def _times(value: float | Expr, k: float) -> float:
    if isinstance(value, Expr):
        raise ProgramError(COMPUTED.format(what=WHAT))
    return value * k


def _maybe(value: float | None, k: float) -> float | None:
    return None if value is None else value * k


def _lengths(values: dict[str, float | Expr], k: float, angle: str | None = None) -> dict[str, float | Expr]:
    return {a: _times(v, k) if a in LINEAR and a != angle else v for a, v in values.items()}
