"""GrblFamilyWriter: the RS274 word writer with what the grbl family (grbl 1.1, grblHAL) writes alike.

* Neither parser takes ``%`` or a program number (``O`` is an o-word in grblHAL, an error in grbl): a tape
  mark and a program number are written as comments.
* A tool length offset from a register is written from the controller's tool table where the build has
  one (``GrblFamily.tool_table``), else it arrives as the dynamic offset with the register's length
  (``postproc.grbl_family.lengths``) [V: grbl ``gcode.c``; grblHAL core ``gcode.c``, the table offset needs
  ``grbl.tool_table.n_tools``].
* No build has M19 [V: neither ``gcode.c`` has an M19 case]: an oriented spindle stop follows the set-up's
  ``<Cycles orientation=...>``: ``m19`` writes M19 anyway (a build with a user M code for it), ``stop`` a
  program pause for the operator, ``error`` (default) refuses. M0 leaves the spindle turning, so a pause for
  the operator (also inside a cycle's expansion) stops a running spindle first with M5.
* Path control: both run one mode, the exact path (``G61``, group 13's only code without path blending
  [V: grbl ``gcode.h`` ``CONTROL_MODE_EXACT_PATH // G61 (Default: Must be zero)``; grblHAL core ``gcode.h``
  ``ControlMode_ExactPath``, G61.1/G64 only under ``ENABLE_PATH_BLENDING``]): every block ends on its programmed
  point, the junction deviation only slowing the tool at a corner. So a cutting mode (``G64``) writes nothing
  (its tolerance noted), and so does a one-shot exact stop (Fanuc ``G09``): the block already runs as it asks,
  its path is the one programmed (verify reads ``G09`` as changing nothing), only the stop at its end may be a
  slowdown at a corner's junction speed instead [K: the planner's junction speed].
"""

from __future__ import annotations

from typing import Any, ClassVar

from mypy_extensions import mypyc_attr

from postproc.ir import Block, ProgramControl, Section
from postproc.rs274.writer import WordWriter

from .dialect import GrblFamily


@mypyc_attr(allow_interpreted_subclasses=True)
class GrblFamilyWriter(WordWriter):
    """What grbl and grblHAL write alike (see the module docstring); each dialect's writer subclasses it."""

    MAX_BLOCK_NUMBER = GrblFamily.MAX_BLOCK_NUMBER
    """The family's limit (``GrblFamily.MAX_BLOCK_NUMBER``): a larger number of the source is dropped with a warning."""

    MACHINE_MOVE_INCREMENTAL_KNOWN: ClassVar[bool] = True
    """G53's words are machine positions under G91 too [V: grbl 1.1 / grblHAL gcode.c]."""

    def tool_table(self) -> bool:
        """The target build under this set-up runs ``G43 H`` from its tool table."""
        target = self.target
        return isinstance(target, type) and issubclass(target, GrblFamily) and target.tool_table(self.ctx.setup)

    def capable(self, flag: str) -> bool:
        """A tool table is the build's (``tool_table``), the other capabilities the dialect's."""
        if flag == "TOOL_LENGTH_OFFSET" and self.tool_table():
            return True
        return super().capable(flag)

    # -- blocks ------------------------------------------------------------------------------------
    def structure_block(self, block: Block) -> str | None:
        """The parser rejects '%': a tape mark is written as a comment."""
        return self.comment("%") + (block.eol or "\n")

    def item_line(self, item: Section, block: Block) -> str:
        """A pause inside an expansion is for the operator to work at the tool (orient it by hand, jog it
        out): M0 leaves the spindle turning, so a running spindle is stopped first."""
        line = super().item_line(item, block)
        pause = isinstance(item, ProgramControl) and item.kind == "stop"
        if pause and self.modal.spindle != "stop":
            self.modal.spindle = "stop"
            return self.code("spindle", "stop", "spindle stop", block) + "\n" + line
        return line

    # -- section words -----------------------------------------------------------------------------
    def path_control_words(self, s: Any, block: Block) -> list[str]:
        """Nothing for a cutting mode or a one-shot exact stop: the build's one mode (module docstring). An
        exact stop mode is written as that one mode's code, the exact path (G61: the same programmed points;
        grbl has no G61.1 [V: ``gcode.c``])."""
        if s.one_shot or s.mode == "cutting":
            if not s.one_shot:
                self.note_unwritten_tolerance(s, block)
            return []
        return self._code("path", "exact_path", f"path control {s.mode}", block)

    def program_start(self, s: Any, block: Block) -> str:
        """The parser takes no program number: it survives as a comment."""
        name = f"O{int(s.number):04d}" if s.number is not None else str(s.name)
        return self.comment(name)

    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        """``G43.1 Z<length>`` (what ``lengths.write_tool_lengths`` makes of a G43 H without a tool table),
        ``G43 H<n>`` from the build's tool table, or ``G49``."""
        if s.mode == "dynamic":
            if not isinstance(s.length, (int, float)):
                self.unsupported("a dynamic tool length offset whose length is computed", block)
            return [self.code("length", "dynamic", "a dynamic tool length offset", block), "Z" + self.number(s.length, "Z")]
        if s.mode != "cancel" and not (s.mode == "positive" and self.tool_table()):
            self.unsupported(self.table_refusal(s.register if isinstance(s.register, int) else None), block)
        return super().tool_length_offset_words(s, block)

    def table_refusal(self, register: int | None) -> str:
        """What cannot be written when a length offset from a table reaches a build without one (the
        dialect spells it with its codes)."""
        return f"a tool length offset from a table (register {register}; this build has no tool table)"

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        mode = self.ctx.setup.cycles.orientation
        if not isinstance(s.angle, (int, float)):  # kept symbolically (LinuxCNC M19 R#<a>): flattened instead
            self.unsupported("an oriented spindle stop at a computed angle", block)
            return []
        angle = float(s.angle)
        if mode == "m19":
            return [self.code("orient", None, "an oriented spindle stop", block)] + (
                [f"R{self.number(angle)}"] if angle else [])
        if mode == "stop":
            stop = self.code("spindle", "stop", "spindle stop", block)
            words = [] if self.modal.spindle == "stop" or "SpindleControl" in block.sections else [stop]
            self.modal.spindle = "stop"
            pause = self.code("program", "stop", "a program stop", block)
            note = self.comment(f"ORIENT THE SPINDLE TO {self.number(angle)} DEG BY HAND, THEN CYCLE START")
            return words + [pause, note]
        code = self.code("orient", None, "an oriented spindle stop", block)  # a row of every family table
        self.unsupported(f"an oriented spindle stop ({code}); a set-up with <Cycles orientation=\"stop\"/> "
                         "pauses for the operator instead", block)
        return []
