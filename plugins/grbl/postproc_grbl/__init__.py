"""grbl 1.1 (and grbl-class) controllers: a dialect plugin written as a third party would write one.

It registers through the ``postproc`` entry points and hooks only, and builds on the grbl family base
``postproc.grbl_family`` (shared with grblHAL: line rules, tool lengths, writer, reader). Writing is its purpose; it also
reads grbl (the RS274/NGC rules with grbl's code tables) so that ``postproc verify`` can simulate a
translated program from its text.

What grbl 1.1 accepts, from its parser ``grbl/gcode.c`` and ``grbl/protocol.c`` (github.com/gnea/grbl,
stored commit 0b5604b) and the "Grbl v1.1 Commands" wiki page (github.com/gnea/grbl/wiki):

* G0-G3 (arcs with I/J/K or R), G4 P (dwell in **seconds**), G10 L2/L20, G17-G19, G20/G21,
  G28/G30 (and .1), G38.2-G38.5, G40 only, G43.1/G49 (dynamic tool length offset only), G53,
  G54-G59, G61 only (exact path, grbl's one mode), G80, G90/G91, G91.1, G92/G92.1, G93/G94.
* M0, M1 (accepted and ignored: "Optional stop not supported"), M2, M30, M3/M4/M5, M8/M9, and M7
  only when built with ENABLE_M7. Every other M code is "Unsupported command" (error 20): **M6** (so
  there is no tool changer: a tool change is written as an M0 pause for a manual change) and **M19**
  (no oriented spindle stop).
* Words F I J K L N P R S T X Y Z. **No canned cycles** (G73-G89 and G98/G99 are unsupported, so the
  lowering expands them: NATIVE_CYCLES is empty), no G41/G42 (the compensated path is written instead,
  where the source's rules are modelled), **no G43 H** (no tool table: a G43 H
  is written as G43.1 Z with the register's value from the set-up, ``postproc.grbl_family.lengths``), no G95, no H, D
  or Q words, no parameters or expressions.
* T is read and ignored. ``( )`` and ``;`` comments are stripped by the protocol layer; ``/`` block
  delete is ignored (the block runs); ``%`` is not supported. A line keeps at most 79 characters
  (``LINE_BUFFER_SIZE`` 80, without spaces and comments), and ``?``, ``!``, ``~`` and bytes above 0x7F
  are real-time commands wherever they stand (``text.py``).

G74/G84 expand with M4/M3 spindle reversal (floating-holder tapping); G76/G87 need an oriented stop and
fail unless the set-up's ``<Cycles orientation="stop"|"m19">`` says how to stand in for it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, ClassVar

from postproc.syntaxes.comments import CommentSyntax
from postproc.cycle_words import CycleWords
from postproc.dialect import Dialect, Lazy, Reader
from postproc.grbl_family.dialect import GrblFamily
from postproc.hookspecs import hookimpl
from postproc.lowering.lazy_step import LazyStep
from postproc.output.line_format import LineRule
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory


if TYPE_CHECKING:
    from postproc.context import Context


write_tool_lengths = LazyStep("postproc.grbl_family.lengths:write_tool_lengths")
drop_resolved_tool_data = LazyStep("postproc.grbl_family.lengths:drop_resolved_tool_data")
lower_for_lean_controller = LazyStep("postproc.rs274.lean_controller:lower_for_lean_controller")


resolve_cutter_compensation = LazyStep("postproc.lowering.cutter_compensation:resolve_cutter_compensation")


class Grbl(GrblFamily):
    NAME = "grbl"
    LOWER_CASE: ClassVar[bool] = True
    """The reader takes lower-case words (the controller reads them as upper case)."""
    DESCRIPTION = "grbl 1.1 (no canned cycles, no tool changer, no tool table; G4 P in seconds)"
    READER = Lazy[type[Reader]](".reader:GrblReader")
    """Imported when a run first reads grbl (``Lazy``), as are the writer and the block syntax."""
    WRITER = Lazy[type[Writer]](".writer:GrblWriter")
    PIPELINE_FILE = "grbl.xml"
    CYCLE_WORDS = Lazy[CycleWords](".codes:CYCLE_WORDS")  # (its code table, imported where a run reads it)
    """R level, Q peck/shift, P dwell (seconds), L repeats."""
    NATIVE_CYCLES = frozenset()
    """No canned cycles: every cycle is expanded to G0/G1/G4/M3/M4/M5."""
    INVERSE_TIME_FEED = True
    """G93: a move in 1/F minutes [K: grbl wiki, "Commands": G93, G94 feed rate modes; its code table reads G93]."""
    SPINDLE_ORIENTATION = False
    """No M19: cycles that need an oriented stop follow the set-up's ``Cycles orientation``."""
    RIGID_TAP_LACK = "grbl 1.1 reads no spindle position: no G33, G33.1 or tap cycle [K: grbl wiki, Commands]"
    """Said where a rigid tap of another family is refused (no ``SYNCHRONISED_TAP``)."""
    TOOL_CHANGER = False
    """M6 is rejected: a tool change is written as an M0 pause (``pause_for_tool_change``)."""
    STOPS_BEFORE_MOTION = True
    """The RS274/NGC order of execution: M5 and M9 act before the block's motion."""
    FEED_BEFORE_UNITS = False
    """grbl reads F in the block's new units [K: grbl gcode.c converts F by the block's G20/G21]."""
    MIST_COOLANT = False
    """M7 runs only in a build with ENABLE_M7, off by default [K: grbl 1.1 config.h ``ENABLE_M7``; gcode.c
    answers error 20 without it]: a set-up says ``<Controller mistCoolant="true">`` for such a build."""
    LOWERING = (write_tool_lengths, resolve_cutter_compensation, drop_resolved_tool_data, lower_for_lean_controller)
    """Rewrites into what grbl runs: a G43 H as ``G43.1 Z<length>`` from the set-up's tool table
    (``postproc.grbl_family.lengths``); G41/G42 as the compensated path, where the source's rules are modelled
    (``postproc.lowering.cutter_compensation``); tool change as a pause, G49 before motion, full circles with an end point; a
    moving block's spindle stop and coolant off after it (grbl runs them before the motion:
    ``postproc.rs274.order_of_execution``)."""
    PATH_CONTROL = "exact_path"
    """grbl runs one mode, the exact path (G61, accepted and changing nothing): the tool goes through every
    programmed point, the junction deviation ($11) only slowing it at a corner [V: grbl ``gcode.h``
    ``CONTROL_MODE_EXACT_PATH // G61 (Default: Must be zero)``, the only group 13 code ``gcode.c`` accepts;
    the planner limits the junction speed, it does not round the path]. So a source's cutting mode (G64) and
    exact stop (G61) both run as programmed (``verify``)."""
    PATH_CONTROL_AT_START = "exact_path"
    """It is also the mode in force at power-on (the same ``gcode.h`` default): a program for a controller that
    powers on blending (Fanuc, LinuxCNC: G64) gets that controller's exact path code before the first move
    (LinuxCNC's G61, the same mode [V: ``g-code.adoc``]; Fanuc's G61, an exact stop [K]: the same points, the
    machine also stopping), so the corners this program reaches are reached there too
    (``postproc.lowering.path_at_start``). Towards a lathe whose table has no modal path code (Fanuc/GSK T) it
    is not written: the program asked for nothing, and refusing it would refuse every grbl lathe program."""
    CUTTER_COMPENSATION = False
    """Only G40."""
    TOOL_LENGTH_OFFSET = False
    """No tool table: a G43 H is written as grbl's own G43.1 with the register's value
    (``postproc.grbl_family.lengths``)."""
    DWELL_UNIT = "seconds"
    """G4 P is in seconds."""
    COMMENTS = Lazy[CommentSyntax](".text:COMMENTS")
    """``( )`` and ``;`` comments, without a real-time character inside (``text.py``)."""
    LINE_RULE = Lazy[LineRule](".text:LINES")
    """Every line written is ASCII without real-time characters and keeps at most 79 characters
    (``text.py``: grbl's ``serial.c`` and ``protocol.c``)."""

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``grbl.xml``, built in Python."""
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import GrblBlockSyntax
        return Pipeline(cls.NAME, [GrblBlockSyntax(), ModalStateSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Grbl)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("GrblBlockSyntax", f"{__name__}.block_syntax:GrblBlockSyntax")
