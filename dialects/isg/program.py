"""IsgProgramSyntax: the interpreter step with ISG's data (P parameters, ``V.`` variables, ``$`` control
flow, ``%L`` local and ``L`` global subroutines).

Integer addresses (G, M, N, T, D, H) are written without a point when evaluated (``N[10+P30]`` ->
``N2010``); the program ends at M30/M02; ``L file`` looks for ``file`` as written in the set-up's and
``--lib`` folders; an ``M17``/``M29`` return in the main program ends it as ``M30`` does [?].
"""

from __future__ import annotations

from typing import ClassVar

from postproc.interp import ProgramSyntax
from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import VariablesFactory

from .variables import IsgVariables


class IsgProgramSyntax(ProgramSyntax):
    XNAME = "IsgProgramSyntax"
    __slots__ = ()

    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("GMNTDH")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 30), ("M", 2)})
    MACRO_LOCALS: ClassVar[int] = 0
    VARIABLES: ClassVar[VariablesFactory] = IsgVariables
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}",)
    PROGRAM_LABEL: ClassVar[str] = "{name}"
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=False,
                                                                  main_return_words=(("M", "30"),))
