"""LinuxCNC reader: the RS274/NGC family reader with o-words, parameters and expressions, naming
LinuxCNC in its messages."""

from __future__ import annotations

from postproc.ir import Block
from postproc.rs274.ngc_lexer import NgcReader

from .calls import read_call


class LinuxcncReader(NgcReader):
    DIALECT = "linuxcnc"
    PARAMETRIC = True

    def read_call(self, block: Block, code: str) -> None:
        """``M98 P L`` and ``M99`` (``calls``): rs274's Fanuc-style subprograms."""
        if "9" in code:
            read_call(block, self.ctx.file, code)
