"""The user's program transforms (``translate --units --transform``), run on the lowered blocks before the
writer: first the map (in the program's own units, as it tracks them), then the units conversion.

A lathe program (``Context.lathe``) takes ``--units``: its X is a length like any (a diameter converts as its
radius), its surface speed under G96 with the lengths (``units``); a lathe cycle kept for the target is refused
(its parameters are not converted), one the target lacks arrives as its moves. ``--transform`` takes a shift
along Z on a lathe and refuses any other map by what it does (``carry.lathe_refusal``).

They run last so that every step before them (frames evaluated, cycles expanded, compensation resolved)
has made the blocks the target gets: what they carry is what is written.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Iterator

from ..context import Context
from ..errors import UsageError
from ..ir import Block
from ..records import record

if TYPE_CHECKING:
    from .spec import ProgramTransform


@record(frozen=True, slots=True)
class ProgramOptions:
    """What the user asked a translation to do to the program besides translating it."""

    units: str | None = None
    """'mm' or 'inch': the output's units (None: as the program has them)."""
    transform: ProgramTransform | None = None

    def active(self) -> bool:
        return self.units is not None or self.transform is not None


def program_options(units: str | None = None, transform: str | ProgramTransform | None = None) -> ProgramOptions:
    """Checked options: a ``UsageError`` for units other than mm or inch, or a transform text that does not
    read (``postproc.transforms.spec``)."""
    if units is not None and units not in ("mm", "inch"):
        raise UsageError(f"--units is mm or inch, not {units!r}")
    if isinstance(transform, str):
        from .spec import parse_transform  # (a transform given: its reading, not at every start)
        transform = parse_transform(transform)
    return ProgramOptions(units, transform)


def transform_program(blocks: Iterator[Block], ctx: Context, options: ProgramOptions) -> Iterator[Block]:
    """The map, then the units (each only when asked for: their modules are imported then, not at every
    start, tests/test_startup_imports.py)."""
    if not options.active():
        return blocks
    from .carry import lathe_refusal, move_program
    from .units import convert_units
    if options.transform is not None and ctx.lathe:
        refusal = lathe_refusal(options.transform)
        if refusal is not None:
            raise UsageError(refusal)
    if options.transform is not None:
        blocks = move_program(blocks, ctx, options.transform)
    if options.units is not None:
        blocks = convert_units(blocks, ctx, options.units)
    return blocks
