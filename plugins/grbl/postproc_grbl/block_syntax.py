"""GrblBlockSyntax: RS274/NGC block rules with grbl's code tables.

grbl's parser follows the NIST RS274/NGC rules (no decimal-point scaling, G4 P in seconds, G80 leaves
no motion mode) and accepts a subset of the codes, so this is the grbl family's block syntax
(``postproc.grbl_family.block_syntax``: M19 only where the set-up has it) with grbl's table.
Reading grbl matters for ``verify``: the toolpath of a translated program is simulated from its text.
"""

from __future__ import annotations

from typing import ClassVar, Mapping

from postproc.context import Context
from postproc.grbl_family.block_syntax import GrblFamilyBlockSyntax
from postproc.ir import Block, ToolChange
from postproc.rs274.codes import CodeTable
from postproc.frames.section import SHARED_OFFSET

from .codes import CODES, M_GROUPS, NO_M19


class GrblBlockSyntax(GrblFamilyBlockSyntax):
    """Lexed words -> neutral sections, for grbl 1.1."""

    XNAME = "GrblBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "grbl"
    CONTROL: ClassVar[str] = "grbl"
    CODES: ClassVar[CodeTable] = CODES
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {2: ("work_offset", 0, 6)}
    """G10 L2 P0-P6 sets a work system's offset (P0 the active one); other G10 forms are kept verbatim."""
    DATA_INCREMENTAL: ClassVar[bool] = False
    DATA_P0_ACTIVE: ClassVar[bool] = True
    FRAME_RULES: ClassVar[str] = SHARED_OFFSET
    """G92/G92.1 (``codes``) mean LinuxCNC's."""
    REAL_LETTERS = frozenset("XYZIJKRPF")
    INTEGER_LETTERS = frozenset("NTL")
    M_GROUPS = M_GROUPS
    NO_M19 = NO_M19

    def build(self, block: Block, ctx: Context) -> None:
        """As RS274/NGC, plus grbl's spelling of a manual tool change: ``T<n> M0`` (grbl ignores T, so a
        T word on a program pause only says which tool the operator loads) is a tool change."""
        super().build(block, ctx)
        sections = block.sections
        stop = sections.get("ProgramControl")
        if stop is not None and stop.kind == "stop" and "ToolSelect" in sections:  # type: ignore[attr-defined]
            del sections["ProgramControl"]
            block.add(ToolChange())
