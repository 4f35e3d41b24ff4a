"""ISG variables while a program runs (the interpreter's ``Env``).

* P parameters (the neutral ``#501``-``#999``, see ``expressions``) are shared by the main program and
  every subroutine it calls [?: the manual we read does not say whether a global subroutine gets its
  own]; reading one that was never set is an error (no vacant value is made up).
* ``V.P.``/``V.S.`` self-defined variables are shared like P parameters; ``V.L.`` ones belong to the
  program level that set them (a call starts with none).
* Every other ``V.`` variable (``V.E.`` external, ``V.A.`` axis, ``V.G.`` global, ``V.TOOL.``,
  ``V.SPDL.``...) is the machine's: reading or setting it is an error naming it, so a program that needs
  one cannot be simulated or flattened.
"""

from __future__ import annotations

from typing import Callable, Hashable

from postproc.ir.expr import Arithmetic, EvalError, Vacancy, Value, VarKey
from postproc.interp.variables import MACHINE_ONLY

from postproc.isg_family.expressions import P_BASE, P_LAST

_SHARED = ("V.P.", "V.S.")
_LOCAL = "V.L."


class IsgVariables:
    __slots__ = ("shared", "levels", "_increment")

    def __init__(self, increment: Callable[[], float]) -> None:
        self.shared: dict[VarKey, float] = {}
        self.levels: list[dict[str, float]] = [{}]
        self._increment = increment

    @property
    def vacancy(self) -> Vacancy:
        return Vacancy.NULL  # never consulted for a vacant value: an unset variable is an error here

    @property
    def arithmetic(self) -> Arithmetic:
        """IEEE double [?]: the ISG programming manual we read names the functions (SIN, COS, TAN in
        degrees) but not their precision."""
        return Arithmetic.DOUBLE

    @property
    def increment(self) -> float:
        return self._increment()

    def _store(self, key: VarKey) -> dict[VarKey, float] | dict[str, float]:
        if isinstance(key, int):
            if not P_BASE + 1 <= key <= P_BASE + P_LAST:
                raise EvalError(f"#{key} is not an ISG P parameter (P1-P{P_LAST})")
            return self.shared
        upper = key.upper()
        if upper.startswith(_SHARED):
            return self.shared
        if upper.startswith(_LOCAL):
            return self.levels[-1]
        raise EvalError(f"{key} {MACHINE_ONLY}")

    def read(self, key: VarKey) -> Value:
        store = self._store(key)
        value = store.get(key)  # type: ignore[arg-type]
        if value is None:
            raise EvalError(f"{_spell(key)} is read before it is set")
        return float(value)

    def snapshot(self) -> Hashable | None:
        """The P parameters, the shared and this level's self-defined variables: all a program can read (a
        machine's variable is refused); the least increment beside them."""
        return (len(self.levels), tuple(sorted(self.shared.items(), key=str)), tuple(sorted(self.levels[-1].items())),
                self._increment())

    def plain(self, key: VarKey) -> bool:
        """The P parameters and the self-defined variables (only assignments change them)."""
        try:
            self._store(key)
        except EvalError:
            return False
        return True

    def exists(self, key: VarKey) -> bool:
        """EXIST[V.P.NAME]: the self-defined variable was declared or set (a P parameter: was set); a
        machine's variable is an error (only the machine knows what it has)."""
        return key in self._store(key)

    def write(self, key: VarKey, value: Value) -> None:
        if value is None:
            raise EvalError(f"{_spell(key)} cannot be set to a vacant value")
        self._store(key)[key] = value  # type: ignore[index]

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        if new_level:
            self.levels.append({})

    def leave(self, new_level: bool, value: Value = None) -> None:
        if new_level and len(self.levels) > 1:
            self.levels.pop()

    def returned(self, value: Value) -> None:
        """ISG subroutines return no value."""


def _spell(key: VarKey) -> str:
    return f"P{key - P_BASE}" if isinstance(key, int) else key
