"""``#ROTATION ON [ANGLE=.. CENTER1=.. CENTER2=..]`` / ``#ROTATION OFF``: ISG's other spelling of the contour
rotation G68/G69 select, read on the neutral frame change under the ``isg`` rules where its meaning is settled.

[V: Beckhoff TF5200 programming manual, "Rotate the coordinate system in the plane (#ROTATION ON/OFF)"]: the same
contour rotation as G68/G69 ("as an alternative"), in the current plane (G17/G18/G19), acting on the programmed
coordinates before every offset and mirror; ANGLE in degrees; CENTER1/CENTER2 "the offset of the first/second
main axis relative to the centre of rotation". The keywords take their value with or without ``=`` (the
manual's example writes ``[ANGLE -45 CENTER1=10 CENTER2=100]``).

Read here: ``#ROTATION OFF``, and ``#ROTATION ON`` with a number for ANGLE and both centre offsets 0: the centre
is then the programmed origin whichever sign an offset has. Kept verbatim as before (``NativeCode``: written
back in ISG, refused elsewhere by name) [?]: a centre offset other than 0 (whether CENTER1 is the centre's
coordinate or its negative is not settled: the figure that says so is a picture), an omitted ANGLE or centre
offset (their defaults are not stated), a computed value, a word the command does not take.
"""

from __future__ import annotations

import math
import re
from typing import Final

from postproc.frames.section import ROTATE_FIRST, FrameChange

_ARGUMENT: Final = re.compile(r"\s*([A-Za-z][A-Za-z0-9]*)\s*(?:=\s*|\s+)([+-]?(?:\d+\.?\d*|\.\d+))\s*,?")
_KEYS: Final = ("ANGLE", "CENTER1", "CENTER2")


def rotation_command(text: str) -> FrameChange | None:
    """``text`` (the command as written, from ``#``) as a frame change, or None where it is kept verbatim."""
    words = text.upper().split()
    if words == ["#ROTATION", "OFF"]:
        return FrameChange("rotate_off", {}, ROTATE_FIRST, "isg", text)
    if words[:2] != ["#ROTATION", "ON"]:
        return None
    rest = text[text.upper().index("ON", text.upper().index("#ROTATION") + 9) + 2:].strip()
    if not (rest.startswith("[") and rest.endswith("]")):
        return None
    values: dict[str, float] = {}
    inside = rest[1:-1]
    at = 0
    while at < len(inside.rstrip()):
        found = _ARGUMENT.match(inside, at)
        if found is None:
            return None
        key, number = found.group(1).upper(), float(found.group(2))
        if key not in _KEYS or key in values or not math.isfinite(number):
            return None
        values[key] = number
        at = found.end()
    if set(values) != set(_KEYS) or values["CENTER1"] != 0.0 or values["CENTER2"] != 0.0:
        return None
    # the centre at the programmed origin on the active plane's two main axes (all three are 0)
    return FrameChange("rotate", {"X": 0.0, "Y": 0.0, "Z": 0.0, "R": values["ANGLE"]}, ROTATE_FIRST, "isg", text)
