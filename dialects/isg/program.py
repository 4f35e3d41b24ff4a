"""IsgProgramSyntax: the interpreter step with ISG's data (P parameters, ``V.`` variables, ``$`` control
flow, ``%L`` local and ``L`` global subroutines).

Integer addresses (G, M, N, T, D, H) are written without a point when evaluated (``N[10+P30]`` ->
``N2010``); the program ends at M30/M02; ``L file`` looks for ``file`` as written in the set-up's and
``--lib`` folders; an ``M17``/``M29`` return in the main program is an error.
"""

from __future__ import annotations

from typing import ClassVar

from postproc.syntaxes.kept_lines import KeptLines
from postproc.syntaxes.program import ProgramSyntax, kept_line
from postproc.interp.rules import SubprogramRules
from postproc.interp.variables import VariablesFactory

from .commands import OPENING, command_line
from .variables import IsgVariables


class IsgProgramSyntax(ProgramSyntax):
    XNAME = "IsgProgramSyntax"
    __slots__ = ()

    INTEGER_ADDRESSES: ClassVar[frozenset[str]] = frozenset("GMNTDH")
    END_CODES: ClassVar[frozenset[tuple[str, int]]] = frozenset({("M", 30), ("M", 2)})
    MACRO_LOCALS: ClassVar[int] = 0
    VARIABLES: ClassVar[VariablesFactory] = IsgVariables
    LIBRARY_FILES: ClassVar[tuple[str, ...]] = ("{name}",)
    PROGRAM_LABEL: ClassVar[str] = "{name}"
    RUN_BEFORE_KEEP: ClassVar[bool] = True
    """An unset P parameter stops ISG but reads vacant (Fanuc) or 0 (LinuxCNC): a program kept
    symbolically must run here first, or the target could move where ISG stops."""
    SUBPROGRAM_RULES: ClassVar[SubprogramRules] = SubprogramRules(forward_search=False, main_return_words=None,
                                                                  main_return_refused=True)
    """``M17``/``M29`` end a subroutine; in the main program they are an error [?: the manual we read does
    not say what they do there, and Fanuc's ``M99`` would restart the program]."""

    def reading_context(self, kept: KeptLines) -> list[str]:
        """The streamed lines from a ``#VAR`` (or ``#COMMENT BEGIN``) still open where the construct starts:
        a declaration is read as one only inside it."""
        closing = set(OPENING.values())
        lines: list[str] = []
        for item in reversed(kept):
            line = kept_line(item)
            lines.append(line)
            command = command_line(line)
            if command in closing:
                return []
            if command in OPENING:
                return lines[::-1]
        return []
