"""LinuxCNC's interpreter step: the neutral ``ProgramSyntax`` with LinuxCNC's data.

* ``#1``-``#30`` are a call's arguments (``o<x> call [a] [b]``), ``#31``-``#5000`` and ``#<_name>`` are
  global, ``#<name>`` is local to a call (``NgcVariables``).
* M2 and M30 end the program; a subprogram called by name is looked up as ``name.ngc`` in the set-up's
  library folders (LinuxCNC's ``SUBROUTINE_PATH``), ``o<probe> call`` -> ``probe.ngc``.
* A computed word is written back as a number. An address that takes an integer (M, N, T, H, L)
  accepts a value within 0.0001 of one and rounds it, as rs274's ``read_integer_value`` does; anything
  else is an error naming the word. D is read as a real (rs274 ``read_d``: ``read_real_value``) [V:
  LinuxCNC src/emc/rs274ngc/interp_read.cc]: a diameter after G41.1/G42.1 (``G41.1 D#100``, negative
  to change sides), a whole tool number after G41/G42 (the block's rules refuse any other there). A G code is written as its number (``G59.1``; ``G0`` without a point).
"""

from __future__ import annotations

from typing import Callable, ClassVar

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.frames.parameters import FrameReadings
from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import Variables, VariablesFactory
from postproc.syntaxes.program import ProgramSyntax
from postproc.interp import spell_number
from postproc.rs274.variables import NGC_FRAME_PARAMETERS, NgcVariables

INTEGER_TOLERANCE = 0.0001
"""How far from an integer rs274 still reads an integer word (``interp_read.cc``)."""


class LinuxcncProgramSyntax(ProgramSyntax):
    """Stores and runs LinuxCNC programs that compute (o-words, parameters, expressions)."""

    XNAME = "LinuxcncProgramSyntax"
    __slots__ = ()
    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("MNTHL")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 2), ("M", 30)})
    MACRO_LOCALS: ClassVar[int] = 30
    VARIABLES: ClassVar[VariablesFactory] = NgcVariables
    FRAME_PARAMETERS: ClassVar[range] = NGC_FRAME_PARAMETERS
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}.ngc",)
    PROGRAM_LABEL: ClassVar[str] = "o{raw}"
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=True,
                                                                  main_return_words=(("M", "2"),),
                                                                  definition_runs_its_end=True)
    """rs274: M98 looks for O<n> from the call on and runs to M99; M99 in the main program is M2; a
    definition met in the flow runs its endsub."""

    def variables(self, ctx: Context, increment: Callable[[], float]) -> Variables:
        """The offset parameters (#5210-#5219, a work system's #5221..) read the run's frame, in the
        machine's length units (``NgcVariables``)."""
        return NgcVariables(increment, FrameReadings(ctx), ctx.setup.machine.mm())

    def spell_evaluated(self, letter: str, value: float) -> str:
        if letter == "D" and abs(value - round(value)) <= INTEGER_TOLERANCE:
            return str(int(round(value)))
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
