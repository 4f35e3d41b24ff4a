"""Fagor's hole-cycle words: ``Z`` the reference plane, ``I`` the depth, ``K`` the dwell (DIALECTS.md
2.3 [V]), in the XY plane; no repeat count, no peck or shift word [?]. The dwell's unit comes from the
set-up (``<Cycles fagorDwellUnit>``: seconds by default, the 8070's unit being unconfirmed;
hundredths of a second, the 8055's)."""

from __future__ import annotations

from postproc.cycle_words import CycleWords
from postproc.setup.machine_setup import MachineSetup

NAMES = {"drill_dwell": "G81", "bore_dwell_feed": "G89"}
"""How messages name Fagor's cycles."""

SECONDS = CycleWords(names=NAMES, return_to_r="G99", level="Z", peck="", shift="", dwell="K",
                     spindle={"cw": "M03", "ccw": "M04"}, bottom={"XY": "I", "ZX": "I", "YZ": "I"},
                     repeat=(), dwell_unit=1.0)
HUNDREDTHS = CycleWords(names=NAMES, return_to_r="G99", level="Z", peck="", shift="", dwell="K",
                        spindle={"cw": "M03", "ccw": "M04"}, bottom={"XY": "I", "ZX": "I", "YZ": "I"},
                        repeat=(), dwell_unit=0.01)


def cycle_words(setup: MachineSetup) -> CycleWords:
    """The cycle words under ``setup``'s dwell unit."""
    return HUNDREDTHS if setup.cycles.fagor_dwell_unit == "hundredths" else SECONDS
