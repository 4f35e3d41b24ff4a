"""LinuxCNC (RS274/NGC) milling and lathe dialect, shipped as a separate plugin distribution.

It registers through the ``postproc`` entry-point group and hooks, exactly as a third party would.
Reading follows the RS274/NGC rules (DIALECTS.md §2.1 "LinuxCNC / RS274-NGC baseline"): numbers
without decimal-point scaling, ``;`` comments, ``L`` repeats, G98 as "retract to the old Z when it is
above R", R-plane retract (G99) at start-up as in LinuxCNC's interpreter. O-words (subprograms, loops,
conditions), numbered and named parameters and expressions are read into control sections and
expression values: kept symbolically for a target that has them, run by ``LinuxcncProgramSyntax``
otherwise. Fanuc-style numbered subprograms (``O100`` ... ``M99``, ``M98 P L``) are read (``calls``) and
run as rs274 runs them (``postproc.interp.rules``).
"""

from __future__ import annotations

from typing import Callable, ClassVar

from postproc.rs274.cutter_rules import ARC_CORNERS
from postproc.cycle_words import CycleWords
from postproc.dialect import Dialect, Lazy, Reader
from postproc.rs274.cycle_semantics import RS274 as RS274_CYCLES
from postproc.rs274.order_of_execution import stops_after_motion
from postproc.rs274.arc_ends import RS274NGC_ARC_END
from postproc.errors import Diagnostics
from postproc.hookspecs import hookimpl
from postproc.output.line_format import LineRule
from postproc.lowering.lazy_step import LazyStep
from postproc.lowering.lower import Lowering
from postproc.setup.machine_setup import MachineSetup
from postproc.context import Context
from postproc.rs274.variables import NGC_POSITION_READS
from postproc.syntaxes.syntax import Pipeline
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory


from .active_comments import COMMENTS, warn_active_comments

nest_forward_jumps = LazyStep("postproc.lowering.structured_jumps:nest_forward_jumps")

NATIVE = frozenset({
    "drill", "drill_dwell", "peck_chip", "peck_deep", "tap", "tap_left", "bore_feed", "bore_stop",
    "bore_dwell_feed",
})


_thread_feed_apart = LazyStep(f"{__name__}.lathe_writer:feed_apart", lathe_only=True)


_subprogram_layout = LazyStep(f"{__name__}.layout:subprograms_after_callers")
_exact_stop_for_one_block = LazyStep(f"{__name__}.exact_stop:exact_stop_for_one_block")


class Linuxcnc(Dialect):
    NAME = "linuxcnc"
    LOWER_CASE: ClassVar[bool] = True
    """The reader takes lower-case words (the controller reads them as upper case)."""
    DESCRIPTION = "LinuxCNC 2.9 milling and turning (RS274/NGC with O-words, parameters and expressions)"
    READER = Lazy[type[Reader]](".reader:LinuxcncReader")
    """Imported when a run first reads LinuxCNC (``Lazy``), as are the writer and the syntax objects (with
    the O-word and expression readers)."""
    WRITER = Lazy[type[Writer]](".writer:LinuxcncWriter")
    LATHE_WRITER = Lazy[type[Writer]](".lathe_writer:LinuxcncLatheWriter")
    """The writer of a lathe program (``writer_class``): its own class, so a mill's keeps the fast lane."""
    PIPELINE_FILE = "linuxcnc.xml"
    LATHE_PIPELINE_FILE = "linuxcnc_lathe.xml"
    """A lathe's: its block step follows the G70-G72 cycles' profiles (``block_syntax.NgcLatheBlockSyntax``)."""
    CYCLE_WORDS = Lazy[CycleWords](".codes:CYCLE_WORDS")  # (its code table, imported where a run reads it)
    """R level, Q peck/shift, P dwell (seconds), L repeats."""
    NATIVE_CYCLES = NATIVE
    """G73, G74, G81-G86, G89. Not G76 (threading here), G87/G88 (RS274/NGC words and motion), and
    there is no fine boring: those are expanded."""
    TAPE_MARKS = True
    """``%`` lines may delimit a program (RS274/NGC); there is no program number (O is an O-word)."""
    SYNCHRONISED_TAP = True
    """G33.1 Z.. K..: a rigid tap, spindle-synchronised in and out (``rigid_tap``); another family's rigid
    tap cycle (Fanuc M29 + G84/G74) is written with it."""
    LENGTH_AT_PROGRAMMED_AXIS = True
    """[V: rs274 2.9 run here: ``T1 M6`` ``G43`` then ``G0 X1`` keeps the machine Z (the program Z shifts by
    the length, ``STRAIGHT_TRAVERSE(1, 0, 4)`` from Z5 with length 1); the next ``Z2`` ends at 2 + 1; a
    ``G91 Z-1`` moves by -1; after ``G49``, ``X3`` again keeps the machine Z]."""
    DYNAMIC_TOOL_LENGTH = True
    """``G43.1 Z..`` (and its other axes) [V: rs274 2.9 runs it]."""
    POSITION_READS = NGC_POSITION_READS
    """``#5420``-``#5428``: the current position, set from ``current_x``.. each time a block is read, so a read
    in a block that changes the tool offset sees the point before the change [V: ``rs274ngc_pre.cc``
    ``Interp::read``; rs274 2.9.0~pre1 run here: ``G43 H2 X30 Z#5422`` from Z5 moves to program Z5 under the new
    offset]."""
    POSITION_READ_RADIUS = True
    """[V: ``interp_read.cc`` ``read_x`` halves an X word in diameter mode; ``#5420`` is ``current_x``]."""
    CUTTER_RULES = ARC_CORNERS
    """rs274's cutter radius compensation: tangent entry, arcs around outside corners."""
    ARC_END = RS274NGC_ARC_END
    """The interpreter's arc end tolerance, inch and mm, absolute and relative (``postproc.rs274.arc_ends``)."""
    PROGRAMS = True
    """Numbered and named parameters, expressions, o-word subprograms and control flow."""
    STOPS_BEFORE_MOTION = True
    """The RS274/NGC order of execution: M5 and M9 act before the block's motion."""
    FEED_BEFORE_UNITS = True
    """F in a block that changes units is in the old units [V: rs274 prints ``SET_FEED_RATE`` before
    ``USE_LENGTH_UNITS``, its order of execution]."""
    COMMENTS = COMMENTS
    """``( )`` and ``;`` comments; ``(MSG,`` ``(LOGOPEN,`` ... act (``active_comments.WORDS``)."""
    LINE_RULE = Lazy[LineRule](".lines:LINES")
    """rs274 reads at most 252 bytes a line: a longer comment is shortened (``lines.py``)."""
    LOWERING = (nest_forward_jumps, stops_after_motion, _subprogram_layout, _thread_feed_apart,
                _exact_stop_for_one_block)
    """Another dialect's forward jumps as ``o.. if`` .. ``endif`` (or ``break``) and ``UNTIL`` as ``o.. do`` ..
    ``while`` where they have that shape, exact equalities in conditions as two exact comparisons
    (``postproc.lowering.structured_jumps``). A moving block's spindle stop and coolant off go in a block of
    their own after it: LinuxCNC runs them before the motion (``postproc.rs274.order_of_execution``); another dialect's subprograms stand
    after their callers, and a cycle gets the return level its source assumed (``layout``); a thread
    block's F goes on a line before it (``lathe_writer.feed_apart``: G33 refuses F); a one-shot exact stop is
    G61 for its block, then the mode before (``exact_stop``: rs274 refuses G9)."""
    CYCLE_SEMANTICS = RS274_CYCLES.name
    """How the native cycles move: start below R rises to R first, G98 returns to the old Z only when
    it is above R, G91 R is measured from the Z at the block's start, G74/G84/G89 feed out to the
    clear level, G73/G83 clearances are fixed (0.254 mm / 0.010 in)."""
    INVERSE_TIME_FEED = True
    """G93: a move in 1/F minutes [V: LinuxCNC G-code manual, interp_convert.cc]."""
    DWELL_UNIT = "seconds"
    """G4 P and a cycle's P are seconds."""
    START_RETURN_LEVEL = "r"
    """The retract mode in force at program start (LinuxCNC's interpreter starts in G99)."""
    MACHINE_TYPES = frozenset({"mill", "lathe"})
    """Mills and lathes (the set-up's ``machineType``; mill when it says nothing). A lathe reads G7/G8, G33 K,
    G96 S D into lathe sections (``postproc.rs274.ngc_lathe``), G76 into its moves (``threading``) and the
    RS274/NGC lathe cycles G70-G72.2 into theirs (``lathe_cycles``)."""
    DIAMETER_PROGRAMMING = True
    """G7: X is a diameter (G8 a radius), per the set-up's ``xProgramming``; a translation writes the mode
    (and G18) before its first block, as a LinuxCNC lathe's start-up code may say either [K: the
    interpreter starts in G17 and radius mode unless the ini's RS274NGC_STARTUP_CODE says otherwise]."""
    X_MODE_SWITCH = True
    """G7/G8 inside a lathe program are read and kept (``postproc.rs274.ngc_lathe``)."""
    LATHE_FEED_AT_START = "per_min"
    """LinuxCNC starts in G94, units per minute [K: RS274/NGC default; V: rs274 resets to
    ``SET_FEED_MODE(0, 0)`` at the program end]."""
    LATHE_TURRET = False
    """A lathe tool is changed as a mill's, ``T1 M6`` (its offsets from the tool table): a Fanuc-family
    turret index ``T0101`` is written so (``postproc.cycles.lathe_lowering``)."""
    PECK_CLEARANCE_MM = 0.254
    """G73 retract and G83 re-approach clearance: a constant of the interpreter (0.010 in), not a
    machine parameter, so reading LinuxCNC uses it whatever the set-up's ``Cycles`` say, and a peck
    cycle read with another is expanded for LinuxCNC."""

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``linuxcnc.xml`` (a lathe's ``linuxcnc_lathe.xml``), built in Python."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import NgcBlockSyntax, NgcLatheBlockSyntax
        from .polar import PolarSyntax
        from .program import LinuxcncProgramSyntax
        block = NgcLatheBlockSyntax() if cls.reads_lathe(setup) else NgcBlockSyntax()
        return Pipeline(cls.NAME, [LinuxcncProgramSyntax(), PolarSyntax(), block,
                                   CannedCycleResolveSyntax("rs274"), ModalStateSyntax()])

    @classmethod
    def pipeline_file(cls, setup: MachineSetup) -> str | None:
        """``LATHE_PIPELINE_FILE`` on a lathe set-up, else ``PIPELINE_FILE``."""
        return cls.LATHE_PIPELINE_FILE if cls.reads_lathe(setup) else cls.PIPELINE_FILE

    @classmethod
    def writer_class(cls, ctx: Context) -> type[Writer] | None:
        """``LATHE_WRITER`` for a lathe program, and for a mill program on a set-up LinuxCNC reads as a lathe's
        (its mode line says X is a radius, as the mill's X is: LinuxCNC's lathe may start in G7), else ``WRITER``."""
        return cls.LATHE_WRITER if ctx.lathe or cls.reads_lathe(ctx.setup) else cls.WRITER

    @classmethod
    def context(cls, file: str, setup: MachineSetup, diagnostics: Diagnostics) -> Context:
        ctx = super().context(file, setup, diagnostics)
        ctx.state.return_level = cls.START_RETURN_LEVEL
        return ctx


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Linuxcnc)


@hookimpl
def postproc_register_lowerings(register: Callable[[Lowering], None]) -> None:
    """Active comments (``(MSG,..)``, ``(DEBUG,..)``...) warn when a translation makes them inert."""
    register(warn_active_comments)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("NgcBlockSyntax", f"{__name__}.block_syntax:NgcBlockSyntax")
    factory.register_lazy("NgcLatheBlockSyntax", f"{__name__}.block_syntax:NgcLatheBlockSyntax")
    factory.register_lazy("LinuxcncProgramSyntax", f"{__name__}.program:LinuxcncProgramSyntax")
    factory.register_lazy("PolarSyntax", f"{__name__}.polar:PolarSyntax")
    factory.register_lazy("DynamicCutterCompensation",
                          "postproc.compensation.dynamic:DynamicCutterCompensation")
