"""The interpreter of programs that compute: program store, variables, execution, streaming step.

Public API: ``ProgramSyntax`` (the pipeline step a dialect subclasses), ``Interpreter`` and ``Host``
(execution over a ``ProgramStore`` of ``Program``s), ``FanucVariables``/``NgcVariables`` (the ``Env``s),
``spell_number``/``spell_integer`` (how evaluated words are written back).
"""

from __future__ import annotations

from .machine import Host, Interpreter, spell_integer, spell_number
from .step import ProgramSyntax
from .store import Program, ProgramStore
from .variables import FanucVariables, NgcVariables

__all__ = ["Host", "Interpreter", "ProgramSyntax", "Program", "ProgramStore", "FanucVariables", "NgcVariables",
           "spell_integer", "spell_number"]
