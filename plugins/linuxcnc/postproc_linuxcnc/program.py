"""LinuxCNC's interpreter step: the RS274/NGC one (``postproc.rs274.ngc_program``: arguments #1-#30,
M2/M30, integer words within 0.0001) with LinuxCNC's lookup, subprogram rules and D.

* A subprogram called by name is looked up as ``name.ngc`` in the set-up's library folders (LinuxCNC's
  ``SUBROUTINE_PATH``), ``o<probe> call`` -> ``probe.ngc``.
* D is read as a real (rs274 ``read_d``: ``read_real_value``) [V: LinuxCNC src/emc/rs274ngc/interp_read.cc]:
  a diameter after G41.1/G42.1 (``G41.1 D#100``, negative to change sides), a whole tool number after
  G41/G42 (the block's rules refuse any other there).
"""

from __future__ import annotations

from typing import Callable, ClassVar, Final

from postproc.context import Context
from postproc.frames.parameters import FrameReadings
from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import Variables
from postproc.rs274.ngc_program import INTEGER_TOLERANCE, NgcProgramSyntax
from postproc.rs274.variables import NGC_MACHINE_READS, NgcVariables


CALL_LEVELS: Final = 9
"""Nested calls LinuxCNC runs: ``enter_context`` raises ``call_level`` (the main program's is 0) and refuses at
``INTERP_SUB_ROUTINE_LEVELS`` (10), "Too many subroutine levels" [V: interp_o_word.cc, interp_internal.hh; rs274
runs a sub calling itself 9 deep and refuses the 10th call, tests/test_grblhal_subroutines.py]."""


class LinuxcncProgramSyntax(NgcProgramSyntax):
    """Stores and runs LinuxCNC programs that compute (o-words, parameters, expressions)."""

    XNAME = "LinuxcncProgramSyntax"
    __slots__ = ()
    FRAME_PARAMETERS: ClassVar[frozenset[int]] = NGC_MACHINE_READS
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}.ngc",)
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=True,
                                                                  main_return_words=(("M", "2"),),
                                                                  definition_runs_its_end=True,
                                                                  call_levels=CALL_LEVELS)
    """rs274: M98 looks for O<n> from the call on and runs to M99; M99 in the main program is M2; a
    definition met in the flow runs its endsub; at most 9 nested calls (``CALL_LEVELS``)."""

    def variables(self, ctx: Context, increment: Callable[[], float]) -> Variables:
        """The offset parameters (#5210-#5219, a work system's #5221..) read the run's frame, in the
        machine's length units, and the current position (#5420-#5428) its program position (``NgcVariables``)."""
        return NgcVariables(increment, FrameReadings(ctx), ctx.setup.machine.mm())

    def spell_evaluated(self, letter: str, value: float) -> str:
        if letter == "D" and abs(value - round(value)) <= INTEGER_TOLERANCE:
            return str(int(round(value)))
        return super().spell_evaluated(letter, value)
