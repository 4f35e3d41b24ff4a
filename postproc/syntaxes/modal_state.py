"""ModalStateSyntax: carries the modal state from block to block (neutral, every dialect uses it).

Runs after a dialect's block syntax and the cycle resolution: it applies each block's modal sections
to ``ctx.state`` and tracks the position, so later steps (cycle expansion, lowering) know where the
tool is. A position becomes unknown (None) after moves the IR cannot place, such as a reference return.
"""

from __future__ import annotations

from typing import Any, Callable

from postproc.ir import Block, Motion
from postproc.state import ModalState
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
        state = ctx.state
        for key, section in sections.items():
            apply = _APPLY.get(key)
            if apply is not None:
                apply(state, section)
        motion = sections.get("Motion")
        if motion is not None:
            self._move(block, ctx, motion)  # type: ignore[arg-type]

    def _move(self, block: Block, ctx: Context, motion: Motion) -> None:
        state = ctx.state
        mode = motion.mode
        if mode in _MODAL_MOTION and "MachineCoordinates" not in block.sections:
            state.motion = mode
        elif mode is None:
            return
        pos = state.position
        if mode in ("home", "home2") or "MachineCoordinates" in block.sections:
            for axis in motion.axes:
                pos[axis] = None
            return
        if state.distance != "incremental":
            pos.update(motion.axes)
            return
        for axis, value in motion.axes.items():
            old = pos.get(axis)
            pos[axis] = None if old is None else old + value


def _work_offset(state: ModalState, s: Any) -> None:
    state.work_offset = s.index
    _forget(state.position)


_APPLY: dict[str, Callable[[ModalState, Any], None]] = {
    "Units": lambda st, s: st.set_units(s.system),
    "Plane": lambda st, s: setattr(st, "plane", s.plane),
    "DistanceMode": lambda st, s: setattr(st, "distance", s.mode),
    "FeedMode": lambda st, s: setattr(st, "feed_mode", s.mode),
    "Feed": lambda st, s: setattr(st, "feed", s.value),
    "SpindleSpeed": lambda st, s: setattr(st, "spindle_rpm", s.rpm),
    "SpindleControl": lambda st, s: setattr(st, "spindle", s.direction),
    "ReturnLevel": lambda st, s: setattr(st, "return_level", s.level),
    "WorkOffset": _work_offset,
    "ToolSelect": lambda st, s: setattr(st, "tool", s.number),
}
"""How each modal section changes the state; sections not listed change nothing here."""


def _forget(position: dict[str, float | None]) -> None:
    """A new work offset moves the origin: the work position is unknown until programmed again."""
    for axis in position:
        position[axis] = None
