"""grblHAL's interpreter step and expression spelling, for a build with ``NGC_EXPRESSIONS_ENABLE`` (the set-up's
``<Controller expressions="true">``).

From grblHAL core (stored commit f80fc34) [V]:

* ``ngc_expr.c`` is LinuxCNC's expression reader ported: the operators ``**``, ``* / MOD``, ``+ -``, ``EQ NE GT GE
  LT LE``, ``AND OR XOR`` with LinuxCNC's precedence (``precedence``), MOD always positive, ``EQ``/``NE`` with
  a tolerance, the functions ABS ACOS ASIN ATAN[y]/[x] COS EXP FIX (floor) FUP (ceil) LN ROUND SIN SQRT TAN
  EXISTS, angles in degrees: LinuxCNC's spelling (``LINUXCNC_SPELLING``), with grblHAL's parameter range.
  grblHAL computes in single precision (``float``); the simulation here computes in double, so a program
  whose path depends on the seventh digit may differ [K].
* Numbered parameters ``#1``-``#5060`` are writable (``ngc_param_is_rw``: below the first read-only id, 5061),
  named ones ``#<name>``; ``#n=`` and ``#<name>=`` assignments (``gcode.c``).
* o-words (``ngc_flowctrl.c``): if/elseif/else/endif; do/while/endwhile, repeat/endrepeat, break/continue only
  in a program run from the controller's file system (``hal.stream.file``, else "not executing macro"); sub/
  endsub/call/return likewise, a named sub being a file ``<name>.macro``. Subroutines are not modelled here
  (their scoping of named parameters and the file lookup): reading one is refused, and a program with calls
  reaches grblHAL flattened.
"""

from __future__ import annotations

import dataclasses
from typing import ClassVar, Final

from postproc.errors import ProgramError
from postproc.interp import spell_number
from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import VariablesFactory
from postproc.rs274.expressions import LINUXCNC_SPELLING, ExprSpelling
from postproc.rs274.variables import NgcVariables
from postproc.syntaxes.program import ProgramSyntax

GRBLHAL_SPELLING: Final[ExprSpelling] = dataclasses.replace(LINUXCNC_SPELLING, name="grblhal", parameters=(1, 5060))
"""LinuxCNC's operators and functions (``ngc_expr.c``), writable parameters #1-#5060 (``ngc_params.c``)."""

INTEGER_TOLERANCE = 0.0001
"""How far from an integer an integer word may be (``gcode.c``'s mantissa check is coarser, this is safe)."""


class GrblhalProgramSyntax(ProgramSyntax):
    """Stores and runs grblHAL programs that compute (parameters, expressions, o-word flow control)."""

    XNAME = "GrblhalProgramSyntax"
    __slots__ = ()
    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("MNTHL")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 2), ("M", 30)})
    MACRO_LOCALS: ClassVar[int] = 30
    VARIABLES: ClassVar[VariablesFactory] = NgcVariables
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}.macro",)
    PROGRAM_LABEL: ClassVar[str] = "o{raw}"
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=False,
                                                                  main_return_words=(("M", "2"),),
                                                                  definition_runs_its_end=False)

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
