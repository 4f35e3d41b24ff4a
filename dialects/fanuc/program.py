"""FanucProgramSyntax: the interpreter step with Fanuc's data (Custom Macro B, M98/G65 subprograms).

Integer addresses are written without a point when evaluated (``G#10`` -> ``G81``, ``M98 P#1``); the
program ends at M02/M30 (an ``O`` number after it starts a subprogram); G65 sets locals #1-#33;
a subprogram ``O2000`` not in the file is looked for in the set-up's and ``--lib`` folders as
``O2000``, ``O2000.nc``, ``2000.nc`` and ``2000``, in that order.
"""

from __future__ import annotations

import math
from typing import Callable, ClassVar

from postproc.context import Context
from postproc.syntaxes.program import ProgramSyntax
from postproc.interp.variables import Variables, VariablesFactory
from postproc.rs274.variables import MacroBVariables

from .variables import HaasVariables


class FanucProgramSyntax(ProgramSyntax):
    XNAME = "FanucProgramSyntax"
    __slots__ = ()

    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("GMNOTHDLP")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 30), ("M", 2)})
    MACRO_LOCALS: ClassVar[int] = 33
    VARIABLES: ClassVar[VariablesFactory] = MacroBVariables
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("O{number:04d}", "O{number:04d}.nc", "{name}.nc", "{name}")
    PROGRAM_LABEL: ClassVar[str] = "O{number:04d}"
    OMITS_VACANT_WORDS: ClassVar[bool] = True
    """A vacant variable in an address ignores the address, as if the word were absent (``G90 X#1`` with #1
    vacant is ``G90``) [K: Fanuc Custom Macro B, "Undefined variables": the manual's table of
    <vacant> in an address]."""

    def spell_evaluated(self, letter: str, value: float) -> str:
        """A computed S runs rounded to a whole number, half away from zero (``S[1000.5]`` is S1001) [K: after
        Smid, Fanuc Custom Macros, "real versus integer values"]: a written S takes no decimal point
        (``FanucBlockSyntax.WHOLE_SPINDLE_SPEED``)."""
        if letter == "S":
            return str(int(math.floor(abs(value) + 0.5)) * (-1 if value < 0 else 1))
        return super().spell_evaluated(letter, value)

    def variables(self, ctx: Context, increment: Callable[[], float]) -> Variables:
        """A Haas mill's variables have the NGC's five-digit numbers too (``variables.HaasVariables``)."""
        if ctx.setup.controller.variant == "haas":
            return HaasVariables(increment)
        return super().variables(ctx, increment)

