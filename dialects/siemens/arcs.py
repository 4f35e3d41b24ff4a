"""``AR=`` and ``CIP``: a circle by its opening angle (``arc_words``) or through an intermediate point
(``cip_words``).

``AR=``: a circle by its opening angle, with its centre (``G3 I-10 J0 AR=90``) or with its end point
(``G2 X10 Y0 AR=120``) [K: 840D sl Fundamentals, "Circular interpolation with opening angle and center
point (AR, I, J, K)" and "... with opening angle and end point (AR, X, Y, Z)"; the Autodesk
``siemens-840d.cps`` post formats AR= in degrees]. The angle is in degrees, more than 0 and less than 360
[K]; G2 turns clockwise, G3 counter-clockwise, as every arc.

Read by the block syntax into the words of a plain arc, from the tool's position: the centre form gets
its end point (``X``/``Y``, absolute in G90, from the start in G91), the end-point form its centre
(``I``/``J``, from the start). Only in G17 (the XY plane) with plain numbers and centres from the start (I, J
incremental, their default [K]); a ``Z`` makes a helix as on any arc. Other forms (another plane, both a
centre and an end point, ``CR=`` beside it) are located errors; computed angles are kept verbatim by the
reader.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from postproc.errors import ProgramError
from postproc.ir import Section
from postproc.xmlio import XAttr

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block

_ARC_CODES = {"2": "cw", "02": "cw", "3": "ccw", "03": "ccw"}
_MOTION_CODES = frozenset(("0", "00", "1", "01", "2", "02", "3", "03", "33", "331", "332"))


class SiemensArc(Section):
    """The ``AR=`` of a block, turned into arc words by ``arc_words`` (which removes it)."""

    XNAME = KEY = "SiemensArc"
    __slots__ = ("angle",)
    XATTRS = (XAttr("angle", float),)
    angle: float

    def __init__(self, angle: float) -> None:
        self.angle = angle


def arc_words(block: Block, ctx: Context, arc: SiemensArc) -> None:
    """Add the end point or the centre the opening angle gives (module docstring) to ``block.words``."""
    state = ctx.state
    at = ctx.at(block, (block.text or "").upper().find("AR") + 1 or 1)
    angle = arc.angle
    if not 0.0 < angle < 360.0:
        raise ProgramError(f"AR={angle:g}: the opening angle is more than 0 and less than 360 degrees", at)
    words = {letter.upper(): num for letter, num in block.words}
    motion = [num for letter, num in block.words if letter in "Gg" and num in _MOTION_CODES]
    mode = _ARC_CODES.get(motion[-1]) if motion else state.motion if state.motion in ("cw", "ccw") else None
    if mode is None:
        raise ProgramError("AR= is the opening angle of a circle: G2 or G3 is in force with it", at)
    if state.plane != "XY" or any(letter in "Gg" and num.lstrip("0") in ("18", "19") for letter, num in block.words):
        raise ProgramError("AR= is read in G17 (the XY plane) only", at)
    if "R" in words or "K" in words:
        raise ProgramError("AR= with CR= or K: give the centre by I, J or the end point by X, Y", at)
    x, y = state.position.get("X"), state.position.get("Y")
    if x is None or y is None:
        raise ProgramError("AR=: the tool's X and Y are unknown (position them absolutely first)", at)
    distance = [num.lstrip("0") for letter, num in block.words if letter in "Gg" and num.lstrip("0") in ("90", "91")]
    incremental = distance[-1] == "91" if distance else state.distance == "incremental"  # the block's own first
    centre_given = "I" in words or "J" in words
    end_given = "X" in words or "Y" in words
    if centre_given == end_given:
        raise ProgramError("AR= takes either the centre (I, J) or the end point (X, Y), not both or neither", at)
    turn = math.radians(angle if mode == "ccw" else -angle)
    if centre_given:
        cx, cy = x + float(words.get("I", 0.0)), y + float(words.get("J", 0.0))
        if cx == x and cy == y:
            raise ProgramError("AR=: the centre is the start point", at)
        dx, dy = x - cx, y - cy
        ex = cx + dx * math.cos(turn) - dy * math.sin(turn)
        ey = cy + dx * math.sin(turn) + dy * math.cos(turn)
        block.words.extend([("X", _spell(ex - x if incremental else ex)), ("Y", _spell(ey - y if incremental else ey))])
        return
    ex = x + float(words.get("X", 0.0)) if incremental else float(words.get("X", x))
    ey = y + float(words.get("Y", 0.0)) if incremental else float(words.get("Y", y))
    chord = math.hypot(ex - x, ey - y)
    if chord == 0.0:
        raise ProgramError("AR= with the end point at the start point makes no circle", at)
    half = math.radians(angle) / 2.0
    height = chord / (2.0 * math.tan(half))  # from the chord's middle to the centre, negative past 180 degrees
    nx, ny = -(ey - y) / chord, (ex - x) / chord  # left of the way from start to end
    side = 1.0 if mode == "ccw" else -1.0
    cx = (x + ex) / 2.0 + side * height * nx
    cy = (y + ey) / 2.0 + side * height * ny
    block.words.extend([("I", _spell(cx - x)), ("J", _spell(cy - y))])


def _spell(value: float) -> str:
    return repr(float(value))


CIP_KEY = "siemens_cip"
"""``ctx.state.extra`` key: True while ``CIP`` is the motion code in force."""


class SiemensCip(Section):
    """A ``CIP`` block's intermediate point (``I1=``, ``J1=``, ``K1=``; None: not given), turned into arc words
    by ``cip_words`` (which removes it)."""

    XNAME = KEY = "SiemensCip"
    __slots__ = ("i1", "j1", "k1")
    XATTRS = (XAttr("i1", float, None), XAttr("j1", float, None), XAttr("k1", float, None))
    i1: float | None
    j1: float | None
    k1: float | None

    def __init__(self, i1: float | None = None, j1: float | None = None, k1: float | None = None) -> None:
        self.i1, self.j1, self.k1 = i1, j1, k1


def cip_words(block: Block, ctx: Context, cip: SiemensCip) -> bool:
    """``CIP X.. Y.. I1=.. J1=..``: the circle from where the tool stands through the intermediate point to the
    end point [K: 840D sl Fundamentals, "Circular interpolation with intermediate and end points (CIP)"; the
    Autodesk ``siemens-840d.cps`` post writes ``CIP X Y Z I1= J1= K1=`` with the intermediate point absolute,
    and treats CIP as a motion code in force afterwards]. Read as G2/G3 with its centre where the three points
    lie in the XY plane at one Z under G17 and G90, ``CIP`` first in its block (elsewhere the reader keeps
    the block verbatim); False (the block is kept verbatim) otherwise: a circle in
    space has no neutral arc, and whether I1/J1 are measured from the start under G91 is not confirmed here
    [?]. Three points on a line are a located error."""
    state = ctx.state
    at = ctx.at(block, (block.text or "").upper().find("CIP") + 1 or 1)
    codes = {num.lstrip("0") for letter, num in block.words if letter in "Gg"}
    if state.plane != "XY" or codes & {"18", "19"} or "91" in codes or state.distance == "incremental" \
            and "90" not in codes or cip.i1 is None or cip.j1 is None or not block.values.keys().isdisjoint("XYZ"):
        return False
    words = {letter.upper(): num for letter, num in block.words}
    x, y, z = state.position.get("X"), state.position.get("Y"), state.position.get("Z")
    if x is None or y is None:
        raise ProgramError("CIP: the tool's X and Y are unknown (position them absolutely first)", at)
    if "Z" in words and (z is None or float(words["Z"]) != z) or cip.k1 is not None and cip.k1 != z:
        return False
    ex, ey = float(words.get("X", x)), float(words.get("Y", y))
    mx, my = cip.i1, cip.j1
    d = 2.0 * ((mx - x) * (ey - my) - (my - y) * (ex - mx))  # twice the signed area: > 0 turns left
    scale = max(abs(ex - x), abs(ey - y), abs(mx - x), abs(my - y), 1.0)
    if abs(d) <= 1e-12 * scale * scale:
        raise ProgramError("CIP: the start, the intermediate point and the end point lie on one line", at)
    s2, m2, e2 = x * x + y * y, mx * mx + my * my, ex * ex + ey * ey
    cx = (s2 * (my - ey) + m2 * (ey - y) + e2 * (y - my)) / d  # the circumcentre of the three points
    cy = (s2 * (ex - mx) + m2 * (x - ex) + e2 * (mx - x)) / d
    block.words.extend([("G", "3" if d > 0 else "2"), ("I", _spell(cx - x)), ("J", _spell(cy - y))])
    return True
