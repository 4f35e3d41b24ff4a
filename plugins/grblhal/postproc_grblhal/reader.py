"""grblHAL reader: the grbl family's reader (``%`` as an inert comment), naming grblHAL in errors. ``/`` at the
start of a block skips it when the operator's block delete switch is on [V: grblHAL core ``gcode.c``
``gc_normalize_block``, ``sys.flags.block_delete_enabled``], as RS274/NGC reads it. Parameters, expressions and
o-words are read only for a build with them (``<Controller expressions="true">``, ``program``); o-word
subroutines are refused (not modelled)."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.context import Context
from postproc.control import CONTROL, Call, Return, SubEnd, SubStart
from postproc.errors import Location, ParseError
from postproc.grbl_family.reader import GrblFamilyReader
from postproc.ir import Block

NO_SUBROUTINES = ("grblHAL's o-word subroutines (sub, endsub, call, return) are not modelled by this dialect "
                  "(their named parameters' scope and the file lookup of a named sub): flatten the program")


class GrblhalReader(GrblFamilyReader):
    DIALECT = "grblHAL"

    def __init__(self, ctx: Context) -> None:
        super().__init__(ctx)
        self.PARAMETRIC = bool(ctx.setup.controller.expressions)

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        for block in super().read(lines):
            statement = block.sections.get(CONTROL)
            if isinstance(statement, (SubStart, SubEnd, Call, Return)):
                self.ctx.diagnostics.error(ParseError(NO_SUBROUTINES, Location(self.ctx.file, block.line, 1)),
                                           block.text)
                yield Block(block.line, block.text, block.eol)  # kept as text, as every refused line
                continue
            yield block
