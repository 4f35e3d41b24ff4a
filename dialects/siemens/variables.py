"""SINUMERIK variables while a program runs (the interpreter's ``Env``).

* R parameters (the neutral ``#500``-``#999``, see ``expressions``) are the channel's: shared by the main
  program and its subprograms, and retentive on the control, so one the program never set holds what an
  earlier program left: reading it is an error (no value is made up) [K: R parameters are channel-global
  user data].
* User variables (``DEF``) belong to the program level that declared them (LUD) [K].
* ``$`` system variables are the machine's: reading or setting one is an error naming it, so a program
  that needs one cannot be simulated or flattened (issue 28, item 5; as for Fanuc ``#5021``).
"""

from __future__ import annotations

from typing import Callable, Hashable

from postproc.ir.expr import Arithmetic, EvalError, Vacancy, Value, VarKey
from postproc.interp.variables import MACHINE_ONLY

from .expressions import R_BASE, R_LAST


class SiemensVariables:
    __slots__ = ("shared", "levels", "_increment")

    def __init__(self, increment: Callable[[], float]) -> None:
        self.shared: dict[int, float] = {}
        self.levels: list[dict[str, float]] = [{}]
        self._increment = increment

    @property
    def vacancy(self) -> Vacancy:
        return Vacancy.NULL  # never consulted for a vacant value: an unset variable is an error here

    @property
    def arithmetic(self) -> Arithmetic:
        """IEEE double [?]: the manuals we read name the functions (degrees) but not their precision."""
        return Arithmetic.DOUBLE

    @property
    def increment(self) -> float:
        return self._increment()

    def _check(self, key: VarKey) -> None:
        if isinstance(key, int):
            if not R_BASE <= key <= R_BASE + R_LAST:
                raise EvalError(f"#{key} is not a SINUMERIK R parameter (R0-R{R_LAST})")
        elif key.startswith("$"):
            raise EvalError(f"{key.upper()} (a system variable) {MACHINE_ONLY}")

    def read(self, key: VarKey) -> Value:
        self._check(key)
        value = self.shared.get(key) if isinstance(key, int) else self.levels[-1].get(key)
        if value is None:
            raise EvalError(f"{_spell(key)} is read before it is set")
        return float(value)

    def snapshot(self) -> Hashable | None:
        """The R parameters and this level's user variables and arguments: all a program can read (a ``$``
        variable is refused); the least increment beside them."""
        return (len(self.levels), tuple(sorted(self.shared.items())), tuple(sorted(self.levels[-1].items())),
                self._increment())

    def plain(self, key: VarKey) -> bool:
        """The R parameters and the user variables (not the ``%`` ones a call sets)."""
        if isinstance(key, int):
            return R_BASE <= key <= R_BASE + R_LAST
        return not key.startswith(("$", "%"))

    def exists(self, key: VarKey) -> bool:
        raise EvalError("SINUMERIK has no test for a variable's existence here")

    def write(self, key: VarKey, value: Value) -> None:
        self._check(key)
        if value is None:
            raise EvalError(f"{_spell(key)} cannot be set to a vacant value")
        if key == "%n":  # a PROC's number of parameters: a call may pass no more arguments
            passed = self.levels[-1].get("%passed", 0.0)
            if passed > value:
                raise EvalError(f"the call passes {passed:g} arguments, the PROC takes {value:g}")
        if isinstance(key, int):
            self.shared[key] = value
        else:
            self.levels[-1][key] = value

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        """A call's arguments are the new level's ``%1``, ``%2``... (``call_reading.CallReading.procedure_parameters``)."""
        if new_level:
            self.levels.append({f"%{n}": value for n, value in args.items() if value is not None})
            if len(self.levels) > 1 and args:
                self.levels[-1]["%passed"] = float(max(args))

    def leave(self, new_level: bool, value: Value = None) -> None:
        if new_level and len(self.levels) > 1:
            level = self.levels.pop()
            if "%passed" in level and "%n" not in level:
                raise EvalError(f"the call passes {level['%passed']:g} arguments to a subprogram without PROC "
                                "parameters")

    def returned(self, value: Value) -> None:
        """Subprograms return no value here."""


def _spell(key: VarKey) -> str:
    if isinstance(key, int):
        return f"R{key - R_BASE}"
    if key.startswith("%"):
        return f"argument {key[1:]} (the call passes none in its place)"
    return key.upper()
