"""ModalStateSyntax: carries the modal state from block to block (neutral, every dialect uses it).

Runs after a dialect's block syntax and the cycle resolution: it applies each block's modal sections
to ``ctx.state`` and tracks the position, so later steps (cycle expansion, lowering) know where the
tool is. A position becomes unknown (None) after moves the IR cannot place, such as a reference return.
"""

from __future__ import annotations

from postproc.ir import Block, Motion
from postproc.syntax import Context, Syntax

_MODAL_MOTION = frozenset(("rapid", "linear", "cw", "ccw"))


class ModalStateSyntax(Syntax):
    XNAME = "ModalStateSyntax"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        sections = block.sections
        if not sections:
            return
        state = ctx.state
        s = sections.get("Units")
        if s is not None:
            state.set_units(s.system)  # type: ignore[attr-defined]
        s = sections.get("Plane")
        if s is not None:
            state.plane = s.plane  # type: ignore[attr-defined]
        s = sections.get("DistanceMode")
        if s is not None:
            state.distance = s.mode  # type: ignore[attr-defined]
        s = sections.get("FeedMode")
        if s is not None:
            state.feed_mode = s.mode  # type: ignore[attr-defined]
        s = sections.get("Feed")
        if s is not None:
            state.feed = s.value  # type: ignore[attr-defined]
        s = sections.get("SpindleSpeed")
        if s is not None:
            state.spindle_rpm = s.rpm  # type: ignore[attr-defined]
        s = sections.get("SpindleControl")
        if s is not None:
            state.spindle = s.direction  # type: ignore[attr-defined]
        s = sections.get("ReturnLevel")
        if s is not None:
            state.return_level = s.level  # type: ignore[attr-defined]
        s = sections.get("WorkOffset")
        if s is not None:
            state.work_offset = s.index  # type: ignore[attr-defined]
            _forget(state.position)
        s = sections.get("ToolSelect")
        if s is not None:
            state.tool = s.number  # type: ignore[attr-defined]
        motion = sections.get("Motion")
        if motion is not None:
            self._move(block, ctx, motion)  # type: ignore[arg-type]

    def _move(self, block: Block, ctx: Context, motion: Motion) -> None:
        state = ctx.state
        mode = motion.mode
        if mode in _MODAL_MOTION:
            state.motion = mode
        elif mode is None:
            return
        pos = state.position
        if mode in ("home", "home2") or "MachineCoordinates" in block.sections:
            for axis in motion.axes:
                pos[axis] = None
            return
        incremental = state.distance == "incremental"
        for axis, value in motion.axes.items():
            if incremental:
                old = pos.get(axis)
                pos[axis] = None if old is None else old + value
            else:
                pos[axis] = value


def _forget(position: dict[str, float | None]) -> None:
    """A new work offset moves the origin: the work position is unknown until programmed again."""
    for axis in position:
        position[axis] = None
