"""Fagor's hole-cycle words: ``Z`` the reference plane, ``I`` the depth, ``K`` the dwell (DIALECTS.md
2.3 [V]), in the XY plane; no repeat count, no peck or shift word [?]. The dwell's unit comes from the
set-up (``<Cycles fagorDwellUnit>``: seconds by default, the 8070's unit being unconfirmed;
hundredths of a second, the 8055's)."""

from __future__ import annotations

from postproc.cycle_words import CycleWords
from postproc.setup.machine_setup import MachineSetup

NAMES = {"drill_dwell": "G81", "bore_dwell_feed": "G89", "drill": "G81", "bore_feed": "G89"}
"""How messages name Fagor's cycles."""

UNDWELLED = {"drill_dwell": "drill", "bore_dwell_feed": "bore_feed"}
"""``G81``/``G89`` with no dwell ``K`` in force (absent or ``K0``) drill or bore without one (Fanuc's ``G81``/
``G85``, never a ``G82``/``G89`` with no dwell time) [V: Fagor 8055-M programming manual p.162 (G81), "[K5]
Dwell ... If not programmed, the CNC will take the value of K0"; K for the 8070 and for G89]."""

SECONDS = CycleWords(names=NAMES, return_to_r="G99", level="Z", peck="", shift="", dwell="K",
                     spindle={"cw": "M03", "ccw": "M04"}, bottom={"XY": "I", "ZX": "I", "YZ": "I"},
                     repeat=(), dwell_unit=1.0, undwelled=UNDWELLED)
HUNDREDTHS = CycleWords(names=NAMES, return_to_r="G99", level="Z", peck="", shift="", dwell="K",
                        spindle={"cw": "M03", "ccw": "M04"}, bottom={"XY": "I", "ZX": "I", "YZ": "I"},
                        repeat=(), dwell_unit=0.01, undwelled=UNDWELLED)


def cycle_words(setup: MachineSetup) -> CycleWords:
    """The cycle words under ``setup``'s dwell unit."""
    return HUNDREDTHS if setup.cycles.fagor_dwell_unit == "hundredths" else SECONDS
