"""Mach3BlockSyntax: a block's words -> neutral sections, under the RS274/NGC rules with Mach3's table.

It is a syntax object (an XML element of the dialect's pipeline, ``mach3.xml``), so it has an element
name (``XNAME``) and registers with the factory (``postproc_register_xml`` in ``__init__``)."""

from __future__ import annotations

from typing import ClassVar

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
