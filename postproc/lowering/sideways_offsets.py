"""A tool's offsets across the spindle (the X and Y of a LinuxCNC tool table entry a program writes, ``G10 L1
P- X- Y-``), written into the path for a target whose tool length offset moves the spindle axis only.

[V] LinuxCNC (``postproc_linuxcnc.tool_entry``; rs274 prints ``USE_TOOL_LENGTH_OFFSET(x y z, ...)``): on a mill
``G43`` applies the entry's X and Y as it applies Z, and like Z they move nothing where they change: an
axis keeps its machine position until it is programmed, then goes to the programmed point plus the offset
in force. A target without such offsets (Fanuc, grbl, ISG...) moves the same where each absolute X and Y
in the program's coordinates gets the offset in force added, and nothing else changes: an increment moves
the machine by itself on both sides, an axis not programmed stays on both, a move in machine coordinates
is not offset on either. So this step, for an entry of another family than the target's:

* takes the entry's X and Y out of its setting (the length and radius go on to ``write_tool_entries``) and
  keeps them, in mm, by tool number (absolute, as every ``G10 L1`` value);
* follows which entry a length offset puts in force (``G43 H n``, the register a tool number) and which
  none (``G49``, ``G43`` of an entry without them, ``G44``, a dynamic length);
* adds the offset in force, in the block's units, to each absolute X and Y of a move, of a reference
  return's intermediate point and of the items of an expanded cycle.

While an offset is in force, what writes a program coordinate this step does not rewrite is a located
error naming it: a computed coordinate, a cycle kept for the target, a frame command, a coordinate setting,
a program kept symbolic (its text is not the order it runs in). A program's own ``G92``/``G52`` reach this step
already evaluated into the coordinates (``postproc.frames``) where the target lacks them. Nothing is dropped: an entry's X or Y is
either in the path or refused.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Final

from ..compensation.tool_table import ENTRY, SIDEWAYS
from ..context import Context
from ..interp.control import ASSIGN, CONTROL
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir.expr import Expr
from ..ir import Block, Comments, CompoundMotion, DataSetting, Motion, Section
from .synchronised_tap import RigidTap
from .lower import BlockStep, LoweringStep
from .units_and_distance import MM_PER_INCH, UnitsAndDistance

_UNREWRITTEN: Final = {"CannedCycle": "a canned cycle kept for the target", "FrameChange": "a frame command",
                       "CoordinateSet": "a coordinate setting", "HolePattern": "a hole pattern",
                       "LatheCycle": "a turning cycle", ASSIGN: "a program kept symbolic",
                       CONTROL: "a program kept symbolic"}
"""Sections that state program coordinates this step does not rewrite -> what they are, for the error."""


@mypyc_attr(allow_interpreted_subclasses=True)
class WriteSidewaysOffsets(LoweringStep):
    """Lowering step (the module docstring)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _Sideways(ctx, target)


write_sideways_offsets = WriteSidewaysOffsets()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Sideways(BlockStep):
    """One run: until an entry with offsets across the spindle, only a block with a ``DataSetting`` is its
    business; from then on every block."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.target = target
        self.family = target.family()
        self.entries: dict[int, dict[str, float]] = {}
        self.shift: dict[str, float] = {}
        """The offsets in force, mm (empty: none)."""
        self.modes = UnitsAndDistance()
        """Followed at every block it takes, entries or not: a G20 or G91 before the first entry is in force there."""

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        entries = self.entries
        modes = self.modes
        modes.follow(sections)
        if not entries and "DataSetting" not in sections:
            return None  # the common block: no entry with offsets across the spindle yet
        setting = sections.get("DataSetting")
        if isinstance(setting, DataSetting) and setting.table == ENTRY and setting.family != self.family \
                and self.target.WRITER is not None:
            _take(block, setting, entries, modes.scale)
            self.moves = bool(entries)
        length = sections.get("ToolLengthOffset")
        if length is not None:
            register = length.register  # type: ignore[attr-defined]
            positive = length.mode == "positive" and isinstance(register, int)  # type: ignore[attr-defined]
            self.shift = {a: v for a, v in entries.get(register, {}).items() if v} if positive else {}
        shift = self.shift
        if shift:
            try:
                _offset(block, shift, 1.0 / MM_PER_INCH if modes.inch else 1.0, modes.absolute)
            except UnsupportedError as err:
                ctx = self.ctx
                ctx.diagnostics.error(err.located(ctx.at(block)))
                return []
        return None


def _take(block: Block, setting: DataSetting, entries: dict[int, dict[str, float]], scale: float) -> None:
    """Keep the entry's X and Y (mm) and leave the rest of the setting (none left: no setting)."""
    across = {axis: value for axis, value in setting.values.items() if axis in SIDEWAYS}
    if not across:
        return
    for axis, value in across.items():
        if isinstance(value, Expr):
            raise UnsupportedError(f"a computed tool offset along {axis} ({setting.describe()}): its value is "
                                   "written into the path, which needs the number")
        entries.setdefault(setting.index, {})[axis] = float(value) * scale
    rest = {k: v for k, v in setting.values.items() if k not in SIDEWAYS}
    if rest:
        block.sections["DataSetting"] = DataSetting(setting.family, setting.table, setting.index, rest,
                                                    setting.incremental, setting.text)
    else:
        del block.sections["DataSetting"]
        comments = block.sections.get("Comments")
        note = f"TOOL {setting.index} OFFSETS ACROSS THE SPINDLE: WRITTEN INTO THE PATH"
        block.sections["Comments"] = Comments(([*comments.texts] if isinstance(comments, Comments) else []) + [note])
    block.changed()


def _offset(block: Block, shift: dict[str, float], per_mm: float, absolute: bool) -> None:
    """Add the offsets in force (mm; ``per_mm`` program units per mm) to the block's absolute X and Y."""
    sections = block.sections
    for key, what in _UNREWRITTEN.items():
        if key in sections:
            raise UnsupportedError(f"{what} while a tool offset across the spindle is in force (written into the "
                                   "path here): its coordinates are not offset")
    if sections.get("MachineCoordinates") is not None:
        return  # a move in machine coordinates: no offset on either side
    changed = False
    motion = sections.get("Motion")
    if isinstance(motion, Motion) and absolute:
        changed = _moved(motion, shift, per_mm) or changed
    tap = sections.get("RigidTap")
    if isinstance(tap, RigidTap) and absolute:
        changed = _moved(tap, shift, per_mm) or changed
    compound = sections.get("CompoundMotion")
    if isinstance(compound, CompoundMotion):  # an expansion to be written (a cycle kept is refused above)
        for item in compound.items:  # absolute, as every item of an expansion
            if isinstance(item, (Motion, RigidTap)):
                changed = _moved(item, shift, per_mm) or changed
    if changed:
        block.changed()


def _moved(section: Section, shift: dict[str, float], per_mm: float) -> bool:
    """Offset a move's axes (program units), in a new dictionary (``postproc.lowering.move_words`` keys its reads
    on the old one); True when one was there."""
    axes = dict(section.axes)  # type: ignore[attr-defined]
    moved = False
    for axis, value in shift.items():
        if axis not in axes:
            continue
        word = axes[axis]
        if isinstance(word, Expr):
            raise UnsupportedError(f"a computed {axis} while a tool offset across the spindle is in force (written "
                                   "into the path here): the sum is not written")
        axes[axis] = float(word) + value * per_mm
        moved = True
    if moved:
        section.axes = axes  # type: ignore[attr-defined]
    return moved
