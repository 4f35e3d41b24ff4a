"""NgcBlockSyntax: LinuxCNC's reading of a block, the RS274/NGC word rules with LinuxCNC's code table.

G41.1/G42.1 (cutter compensation by the diameter D, L a lathe tool's orientation) stay verbatim
(``NativeCode``) and, in a block that does nothing else, carry a ``DynamicCutterCompensation`` the
simulation applies (``postproc.compensation.dynamic``) [V: LinuxCNC interp_convert.cc
convert_cutter_compensation_on: "G41.1 with no D word", "G41.1 with L word, but plane is not G18"].
"""

from __future__ import annotations

from typing import ClassVar, Mapping

from postproc.compensation.dynamic import DynamicCutterCompensation
from postproc.context import Context
from postproc.errors import ProgramError
from postproc.expr import Expr
from postproc.ir import Block
from postproc.rs274.codes import CodeTable, g_key
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax

from .codes import CODES, M_GROUPS

DYNAMIC_SIDES: dict[str, str] = {"41.1": "left", "42.1": "right"}
"""G41.1/G42.1 -> the side of the path."""
_DYNAMIC_WORDS = frozenset("NDL")
"""The words a dynamic compensation block may have besides its G code to be simulated."""


class NgcBlockSyntax(NgcWordBlockSyntax):
    """Lexed words -> neutral sections, for LinuxCNC milling (RS274/NGC)."""

    XNAME = "NgcBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "linuxcnc"
    CONTROL: ClassVar[str] = "LinuxCNC"
    CODES: ClassVar[CodeTable] = CODES
    N_FIRST: ClassVar[bool] = True
    FEED_MODE_RESETS_FEED: ClassVar[bool] = True
    CUTTER_TAKES_LOADED_TOOL: ClassVar[bool] = True
    """[K: LinuxCNC G-code reference, G41/G42: "if there is no D word, the radius of the currently loaded
    tool is used"; V: rs274, T1 M6 then G41 offsets by tool 1's radius]."""
    CYCLE_CANCEL_WITH_MOTION: ClassVar[bool] = True
    M_GROUPS: ClassVar[dict[int, str]] = M_GROUPS
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {2: ("work_offset", 0, 9)}
    """G10 L2 P0-P9 sets a work system's offset (P0 the active one); other G10 forms are kept verbatim."""
    DATA_INCREMENTAL: ClassVar[bool] = False
    DATA_P0_ACTIVE: ClassVar[bool] = True

    def _native(self, block: Block, ctx: Context, natives: list[str], raw: dict[str, str]) -> None:
        super()._native(block, ctx, natives, raw)
        side = DYNAMIC_SIDES.get(natives[0]) if len(natives) == 1 else None
        if side is None:
            return
        code = f"G{natives[0]}"
        values = block.values
        if "D" not in values:
            raise ProgramError(f"{code} with no D word (the tool's diameter)",
                               ctx.at(block, ctx.column_of(block, "G")))
        orientation = values.get("L")
        if orientation is not None and ctx.state.plane != "ZX":
            raise ProgramError(f"{code} with an L word (a lathe tool's orientation), but the plane is not G18",
                               ctx.at(block, ctx.column_of(block, "L")))
        diameter = values["D"]
        if isinstance(diameter, Expr) or isinstance(orientation, Expr):
            return  # known when the program runs: the run reads the block again with numbers
        for letter, num in block.words:
            up = letter.upper()
            if up not in _DYNAMIC_WORDS and not (up == "G" and g_key(num) == natives[0]):
                return  # another word acts too: the block stays verbatim and the simulation refuses it
        block.sections["NativeCode"].inert = True  # type: ignore[attr-defined]
        block.add(DynamicCutterCompensation(side, float(diameter),
                                            None if orientation is None else int(orientation)))
