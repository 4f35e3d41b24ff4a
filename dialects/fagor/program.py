"""FagorProgramSyntax: the interpreter step with Fagor's data (P parameters and expressions [K]).

Control flow and subroutines are kept verbatim by the reader [?], so the interpreter sees straight
programs: it evaluates P parameters and computed words, for the simulator and for targets without
variables. Integer addresses (G, M, N, T, D, H) are written without a point when evaluated; the
program ends at M30/M02.
"""

from __future__ import annotations

from typing import ClassVar

from postproc.syntaxes.program import ProgramSyntax
from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import VariablesFactory

from .variables import FagorVariables


class FagorProgramSyntax(ProgramSyntax):
    XNAME = "FagorProgramSyntax"
    __slots__ = ()

    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("GMNTDH")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 30), ("M", 2)})
    MACRO_LOCALS: ClassVar[int] = 0
    VARIABLES: ClassVar[VariablesFactory] = FagorVariables
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}",)
    PROGRAM_LABEL: ClassVar[str] = "{name}"
    RUN_BEFORE_KEEP: ClassVar[bool] = True
    """An unset P parameter stops the control (as on ISG, [?]): a program kept symbolically runs here
    first."""
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=False, main_return_words=None,
                                                                  main_return_refused=True)
    """Subroutines are kept verbatim [?]: nothing here calls or returns."""
