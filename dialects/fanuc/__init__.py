"""Fanuc 0i/30i dialect, milling (M) and turning (T): reader, writer, reading pipelines and capability
table. The set-up's ``machineType`` picks the machine's code table and pipeline (``fanuc.xml`` or
``fanuc_lathe.xml``), its ``gcodeSystem`` the lathe's table (A, B or C)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, Iterator

from postproc.syntaxes.comments import CommentSyntax
from postproc.compensation.rules import CutterRules
from postproc.rs274.cutter_rules import FANUC_A, FANUC_B, FANUC_T, FANUC_T_B, HAAS_A, HAAS_B, HAAS_T, HAAS_T_B
from postproc.cycle_words import CycleWords
from postproc.dialect import Dialect, Lazy, Reader
from postproc.rs274.cycle_semantics import FANUC as FANUC_CYCLES
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.hookspecs import hookimpl
from postproc.rs274.arc_ends import FANUC_ARC_END
from postproc.rs274.lathe_axes import LATHE_INCREMENTS
from postproc.rs274.order_of_execution import stops_before_motion
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory

from .arguments import LETTER_LOCALS

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block


def number_jumps(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """``postproc.rs274.macro_jumps.number_jumps``, imported when a translation first lowers for Fanuc."""
    from postproc.rs274.macro_jumps import number_jumps as step
    return step(blocks, ctx, target)


ALL_MILLING_CYCLES = frozenset({
    "drill", "drill_dwell", "peck_chip", "peck_deep", "tap", "tap_left", "bore_feed", "bore_stop",
    "bore_dwell_feed", "fine_bore", "back_bore", "bore_manual",
})


class Fanuc(Dialect):
    NAME = "fanuc"
    DESCRIPTION = "Fanuc 0i/30i milling, Custom Macro B and subprograms"
    READER = Lazy[type[Reader]](".reader:FanucReader")
    """Imported when a run first reads Fanuc (``Lazy``), as are the writer and the syntax objects."""
    WRITER = Lazy[type[Writer]](".writer:FanucWriter")
    PIPELINE_FILE = "fanuc.xml"
    CYCLE_WORDS = Lazy[CycleWords](".codes:CYCLE_WORDS")  # (its code table, imported where a run reads it)
    """R level, Q peck/shift, P dwell (ms); K, L or K+L repeats (0-9999) per the set-up; cycles named
    G73-G89."""
    NATIVE_CYCLES = ALL_MILLING_CYCLES
    """G73, G74, G76, G81-G89 all run natively."""
    CYCLE_SEMANTICS = FANUC_CYCLES.name
    """Fanuc's cycle rules (``postproc.cycles.semantics``: initial level, G98/G99, K repeats)."""
    TAPE_MARKS = True
    """``%`` opens and closes a program on tape or DNC."""
    LEADER_TITLE = True
    """The control skips what follows the first ``%`` up to the end of its line, where a title may stand
    [V: Fanuc 16i/18i-TB operator's manual B-63524EN/01, memory card file format; Fanuc Data Server
    manual B-64014EN/03, ``% TITLE ;``]."""
    PROGRAM_NUMBERS = True
    """``O1001``: the number the control stores the program under."""
    FAMILY = "fanuc"
    """Machine builders' codes (``machine_codes``) pass verbatim between Fanuc-family controls."""
    RIGID_TAP_CODE = "M29"
    """``M29 S..`` before G84/G74 makes them rigid taps [K: Fanuc 0i-MF operator's manual, rigid tapping;
    the family's default machine code, ``machine_codes.FANUC``]: LinuxCNC's G33.1 is written with it."""
    COMMENTS = CommentSyntax(parens=True, nested=False, semicolon=False)
    """``( )`` control-out/control-in, no nesting; ``;`` is the end of block shown on screen, no comment
    [K: DIALECTS.md 1.1]."""
    PROGRAMS = True
    """Custom Macro B variables, expressions, IF/GOTO, WHILE, M98/G65 subprograms."""
    WHOLE_SPINDLE_SPEED = True
    """``S1000.0`` is an illegal statement (S takes an integer); a computed ``S[1000.5]`` runs as S1001, rounded
    half away from zero; parameter 3451#2 (mills only) admits one decimal place, still run rounded to the
    whole number [K: cncarea.com / cnccode.com "CNC Macro: real versus integer values", after Smid's Fanuc
    Custom Macros; B-64484EN's decimal-point address list leaves S out [?: not read here]]."""
    MACHINE_TYPES = frozenset({"mill", "lathe"})
    """Fanuc M and Fanuc T (the set-up's ``machineType``; mill when it says nothing)."""
    DIAMETER_PROGRAMMING = True
    """Fanuc T programs X as a diameter (or a radius: the set-up's ``xProgramming``)."""
    LATHE_CYCLES = frozenset(("turn_finish", "turn_rough", "face_rough", "pattern_repeat", "face_peck", "groove",
                              "thread_multi", "turn_single", "thread_single", "face_single"))
    """G70-G76 and the single cycles (G90/G92/G94 in system A, renumbered in B and C)."""
    INCREMENTAL_AXES = LATHE_INCREMENTS
    """Fanuc T: U and W are incremental X (a diameter) and Z (``postproc.rs274.lathe_axes``)."""
    LATHE_FEED_AT_START = "per_rev"
    """Fanuc T starts in G99 (feed per revolution; parameter 3402#4 FPM = 0, the default)."""
    LATHE_PATH_CONTROL = False
    """The lathe code table has no G61/G64 [?: the writer's ``PATH_CONTROL_LACK``]."""
    LATHE_ONE_BLOCK = True
    """10/11/15-T read ``G71 P Q U W D F`` and ``G76 X Z I K D F A P`` (the set-up's ``latheCycleFormat``)."""
    MACRO_ARGUMENTS = LETTER_LOCALS
    """``G65`` arguments by address (argument specification I), for a macro file run on its own (``--arg``)."""
    MOTION_AT_START = "rapid"
    """Fanuc M and T power on (and clear on reset) in G00, or in G01 with parameter 3402#0 G01 = 1 (the
    set-up's ``<Controller startMotion="linear"/>``) [K: Fanuc 0i-F operator's manual, G code list notes;
    cnc.wiki "Fanuc Parameter 3402"]."""
    LATHE_PIPELINE_FILE = "fanuc_lathe.xml"
    CUTTER_RULES = FANUC_A
    """Cutter compensation C with start-up type A, parameter SUP (5003#0) = 0, the default
    (``postproc.compensation.rules``, where each rule is tagged with its source); type B by the set-up's
    ``<Controller cutterStartup="B">`` (``cutter_rules``)."""
    ARC_END = FANUC_ARC_END
    """Parameter 3410 in the program's units, a spiral within it (``postproc.rs274.arc_ends``)."""
    LOWERING = (stops_before_motion, number_jumps)
    """A spindle stop or coolant off that the source made before its block's motion goes in a block of
    its own before it (Fanuc makes them after the motion); another dialect's ``IF .. ELSE``, loop tested at
    its end and named labels as jumps to block numbers (``postproc.rs274.macro_jumps``)."""

    @classmethod
    def cutter_rules(cls, setup: MachineSetup) -> CutterRules | None:
        """Fanuc M: cutter compensation C, Fanuc T: tool nose radius compensation, start-up type A or B by
        parameter SUP (the set-up's ``cutterStartup``). A Haas mill: Fanuc's with what its manual leaves out
        refused, start-up type A or B by its setting 43 (the set-up's ``cutterStartup``; setting 58 FANUC,
        ``postproc.rs274.cutter_rules.HAAS_A``). A Haas lathe: Fanuc T's rules, type A by default, type B by the
        set-up's ``cutterStartup`` (``cutter_rules.HAAS_T``, where its manual says so)."""
        if setup.controller.variant == "haas":
            if cls.reads_lathe(setup):
                return HAAS_T_B if setup.controller.cutter_startup == "B" else HAAS_T
            return HAAS_B if setup.controller.cutter_startup == "B" else HAAS_A
        if cls.reads_lathe(setup):
            return FANUC_T_B if setup.controller.cutter_startup == "B" else FANUC_T
        return FANUC_B if setup.controller.cutter_startup == "B" else FANUC_A

    @classmethod
    def pipeline_file(cls, setup: MachineSetup) -> str:
        """The lathe pipeline (profile look-ahead, lathe cycles) for a lathe set-up, else the milling one."""
        return cls.LATHE_PIPELINE_FILE if cls.reads_lathe(setup) else cls.PIPELINE_FILE

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``fanuc_lathe.xml`` or ``fanuc.xml`` (``pipeline_file``), built in Python."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .program import FanucProgramSyntax
        if cls.reads_lathe(setup):
            from postproc.rs274.lathe_cycles import LatheCycleSyntax
            from .lathe_block_syntax import FanucLatheBlockSyntax
            return Pipeline(cls.NAME, [FanucProgramSyntax(), FanucLatheBlockSyntax(), ModalStateSyntax(),
                                       LatheCycleSyntax()])
        from .block_syntax import FanucBlockSyntax
        return Pipeline(cls.NAME, [FanucProgramSyntax(), FanucBlockSyntax(), CannedCycleResolveSyntax("fanuc"),
                                   ModalStateSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Fanuc)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    """The syntax objects, imported when an element names one (``XFactory.register_lazy``)."""
    factory.register_lazy("FanucBlockSyntax", f"{__name__}.block_syntax:FanucBlockSyntax")
    factory.register_lazy("FanucLatheBlockSyntax", f"{__name__}.lathe_block_syntax:FanucLatheBlockSyntax")
    factory.register_lazy("FanucProgramSyntax", f"{__name__}.program:FanucProgramSyntax")
