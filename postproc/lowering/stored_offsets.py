"""hold_stored_offsets: a work offset written into the controller's table for the active work system, which
that controller takes only at the system's next selection (``STORED_WORK_OFFSET``: ISG ``V.G.NP[n]``, Fagor
``V.A.ORGT[n]``, SINUMERIK ``$P_UIFR[n]``), towards a target whose setting acts at once (``G10 L2``: rs274,
Fanuc, grbl, Mach3).

Written where it stands, the target would move the next absolute points by the new offset, the source not
until the selection: so the setting waits, and is written as the target's setting right before the next
block that selects a work system (rs274 then takes it at once, and the selection keeps it: the same points
as the source from there). Where the program selects no system after it, the setting changed no move and is
left out. A units change while it waits is a located error (its values are in the units of its block).

A setting of a system that is not the active one means the same under both rules and is left alone, as is
every setting towards a target that writes the table itself (``WORK_OFFSET_VARIABLE``) or has no setting at
all (its writer refuses it by name).
"""

from __future__ import annotations

from typing import Iterator

from ..context import Context
from ..dialect import STORED_OFFSETS_KEY, Dialect
from ..errors import UnsupportedError
from ..ir import Block, Comments, DataSetting
from ..ir.verbatim import STORED_WORK_OFFSET
from ..ir.state import ModalState, changes_nothing


def hold_stored_offsets(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step (module docstring): only towards a target whose work offset setting acts at once."""
    if not ctx.run_data.get(STORED_OFFSETS_KEY):
        return blocks  # the source writes no table entry (``Dialect.STORED_WORK_OFFSETS``): a translation pays nothing
    writer = target.WRITER
    if writer is None:
        return blocks
    variable = str(getattr(writer, "WORK_OFFSET_VARIABLE", ""))
    at_once = str(getattr(writer, "WORK_OFFSET_SETTING", ""))
    if variable or not at_once:
        return blocks
    return _held(blocks, ctx, target.family())


def _held(blocks: Iterator[Block], ctx: Context, family: str) -> Iterator[Block]:
    modal = ModalState()
    held: list[tuple[int, DataSetting]] = []
    for block in blocks:
        s = block.sections
        if not s:
            yield block
            continue
        if held and "WorkOffset" in s:
            for line, waiting in held:
                before = Block(line, None, block.eol or "\n")
                before.add(waiting)
                yield before
            held = []
        if held and "Units" in s:
            ctx.diagnostics.error(UnsupportedError(
                "a units change while a work offset setting waits for the work system's next selection (the "
                "source's controller takes it there, the target at once): select the work system before the units "
                "change", ctx.at(block)))
            held = []  # reported: not written in the other units
        if not changes_nothing(s):
            modal.apply(s)
        setting = s.get("DataSetting")
        if isinstance(setting, DataSetting) and setting.table == STORED_WORK_OFFSET and setting.family != family \
                and setting.index == modal.work_offset:
            del s["DataSetting"]
            held.append((block.line, DataSetting(setting.family, "work_offset", setting.index, dict(setting.values),
                                                 setting.incremental, setting.text)))
            note = f"{setting.text}: written before the next work system selection"
            comments = s.get("Comments")
            if isinstance(comments, Comments):
                comments.texts.append(note)
            else:
                block.add(Comments([note]))
            block.changed()
        yield block
