"""The interpreter of programs that compute: program store, variables, execution, streaming step.

Public API: ``ProgramSyntax`` (the pipeline step a dialect subclasses), ``FanucVariables``/``NgcVariables``
(the ``Env``s), ``spell_number``/``spell_integer`` (how evaluated words are written back); the execution
itself is ``postproc.interp.machine`` (``Interpreter``, ``Host``) over ``postproc.interp.store``
(``ProgramStore`` of ``Program``s), imported only when a program is run: a straight program never loads it.
"""

from __future__ import annotations

from .spelling import spell_integer, spell_number
from .step import ProgramSyntax
from .variables import FanucVariables, NgcVariables

__all__ = ["ProgramSyntax", "FanucVariables", "NgcVariables", "spell_integer", "spell_number"]
