"""Polar points in the XY plane about the origin: the geometry of a dialect that programs a point by its
radius and angle (LinuxCNC's ``@``/``^``, read in ``postproc_linuxcnc.polar``). The rules of each
controller stay in its reader; these functions only compute, raising ``ProgramError`` at ``where`` for a
point that has no angle [V: LinuxCNC src/emc/rs274ngc/interp_find.cc find_ends, interp_cycles.cc]."""

from __future__ import annotations

import math
from typing import Final

from ..errors import Location, ProgramError

EPS: Final = 1e-12
"""Closer to the origin than this is at the origin (no angle)."""


def polar_absolute(x: float, y: float, radius: float | None, angle: float | None, cycle: bool,
                   where: Location) -> tuple[float, float]:
    """The absolute end point: a missing radius or angle is the tool's (``x``, ``y``); a radius alone at the
    origin has no angle, unless ``cycle`` (a hole cycle takes it unchecked)."""
    if radius is None:
        radius = math.hypot(x, y)
    elif angle is None and not cycle and abs(x) < EPS and abs(y) < EPS:
        raise ProgramError("a polar radius alone at the origin needs an angle too (the point has none)", where)
    theta = math.radians(angle) if angle is not None else math.atan2(y, x)
    return radius * math.cos(theta), radius * math.sin(theta)


def polar_turned(x: float, y: float, radius: float | None, angle: float | None,
                 where: Location) -> tuple[float, float]:
    """The incremental end point: the radius stretched, then the angle turned, about the origin."""
    if abs(x) < EPS and abs(y) < EPS:
        raise ProgramError("incremental polar coordinates are indeterminate at the origin", where)
    if radius is not None:
        theta, r = math.atan2(y, x), math.hypot(x, y) + radius
        x, y = r * math.cos(theta), r * math.sin(theta)
    if angle is not None:
        theta, r = math.atan2(y, x) + math.radians(angle), math.hypot(x, y)
        x, y = r * math.cos(theta), r * math.sin(theta)
    return x, y


def clean(value: float) -> float:
    """A coordinate within float noise of a round value is that value (cos 90 deg is 6e-17, not 0)."""
    rounded = round(value, 9)
    return rounded + 0.0 if abs(value - rounded) < 1e-12 else value
