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

_MODAL_MOTION = frozenset(("rapid", "linear", "cw", "ccw", "thread"))
LATHE_INCREMENTS = {"U": "X", "W": "Z"}
"""On a lathe, U and W are incremental X and Z whatever the distance mode (Fanuc T system A, GSK)."""


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
        if ctx.lathe and ("U" in motion.axes or "W" in motion.axes):
            _lathe_move(ctx, motion)
            return
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


def _lathe_move(ctx: Context, motion: Motion) -> None:
    """A lathe move with U/W words: each is an increment of X/Z, beside absolute X/Z words."""
    pos = ctx.state.position
    homing = motion.mode in ("home", "home2")
    for axis, value in motion.axes.items():
        target = LATHE_INCREMENTS.get(axis)
        if homing:
            pos[target or axis] = None
        elif target is None:
            if ctx.state.distance == "incremental":
                old = pos.get(axis)
                pos[axis] = None if old is None or isinstance(value, Expr) else old + value
            else:
                pos[axis] = None if isinstance(value, Expr) else value
        else:
            old = pos.get(target)
            pos[target] = None if old is None or isinstance(value, Expr) else old + value


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
    increments = ("U", "W") if ctx.lathe else ()
    if motion.radius is not None and not any(
            a in motion.axes and (state.distance != "incremental" or motion.axes[a] != 0.0) for a in (a1, a2)) \
            and not any(motion.axes.get(a, 0.0) != 0.0 for a in increments):
        # no end point in the plane: an R arc that ends where it starts, wherever that is
        _refuse(block, ctx, motion, ArcError("a full circle cannot be programmed with R (use I/J/K)", "R"))
    p1, p2 = state.position.get(a1), state.position.get(a2)
    if p1 is None or p2 is None:
        return
    s0, s1 = p1, p2
    incremental = state.distance == "incremental"
    end = [s0, s1]
    for i, axis in enumerate((a1, a2)):
        value = motion.axes.get(axis)
        if value is not None:
            end[i] = end[i] + value if incremental else value
        step = motion.axes.get(_INCREMENT_OF.get(axis, "")) if ctx.lathe else None
        if step is not None:
            end[i] = end[i] + step
    scale = MM_PER_INCH if state.units == "inch" else 1.0
    if ctx.diameter and "X" in (a1, a2):  # X words are diameters, the centre offset I a radius
        if a1 == "X":
            s0, end[0] = s0 / 2.0, end[0] / 2.0
        else:
            s1, end[1] = s1 / 2.0, end[1] / 2.0
    offsets = {a: v * scale for a, v in (motion.center or {}).items() if a in (a1, a2)}
    radius = None if motion.radius is None else motion.radius * scale
    try:
        arc_centre((s0 * scale, s1 * scale), (end[0] * scale, end[1] * scale), (a1, a2), radius,
                   offsets, motion.mode == "cw")
    except ArcError as err:
        _refuse(block, ctx, motion, err)


_CENTRE_LETTERS = {"X": "I", "Y": "J", "Z": "K"}
_INCREMENT_OF = {"X": "U", "Z": "W"}


def _refuse(block: Block, ctx: Context, motion: Motion, err: ArcError) -> NoReturn:
    """The arc goes from the block (reported once, here), and the tool's place is unknown after it."""
    del block.sections["Motion"]
    for axis in motion.axes:
        ctx.state.position[axis] = None
    raise err.located(ctx.at(block, ctx.column_of(block, err.letter))) from None
