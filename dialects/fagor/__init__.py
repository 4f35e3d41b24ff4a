"""Fagor CNC 8070 milling dialect: reader, writer, reading pipeline, capability table.

Fagor shares the ISG kernel's language family: it reads with ``postproc.isg_family`` (lexer,
expressions, ``$`` statements) and keeps its own code table (``codes``), hole-cycle words
(``cycle_words``: ``Z`` reference plane, ``I`` depth, ``K`` dwell), reader, writer and variables.
What DIALECTS.md marks uncertain for the 8070 [?] is kept verbatim (``reader``). Multiple machining
(``G160``-``G165``) is read through ``FagorBlockSyntax.multiple_machining`` (see README.md).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

from postproc.context import Context
from postproc.syntaxes.comments import CommentSyntax
from postproc.geometry.arc_end import NEAREST_CENTRE, ArcEndRule
from postproc.ir.state import MM_PER_INCH
from postproc.cycle_words import CycleWords
from postproc.dialect import Dialect, Lazy, Reader
from postproc.rs274.cycle_semantics import FANUC as FANUC_CYCLES
from postproc.errors import Diagnostics
from postproc.hookspecs import hookimpl
from postproc.lowering.lower import BlockStep, LoweringStep
from postproc.rs274.order_of_execution import stops_before_motion
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory

if TYPE_CHECKING:
    from postproc.ir import Block


class _SelectToolData(LoweringStep):
    """``postproc.isg_family.tool_data.select_tool_data``, imported when a translation first lowers for
    this dialect."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from postproc.isg_family.tool_data import select_tool_data as step
        return step.start(ctx, target)


class _EndCyclesBeforeMoves(LoweringStep):
    """``cycle_end.end_cycles_before_moves``, imported when a translation first lowers for this dialect."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from .cycle_end import end_cycles_before_moves as step
        return step.start(ctx, target)


class _ResolveRadiusWhereDCannot(LoweringStep):
    """``postproc.isg_family.tool_data.resolve_radius_where_d_cannot``, imported when first used."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from postproc.isg_family.tool_data import resolve_radius_where_d_cannot as step
        return step.start(ctx, target)


select_tool_data = _SelectToolData()
end_cycles_before_moves = _EndCyclesBeforeMoves()
resolve_radius_where_d_cannot = _ResolveRadiusWhereDCannot()


class _AbsoluteMachineMoves(LoweringStep):
    """``postproc.isg_family.machine_moves.absolute_machine_moves``, imported when first used."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from postproc.isg_family.machine_moves import absolute_machine_moves as step
        return step.start(ctx, target)


absolute_machine_moves = _AbsoluteMachineMoves()


class Fagor(Dialect):
    NAME = "fagor"
    LENGTH_REGISTER_ADDRESS = "D"
    """D selects the tool data, length and radius together [K] (postproc.isg_family.tool_data)."""
    CUTTER_RULES_LACK = ("its start, corner and cancel constructions (G136/G137, G138/G139) are given by figures "
                         "only in the 8070 programming manual [?]: dialects/fagor/cutter_rules.py")
    """Why its compensation is a setting, not a path: the research, tagged, is ``dialects/fagor/cutter_rules.py``'s
    docstring (a module no run imports)."""
    RIGID_TAP_LACK = ("the 8070's G84 R word selecting rigid tapping and its G63 rigid tap are [?]: their words and "
                      "how the feed follows the pitch are not confirmed from a Fagor manual, DIALECTS.md 2.3")
    """``codes.py``: a rigid tap is refused by name until the 8070 manual's G84/G63 pages are at hand."""
    STORED_WORK_OFFSETS = True
    """Its zero offset variables write the table, taken at the work system's next selection (the reader's
    ``ZERO_OFFSETS``)."""
    ARC_END = ArcEndRule(metric=0.01, inch=0.01 / MM_PER_INCH, runs=NEAREST_CENTRE)
    """G265, the state at power-on, after M02/M30 and after a reset, moves the centre of an arc whose start and
    end radii differ so that an arc runs between the programmed points "as close as possible to the defined
    arc", where the difference of radii is within the absolute tolerance CIRINERR or the relative one
    CIRINFACT (either suffices), else an error [K: Fagor CNC 8070 programming manual (soft V02.0x) 6.3.6 "Arc
    center correction (G264/G265)"]. The least move, onto the chord's perpendicular bisector
    (``NEAREST_CENTRE``), is taken as that arc [?]. The two parameters' defaults are not in the manuals found
    [?]: 0.01 mm absolute (the neutral rule) and no relative share are taken unless the set-up gives the
    machine's (``arc_end_rule``). G264 (start radius about the programmed centre) is not read."""

    @classmethod
    def arc_end_rule(cls, setup: MachineSetup) -> ArcEndRule:
        """``ARC_END`` with the machine's CIRINERR/CIRINFACT (``<Controller arcRadiusError arcRadiusShare>``, in mm
        whatever the program's units)."""
        return cls.ARC_END.with_machine(setup.controller.arc_radius_error, setup.controller.arc_radius_share)

    DESCRIPTION = "Fagor CNC 8070 milling: Z/I/K drilling words, G70/G71 units, G159 offsets, P parameters"
    READER = Lazy[type[Reader]](".reader:FagorReader")
    """Imported when a run first reads Fagor (``Lazy``), as are the writer and the syntax objects (with the
    ISG family's lexer and expressions, and multiple machining)."""
    WRITER = Lazy[type[Writer]](".writer:FagorWriter")
    PIPELINE_FILE = "fagor.xml"
    CYCLE_WORDS = Lazy[CycleWords](".cycle_words:SECONDS")
    """Z reference plane, I depth, K dwell (seconds; the set-up's ``fagorDwellUnit`` may say hundredths)."""
    NATIVE_CYCLES = frozenset({"drill", "drill_dwell", "bore_feed", "bore_dwell_feed"})
    """G81 (drilling, dwell K) and G89 (boring, dwell K, feed out) [K]; Fanuc's G81/G85 are written as them
    with no dwell. Every other cycle is expanded (Fagor's G82-G88 are other cycles or unconfirmed)."""
    CYCLE_SEMANTICS = FANUC_CYCLES.name
    """Its G81/G89 move as Fanuc's G81/G85 do (the mapping above) [K]."""
    PROGRAM_NUMBERS = True
    """``%1001`` names the main program [V: the ``%<name>`` header]."""
    HOLE_PATTERNS = frozenset({"line", "parallelogram", "grid", "circle", "arc"})
    """Multiple machining G160-G164 repeats the active cycle at a line, parallelogram, grid, circle or arc
    of points (``multiple_machining.py``): kept native between Fagor programs. G165 (chord) is not read."""
    SPINDLE_ORIENTATION = False
    """No confirmed 8070 oriented spindle stop: M19 [?] is written only when the set-up's
    ``<Cycles orientation="m19"/>`` asks for it."""
    COMMENTS = CommentSyntax(parens=False, semicolon=True)
    """``;`` to the end of the block, as the writer writes comments; ``( )`` is not confirmed as a comment on
    the 8070 [?: DIALECTS.md 1.4], so no value is written between parentheses."""
    CUTTER_COMPENSATION = True
    """G40/G41/G42."""
    TOOL_LENGTH_OFFSET = True
    """``G43 D<n>`` applies tool offset n's length, ``G44`` cancels it (``postproc.isg_family.tool_data``):
    a Fanuc ``G43 H``/``G41 D`` is written with the D it needs; Fanuc's G44 (a negative offset) is refused."""
    LENGTH_AT_AXIS_MOVE = True
    """"Function G43 only indicates that a longitudinal compensation is to be applied. The CNC starts applying it
    when the longitudinal (perpendicular) axis starts moving" [V: Fagor CNC 8055/8055i programming manual (M & EN
    models, soft V02.2x) 8.2 "Tool length compensation (G43, G44, G15)"; the 8070 taken to keep its family's
    rule [K]: its manual's tool-length page was not at hand]. A Fanuc change without a Z move
    (``G43 H07`` then ``G00 X.. Y..``, which Fanuc applies at that move) is written beside that move with the Z
    the program stands at (``postproc.lowering.length_timing``): the Fagor applies it there too."""
    PROGRAMS = False
    """P parameters and expressions are read [K]; control flow and subroutines are kept verbatim [?], so a
    program that computes reaches Fagor flattened."""
    LOWERING = (stops_before_motion, resolve_radius_where_d_cannot, select_tool_data, end_cycles_before_moves,
                absolute_machine_moves)
    """A run of moves in machine coordinates or reference returns under G91 is written after one G90, G91 again
    where the program next reads it (``postproc.isg_family.machine_moves``). A spindle stop or coolant off that the source made before its block's motion goes in a block of
    its own before it (Fagor acts on M05/M09 after the block's motion, as Fanuc [?]); a G41/G42 whose D
    would bring another length than the one G43 has on is the compensated path, where the source's rules
    are modelled (``resolve_radius_where_d_cannot``, as for ISG); another family's length and radius
    registers become the D that selects them (``select_tool_data``); a ``G80`` ends a written cycle before
    any move outside it, as whether a motion code ends it on the 8070 is not confirmed [?]
    (``cycle_end``)."""

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``fagor.xml``, built in Python."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import FagorBlockSyntax
        from .program import FagorProgramSyntax
        return Pipeline(cls.NAME, [FagorProgramSyntax(), FagorBlockSyntax(), CannedCycleResolveSyntax("fanuc"),
                                   ModalStateSyntax()])

    @classmethod
    def context(cls, file: str, setup: MachineSetup, diagnostics: Diagnostics) -> Context:
        from .cycle_words import cycle_words  # (a run's, read from Fagor: not at registration)
        ctx = super().context(file, setup, diagnostics)
        ctx.cycle_words = cycle_words(setup)
        return ctx


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Fagor)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("FagorBlockSyntax", f"{__name__}.block_syntax:FagorBlockSyntax")
    factory.register_lazy("FagorProgramSyntax", f"{__name__}.program:FagorProgramSyntax")
