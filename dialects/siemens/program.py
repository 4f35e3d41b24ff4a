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
                                                                  main_return_refused=True, jumps_past_end=True)
    """``RET``/``M17`` end a subprogram; in the main program they are refused [?: the manuals we read do not
    say what they do there]. A jump in the main program may go to a label or block number after its M30/M2
    and runs on from there to the next end that runs: with jumps, the end of program need not be its last
    block [K: SINUMERIK ONE NC programming manual 12/2019 4.1.5.2 "Program jumps to jump markers", as cited by
    CEAD-group/nc-gcode-interpreter (python/tests/test_jumps.py, README "Program Jumps"), whose
    examples/goto.mpf jumps by GOTOF to a label after M30 and runs it (examples/goto.csv)]. In a subprogram a
    jump past its M17/RET stays refused [?: the note speaks of M2/M30]."""
    RUN_BEFORE_KEEP: ClassVar[bool] = True
    """An R parameter never set stops the run here but reads vacant (Fanuc) or 0 (LinuxCNC): a program kept
    symbolically must run here first, or the target could move where SINUMERIK stops."""
