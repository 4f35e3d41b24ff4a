"""A tool table entry measured where the tool stands (LinuxCNC ``G10 L10 P- X- Y- Z- R-``) worked out for a target
of another family: the entry it sets, as a whole entry written with its values (``G10 L1``'s neutral
``tool_entry``), which ``write_sideways_offsets`` and ``write_tool_entries`` then write in the target's
spelling or into the path.

[V] LinuxCNC ``interp_convert.cc`` ``convert_setup_tool`` (``postproc.simulate.position.Position.touch_off``, checked
against rs274): for ``L10`` each axis word's offset is the tool's point without its offset in the active
work system, less the word; the work system's origin cancels, so that point is the program's current
point plus the tool offset in force. This step follows both where the translation can know them exactly:

* the current point: the one the frame evaluation follows (``postproc.frames.lowering.FrameRun.p``: the
  points as programmed, None where unknown: after a move in machine coordinates, a cycle, a change of work
  system), which on a controller that moves nothing at an offset change (``LENGTH_AT_PROGRAMMED_AXIS``)
  takes the change, as in the simulation (``FrameEvaluator.tool_change``); unknown after a reference return
  until the axis is programmed absolutely;
* the offset in force: ``G43 H n`` reads entry n (the program's own ``G10 L1`` values, else the set-up's
  ``<Tool length>``), ``G49`` none.

Where either is unknown, or the entry is measured in work system 9 (``L11``, whose origin the translation
does not know), it is a located error naming what is missing: never a guessed or a dropped entry.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import Final

from ..compensation.tool_table import ENTRY, SIDEWAYS, ToolTable
from ..context import Context
from ..dialect import Dialect
from ..errors import PostprocError, UnsupportedError
from ..ir.expr import Expr
from .run_state import FrameRun
from ..ir import Block, DataSetting, Motion, Section
from ..ir.keys import watches_none
from ..lowering.lower import BlockStep, LoweringStep, still_moving
from ..ir.state import MM_PER_INCH

MEASURED: Final = "tool_entry_at_point"
"""``G10 L10``'s neutral table (the active work system)."""
MEASURED_9: Final = "tool_entry_at_point_9"
"""``G10 L11``'s (work system 9)."""
AXES: Final = ("X", "Y", "Z")


@mypyc_attr(allow_interpreted_subclasses=True)
class WriteMeasuredEntries(LoweringStep):
    """Lowering step (the module docstring): a measured entry of another family -> the whole entry it sets."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _Entries(ctx, target)


write_measured_entries = WriteMeasuredEntries()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Entries(BlockStep):
    """One run. A plain move (``lowering.lower.plain_move``: no reference return) is its business only while a
    reference return has taken an axis home (``homed``: the move may bring it back), so ``moves`` is that: a CAM
    program's moves go past unseen (~400 instructions a block compiled), its reference returns come through
    ``take``."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.ctx = ctx
        self.target = target
        self.family = target.family()
        self.run = _Run(ctx)
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        out = self._take(block, watches_none(block.sections, _WATCHED))
        self.moves = bool(self.run.homed)
        return out

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block the loop found only a plain move (while ``homed``): it holds none of ``_WATCHED``,
        and is not asked again; a block given back as it came stays only a move (``still_moving`` for the rest)."""
        out = still_moving(block, self._take(block, True))
        self.moves = bool(self.run.homed)
        return out

    def _take(self, block: Block, quiet: bool) -> list[Block] | None:
        """``take``; ``quiet``: the block holds none of ``_WATCHED`` (``watches_none``)."""
        s = block.sections
        run = self.run
        if not run.homed and quiet:
            m = s.get("Motion")
            if m is None or isinstance(m, Motion) and m.mode not in _HOME:
                return None  # the common block: the frame evaluation follows its point
            if not isinstance(m, Motion) and m.mode not in _HOME:  # type: ignore[attr-defined]
                return None
        setting = s.get("DataSetting")
        if isinstance(setting, DataSetting) and setting.table in (MEASURED, MEASURED_9) \
                and setting.family != self.family and self.target.WRITER is not None:
            try:
                s["DataSetting"] = run.entry(setting)
                block.changed()
            except PostprocError as err:
                run.follow(block)
                ctx = self.ctx
                ctx.diagnostics.error(err.located(ctx.at(block)))
                return []
        run.follow(block)
        return None


_HOME: Final = ("home", "home2")
_WATCHED: Final = frozenset(("ToolLengthOffset", "DataSetting", "Units", "DistanceMode"))
"""Sections ``_Run.follow`` reads in a block that makes no reference return while nothing is pending."""


@mypyc_attr(allow_interpreted_subclasses=True)
class _Run:
    """The offsets in force (mm) and the axes a reference return took home."""

    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx
        self.table = ToolTable(ctx.setup)
        self.keeps_machine_point = ctx.length_at_axis
        self.offset: dict[str, float] | None = {}
        """The tool offsets in force along X, Y, Z (mm); None: not known here."""
        self.homed: set[str] = set()
        """Axes a reference return took home: their point is the machine's until programmed absolutely."""
        self.scale = 1.0
        self.absolute = True

    def entry(self, setting: DataSetting) -> DataSetting:
        """The whole entry a measured one sets (values absolute, program units)."""
        if setting.table == MEASURED_9:
            raise UnsupportedError(f"{setting.describe()}: an entry measured in work system 9 needs that system's "
                                   "origin and the active one's, which only the machine knows here")
        if self.offset is None:
            raise UnsupportedError(f"{setting.describe()}: the tool offset in force is not known here (a computed "
                                   "register, a negative or dynamic offset, or a register the set-up does not give)")
        run = self.ctx.frame_run
        point = run.point() if isinstance(run, FrameRun) else {}
        values: dict[str, float | Expr] = {}
        for letter, value in setting.values.items():
            if isinstance(value, Expr):
                raise UnsupportedError(f"a computed {letter} in {setting.describe()}: the entry is worked out here, "
                                       "which needs the number")
            if letter not in AXES:
                values[letter] = value
                continue
            here = point.get(letter)
            if here is None or letter in self.homed:
                raise UnsupportedError(f"{setting.describe()} where the tool's {letter} is not known here (after a "
                                       "reference return, a move in machine coordinates, a cycle or a change of work "
                                       "offset): program a move to a known point first")
            values[letter] = (here + self.offset.get(letter, 0.0)) / self.scale - float(value)
        return DataSetting(setting.family, ENTRY, setting.index, values, False, setting.text)

    def follow(self, block: Block) -> None:
        """The block's effect on the offsets in force and on the correction of the followed point."""
        s = block.sections
        units = s.get("Units")
        if units is not None:
            self.scale = MM_PER_INCH if units.system == "inch" else 1.0  # type: ignore[attr-defined]
        setting = s.get("DataSetting")
        if isinstance(setting, DataSetting) and setting.table == ENTRY:
            self.table.write(setting, self.scale)
        distance = s.get("DistanceMode")
        if distance is not None:
            self.absolute = distance.mode != "incremental"  # type: ignore[attr-defined]
        m = s.get("Motion")
        if isinstance(m, Motion) and m.mode in _HOME:
            self.homed.update(m.axes or AXES)
        elif isinstance(m, Motion) and m.mode is not None and self.absolute and "MachineCoordinates" not in s:
            for axis in m.axes:
                self.homed.discard(axis)
        length = s.get("ToolLengthOffset")
        if length is not None:
            self._offset(length.mode, length.register)  # type: ignore[attr-defined]

    def _offset(self, mode: str, register: object) -> None:
        new: dict[str, float] | None = {}
        if mode == "positive" and isinstance(register, int):
            try:
                new = {"Z": self.table.length(register), **self.table.sideways(register)}
            except PostprocError:
                new = None
        elif mode != "cancel":
            new = None
        if self.keeps_machine_point and self.offset is None:
            new = None  # the point's move at the change is not known
        self.offset = new
