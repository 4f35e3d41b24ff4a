"""The canned-cycle return level a native cycle needs, written where the target would assume another.

A controller starts in one return level (RS274/NGC's G98/G99: LinuxCNC's interpreter in G99, Mach3 in
G98; ``Dialect.START_RETURN_LEVEL``), and a program may leave its cycles to that default. A cycle read
from one dialect carries the level it returns to (``CannedCycle.return_level``); written natively for a
target whose level in force differs (its start level, or the last one written), the block gets the
return-level word (a ``ReturnLevel`` section). A lowering step for targets that write G98/G99.
"""

from __future__ import annotations

from typing import Iterator

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..ir import Block, ReturnLevel


def return_level_in_force(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering step (see the module docstring); a program of the target's own dialect is as written."""
    if ctx.dialect == target.NAME:
        yield from blocks
        return
    see = ReturnLevels(target).see
    for block in blocks:
        see(block)
        yield block


@mypyc_attr(allow_interpreted_subclasses=True)
class ReturnLevels:
    """The return level in force on the target, block by block: ``see`` adds the return-level word a
    cycle needs (for a target step that fuses it into its own loop, one generator less per block)."""

    __slots__ = ("level",)

    def __init__(self, target: type[Dialect]) -> None:
        self.level = target.START_RETURN_LEVEL

    def see(self, block: Block) -> None:
        sections = block.sections
        written = sections.get("ReturnLevel")
        if written is not None:
            self.level = written.level  # type: ignore[attr-defined]
        cycle = sections.get("CannedCycle")
        if cycle is not None:
            wanted = cycle.return_level  # type: ignore[attr-defined]
            if wanted != self.level:
                sections["ReturnLevel"] = ReturnLevel(wanted)
                block.changed()
                self.level = wanted
