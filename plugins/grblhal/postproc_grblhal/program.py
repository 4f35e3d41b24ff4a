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
  endsub/call/return likewise, a named sub being a file ``<name>.macro``. Numbered subs are run as grblHAL runs
  them: found once the flow has passed their definition (the reader's rules), arguments not given inherited
  from the caller (``variables``); named subs (the file lookup) are refused where read.
"""

from __future__ import annotations

import dataclasses
from typing import ClassVar, Final

from postproc.interp.rules import SubprogramRules
from postproc.rs274.expressions import LINUXCNC_SPELLING, ExprSpelling
from postproc.interp.variables import VariablesFactory
from postproc.rs274.ngc_program import NgcProgramSyntax

from .variables import GrblhalVariables

FLOW_STACK: Final = 20
"""Open flow constructs grblHAL holds: ``stack_push`` (if, do, while, repeat, call) refuses one once ``stack_idx``
(from -1) reached ``NGC_STACK_DEPTH - 1`` (20 - 1), "flow control stack overflow"; elseif, else and a sub's
definition push nothing [V: ngc_flowctrl.c, stored commit f80fc34]."""
CALL_LEVELS: Final = 10
"""Nested calls grblHAL runs: ``ngc_call_push`` refuses a call once ``call_level`` (from -1) reached
``NGC_MAX_CALL_LEVEL - 1`` (10 - 1), "flow control stack overflow" [V: ngc_params.c, ngc_flowctrl.c
``stack_push``, stored commit f80fc34]. A sub may call itself, to that depth."""
GRBLHAL_SPELLING: Final[ExprSpelling] = dataclasses.replace(LINUXCNC_SPELLING, name="grblhal", parameters=(1, 5060))
"""LinuxCNC's operators and functions (``ngc_expr.c``), writable parameters #1-#5060 (``ngc_params.c``)."""


class GrblhalProgramSyntax(NgcProgramSyntax):
    """Stores and runs grblHAL programs that compute (parameters, expressions, o-word flow control): the
    RS274/NGC step (``postproc.rs274.ngc_program``) with a named sub's file ``<name>.macro``."""

    XNAME = "GrblhalProgramSyntax"
    __slots__ = ()
    VARIABLES: ClassVar[VariablesFactory] = GrblhalVariables
    """A call's arguments not given are the caller's (``variables``)."""
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}.macro",)
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=False,
                                                                  main_return_words=(("M", "2"),),
                                                                  definition_runs_its_end=False,
                                                                  value_in_caller=True,
                                                                  call_levels=CALL_LEVELS,
                                                                  flow_stack=FLOW_STACK)
