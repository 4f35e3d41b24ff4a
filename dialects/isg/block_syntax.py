"""IsgBlockSyntax: ISG's reading of a block's DIN words, the family's word rules with ISG's table.

A number without a decimal point is in mm/inch (``X10`` = 10 mm, the opposite of Fanuc's default),
whatever the set-up's ``Input`` says. A computed block number (``N[10+P30]``) only names the block.
``D<n>`` selects tool data n: its length applies (``D0``: none) and G41/G42 take its radius
(``postproc.isg_family.tool_data``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir import Block, Motion
from postproc.isg_family.tool_data import read_tool_data
from postproc.rs274.block_syntax import WordBlockSyntax
from postproc.rs274.codes import CodeTable

from .codes import CODES

TAP_CODES = {"in": "G331", "out": "G332"}
"""The rigid tap strokes' spelling, for the messages of ``read_tap_stroke``."""
from postproc.isg_family.taps import MODES, read_tap_stroke
from postproc.frames.section import ROTATE_FIRST


class IsgBlockSyntax(WordBlockSyntax):
    """Lexed words -> neutral sections, for Beckhoff TwinCAT CNC (ISG kernel) controls."""

    XNAME = "IsgBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "isg"
    TITLE: ClassVar[str] = "ISG"
    CODES: ClassVar[CodeTable] = CODES
    POINTLESS_IN_UNITS: ClassVar[bool] = True
    FRAME_RULES: ClassVar[str] = ROTATE_FIRST
    """G68/G69 (``codes``) under the ``isg`` rules of ``postproc.frames``."""

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        super().g_sections(block, ctx, codes, values, used, cycle_block)
        read_tool_data(block, ctx, values, used, toggles=False, first=0)
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in MODES:
            read_tap_stroke(block, ctx, motion, values, used, TAP_CODES)
            return
        if "MachineCoordinates" in block.sections and isinstance(motion, Motion):
            mode = ctx.state.motion  # ``#SUPPRESS OFFSETS`` moves in the motion mode in force
            if mode not in ("rapid", "linear"):
                raise ProgramError("#SUPPRESS OFFSETS needs G00 or G01 in force", ctx.at(block))
            block.sections["Motion"] = Motion(mode, motion.axes)
