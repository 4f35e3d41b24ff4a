"""NgcBlockSyntax: LinuxCNC's reading of a block, the RS274/NGC word rules with LinuxCNC's code table."""

from __future__ import annotations

from typing import ClassVar, Mapping

from postproc.rs274.codes import CodeTable
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax

from .codes import CODES, M_GROUPS


class NgcBlockSyntax(NgcWordBlockSyntax):
    """Lexed words -> neutral sections, for LinuxCNC milling (RS274/NGC)."""

    XNAME = "NgcBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "linuxcnc"
    CONTROL: ClassVar[str] = "LinuxCNC"
    CODES: ClassVar[CodeTable] = CODES
    N_FIRST: ClassVar[bool] = True
    FEED_MODE_RESETS_FEED: ClassVar[bool] = True
    CYCLE_CANCEL_WITH_MOTION: ClassVar[bool] = True
    M_GROUPS: ClassVar[dict[int, str]] = M_GROUPS
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {2: ("work_offset", 0, 9)}
    """G10 L2 P0-P9 sets a work system's offset (P0 the active one); other G10 forms are kept verbatim."""
    DATA_INCREMENTAL: ClassVar[bool] = False
    DATA_P0_ACTIVE: ClassVar[bool] = True
    DATA_ROTATION: ClassVar[bool] = True
    FRAME_RULES: ClassVar[str] = "rs274"
