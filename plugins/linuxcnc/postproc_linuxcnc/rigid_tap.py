"""LinuxCNC's ``G33.1 X- Y- Z- K- I-`` read into the neutral ``RigidTap``.

[V] LinuxCNC ``docs/src/gcode/g-code.adoc`` "G33.1 Rigid Tapping" and ``interp_convert.cc``
(``convert_straight``, ``move == G_33_1``); each rule below checked with rs274:

* K is the distance per spindle revolution and is required ("K word missing with g33/g33.1"); at least
  one axis word is required;
* I (optional) speeds the spindle up on the way out (values below 1 count as 1): it changes no point;
* the tap goes from the current point to the end point and back: the current point does not change;
* G33.1 is a group-1 motion mode: a later block with axis words and K taps again (``Z-5 K1``), one
  without K is refused as rs274 refuses it.
"""

from __future__ import annotations

from typing import Any

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, Motion
from postproc.rs274.codes import g_key
from postproc.lowering.synchronised_tap import RigidTap

MODE = "rigid_tap"
"""The motion mode of the code table's G33.1 row (never left in the IR: ``read_rigid_tap`` replaces it)."""


def read_rigid_tap(block: Block, ctx: Context, motion: Motion, values: dict[str, Any], used: set[str]) -> None:
    """Replace the block's ``Motion`` of mode ``MODE`` by its ``RigidTap``; K and I are taken. An error points
    at the block's G33.1 (at its first word when the mode is the one in force)."""
    code = next((num for letter, num in block.words if letter.upper() == "G" and g_key(num) == "33.1"), None)
    col = ctx.column_of(block, "G", code) if code is not None else 1
    del block.sections["Motion"]  # (first: a refused block leaves no motion the simulation cannot run)
    if ctx.state.cycle is not None:
        raise ProgramError("G33.1 while a canned cycle is in force: cancel it with G80 first",
                           ctx.at(block, col))
    if not motion.axes:
        raise ProgramError("G33.1 needs an axis word (the end point of the tap)",
                           ctx.at(block, col))
    pitch = values.get("K")
    if pitch is None:
        raise ProgramError("G33.1 needs K, the distance per spindle revolution", ctx.at(block, col))
    if not isinstance(pitch, Expr) and pitch <= 0.0:
        raise ProgramError(f"G33.1 K{pitch:g}: the distance per revolution must be positive",
                           ctx.at(block, ctx.column_of(block, "K")))
    speedup = values.get("I")
    if isinstance(speedup, Expr):
        raise ProgramError("a computed I in G33.1 is not supported (write the number)",
                           ctx.at(block, ctx.column_of(block, "I")))
    used.update(k for k in "KI" if k in values)
    block.add(RigidTap(dict(motion.axes), pitch if isinstance(pitch, Expr) else float(pitch),
                       None, None if speedup is None else float(speedup)))
    ctx.state.motion = MODE
