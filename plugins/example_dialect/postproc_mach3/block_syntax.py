"""Mach3BlockSyntax: a block's words -> neutral sections, under the RS274/NGC rules with Mach3's table.

It is a syntax object (an XML element of the dialect's pipeline, ``mach3.xml``), so it has an element
name (``XNAME``) and registers with the factory (``postproc_register_xml`` in ``__init__``)."""

from __future__ import annotations

from typing import ClassVar, Mapping

from postproc.rs274.codes import CodeTable
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax

from .codes import CODES, M_GROUPS


class Mach3BlockSyntax(NgcWordBlockSyntax):
    XNAME = "Mach3BlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "mach3"
    CONTROL: ClassVar[str] = "Mach3"
    CODES: ClassVar[CodeTable] = CODES
    CYCLE_CANCEL_WITH_MOTION: ClassVar[bool] = True
    """G80 and a motion code are one modal group (RS274/NGC): the motion code wins."""
    M_GROUPS: ClassVar[dict[int, str]] = M_GROUPS
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {2: ("work_offset", 1, 6)}
    """G10 L2 P1-P6 sets fixture P's origin (``codes.NATIVE_G``): the fixtures G54-G59 select. Mach3's fixture
    table is longer (``G59 P7``...), but this dialect selects no fixture beyond G59, so P7 and up are refused
    here by name rather than set and never used."""
    DATA_INCREMENTAL: ClassVar[bool] = False
    """The origin is given in absolute (machine) coordinates whatever G90/G91 (RS274/NGC v3 3.5.5) [K]."""
