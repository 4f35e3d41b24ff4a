"""GSK writer: the family's lathe writer spelling every code from GSK's table; every lathe-cycle word is
written, defaults included (an omitted word would take the machine's data parameter, No.051-060)."""

from __future__ import annotations

from typing import ClassVar, Iterable, Iterator, TextIO

from postproc.errors import ProgramError
from postproc.ir import Block
from postproc.output.line_format import numbering
from postproc.rs274.codes import CodeTable
from postproc.rs274.lathe_writer import LatheWordWriter

from .codes import CODES


class GskWriter(LatheWordWriter):
    DIALECT: ClassVar[str] = "gsk"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "X"
    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid",))
    EXPLICIT_FIRST_BLOCKS: ClassVar[bool] = True
    """GSK takes an omitted G71-G76 word from its data parameters: every cycle gets its first block."""
    MONOTONIC_CHECK_WORD: ClassVar[str] = "K"
    """G71/G72 K1: the control checks the profile's monotonicity (the seed's GSK G71)."""
    PATH_CONTROL_LACK: ClassVar[str] = (
        "whether the GSK 980TDc has a cutting mode G64 that blends as LinuxCNC's does is [?], not found in a GSK "
        "manual here; postproc's GSK table (DIALECTS.md) has neither G61 nor G64: refused by name")

    MACRO_JUMPS: ClassVar[frozenset[int]] = frozenset(range(80, 87))
    """``G65 H80 Pn`` jumps to block Nn, ``H81``-``H86`` when their condition holds [K: GSK 980TDc user manual,
    macro instruction G65, "unconditional transfer" H80 and "conditional transfer" H81-H86, P the sequence
    number; as known, not re-read here]."""

    def native_block_reference(self, block: Block) -> str | None:
        """A ``G65 H80``-``H86`` jump (kept verbatim, ``NativeCode``: postproc runs no GSK macro) names its target
        by its number: a renumbering would leave it jumping elsewhere."""
        if "NativeCode" in block.sections and block.values.get("H") in self.MACRO_JUMPS and any(
                letter in "Gg" and num.lstrip("0") == "65" for letter, num in block.words):
            return f"G65 H{block.values['H']}"
        return None

    def write(self, blocks: Iterable[Block], out: TextIO) -> None:
        """With ``<Output blockNumbers>`` numbering the written lines (``postproc.output.line_format``), which
        rewrites every number after the writer, a macro jump is refused as ``--renumber`` refuses it (``normalized``)."""
        if numbering(self.ctx.setup.output, self.source_dialect != self.DIALECT) != "keep":
            blocks = self._macro_jumps_refused(blocks)
        super().write(blocks, out)

    def _macro_jumps_refused(self, blocks: Iterable[Block]) -> Iterator[Block]:
        for block in blocks:
            native = self.native_block_reference(block)
            if native is not None:
                self.ctx.diagnostics.error(ProgramError(
                    f"block numbers cannot be rewritten in a program that jumps to block numbers: {native} names one "
                    f"(the line is kept as written), whose number would change", self.ctx.at(block)))
            yield block
