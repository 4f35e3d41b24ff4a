"""grblHAL controllers: a dialect plugin on the grbl family base (``postproc.grbl_family``), written as a third
party would write one. It registers through the ``postproc`` entry points and hooks only.

What grblHAL accepts, from its source (github.com/grblHAL/core, stored commit f80fc34, ``GRBL_BUILD``
20260817), tagged [V] where read there:

* grbl 1.1's codes [V: ``gcode.c``], and: G43 H from the tool table and G43.2, only with a tool table
  (``N_TOOLS`` above 0, default 0 in ``config.h``, or a tool table plugin: ``grbl.tool_table.n_tools``);
  G59.1-G59.3 (nine work systems with ``COMPATIBILITY_LEVEL`` <= 1, the default); G95 feed per revolution,
  only with a spindle that reports its position (``spindle->hal->get_data``); G98/G99; M6 (every build: the
  ``$341`` setting asks for a manual change or ignores it, an ATC runs it); G5/G5.1 splines, G10 L1/L10/L11
  (tool data), G92.3, M61-M68 and M70-M73 kept verbatim. G92, G92.1 and G92.2 are LinuxCNC's, simulated and
  evaluated for other targets as grbl's G92 (``codes``).
* Canned cycles G73, G81-G89 are parsed; the motion control runs G73 and G81-G84 (``motion_control.c``
  ``mc_canned_drill``), G85/G86/G89 are "not implemented" (``gcode.h``). G81/G82 move as RS274/NGC's
  except for G98's level (``cycles``), so they stay native where the source's cycle moves alike; G73/G83
  (a 0.25 s dwell at each peck, G83 feeding from the retract level: ``pecking``) are read as grblHAL runs them
  and expanded from any other family; the experimental G84 is expanded.
* Parameters, expressions (LinuxCNC's operators, precedence and functions: ``ngc_expr.c``) and o-word
  flow control (``ngc_flowctrl.c``: if/elseif/else/endif, do/while/endwhile, repeat/endrepeat,
  break/continue, sub/endsub/call/return; loops and subroutines only in a program run from the
  controller's file system) exist only with ``NGC_EXPRESSIONS_ENABLE`` (off by default): read and written
  for a set-up that says the build has them (``<Controller expressions="true">``, ``program``); numbered subs
  as grblHAL runs them (``reader``, ``variables``), Fanuc-style subprograms as subs (``subprograms``), named
  subs refused. G65/G66 and M98 need a macro plugin (``grbl.on_macro_execute``): refused.
* Lathe mode (``$32``): G7/G8, G33 K, G96 S D/G97 read and written on a lathe set-up (``lathe``), with G95 and
  G43 H as a mill's; its G76 threading cycle read into its moves (``threading``, kept native in a grblHAL
  program; another controller's threading cycle is written as G33 passes); G70-G72 (``LATHE_UVW_OPTION``) are
  not in the core (``mc_lathe_cycle`` is a weak stub answering "unsupported command": refused; another
  controller's roughing cycles are written as their moves); G41/G42 only with
  ``CUTTER_COMP_ENABLE`` (off, experimental): the compensated path is written instead, as for grbl. No G52,
  G44 or M19.
* ``( )`` and ``;`` comments; ``/`` block delete at the start of a block; a line keeps 256 characters
  (``LINE_BUFFER_SIZE`` 257, ``protocol.h``), comments and spaces included; ``?``, ``!``, ``~`` and bytes above
  0x7F are real-time commands (``text``).

What a build chooses is said by the set-up's ``<Controller toolTable spindleSync mistCoolant expressions>``,
read where a program is read and written.
"""

from __future__ import annotations

from typing import Callable, ClassVar, Mapping, TYPE_CHECKING

from postproc.syntaxes.comments import CommentSyntax
from postproc.cycle_words import CycleWords
from postproc.dialect import Dialect, Lazy, Reader, ResolvedCycle
from postproc.rs274.cycle_semantics import RS274 as RS274_CYCLES
from postproc.grbl_family.dialect import GrblFamily
from postproc.hookspecs import hookimpl
from postproc.lowering.lazy_step import LazyStep
from postproc.output.line_format import LineRule
from postproc.output.writer_base import Writer
from postproc.rs274.order_of_execution import stops_after_motion
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.xmlio import XFactory


comment_numbered_subs_after_end = LazyStep("postproc.lowering.program_end:comment_numbered_subs_after_end")

if TYPE_CHECKING:
    from postproc.context import Context


write_tool_lengths = LazyStep("postproc.grbl_family.lengths:write_tool_lengths")
drop_resolved_tool_data = LazyStep("postproc.grbl_family.lengths:drop_resolved_tool_data")
close_full_circles = LazyStep("postproc.rs274.lean_controller:close_full_circles")


cancel_cycles_alone = LazyStep(f"{__name__}.cancels:cancel_cycles_alone")
resolve_cutter_compensation = LazyStep("postproc.lowering.cutter_compensation:resolve_cutter_compensation")
thread_feed_apart = LazyStep("postproc.rs274.ngc_lathe_writer:feed_apart", lathe_only=True)
subprograms_as_subs = LazyStep(f"{__name__}.subprograms:subprograms_as_subs")


class Grblhal(GrblFamily):
    NAME = "grblhal"
    LOWER_CASE: ClassVar[bool] = True
    """The reader takes lower-case words (the controller reads them as upper case)."""
    DESCRIPTION = ("grblHAL (G81/G82 native, its G73/G83 read, M6, a tool table, G95 and o-word subs where the build "
                   "has them; lathe mode: G7, G96 S D, G33 K; G4 P in seconds)")
    READER = Lazy[type[Reader]](".reader:GrblhalReader")
    """Imported when a run first reads grblHAL (``Lazy``), as are the writer and the block syntax."""
    WRITER = Lazy[type[Writer]](".writer:GrblhalWriter")
    LATHE_WRITER = Lazy[type[Writer]](".lathe_writer:GrblhalLatheWriter")
    """The writer of a lathe program (``writer_class``)."""
    OWN_WRITER = Lazy[type[Writer]](".writer:GrblhalOwnWriter")
    """The writer of a grblHAL mill program written back to grblHAL (``writer_class``)."""
    PIPELINE_FILE = "grblhal.xml"
    CYCLE_WORDS = Lazy[CycleWords](".codes:CYCLE_WORDS")  # (its code table, imported where a run reads it)
    """R level, P dwell (seconds), L repeats."""
    NATIVE_CYCLES = frozenset({"drill", "drill_dwell"})
    """G81 and G82, kept native where they move as the source's cycle (``moves_like``); every other cycle
    is expanded."""
    PECK_CLEARANCE_MM = 0.1
    """G73's retract after each peck: the setting ``$73``, 0.1 mm by default [V: ``config.h``
    ``DEFAULT_G73_RETRACT``; a build whose ``$73`` differs is not modelled]. G83 has no clearance (``pecking``)."""
    CYCLE_SEMANTICS = RS274_CYCLES.name
    """grblHAL's G81/G82 are read under RS274/NGC rules (``cycles``: a block where grblHAL's G98 differs is
    refused when read, expanded when written)."""
    INVERSE_TIME_FEED = True
    """G93: a move in 1/F minutes [V: gcode.c, ``FeedMode_InverseTime``]."""
    SPINDLE_ORIENTATION = False
    """No M19: cycles that need an oriented stop follow the set-up's ``Cycles orientation``."""
    TOOL_CHANGER = True
    """M6 is accepted by every build (``$341``: a manual change, or ignored; an ATC runs it). Whether the spindle
    keeps turning through it depends on ``$341``: the core stops it only in ``tool_change.c``'s ``tool_change``,
    installed for modes 1-3; under 4 ("Ignore M6") the T word selects the tool at once [V: ``gcode.c``,
    ``tool_change.c`` ``tc_init``]: a lathe set-up says ``<Controller toolChangeWithSpindleOn="true"/>`` for such a
    build (``tests/test_grblhal_tool_change.py``)."""
    STOPS_BEFORE_MOTION = True
    """The RS274/NGC order of execution: M5 and M9 act before the block's motion (grbl's ``gcode.c``)."""
    FEED_BEFORE_UNITS = False
    """grblHAL reads F in the block's new units [K: its gcode.c, grbl's, converts F by the block's G20/G21]."""
    MIST_COOLANT = False
    """M7 runs only with a driver that has mist coolant [V: gcode.c, ``hal.coolant_cap.mist``]: a set-up says
    ``<Controller mistCoolant="true">`` for such a build."""
    LOWERING = (write_tool_lengths, resolve_cutter_compensation, drop_resolved_tool_data, close_full_circles, cancel_cycles_alone,
                stops_after_motion, subprograms_as_subs, comment_numbered_subs_after_end, thread_feed_apart)
    """Rewrites into what grblHAL runs: a G43 H as ``G43.1 Z<length>`` where the build has no tool table
    (``postproc.grbl_family.lengths``); G41/G42 as the compensated path, where the source's rules are modelled;
    a full circle with an end point in its plane (grbl's arc rules, ``postproc.rs274.lean_controller``); a cycle
    cancel beside an axis command in a block of its own (``cancels``: it is written as a bare G0); a moving block's spindle stop and coolant off after it (``postproc.rs274.order_of_execution``); ``M98`` subprograms as o-word subs written before the first call, on a build with expressions (``subprograms``); a numbered definition no call made a sub, left after the end, as comments (grblHAL reads only ``o<n> sub`` [V: ngc_flowctrl.c]: it was live code after the end); a thread block's F on a line before it (the lathe writer writes K: ``postproc.rs274.ngc_lathe_writer.feed_apart``). Not grbl's
    G49 before motion: grblHAL's G49 is no axis command [V: gcode.c, "changed to match LinuxCNC behaviour in
    build 20210513"], nor its tool change pause (M6 exists)."""
    MACHINE_TYPES = frozenset({"mill", "lathe"})
    """Mills and lathes (the set-up's ``machineType``): a lathe set-up is grblHAL's lathe mode, ``$32``
    (``lathe``)."""
    DIAMETER_PROGRAMMING = True
    """G7: X is a diameter (G8 a radius), per the set-up's ``xProgramming``; a translation writes ``G18 G7``
    before its first block [V: gcode.c, G7/G8 set ``diameter_mode`` in lathe mode]."""
    X_MODE_SWITCH = True
    """G7/G8 inside a lathe program are read and kept (``block_syntax``)."""
    LATHE_FEED_AT_START = "per_min"
    """grblHAL starts in G94 [K: grbl's power-on modes, ``gc_init``]."""
    LATHE_TURRET = False
    """A lathe tool is changed with M6 and its offsets applied by ``G43 H`` (``lathe``): ``T0101`` is written
    ``T1 M6`` .. ``G43 H1`` (``postproc.cycles.lathe_lowering``)."""
    PATH_CONTROL = "exact_path"
    """grblHAL runs grbl's one mode, the exact path (G61 changes nothing; ``ENABLE_PATH_BLENDING``, G64, is
    off in every build): the tool goes through every programmed point, the junction deviation only slowing it
    at a corner [V: grblHAL core ``gcode.h`` ``control_mode_t``: ``ControlMode_ExactPath`` "G61 - Default"; G61.1 and G64
    only under ``ENABLE_PATH_BLENDING``]."""
    PATH_CONTROL_AT_START = "exact_path"
    """It is also the mode in force at power-on (the same ``gcode.h`` default): a program for a controller that
    powers on blending (Fanuc, LinuxCNC: G64) gets that controller's exact path code before the first move
    (LinuxCNC's G61, the same mode [V: ``g-code.adoc``]; Fanuc's G61, an exact stop [K]: the same points, the
    machine also stopping), so the corners this program reaches are reached there too
    (``postproc.lowering.path_at_start``). Towards a lathe whose table has no modal path code (Fanuc/GSK T) it
    is not written: the program asked for nothing, and refusing it would refuse every grbl lathe program."""
    CUTTER_COMPENSATION = False
    """Only G40 (``CUTTER_COMP_ENABLE`` is off, experimental)."""
    TOOL_LENGTH_OFFSET = False
    """No tool table in a default build (``N_TOOLS`` 0): ``<Controller toolTable="true">`` says a build has one
    (``tool_table``); without it a G43 H is written as G43.1 with the register's value."""
    DWELL_UNIT = "seconds"
    """G4 P is in seconds."""
    PROGRAMS = True
    """Parameters, expressions and o-word conditions and loops, on a build with them (``<Controller
    expressions="true">``: ``expressions``); on any other the writer refuses every statement, so a program
    that computes reaches grblHAL flattened."""
    POSITION_READS: ClassVar[Mapping[str, int]] = {}
    """None written: a build with expressions reads #5420-#5428 as the steppers' position less the offsets when the
    block is parsed [V: grblHAL core ``ngc_params.c`` ``work_position``, ``sys.position``], which runs ahead of
    the planner's queued moves; whether the parser waits for them there is not known [?], so a read is not the
    previous block's end as LinuxCNC's is (``postproc.lowering.length_timing`` refuses instead)."""
    TAPE_MARKS = False
    """``%`` is no word of grblHAL's parser: written as a comment."""
    COMMENTS = Lazy[CommentSyntax](".text:COMMENTS")
    """``( )`` and ``;`` comments, without a real-time character inside (``postproc.grbl_family.text``)."""
    LINE_RULE = Lazy[LineRule](".text:LINES")
    """Every line written is ASCII without real-time characters and keeps at most 256 characters."""

    @classmethod
    def writer_class(cls, ctx: Context) -> type[Writer] | None:
        """``LATHE_WRITER`` for a lathe program (grblHAL's lathe mode) and for a mill program on a lathe set-up
        (its mode line says X is a radius, as the mill's X is: #20), ``OWN_WRITER`` for a grblHAL program
        (its copied blocks end a generated cycle: ``writer.GrblhalOwnWriter``), else ``WRITER``."""
        if ctx.lathe or cls.reads_lathe(ctx.setup):
            return cls.LATHE_WRITER
        return cls.OWN_WRITER if ctx.dialect == cls.NAME else cls.WRITER

    @classmethod
    def tool_table(cls, setup: MachineSetup) -> bool:
        """A build with a tool table, as the set-up says (``<Controller toolTable>``; none by default)."""
        return bool(setup.controller.tool_table)

    @classmethod
    def expressions(cls, setup: MachineSetup) -> bool:
        """A build with ``NGC_EXPRESSIONS_ENABLE``, as the set-up says (``<Controller expressions>``; none by default)."""
        return bool(setup.controller.expressions)

    @classmethod
    def pipeline_file(cls, setup: MachineSetup) -> str | None:
        """``grblhal_expressions.xml`` (the interpreter step first) for a build with expressions."""
        return "grblhal_expressions.xml" if cls.expressions(setup) else cls.PIPELINE_FILE

    @classmethod
    def moves_like(cls, cycle: ResolvedCycle) -> bool:
        """G81/G82 whose motion on grblHAL is the source's (``cycles.native_motion_matches``)."""
        from postproc.cycles.section import CannedCycle
        from .cycles import native_motion_matches
        return isinstance(cycle, CannedCycle) and native_motion_matches(cycle)

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``grblhal.xml`` (``grblhal_expressions.xml`` for a build with expressions), built in Python."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import GrblhalBlockSyntax
        from .cycles import GrblhalCycleRules
        from .pecking import GrblhalPeckExpansion
        from .program import GrblhalProgramSyntax
        first = [GrblhalProgramSyntax()] if cls.expressions(setup) else []
        return Pipeline(cls.NAME, [*first, GrblhalBlockSyntax(), CannedCycleResolveSyntax("rs274", [GrblhalPeckExpansion()]),
                                   GrblhalCycleRules(), ModalStateSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Grblhal)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("GrblhalBlockSyntax", f"{__name__}.block_syntax:GrblhalBlockSyntax")
    factory.register_lazy("GrblhalCycleRules", f"{__name__}.cycles:GrblhalCycleRules")
    factory.register_lazy("GrblhalPeckSyntax", f"{__name__}.pecking:GrblhalPeckExpansion")
    factory.register_lazy("GrblhalProgramSyntax", f"{__name__}.program:GrblhalProgramSyntax")
