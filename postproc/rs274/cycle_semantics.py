"""The RS274 family's hole-cycle rules: Fanuc's and RS274/NGC's (LinuxCNC), registered by name.

The two differ in a handful of rules (DIALECTS.md §2.1, "LinuxCNC / RS274-NGC baseline"), so one
small table per family keeps the switch in one place; the resolve step and the expansions read it
(``postproc.cycles.semantics.Semantics``, looked up by name). A dialect names its rules by the table's name
(``CYCLE_SEMANTICS = FANUC.name``); importing this module registers both.

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
G74/G84, G86, G88, G89 motion per DIALECTS.md's Fanuc table        as LinuxCNC's interpreter prints it:
                                                                   P required (G82, G86, G88, G89), the
                                                                   spindle checked, a zero dwell without
                                                                   P, the spindle resumes its direction,
                                                                   G89 and G84 feed out to the clear
                                                                   level, G88 leaves no retract move
============================  ===================================  ====================================

[K] The fanuc column: DIALECTS.md §2.1's Fanuc table. [V] The rs274 column was checked against the packaged interpreter (``rs274`` from linuxcnc-uspace
2.9.0~pre1+git20230208) and the shared conformance cases; its docs still describe older rules (G98 to
the Z at the block's start, G91 R from it), which that interpreter no longer follows.
"""

from __future__ import annotations

from typing import Final

from postproc.cycles.semantics import Semantics, register_semantics

FANUC: Final = Semantics(
    "fanuc", rise_to_r=False, clear_above_r=False, position_at_clear=False, dwell_ms=True, carry_over=True,
    any_axis_repeats=False, zero_repeat_error=False, sticky_tap_dwell=False, unsupported=frozenset(),
    dwell_required=False, spindle_checked=False, dwell_always=False, spindle_resumes=False,
    feeds_out_to_clear=False, stops_to_reverse=False, manual_retracts=True)
RS274: Final = Semantics(
    "rs274", rise_to_r=True, clear_above_r=True, position_at_clear=True, dwell_ms=False, carry_over=False,
    any_axis_repeats=True, zero_repeat_error=True, sticky_tap_dwell=True,
    unsupported=frozenset(("fine_bore", "back_bore")),
    dwell_required=True, spindle_checked=True, dwell_always=True, spindle_resumes=True,
    feeds_out_to_clear=True, stops_to_reverse=True, manual_retracts=False)
"""LinuxCNC has no fine boring (G76 threads) and its G87 takes I/J/K: its reader keeps G87 verbatim."""

register_semantics(FANUC)
register_semantics(RS274)
