"""LinuxCNC reader: the RS274/NGC family reader with o-words, parameters and expressions, naming
LinuxCNC in its messages. On a lathe set-up it keeps each subprogram's blocks as they were written, for the
G70-G72 cycles that run one as their profile (``lathe_cycles``)."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.errors import Location, ParseError
from postproc.ir import Block
from postproc.rs274.ngc_lexer import NgcReader

from .calls import read_call
from .lathe_cycles import ProfileCollector


class LinuxcncReader(NgcReader):
    DIALECT = "linuxcnc"
    PARAMETRIC = True
    POLAR = True
    """``@`` radius and ``^`` angle [V: LinuxCNC src/emc/rs274ngc/interp_read.cc read_atsign, read_carat]."""

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        """A ``%`` is the program's first line or closes a program opened with one: rs274 refuses any
        other ("Bad character '%' used"), unless the program has already ended (M2/M30)."""
        opened: bool | None = None  # None until the first line with content
        ended = False
        profiles = ProfileCollector(self.ctx) if self.ctx.lathe else None
        for block in super().read(lines):
            sections = block.sections
            if profiles is not None:
                profiles.see(block)
            if "TapeMark" in sections:
                if opened is False and not ended:
                    self.ctx.diagnostics.error(ParseError(
                        "'%' closes only a program that opens with '%' on its first line (LinuxCNC: \"Bad "
                        "character '%' used\")", Location(self.ctx.file, block.line, 1)), block.text)
                    yield Block(block.line, block.text, block.eol)  # kept as text, as every refused line
                    continue
                opened = opened is None or opened
            elif sections or block.words:
                if opened is None:
                    opened = False
                text = block.text  # (an M word's letter is in its line: most lines are not looked through)
                if not ended and text is not None and ("M" in text or "m" in text):
                    for a, n in block.words:  # a plain loop: a generator per block cost ~3k instructions
                        if (a == "M" or a == "m") and n.lstrip("0") in ("2", "30"):
                            ended = True
                            break
            yield block

    def read_call(self, block: Block, code: str) -> None:
        """``M98 P L`` and ``M99`` (``calls``): rs274's Fanuc-style subprograms."""
        if "9" in code and ("M" in code or "m" in code):  # no M word, no M98/M99: most lines, not read twice
            read_call(block, self.ctx.file, code)
