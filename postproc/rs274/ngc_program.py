"""The RS274/NGC interpreter step: the neutral ``ProgramSyntax`` with the data the o-word dialects share
(LinuxCNC, grblHAL: its ``ngc_expr.c``/``ngc_flowctrl.c`` are LinuxCNC's ported). A dialect subclasses
``NgcProgramSyntax`` and says what differs: where a named subprogram is looked up (``LIBRARY_FILES``) and
how a subprogram definition and a return behave (``SUBPROGRAM_RULES``).

* ``#1``-``#30`` are a call's arguments (``o<x> call [a] [b]``), ``#<name>`` is local to a call, the rest
  global (``NgcVariables``); M2 and M30 end the program; a program label is written ``o<raw>``.
* A computed word is written back as a number. An address that takes an integer (M, N, T, H, L) accepts a
  value within 0.0001 of one and rounds it, as rs274's ``read_integer_value`` does [V: LinuxCNC
  src/emc/rs274ngc/interp_read.cc]; anything else is an error naming the word. A G code is written as its
  number with at most one decimal (``G59.1``; ``G0`` without a point).
"""

from __future__ import annotations

from typing import ClassVar

from ..errors import ProgramError
from ..interp import spell_number
from ..interp.variables import VariablesFactory
from ..syntaxes.program import ProgramSyntax
from .variables import NgcVariables

INTEGER_TOLERANCE = 0.0001
"""How far from an integer rs274 still reads an integer word (``interp_read.cc``)."""


class NgcProgramSyntax(ProgramSyntax):
    """Stores and runs RS274/NGC programs that compute (o-words, parameters, expressions)."""

    XNAME = "NgcProgramSyntax"
    __slots__ = ()
    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("MNTHL")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 2), ("M", 30)})
    MACRO_LOCALS: ClassVar[int] = 30
    VARIABLES: ClassVar[VariablesFactory] = NgcVariables
    PROGRAM_LABEL: ClassVar[str] = "o{raw}"

    def spell_evaluated(self, letter: str, value: float) -> str:
        if letter in self.INTEGER_ADDRESSES:
            nearest = round(value)
            if abs(value - nearest) > INTEGER_TOLERANCE:
                raise ProgramError(f"address {letter} takes an integer, the expression gives {value:g}")
            return str(int(nearest))
        if letter == "G":
            tenths = round(value * 10.0)
            if abs(value * 10.0 - tenths) > INTEGER_TOLERANCE:
                raise ProgramError(f"G codes have at most one decimal place, the expression gives {value:g}")
            return str(tenths // 10) if tenths % 10 == 0 else f"{tenths // 10}.{tenths % 10}"
        return spell_number(value)
