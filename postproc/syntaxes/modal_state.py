"""ModalStateSyntax: carries the modal state from block to block (neutral, every dialect uses it).

Runs after a dialect's block syntax and the cycle resolution: it applies each block's modal sections
to ``ctx.state`` (``ModalState.apply``, the one place that says how a section changes the modal state,
shared with the writer and the simulator) and tracks the position, so later steps (cycle expansion, lowering) know where the
tool is. A position becomes unknown (None) after moves the IR cannot place, such as a reference return
or a computed coordinate (a program kept symbolically).
It also refuses a negative F or S (``postproc.block_rules``): every reading passes here, so
``translate``, ``toolpath`` and ``verify`` refuse them alike.
"""

from __future__ import annotations

from typing import NoReturn

from postproc.block_rules import ArcError, arc_centre, check_values
from postproc.expr import Expr
from postproc.ir import Block, Motion
from postproc.state import MM_PER_INCH, PLANE_AXES, changes_nothing
from postproc.context import Context
from postproc.syntax import Syntax

_MODAL_MOTION = frozenset(("rapid", "linear", "cw", "ccw"))


class ModalStateSyntax(Syntax):
    XNAME = "ModalStateSyntax"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        sections = block.sections
        if not sections:
            return
        if not changes_nothing(sections):
            ctx.state.apply(sections)
        motion = sections.get("Motion")
        if motion is not None:
            self._move(block, ctx, motion)  # type: ignore[arg-type]
        if "Feed" in sections or "SpindleSpeed" in sections:
            check_values(block, ctx)  # after the state is carried: an error keeps the block's settings

    def _move(self, block: Block, ctx: Context, motion: Motion) -> None:
        state = ctx.state
        mode = motion.mode
        if mode in _MODAL_MOTION and "MachineCoordinates" not in block.sections:
            state.motion = mode
        elif mode is None:
            return
        if mode == "cw" or mode == "ccw":
            _check_arc(block, ctx, motion)  # whatever else the block says: the simulator checks every arc
        pos = state.position
        if mode in ("home", "home2") or "MachineCoordinates" in block.sections:
            for axis in motion.axes:
                pos[axis] = None
            return
        if state.distance != "incremental":
            pos.update(motion.axes)
        else:
            for axis, value in motion.axes.items():
                old = pos.get(axis)
                pos[axis] = None if old is None or isinstance(value, Expr) else old + value
        if state.symbolic:
            for axis, value in motion.axes.items():
                if isinstance(value, Expr):
                    pos[axis] = None  # computed: known only when the program runs


def _check_arc(block: Block, ctx: Context, motion: Motion) -> None:
    """Refuse an arc no controller runs (``postproc.block_rules.arc_centre``) when its start is known,
    so ``translate`` refuses what ``toolpath`` refuses; an arc with a computed word waits for the run."""
    state = ctx.state
    a1, a2, _ = PLANE_AXES[state.plane]
    for axis in motion.center or {}:
        if axis not in (a1, a2):
            _refuse(block, ctx, motion, ArcError(f"arc centre offset along {axis} is outside the {state.plane} "
                                                 "plane", _CENTRE_LETTERS.get(axis, "G")))
    values = [*motion.axes.values(), *(motion.center or {}).values(), motion.radius]
    if any(isinstance(v, Expr) for v in values):
        return
    if motion.radius is not None and not any(
            a in motion.axes and (state.distance != "incremental" or motion.axes[a] != 0.0) for a in (a1, a2)):
        # no end point in the plane: an R arc that ends where it starts, wherever that is
        _refuse(block, ctx, motion, ArcError("a full circle cannot be programmed with R (use I/J/K)", "R"))
    start = (state.position.get(a1), state.position.get(a2))
    if start[0] is None or start[1] is None:
        return
    incremental = state.distance == "incremental"
    end = [start[0], start[1]]
    for i, axis in enumerate((a1, a2)):
        value = motion.axes.get(axis)
        if value is not None:
            end[i] = end[i] + value if incremental else value
    scale = MM_PER_INCH if state.units == "inch" else 1.0
    offsets = {a: v * scale for a, v in (motion.center or {}).items() if a in (a1, a2)}
    radius = None if motion.radius is None else motion.radius * scale
    try:
        arc_centre((start[0] * scale, start[1] * scale), (end[0] * scale, end[1] * scale), (a1, a2), radius,
                   offsets, motion.mode == "cw")
    except ArcError as err:
        _refuse(block, ctx, motion, err)


_CENTRE_LETTERS = {"X": "I", "Y": "J", "Z": "K"}


def _refuse(block: Block, ctx: Context, motion: Motion, err: ArcError) -> NoReturn:
    """The arc goes from the block (reported once, here), and the tool's place is unknown after it."""
    del block.sections["Motion"]
    for axis in motion.axes:
        ctx.state.position[axis] = None
    raise err.located(ctx.at(block, ctx.column_of(block, err.letter))) from None
