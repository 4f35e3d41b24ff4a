"""The lathe's generic lowering steps as the registry holds them (``core_plugin``): each imports its work when a
lathe program is first lowered. Both pass a mill's program untouched (``ctx.lathe`` False: the first thing each
decides), so a mill's run, most runs, imports neither the lathe cycles' expansion (and the offsets and tool
geometry it reads) nor the turret's indexing."""

from __future__ import annotations

from typing import TYPE_CHECKING, Iterator

if TYPE_CHECKING:
    from ..context import Context
    from ..dialect import Dialect
    from ..ir import Block


def expand_lathe_cycles(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """``postproc.cycles.lathe_lowering.expand_lathe_cycles``."""
    if not ctx.lathe:
        return blocks
    from ..cycles.lathe_lowering import expand_lathe_cycles as step
    return step(blocks, ctx, target)


def index_turret(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """``postproc.rs274.lathe_tool_index.index_turret``."""
    if not ctx.lathe:
        return blocks
    from ..rs274.lathe_tool_index import index_turret as step
    return step(blocks, ctx, target)
