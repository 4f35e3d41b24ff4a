"""Tool nose radius compensation around a lathe cycle run under it (Fanuc T's notes on the multiple repetitive
cycles, [K] in ``cutter_rules.FANUC_T``): one algorithm for the simulation (``simulate.simulator``) and the resolver
that writes the compensated moves (``lowering.cutter_resolver``).

The offset is temporarily cancelled on the move to the cycle's start point (``CutterRadius.suspend``); a
roughing cycle (``CutterRules.roughing_cycles``) then runs its own moves, already the imaginary tip's path to
the compensated shape (``rs274.lathe_cycles``); a finishing cycle (``profile_cycles``) starts compensation up at
its first block, cancels it for its return to the start point (its last move, a rapid: the profile's last
block ends square to itself) and the move after the cycle starts it up again (``CutterRadius.resume``).
"""

from __future__ import annotations

from typing import Sequence

from ..errors import UnsupportedError
from ..ir import Motion, Section
from .cutter_radius import CutterRadius, Suspended


def finishing_entry(cutter: CutterRadius, items: Sequence[Section]) -> tuple[Suspended | None, Section]:
    """A finishing cycle's start under the mode set before it: the move to the start point ends there, the
    profile's first move is a start-up; returns what to resume after the cycle and its return move, before
    which the caller cancels (``CutterRadius.cancel``)."""
    back = items[-1] if items else None
    if not isinstance(back, Motion) or back.mode != "rapid":
        raise UnsupportedError("a finishing cycle under tool nose radius compensation without its return to the "
                               "start point cannot be run through the compensation")
    held = cutter.suspend()
    if held is not None:
        cutter.resume(held)
    return held, back
