"""The Haas variant's macro variables: Custom Macro B with the NGC control's five-digit numbers.

A Haas NGC mill numbers its general-purpose variables #10000-#10999 (saved at power-off), beside the
#1-#33 locals and the Fanuc-style #100-#199 and #500-#999 it still reads; #10150-#10199 and
#10550-#10599 hold probe results and calibration (the probing option writes them), #11000-#11063 are
discrete inputs [K: Haas NGC system variables table, zappettiniconsulting.com wiki "Haas System
Variables", reproducing the Haas mill operator's manual]. Whether #10100 and #100 are one variable is
not settled by that table (it pairs #10000-#10149 with #100-#149 but #10500-#10549 with #500-#549) [?]:
a program that uses both numberings is refused by name instead of simulated on a guess.

Above Fanuc's work offsets, a Haas numbers its tool timers and monitors (``HAAS_TOOL_DATA``): #5401-#5999 are
not work offsets there, and a message about them says what they are. Reading them is refused either way (the
machine's data).
"""

from __future__ import annotations

from typing import Callable

from postproc.ir.expr import EvalError, Value, VarKey
from postproc.interp.variables import MACHINE_ONLY
from postproc.rs274.variables import MacroBVariables

GENERAL = (10000, 10999)
"""The NGC's general-purpose variables."""
HAAS_SYSTEM: tuple[tuple[int, int, str], ...] = (
    (10150, 10199, "probe value"),
    (10550, 10599, "probe calibration data"),
    (11000, 11063, "discrete input"),
)
"""Five-digit numbers the machine sets (what a message calls them); the rest of #10000-#10999 is the
program's."""
HAAS_TOOL_DATA: tuple[tuple[int, int, str], ...] = (
    (5401, 5500, "tool feed timer"),
    (5501, 5600, "total tool timer"),
    (5601, 5700, "tool life monitor limit"),
    (5701, 5800, "tool life monitor counter"),
    (5801, 5900, "tool load monitor maximum"),
    (5901, 6000, "tool load monitor limit"),
)
"""Haas per-tool timers and monitors, where Fanuc's table goes on with work offsets (``MACRO_B_SYSTEM``'s
#5201-#5999) [K: Haas mill operator's manual, macro system variables table, as reproduced by third-party
Haas tooling tables: #5401-#5500 tool feed timers (seconds), #5501-#5600 total tool timers, #5601-#5700 tool
life limits, #5701-#5800 life counters, #5801-#5900 maximum loads, #5901-#6000 load limits]. #5201-#5206 (G52)
and #5221-#5326 (G54-G59) are work offsets on both [K]."""


def _legacy(key: int) -> bool:
    return 100 <= key <= 199 or 500 <= key <= 999


class HaasVariables(MacroBVariables):
    """Custom Macro B variables of a Haas mill: Fanuc's, and the NGC's general-purpose #10000-#10999."""

    __slots__ = ("numbering",)

    def __init__(self, increment: Callable[[], float]) -> None:
        super().__init__(increment)
        self.numbering: tuple[str, int] | None = None
        """The common numbering the program used first ('legacy' #100-#999 or 'NGC' #10000-#10999) and the
        variable that used it."""

    def read(self, key: VarKey) -> Value:
        if isinstance(key, int) and self._ngc(key):
            return self.commons.get(key)
        self._saw(key)
        return super().read(key)

    def write(self, key: VarKey, value: Value) -> None:
        if isinstance(key, int) and self._ngc(key):
            if value is None:
                self.commons.pop(key, None)
            else:
                self.commons[key] = value
            return
        self._saw(key)
        super().write(key, value)

    def plain(self, key: VarKey) -> bool:
        """Fanuc's plain variables and the NGC's general-purpose ones, but a common of a numbering the
        program has not used first (its write may be the error of mixing the two)."""
        if not isinstance(key, int):
            return False
        ngc = GENERAL[0] <= key <= GENERAL[1] and not any(low <= key <= high for low, high, _ in HAAS_SYSTEM)
        if not ngc and not super().plain(key):
            return False
        numbering = "NGC" if ngc else "legacy" if _legacy(key) else None
        return numbering is None or self.numbering is not None and self.numbering[0] == numbering

    def _ngc(self, key: int) -> bool:
        """True for a general-purpose NGC number (the program's); a machine-set one is refused here."""
        if not GENERAL[0] <= key <= GENERAL[1] and not HAAS_SYSTEM[-1][0] <= key <= HAAS_SYSTEM[-1][1]:
            return False
        for low, high, what in HAAS_SYSTEM:
            if low <= key <= high:
                raise EvalError(f"#{key} ({what}) {MACHINE_ONLY}")
        self._note("NGC", key)
        return True

    def _unknown(self, key: int) -> EvalError:
        """A machine-only variable named as a Haas names it (``HAAS_TOOL_DATA``), else as Fanuc does."""
        for low, high, what in HAAS_TOOL_DATA:
            if low <= key <= high:
                return EvalError(f"#{key} ({what}) {MACHINE_ONLY}")
        return super()._unknown(key)

    def _saw(self, key: VarKey) -> None:
        if isinstance(key, int) and _legacy(key):
            self._note("legacy", key)

    def _note(self, numbering: str, key: int) -> None:
        if self.numbering is None:
            self.numbering = (numbering, key)
        elif self.numbering[0] != numbering:
            raise EvalError(f"#{key} and #{self.numbering[1]}: a Haas program that uses both the five-digit "
                            "NGC variables (#10000-#10999) and the legacy ones (#100-#199, #500-#999) cannot be "
                            "simulated: whether they share storage is unconfirmed; use one numbering")
