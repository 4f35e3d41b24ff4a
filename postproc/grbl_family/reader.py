"""GrblFamilyReader: the RS274/NGC lexer for the grbl family. A ``%`` line is no tape mark there (neither
parser has such a word; senders strip it): it is read as an inert comment, so nothing after it is taken for
dead code. A block number above the family's limit is a located error: the controller refuses the line
(``GrblFamily.MAX_BLOCK_NUMBER``)."""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.ir import Block, Comments
from postproc.rs274.ngc_lexer import NgcReader

from .dialect import GrblFamily


class GrblFamilyReader(NgcReader):
    """The family's reader (each dialect names itself and says how it reads ``/``)."""

    MAX_BLOCK_NUMBER = GrblFamily.MAX_BLOCK_NUMBER

    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        for block in super().read(lines):
            if "TapeMark" in block.sections:
                del block.sections["TapeMark"]
                block.sections["Comments"] = Comments(["%"])
            yield block
