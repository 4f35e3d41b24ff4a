"""``TURN=``: a helix with additional full circles, read as its full circles and its last arc.

The facts [V: SINUMERIK ONE NC programming manual 12/2019 6FC5398-2EP40-0BA0, 2.9.7 "Helical interpolation (G2/G3,
TURN)", pp. 204-205]: ``G2``/``G3`` with ``TURN=`` n makes n additional full circles, 0 to 999; the motion is the
approach of the starting point, the n full circles, then the circle to the end point; the circular motion in the
plane and a linear motion along the axis perpendicular to it are superimposed and executed in parallel. So the
perpendicular axis moves in proportion to the angle turned over the whole helix [K: "in parallel"; the 808D
manual 01/2014 p.78 says the same: "two movements are overlaid"].

Read where the arc is a plain one: G17 and G90, the centre by ``I``/``J`` (or by ``AR=``, which gives them),
numbers, the tool's position known. The block becomes its moves (``CompoundMotion``): n full circles back to
the starting point in X/Y, each taking Z on by its share, then the programmed arc to the end point; G2/G3 stays
in force. ``CR=`` (the centre of a multi-turn circle by its radius is not worked out here), another plane, G91
and computed values are kept verbatim, named.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import CompoundMotion, Motion, Section
from postproc.xmlio import XAttr

from .cycles import keep_verbatim

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block

MAX_TURNS = 999
"""[V: ONE NC programming 12/2019 p.205: "TURN= ... in the range from 0 to 999"]."""
_ARCS = {"2": "cw", "3": "ccw"}
_PLANE_CODES = frozenset(("18", "19"))
SAME = 1e-9


class SiemensTurn(Section):
    """The ``TURN=`` of a block, from the reader to the block syntax (``before``/``after``)."""

    XNAME = KEY = "SiemensTurn"
    __slots__ = ("turns",)
    XATTRS = (XAttr("turns", int),)
    turns: int

    def __init__(self, turns: int) -> None:
        self.turns = turns


def before(block: Block, ctx: Context, turn: SiemensTurn) -> dict[str, float] | None:
    """The tool's X, Y, Z before a ``TURN=`` block whose helix is read (module docstring); None when the block
    is kept verbatim (``keep_verbatim``) or has no additional turn."""
    state = ctx.state
    codes = [num.lstrip("0") for letter, num in block.words if letter in "Gg"]
    motion = next((code for code in reversed(codes) if code in ("", "1", "2", "3", "33")), None)
    mode = _ARCS.get(motion) if motion is not None else state.motion
    letters = {letter.upper() for letter, _ in block.words}
    if mode not in ("cw", "ccw"):
        raise ProgramError("TURN= counts the full circles of a helix: G2 or G3 is in force with it",
                           ctx.at(block, (block.text or "").upper().find("TURN") + 1 or 1))
    why = None
    if state.plane != "XY" or not _PLANE_CODES.isdisjoint(codes):
        why = "in another plane than G17"
    elif "91" in codes or state.distance != "absolute" and "90" not in codes:
        why = "in G91"
    elif "R" in letters:
        why = "with CR="
    elif not letters & {"I", "J"}:
        why = "without its centre I, J"
    elif block.values:
        why = "with computed values"
    elif any(state.position.get(axis) is None for axis in "XYZ"):
        why = "with the tool's position unknown"
    if why is not None:
        keep_verbatim(block, f"TURN= {why}")
        return None
    if turn.turns == 0:
        return None
    return {axis: float(state.position[axis] or 0.0) for axis in "XYZ"}


def after(block: Block, ctx: Context, turn: SiemensTurn, start: dict[str, float]) -> None:
    """Replace the block's arc by its full circles and its last arc (module docstring)."""
    motion = block.sections.get("Motion")
    if not isinstance(motion, Motion) or motion.mode not in ("cw", "ccw") or motion.center is None:
        raise ProgramError("TURN= needs a circle by its centre (I, J) here", ctx.at(block))
    values = [motion.center.get("X", 0.0), motion.center.get("Y", 0.0),
              *(motion.axes.get(axis, start[axis]) for axis in "XYZ")]
    if any(isinstance(value, Expr) for value in values):
        raise ProgramError("TURN= on a circle with computed coordinates is not read", ctx.at(block))
    ci, cj, ex, ey, ez = (float(value) for value in values)  # type: ignore[arg-type]
    end = {"X": ex, "Y": ey, "Z": ez}
    cx, cy = start["X"] + ci, start["Y"] + cj
    a0 = math.atan2(start["Y"] - cy, start["X"] - cx)
    a1 = math.atan2(end["Y"] - cy, end["X"] - cx)
    sweep = (a1 - a0 if motion.mode == "ccw" else a0 - a1) % (2 * math.pi)
    if sweep <= SAME:
        sweep = 2 * math.pi  # the end point is the start: a full circle, as any arc reads it
    total = sweep + 2 * math.pi * turn.turns
    rise = end["Z"] - start["Z"]
    items: list[Section] = []
    for n in range(1, turn.turns + 1):
        z = start["Z"] + rise * (2 * math.pi * n) / total
        items.append(Motion(motion.mode, {"X": start["X"], "Y": start["Y"], "Z": z}, {"X": ci, "Y": cj}))
    items.append(Motion(motion.mode, dict(end), {"X": ci, "Y": cj}))
    del block.sections["Motion"]
    block.add(CompoundMotion("helix", items))
    state = ctx.state
    state.motion = motion.mode
    for axis, value in end.items():
        state.position[axis] = value
    ctx.moves_made += len(items)
