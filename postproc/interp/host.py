"""What the interpreter needs from the run it serves: the reading dialect (``Host``), where the moves made
downstream are counted (``MoveCount``) and where a located error goes (``Reporter``)."""

from __future__ import annotations

from typing import Protocol

from ..errors import PostprocError
from ..ir import Block


class Host(Protocol):
    """What the interpreter needs from the reading dialect."""

    @property
    def SEQUENCE_LETTER(self) -> str:
        """The address of block numbers (its word alone does not make a control block run)."""

    @property
    def AXIS_LETTERS(self) -> frozenset[str]:
        """Addresses that move an axis (a modal call follows such a block)."""

    @property
    def MACRO_LOCALS(self) -> int:
        """Highest local variable number an argument may set."""

    def spell_evaluated(self, letter: str, value: float) -> str:
        """The number text of an evaluated word (raises ``ProgramError`` if the address cannot take it)."""

    def program_label(self, name: str) -> str:
        """A subprogram name as the dialect writes it (``O2000``, ``o<probe>``)."""

    def is_program_end(self, block: Block) -> bool:
        """The block ends the program (M02/M30): nothing after it runs."""


class Interrupt(Exception):
    """Stops the run after a located error was reported."""


class MoveCount(Protocol):
    """Where the moves made downstream are counted (the run's ``Context``)."""

    @property
    def moves_made(self) -> int: ...


class NoMoves:
    """No count: nothing downstream makes moves the interpreter charges."""

    moves_made = 0


NO_MOVES = NoMoves()


class Reporter(Protocol):
    """Reports a located error (the run's diagnostics)."""

    def __call__(self, err: PostprocError) -> None: ...
