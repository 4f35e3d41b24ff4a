"""LinuxCNC's arc centre modes: ``G91.1`` (I/J/K are offsets from the arc's start: the default, and the IR's
only meaning) and ``G90.1`` (I/J/K are the centre's coordinates).

[V] LinuxCNC ``interp_convert.cc``: ``convert_ijk_distance_mode`` sets the mode (modal group 13, applied
before the block's motion, so ``G90.1 G2 X.. I.. J..`` is read absolute), and ``convert_arc`` under
``DISTANCE_MODE::ABSOLUTE`` refuses an arc that leaves out a centre word of its plane ("I word missing in
absolute center arc"), where the incremental mode takes it as 0. Checked with rs274 (``ARC_FEED`` prints the
absolute centre either way).

Under G90.1 the reader turns each centre into the offset from the arc's start, so every later step (the
simulation, the writers) sees one meaning. The start is where the reading has the tool (program units, the
current coordinate system, as LinuxCNC reads absolute I/J/K): where that is unknown (after a reference
return, a move in machine coordinates, a computed position) or where the text's order is not the order of
execution (a program with variables or control flow), the arc is a located error. The blocks that say
G90.1 (written as a comment, ``NOTE``) and the arcs read under it are marked changed: a writer writes them from their sections, with
offsets (a copy of the source text would keep the absolute numbers, and the code, without their meaning).
"""

from __future__ import annotations

from typing import Any, Final

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, Comments, Motion
from postproc.ir.state import MM_PER_INCH, PLANE_AXES

GROUP: Final = "13"
"""The modal group of G90.1/G91.1 in the code table (LinuxCNC's ``GM_IJK_DISTANCE_MODE``; kind
``arc_centres``): the reader keeps the block's code under it."""
STATE_KEY: Final = "NgcArcCentres"
"""``ctx.state.extra`` key: "absolute" while G90.1 is in force (absent: incremental)."""
_LETTER: Final = {"X": "I", "Y": "J", "Z": "K"}
NOTE: Final = "{code}: absolute arc centres, written as offsets from each arc's start"
"""The trace a G90.1 leaves where it stood (the code itself is not written: the centres after it are offsets)."""


def apply_mode(block: Block, ctx: Context, codes: dict[str, Any]) -> None:
    """Put the block's mode in force (before its motion), then give an arc read under G90.1 its offsets."""
    code = codes.get(GROUP)
    extra = ctx.state.extra
    if code is not None:
        if code[2] == "absolute":
            extra[STATE_KEY] = "absolute"
        else:
            extra.pop(STATE_KEY, None)
    if STATE_KEY not in extra:
        return
    motion = block.sections.get("Motion")
    if isinstance(motion, Motion) and motion.mode in ("cw", "ccw") and motion.center is not None:
        _to_offsets(block, ctx, motion)  # (first: an error points at the block's text)
        block.changed()
    if code is not None:
        comments = block.sections.get("Comments")
        texts = list(comments.texts) if isinstance(comments, Comments) else []
        block.sections["Comments"] = Comments([*texts, NOTE.format(code=f"G{code[3]}")])
        block.changed()


def _to_offsets(block: Block, ctx: Context, motion: Motion) -> None:
    state = ctx.state
    first, second, _ = PLANE_AXES[state.plane if "Plane" not in block.sections
                                  else block.sections["Plane"].plane]  # type: ignore[attr-defined]
    centre = motion.center or {}
    for axis in (first, second):
        if axis not in centre:
            raise ProgramError(f"{_LETTER[axis]} word missing in an absolute centre arc (G90.1 gives both centre "
                               "coordinates of the plane)", ctx.at(block, ctx.column_of(block, "G")))
    if state.computes or state.symbolic:
        raise ProgramError("an arc with absolute centres (G90.1) in a program with variables or control flow is "
                           "not supported: its start is known only when the program runs",
                           ctx.at(block, ctx.column_of(block, _LETTER[first])))
    factor = 1.0
    units = block.sections.get("Units")
    if units is not None and units.system != state.units:  # type: ignore[attr-defined]
        factor = MM_PER_INCH if units.system == "mm" else 1.0 / MM_PER_INCH  # type: ignore[attr-defined]
    offsets: dict[str, float | Expr] = {}
    for axis, value in centre.items():
        start = state.position.get(axis)
        if start is None:
            raise ProgramError(f"an arc with absolute centres (G90.1) where the tool's {axis} position is unknown "
                               "(after a reference return, a move in machine coordinates or a computed position): "
                               "program a move to a known point first",
                               ctx.at(block, ctx.column_of(block, _LETTER.get(axis, "G"))))
        offsets[axis] = float(value) - start * factor  # type: ignore[arg-type]
    motion.center = offsets
