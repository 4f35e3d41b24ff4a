"""SiemensProgramSyntax: the interpreter step with SINUMERIK's data (R parameters, DEF variables, control
structures and jumps).

Integer addresses (G, M, T, D, H) are written without a point when evaluated; the program ends at
M30/M2. A subprogram ``NAME`` is the file ``NAME.SPF`` in the set-up's and ``--lib`` folders.
"""

from __future__ import annotations

from typing import ClassVar

from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import VariablesFactory
from postproc.syntaxes.program import ProgramSyntax

from .variables import SiemensVariables


class SiemensProgramSyntax(ProgramSyntax):
    XNAME = "SiemensProgramSyntax"
    __slots__ = ()

    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("GMNTDH")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 30), ("M", 2)})
    MACRO_LOCALS: ClassVar[int] = 64
    """A call passes at most 64 arguments (``call_reading.MAX_PARAMETERS``), the callee's ``%1``...``%64``."""
    VARIABLES: ClassVar[VariablesFactory] = SiemensVariables
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}.SPF", "{name}.spf")
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=False, main_return_words=None,
                                                                  main_return_refused=True)
    """``RET``/``M17`` end a subprogram; in the main program they are refused [?: the manuals we read do not
    say what they do there]."""
    RUN_BEFORE_KEEP: ClassVar[bool] = True
    """An R parameter never set stops the run here but reads vacant (Fanuc) or 0 (LinuxCNC): a program kept
    symbolically must run here first, or the target could move where SINUMERIK stops."""
