"""Variables of a running program: what the interpreter needs of a dialect family's variable model.

The interpreter names no family: each dialect's ``ProgramSyntax.VARIABLES`` brings its own table (the RS274
family's Custom Macro B and LinuxCNC models are in ``postproc.rs274.variables``, ISG's and Fagor's in their
dialects). A table reads and writes the ``Env`` of ``postproc.interp.evaluation.evaluate`` and keeps the call levels.
Reading or writing a variable only the machine knows is an ``EvalError`` naming it (``MACHINE_ONLY``): such a
program cannot be simulated or flattened.
"""

from __future__ import annotations

from typing import Callable, Hashable, Protocol, runtime_checkable

from ..ir.expr import Arithmetic, EvalError, Vacancy, Value, VarKey

MACHINE_ONLY = "is known only to the machine: the program cannot be simulated or flattened"

RUN_VARIABLES_KEY = "interp.variables"
"""``ctx.run_data`` key: the running program's ``Variables``, as they stand at the block a later step reads (the
interpreter's blocks stream through the steps one by one). A step that runs words kept as written (LinuxCNC's
G70-G72 reading their profile subprogram when the cycle runs) evaluates them there."""

RUN_INTERPRETER_KEY = "interp.interpreter"
"""``ctx.run_data`` key: the running program's interpreter (``postproc.interp.machine.Interpreter``), suspended at the
block a later step reads: a step that runs a subprogram as the controller does at that block (LinuxCNC's G70-G72
running their profile) runs it there (``Interpreter.call_apart``). Absent: no program runs (it is kept as written,
or it computes nothing)."""

SystemRanges = tuple[tuple[int, int, str], ...]
"""A family's system variables by range ``(first, last, what a message calls them)``; the first match wins."""


def system_variable(table: SystemRanges, key: int) -> str:
    """What ``table`` calls variable ``key`` ("system variable" where no range holds it)."""
    for low, high, what in table:
        if low <= key <= high:
            return what
    return "system variable"


class ProgramAlarm(EvalError):
    """The program raises its own alarm (a write to the family's alarm variable): the run stops there, as
    the machine does. ``word`` is how the program spells the variable (the error's column is where the block
    names it); the interpreter completes the message with the block's comment (``with_message``)."""

    def __init__(self, message: str, word: str) -> None:
        super().__init__(message)
        self.word = word

    def with_message(self, comments: list[str]) -> "ProgramAlarm":
        """Add the alarm's message (the block's comment, as the machine shows it)."""
        if comments:
            self.message = f"{self.message} ({' '.join(comments)})"
        return self


class Variables(Protocol):
    """What the interpreter needs of a dialect family's variables: the ``Env`` of ``evaluate`` plus the
    call levels. A class taking the least-increment callable (``VariablesFactory``)."""

    @property
    def vacancy(self) -> Vacancy: ...

    @property
    def arithmetic(self) -> Arithmetic: ...

    @property
    def increment(self) -> float: ...

    def read(self, key: VarKey) -> Value: ...

    def exists(self, key: VarKey) -> bool: ...

    def write(self, key: VarKey, value: Value) -> None: ...

    def enter(self, args: dict[int, Value], new_level: bool) -> None: ...

    def leave(self, new_level: bool, value: Value = None) -> None: ...

    def returned(self, value: Value) -> None:
        """A subprogram's end ran with ``value`` (None: without one), on a return or where the flow passes
        a definition and the rules say its end runs (``SubprogramRules.definition_runs_its_end``): what
        the program then reads of it (LinuxCNC ``#<_value>``); nothing for a family without one."""


@runtime_checkable
class Snapshots(Protocol):
    """Variables that can say everything a program reads of them as one comparable value: the interpreter
    then knows a loop that ends an iteration as it ended the one before can never end, and which of them
    only the program's assignments change."""

    def snapshot(self) -> Hashable | None:
        """Every value a program can read now (None: some depend on more than the variables, such as
        the machine's frames, so no two moments compare)."""

    def plain(self, key: VarKey) -> bool:
        """Only the program's assignments change ``key``, and assigning it does nothing else (False: the
        machine's, an alarm, or one a call sets): a loop whose test reads only plain variables its body
        never sets cannot end by its test (``postproc.interp.fixed_condition``)."""


VariablesFactory = Callable[[Callable[[], float]], Variables]
"""A variables class (or any callable) taking the least-increment callable."""
