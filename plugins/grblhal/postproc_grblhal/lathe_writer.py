"""grblHAL's writer of a lathe program (lathe mode, ``lathe``): the RS274/NGC lathe words
(``postproc.rs274.ngc_lathe_writer``: ``G18 G7`` first, G96 S D with the clamp in force, G33 with K) on grblHAL's
writer, with what grblHAL adds: G33 only with a spindle that reports its position (``<Controller
spindleSync="true">``), and no feed move under constant surface speed while the spindle is stopped (grblHAL's
error 41, ``Status_GcodeSpindleNotRunning`` [V: ``gcode.c``]). Its own class (``Grblhal.writer_class``), so a
mill program's writer is unchanged.
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.ir.event_order import after_motion
from postproc.ir import Block, Motion, SpindleControl
from postproc.ir.lathe_sections import SpindleMode
from postproc.rs274.ngc_lathe_writer import NgcLatheWriting

from .lathe import NO_SYNC_WRITTEN
from .writer import GrblhalWriter

_FEED_MOVES = frozenset(("linear", "cw", "ccw", "thread"))
"""The moves grblHAL checks the spindle for under G96 (all but G0 and G80)."""


class GrblhalLatheWriter(NgcLatheWriting, GrblhalWriter):
    """grblHAL's writer for a lathe program (module docstring)."""

    MODE_LINES: ClassVar[dict[str, str]] = {"diameter": "G18 G7", "radius": "G18 G8"}
    """The ZX plane and how X reads, first in a program translated here."""
    X_MODE_CODES: ClassVar[dict[str, str]] = {"diameter": "G7", "radius": "G8"}
    """A switch inside the program [V: gcode.c, ``diameter_mode``; ``block_syntax``]."""

    def write_block(self, block: Block) -> str | None:
        self.refuse_css_with_spindle_stopped(block)
        self.end_cycle(block)  # (a copied block too, as ``GrblhalOwnWriter``)
        return super().write_block(block)

    def refuse_css_with_spindle_stopped(self, block: Block) -> None:
        """A feed move, or a cycle's moves, under G96 while the spindle is stopped (module docstring): the
        block's own G96/G97 and its spindle start or stop (before the motion) come first."""
        sections = block.sections
        motion = sections.get("Motion")
        if not (isinstance(motion, Motion) and motion.mode in _FEED_MOVES and motion.axes) \
                and "CompoundMotion" not in sections:
            return
        mode = sections.get("SpindleMode")
        css = self.lathe.css if not isinstance(mode, SpindleMode) else mode.mode == "css"
        if not css:
            return
        control = sections.get("SpindleControl")
        turning = self.modal.spindle if not isinstance(control, SpindleControl) or after_motion("SpindleControl", control) \
            else control.direction
        if turning == "stop":
            self.unsupported("a feed move under constant surface speed (G96) while the spindle is stopped (grblHAL: "
                             "error 41, spindle not running)", block)

    def motion_words(self, s: Any, block: Block) -> list[str]:
        """G33 needs a spindle encoder (``lathe``)."""
        if s.mode == "thread" and not self.ctx.setup.controller.spindle_sync:
            self.unsupported(NO_SYNC_WRITTEN, block)
            return []
        return super().motion_words(s, block)
