"""GSK writer: the family's lathe writer spelling every code from GSK's table; every lathe-cycle word is
written, defaults included (an omitted word would take the machine's data parameter, No.051-060)."""

from __future__ import annotations

from typing import ClassVar

from postproc.ir import Block
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
