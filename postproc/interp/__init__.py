"""The interpreter of programs that compute: program store, variables, execution, streaming step.

Public API: ``ProgramSyntax`` (the pipeline step a dialect subclasses, naming its family's ``Variables``
table: ``postproc.rs274.variables``, or its own), ``spell_number``/``spell_integer`` (how evaluated words
are written back); the execution itself is ``postproc.interp.machine`` (``Interpreter``, ``Host``) over
``postproc.interp.store`` (``ProgramStore`` of ``Program``s), imported only when a program is run: a
straight program never loads it.
"""

from __future__ import annotations

from .spelling import spell_integer, spell_number
from .step import ProgramSyntax

__all__ = ["ProgramSyntax", "spell_integer", "spell_number"]
