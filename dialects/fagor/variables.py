"""Fagor variables while a program runs (the interpreter's ``Env``).

* ``P1``-``P499`` (the neutral ``#501``-``#999``, the family's mapping in
  ``postproc.isg_family.expressions``) are shared by the whole program [?: the 8070's local/global
  ranges are not confirmed]; reading one that was never set is an error (no vacant value is made up).
* Every ``V.`` variable is the machine's [?]: reading or setting it is an error naming it, so a program
  that needs one cannot be simulated or flattened.
"""

from __future__ import annotations

from typing import Callable, Hashable

from postproc.ir.expr import Arithmetic, EvalError, Vacancy, Value, VarKey
from postproc.interp.variables import MACHINE_ONLY
from postproc.isg_family.expressions import P_BASE, P_LAST


class FagorVariables:
    __slots__ = ("shared", "_increment")

    def __init__(self, increment: Callable[[], float]) -> None:
        self.shared: dict[int, float] = {}
        self._increment = increment

    @property
    def vacancy(self) -> Vacancy:
        return Vacancy.NULL  # never consulted for a vacant value: an unset parameter is an error here

    @property
    def arithmetic(self) -> Arithmetic:
        """IEEE double [?]: the 8070 programming manual we read names the functions (SIN, COS, TAN in
        degrees) but not their precision."""
        return Arithmetic.DOUBLE

    @property
    def increment(self) -> float:
        return self._increment()

    def _key(self, key: VarKey) -> int:
        if isinstance(key, str):
            raise EvalError(f"{key} {MACHINE_ONLY}")
        if not P_BASE + 1 <= key <= P_BASE + P_LAST:
            raise EvalError(f"#{key} is not a Fagor P parameter (P1-P{P_LAST})")
        return key

    def read(self, key: VarKey) -> Value:
        value = self.shared.get(self._key(key))
        if value is None:
            raise EvalError(f"P{int(key) - P_BASE} is read before it is set")
        return value

    def snapshot(self) -> Hashable | None:
        """The P parameters: all a program can read (a ``V.`` variable is refused); the least increment."""
        return (tuple(sorted(self.shared.items())), self._increment())

    def plain(self, key: VarKey) -> bool:
        """The P parameters (only assignments change them)."""
        return isinstance(key, int) and P_BASE + 1 <= key <= P_BASE + P_LAST

    def exists(self, key: VarKey) -> bool:
        """The family reads ``EXIST[..]`` (ISG's); whether the 8070 has it is not known [?]."""
        raise EvalError("EXIST is not known on the Fagor 8070 [?]")

    def write(self, key: VarKey, value: Value) -> None:
        if value is None:
            raise EvalError(f"P{int(key) - P_BASE} cannot be set to a vacant value")
        self.shared[self._key(key)] = value

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        """Calls are kept verbatim [?]: the interpreter never enters one."""

    def leave(self, new_level: bool, value: Value = None) -> None:
        """See ``enter``."""

    def returned(self, value: Value) -> None:
        """See ``enter``."""
