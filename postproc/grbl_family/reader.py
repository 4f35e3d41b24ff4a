"""GrblFamilyReader: the RS274/NGC lexer for the grbl family. A ``%`` line is no tape mark there (neither
parser has such a word; senders strip it): it is read as an inert comment, so nothing after it is taken for
dead code."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.ir import Block, Comments
from postproc.rs274.ngc_lexer import NgcReader


class GrblFamilyReader(NgcReader):
    """The family's reader (each dialect names itself and says how it reads ``/``)."""

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        for block in super().read(lines):
            if "TapeMark" in block.sections:
                del block.sections["TapeMark"]
                block.sections["Comments"] = Comments(["%"])
            yield block
