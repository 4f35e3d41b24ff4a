"""LinuxCNC reader: the RS274/NGC family reader with o-words, parameters and expressions, naming
LinuxCNC in its messages. On a lathe set-up it keeps each subprogram's blocks as they were written, for the
G70-G72 cycles that run one as their profile (``lathe_cycles``)."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.ir import Block
from postproc.rs274.ngc_lexer import NgcReader

from .calls import read_call
from .lathe_cycles import ProfileCollector


class LinuxcncReader(NgcReader):
    DIALECT = "linuxcnc"
    PARAMETRIC = True
    POLAR = True
    """``@`` radius and ``^`` angle [V: LinuxCNC src/emc/rs274ngc/interp_read.cc read_atsign, read_carat]."""

    TAPE_MARK_REFUSED = 'LinuxCNC: "Bad character \'%\' used"'
    """A ``%`` is the program's first line or closes a program opened with one: rs274 refuses any other ("Bad
    character '%' used"), unless the program has already ended (M2/M30) (``NgcReader.TAPE_MARK_REFUSED``)."""

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        """On a lathe set-up, each subprogram's blocks are kept as they were written (``ProfileCollector``)."""
        blocks = super().read(lines)
        return blocks if not self.ctx.lathe else _profiled(blocks, ProfileCollector(self.ctx))

    def read_call(self, block: Block, code: str) -> None:
        """``M98 P L`` and ``M99`` (``calls``): rs274's Fanuc-style subprograms."""
        if "9" in code and ("M" in code or "m" in code):  # no M word, no M98/M99: most lines, not read twice
            read_call(block, self.ctx.file, code)


def _profiled(blocks: Iterator[Block], profiles: ProfileCollector) -> Iterator[Block]:
    for block in blocks:
        profiles.see(block)
        yield block
