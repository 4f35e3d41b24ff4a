"""A whole tool table entry written by the program (table ``tool_entry``: LinuxCNC ``G10 L1 P- Z- R-``, whose
P is a tool number and whose H and D registers are tool numbers too) for a target of another family.

The entry's new length and radius are known where the block runs, and the target reads them where the
source does (a length or a radius is read when ``G43``/``G41`` is programmed, on either side:
``postproc.compensation.tool_length``), so the entry becomes settings of the neutral registers of the
same number: ``tool_length`` from Z and ``cutter_offset`` from R, one block each, absolute as the entry is.
Then a target with a programmable data input for its offset memory writes them in its own spelling (Fanuc
``G10 L10``/``L12``: ``WordWriter.TOOL_DATA_SETTINGS``); a target that takes every length and radius into
its path (grbl without a tool table: ``postproc.grbl_family.lengths.drop_resolved_tool_data``) reads them
and writes nothing; any other refuses the setting, naming it.

Where the target's set-up keeps one value per register for H and D (``<Tool offset>``: Fanuc tool
compensation memory A or B [K: Fanuc Series 0i Model B connection manual (function) B-63833EN-1/02, 10.2
"Tool compensation memory", as ``postproc.setup.machine.ToolData``]), an entry giving both a length and a
radius cannot be written: refused. There a length or a radius alone is the register's one value: written
into ``tool_length`` on memory B (its geometry, ``G10 L10``) and ``tool_length_wear`` on memory A, whose
``G10 L11`` sets the one value [K: the same manual] (``ToolTable.write`` reads both so).

The entry's X and Y offsets (a mill's length offset moves X and Y by them, ``ToolTable.sideways``) have no
register on another controller: a value other than zero is refused; zero, the entry's value until a
program writes another, is left out.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Final

from ..compensation.tool_table import ENTRY, SIDEWAYS
from ..context import Context
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir import Block, Comments, DataSetting
from .lower import BlockStep, LoweringStep

LENGTH: Final = "Z"
"""The entry's word for its length."""
RADIUS: Final = "R"
"""The entry's word for its radius."""


@mypyc_attr(allow_interpreted_subclasses=True)
class WriteToolEntries(LoweringStep):
    """Lowering step: a ``tool_entry`` setting of another family -> ``tool_length`` and ``cutter_offset``
    settings (see the module docstring); every other block as it is. Back to the program's own dialect
    (whose settings are of its family) or to a target without a writer, the stream passes through."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME or target.WRITER is None:
            return None
        return _Entries(ctx, target.family())


write_tool_entries = WriteToolEntries()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Entries(BlockStep):
    """One run: only a block with a ``DataSetting`` is its business."""

    def __init__(self, ctx: Context, family: str) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.family = family

    def take(self, block: Block) -> list[Block] | None:
        setting = block.sections.get("DataSetting")
        if not isinstance(setting, DataSetting) or setting.table != ENTRY or setting.family == self.family:
            return None
        ctx = self.ctx
        try:
            return _registers(block, setting, ctx)
        except UnsupportedError as err:
            if ctx.on_unsupported == "warn":
                return None  # the writer refuses the entry and comments it out, with its warning
            ctx.diagnostics.error(err.located(ctx.at(block)))
            return []


def _registers(block: Block, setting: DataSetting, ctx: Context) -> list[Block]:
    """The block with its entry replaced by the register settings it makes (a second block for the radius)."""
    for axis in SIDEWAYS:
        value = setting.values.get(axis)
        if value is not None and (not isinstance(value, (int, float)) or value):
            raise UnsupportedError(f"a tool offset along {axis} ({setting.describe()}): the target's tool length "
                                   "offset moves the spindle axis only",
                                   ctx.at(block, ctx.column_of(block, axis)))
    if ctx.lathe:
        raise UnsupportedError(f"{setting.describe()} on a lathe: the target's lathe offsets are not written from "
                               "a tool table entry")
    tables = _tables(setting, ctx)
    settings = [DataSetting(setting.family, table, setting.index, {"R": setting.values[letter]}, False,
                            setting.text) for letter, table in tables]
    sections = block.sections
    del sections["DataSetting"]
    block.changed()
    if not settings:
        note = f"TOOL {setting.index} OFFSETS ACROSS THE SPINDLE ZERO: NOTHING TO WRITE"
        comments = sections.get("Comments")
        sections["Comments"] = Comments(([*comments.texts] if isinstance(comments, Comments) else []) + [note])
        return [block]
    sections["DataSetting"] = settings[0]
    out = [block]
    for extra in settings[1:]:
        more = Block(block.line, None, "\n")
        more.sections = {"DataSetting": extra}
        if "BlockDelete" in sections:  # skipped with the block
            more.sections["BlockDelete"] = sections["BlockDelete"]
        out.append(more)
    return out


def _tables(setting: DataSetting, ctx: Context) -> list[tuple[str, str]]:
    """(the entry's word, the neutral table it is written into), the length first."""
    given = [letter for letter in (LENGTH, RADIUS) if letter in setting.values]
    tool = ctx.setup.tools.get(str(setting.index))
    if tool is None or not tool.shared():
        return [(letter, "tool_length" if letter == LENGTH else "cutter_offset") for letter in given]
    if len(given) == 2:
        raise UnsupportedError(f"{setting.describe()} sets a length and a radius, and register {setting.index} is "
                               "one value for both on this set-up (<Tool offset>: tool compensation memory A or B)")
    return [(letter, "tool_length" if tool.offset_wear is not None else "tool_length_wear") for letter in given]
