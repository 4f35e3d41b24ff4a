"""The interpreter of programs that compute: program store, variables, execution.

Public API: ``spell_number``/``spell_integer`` (how evaluated words are written back). The step that runs
the interpreter in a reading pipeline is ``postproc.syntaxes.program.ProgramSyntax``; the execution
itself is ``postproc.interp.machine`` (``Interpreter``, on its ``RunState`` in ``postproc.interp.run_state``;
its ``Host`` in ``postproc.interp.host``) over
``postproc.interp.store`` (``ProgramStore`` of ``Program``s), imported only when a program is run: a
straight program never loads it.
"""

from __future__ import annotations

from .spelling import spell_integer, spell_number

__all__ = ["spell_integer", "spell_number"]
