"""``--on-unsupported warn``: what a dropped move leaves behind, and the moves that may follow it.

A block written without its motion (a thread move the target lacks, a hole cycle, a verbatim code with axis
words) leaves the tool where the move started, not where it ended: every later move that takes its start
for granted would run displaced (an arc's centre offsets, an incremental word, a straight move that keeps
a displaced axis where it is), and an arc would even be invalid (grbl refuses an R arc whose chord grew).
So from the drop on, the axes the dropped move programmed are displaced, and each is put right only by
a straight move (rapid or feed) that programs it absolutely; any other move before all are put right
fails the translation at its line, naming the drop. (What the dropped move itself would have cut is gone:
the warning says so.) The distance mode is followed from the blocks written, absolute at the start, as on
every controller here.
"""

from __future__ import annotations

from typing import Any, Final, Mapping

from ..ir.event_order import MOVING
from ..ir import Block

_STRAIGHT: Final = frozenset(("rapid", "linear"))
"""Motion modes whose end point does not depend on where they start (when programmed absolutely)."""
_MOVES: Final = MOVING | {"Motion", "NativeCode"}
"""Sections whose drop may leave the tool elsewhere (a verbatim code only with axis words)."""


class Displacement:
    """The axes a dropped move left elsewhere, and the source line of that drop."""

    __slots__ = ("axes", "line", "incremental", "increments", "machine_axes")

    def __init__(self, increments: Mapping[str, str], machine_axes: frozenset[str]) -> None:
        self.axes: set[str] = set()
        """The displaced axes (empty: every axis is where the source puts it). One set for the run, changed in
        place, never replaced: the writer's loop holds it (``Writer._write``)."""
        self.line = 0
        self.incremental = False
        """The distance mode of the blocks written so far (``note``)."""
        self.increments = increments
        """The reading dialect's incremental addresses (U -> X on a lathe)."""
        self.machine_axes = machine_axes

    def note(self, sections: dict[str, Any]) -> None:
        """Follow the distance mode (called for a block that has a ``DistanceMode``)."""
        self.incremental = sections["DistanceMode"].mode == "incremental"

    def dropped(self, block: Block, keys: set[str]) -> None:
        """The writer left out ``keys`` of ``block``: the axes its motion would have moved are displaced."""
        if _MOVES.isdisjoint(keys):
            return
        moved = self._moved(block, keys)
        if moved:
            if not self.axes:
                self.line = block.line
            self.axes |= moved

    def lowered(self, lines: list[int]) -> None:
        """A lowering step dropped the moves of these source lines (a hole cycle): every axis is displaced."""
        if not self.axes:
            self.line = lines[0]
        self.axes |= self.machine_axes
        lines.clear()

    def problem(self, block: Block) -> str | None:
        """Why ``block`` cannot be written exactly after the drop (None: it can, or it does not move);
        a straight absolute move puts right the displaced axes it programs."""
        sections = block.sections
        if MOVING.isdisjoint(sections.keys()) and not _moving_native(sections):
            motion = sections.get("Motion")
            axes = getattr(motion, "axes", None)
            if not axes:
                return None
            incremental = self.incremental
            distance = sections.get("DistanceMode")
            if distance is not None:
                incremental = distance.mode == "incremental"  # type: ignore[attr-defined]
            increments = self.increments  # a lathe's U/W start from the displaced point, as G91 words do
            if getattr(motion, "mode", None) in _STRAIGHT and not incremental \
                    and (not increments or increments.keys().isdisjoint(axes)):
                still = self.axes - axes.keys()
                if not still:
                    self.axes.clear()
                    return None
                return self._message(still)
        return self._message(self.axes)

    def _message(self, axes: set[str]) -> str:
        named = "".join(sorted(axes))
        return (f"this move would start or run {'axis' if len(axes) == 1 else 'axes'} {named} where the move "
                f"dropped at line {self.line} left them, not where the source has them: after a dropped move, "
                "only straight moves to absolute points of every axis it moved can be written exactly "
                "(--on-unsupported warn fails here rather than write a displaced program)")

    def _moved(self, block: Block, keys: set[str]) -> set[str]:
        """The axes the dropped sections move: a motion's words; a cycle or a verbatim code, every axis
        it has a word for, or every axis of the machine (a cycle moves what its words do not say)."""
        sections = block.sections
        moved: set[str] = set()
        if "Motion" in keys:
            motion = sections.get("Motion")
            for letter in getattr(motion, "axes", None) or ():
                moved.add(self.increments.get(letter, letter))
        if not MOVING.isdisjoint(keys):
            moved |= self.machine_axes
        if "NativeCode" in keys:
            moved |= {self.increments.get(l.upper(), l.upper()) for l, _ in block.words} & self.machine_axes
        return moved


def _moving_native(sections: dict[str, Any]) -> bool:
    """A verbatim code that moves (it has axis words): its end point is unknown here."""
    native = sections.get("NativeCode")
    motion = sections.get("Motion")
    return native is not None and bool(getattr(motion, "axes", None))
