"""A thread move's lead, along its major axis or along its path.

The neutral lead (``ThreadLead``, and a Fanuc-family ``G32 F``) is the advance per spindle revolution along
the thread's major axis: Z when the move's Z travel is at least its X travel, else X [K: Fanuc T G32, "F:
lead along the long axis"]. LinuxCNC's ``G33 K`` is the distance per revolution "in the direction" of the
move, along its path [V: LinuxCNC g-code.adoc "G33 Spindle Synchronized Motion": K "determines the distance
moved in that direction per spindle revolution"]. Straight threads agree; a taper or a pull-out chamfer
needs the conversion. X travel is a true distance here (a radius): the caller halves a diameter.
"""

from __future__ import annotations

import math


ROUNDING = 1e-9
"""Relative: a move at 45 degrees whose travels differ by rounding alone has Z as its major axis (at 45
degrees either axis gives the same lead)."""


def major_is_z(dx: float, dz: float) -> bool:
    """Whether Z is the thread's major axis (``dx`` a radius travel)."""
    return abs(dz) >= abs(dx) * (1.0 - ROUNDING)


def lead_along_path(lead: float, dx: float, dz: float) -> float:
    """The distance per revolution along the path of a move whose major-axis lead is ``lead``."""
    major = max(abs(dx), abs(dz))
    return lead if major == 0.0 else lead * math.hypot(dx, dz) / major


def lead_along_major(along_path: float, dx: float, dz: float) -> float:
    """The major-axis lead of a move that advances ``along_path`` per revolution along its path."""
    length = math.hypot(dx, dz)
    return along_path if length == 0.0 else along_path * max(abs(dx), abs(dz)) / length
