"""How a controller family moves through a hole cycle: Fanuc, or RS274/NGC (LinuxCNC).

The two differ in a handful of rules (DIALECTS.md §2.1, "LinuxCNC / RS274-NGC baseline"), so one
small table per family keeps the switch in one place; the resolve step and the expansions read it.

============================  ===================================  ====================================
rule                          fanuc                                rs274
============================  ===================================  ====================================
initial level                 Z when the cycle is first commanded after a cancel (G80, G00-G03): both
G91 R measured from           the initial level: both
start below R                 positions in the plane, then to R    rapid up to R first, where the tool
                                                                   stands (every block whose initial
                                                                   level is below R)
G98 return level              the initial level                    the initial level, or R if higher
positioning level             the tool's current level             the current level if above R, else
                                                                   the return level (one traverse)
repeat count 0                no hole                              an error (the letters: CycleWords)
dwell P                       milliseconds (integer)               seconds
cycle data after a new code   carried over (Z, R, Q, P)            Z and R (Q, P) must be given again
G74/G84 without P             no dwell                             the last P of any cycle, even one
                                                                   before a G80
plain hole position words     X/Y in the plane only                any axis word repeats the cycle
G74/G84, G86, G88, G89 motion per DIALECTS.md's Fanuc table        as LinuxCNC's interpreter prints it
============================  ===================================  ====================================

The rs274 column was checked against the packaged interpreter (``rs274`` from linuxcnc-uspace
2.9.0~pre1+git20230208) and the shared conformance cases; its docs still describe older rules (G98 to
the Z at the block's start, G91 R from it), which that interpreter no longer follows.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final

from mypy_extensions import mypyc_attr

PECK: Final = frozenset(("peck_chip", "peck_deep"))
TAP: Final = frozenset(("tap", "tap_left"))
SHIFT: Final = frozenset(("fine_bore", "back_bore"))
DWELLING: Final = frozenset(("drill_dwell", "bore_stop", "bore_manual", "bore_dwell_feed"))
"""Cycles RS274/NGC refuses without a P when newly commanded."""


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(frozen=True, slots=True)
class Semantics:
    """The rules of one family (see the module table)."""

    name: str
    rise_to_r: bool
    clear_above_r: bool
    position_at_clear: bool
    dwell_ms: bool
    carry_over: bool
    any_axis_repeats: bool
    zero_repeat_error: bool
    sticky_tap_dwell: bool
    unsupported: frozenset[str]
    """Cycles with no meaning under this family's words."""

    # A family's rules are one constant shared by every run: a copy of the state that reaches them (the
    # dry run of a loop copies the modal state, whose next-hole memo holds its resolve step) shares them
    # too. Copying field by field is also what fails compiled: mypyc's __setstate__ assigns through the
    # frozen class's refusing __setattr__ (FrozenInstanceError).
    def __copy__(self) -> Semantics:
        return self

    def __deepcopy__(self, memo: dict[int, object]) -> Semantics:
        return self


FANUC: Final = Semantics("fanuc", rise_to_r=False, clear_above_r=False, position_at_clear=False,
                  dwell_ms=True, carry_over=True, any_axis_repeats=False, zero_repeat_error=False,
                  sticky_tap_dwell=False, unsupported=frozenset())
RS274: Final = Semantics("rs274", rise_to_r=True, clear_above_r=True, position_at_clear=True,
                  dwell_ms=False, carry_over=False, any_axis_repeats=True, zero_repeat_error=True,
                  sticky_tap_dwell=True, unsupported=frozenset(("fine_bore", "back_bore")))
"""LinuxCNC has no fine boring (G76 threads) and its G87 takes I/J/K: its reader keeps G87 verbatim."""

SEMANTICS: Final = {"fanuc": FANUC, "rs274": RS274}
