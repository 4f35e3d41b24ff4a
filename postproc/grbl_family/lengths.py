"""Tool length offsets for a grbl-family controller without a tool table (grbl 1.1; a grblHAL build without
one, ``GrblFamily.tool_table``): a length offset from a register (Fanuc and
LinuxCNC ``G43 H<n>``, ``G44 H<n>``) becomes grbl's dynamic offset ``G43.1 Z<length>`` with the
register's value, taken where the simulation takes it (``postproc.compensation.tool_table``: the
program's own data settings, else the set-up's ``<Tools><Tool length>``); ``G49`` stays.

Facts: [V] grbl wiki "Grbl v1.1 Commands" and ``grbl/gcode.c``: ``G43.1`` takes the offset from the Z
word of its block (an axis command of its own, so no motion may share the block), ``G49`` cancels it;
grbl changes no position at either (the offset applies from the next move on), as the simulation does
(``postproc.compensation.tool_length``). A G44 subtracts the length ([K] Fanuc), so it is written as
``G43.1`` with the negated length.

A set-up whose tools are touched off at their change (``<Machine toolLengths="touched_off">``: a
router's touch-off plate) has no lengths to write: each offset is dropped, with a comment saying so
where it stood; the simulation of such a machine reads every length as zero, so ``verify`` compares
the same path on both sides.

A register the set-up does not give is a located error naming the ``<Tool>`` element to add.

On a lathe (grblHAL's lathe mode) a register's offset has an X as well as a Z (a turret index ``T0101``
written ``T1 M6`` .. ``G43 H1``): ``G43.1 Z`` would drop the X, and a ``G43.1 X`` is halved under G7 [V: grblHAL
``gcode.c`` halves every X word in diameter mode], which is not modelled, so the offset is refused and the
set-up is told to say the build has a tool table.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Final

from postproc.compensation.tool_table import TABLES, ToolTable
from postproc.context import Context
from postproc.dialect import Dialect
from postproc.grbl_family.dialect import GrblFamily
from postproc.errors import PostprocError, UnsupportedError
from postproc.ir import Block, Comments, DataSetting, Section, ToolLengthOffset
from postproc.ir.keys import watches_none
from postproc.lowering.lower import BlockStep, LoweringStep
from postproc.lowering.units_and_distance import UnitsAndDistance

MM_PER_INCH: Final = 25.4
_WATCHED: Final = frozenset(("ToolLengthOffset", "DataSetting", "Units"))


@mypyc_attr(allow_interpreted_subclasses=True)
class WriteToolLengths(LoweringStep):
    """Lowering step: ``G43 H<n>``/``G44 H<n>`` -> ``G43.1 Z<length>`` (see the module docstring)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME or target.TOOL_LENGTH_OFFSET:
            return None
        if issubclass(target, GrblFamily) and target.tool_table(ctx.setup):
            return _Lengths(ctx, ("negative",))  # a table runs G43 H, but the family has no G44
        return _Lengths(ctx, ("positive", "negative"))


write_tool_lengths = WriteToolLengths()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Lengths(BlockStep):
    """One run: only a block with a length offset, a data setting or units is its business."""

    def __init__(self, ctx: Context, modes: tuple[str, ...]) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.modes = modes
        self.table = ToolTable(ctx.setup)
        self.units = UnitsAndDistance()
        """The units in force (the step takes every block with units: ``_WATCHED``; it reads no distance mode)."""

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if watches_none(sections, _WATCHED):
            return None
        units = self.units
        before = units.inch
        units.follow(sections)
        setting = sections.get("DataSetting")
        if isinstance(setting, DataSetting):
            self.table.write(setting, units.scale)
        offset = sections.get("ToolLengthOffset")
        if not isinstance(offset, ToolLengthOffset) or offset.mode not in self.modes:
            return None
        ctx = self.ctx
        at = ctx.at(block, ctx.column_of(block, "H"))  # before the block is rewritten (a rare block)
        try:
            return _dynamic(block, ctx, self.table, offset, units.inch, before)
        except PostprocError as err:
            ctx.diagnostics.error(err.located(at))
            return []


def _dynamic(block: Block, ctx: Context, table: ToolTable, offset: ToolLengthOffset, inch: bool,
             before: bool) -> list[Block]:
    """The block with its offset from a register replaced: by ``G43.1`` in a block of its own before
    it, or (tools touched off) by a comment. ``inch``: the units after the block, ``before``: before it
    (the units a ``G43.1`` written ahead of the block's own G20/G21 is read in)."""
    register = offset.register
    if ctx.lathe:
        raise UnsupportedError(f"a lathe tool's offsets (register {register}: X and Z) on a build without a tool table "
                               "(the dynamic offset would take only Z): a set-up with <Controller toolTable=\"true\"/> "
                               "has one")
    if not isinstance(register, int):
        raise UnsupportedError("a tool length offset whose register is computed (the dynamic offset needs its value)")
    across = table.sideways(register)
    if across:
        raise UnsupportedError(f"a tool offset along {' and '.join(across)} (entry {register} of the tool table): "
                               "the dynamic length offset moves the spindle axis only")
    sections = block.sections
    del sections["ToolLengthOffset"]
    block.changed()
    if table.touched_off:
        note = f"TOOL LENGTH H{register} DROPPED: TOOLS ARE TOUCHED OFF AT THE CHANGE"
        comments = sections.get("Comments")
        sections["Comments"] = Comments(([*comments.texts] if isinstance(comments, Comments) else []) + [note])
        return [block]
    def dynamic(inch: bool) -> ToolLengthOffset:
        length = table.length(register) / (MM_PER_INCH if inch else 1.0)
        return ToolLengthOffset("dynamic", None, length if offset.mode == "positive" else -length)
    if not _rest(sections):
        sections["ToolLengthOffset"] = dynamic(inch)
        return [block]
    first = Block(block.line, None, "\n")
    first.sections = {key: sections.pop(key) for key in ("Sequence",) if key in sections}
    if "BlockDelete" in sections:  # both halves are skipped with the block
        first.sections["BlockDelete"] = sections["BlockDelete"]
    first.sections["ToolLengthOffset"] = dynamic(before)  # run before the block's G20/G21
    return [first, block]


@mypyc_attr(allow_interpreted_subclasses=True)
class DropResolvedToolData(LoweringStep):
    """Lowering step, after ``write_tool_lengths`` and the cutter compensation's resolution: on a controller
    without a tool table every length and radius a program writes into a register has been read where it
    is used (``G43.1 Z<length>``, the compensated path), so the setting itself is left as a comment
    (``postproc.lowering.tool_entries`` makes them from a tool table entry; a Fanuc ``G10 L10``..``L13``).
    With a tool table the writer refuses it (it would be the machine's own register)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME or (issubclass(target, GrblFamily) and target.tool_table(ctx.setup)):
            return None
        return _DropResolved()


drop_resolved_tool_data = DropResolvedToolData()


@mypyc_attr(allow_interpreted_subclasses=True)
class _DropResolved(BlockStep):
    """One run: only a block with a data setting is its business."""

    def __init__(self) -> None:
        super().__init__()
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        setting = block.sections.get("DataSetting")
        if isinstance(setting, DataSetting) and setting.table in TABLES:
            sections = block.sections
            del sections["DataSetting"]
            block.changed()
            note = f"{setting.table.replace('_', ' ').upper()} {setting.index} SET: TAKEN INTO THE PATH"
            comments = sections.get("Comments")
            sections["Comments"] = Comments(([*comments.texts] if isinstance(comments, Comments) else []) + [note])
        return None


def _rest(sections: dict[str, Section]) -> bool:
    """The block does something besides the offset (and its number and comments)."""
    return any(key not in ("Sequence", "BlockDelete", "Comments") for key in sections)
