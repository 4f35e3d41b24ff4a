"""Beckhoff TwinCAT CNC (ISG kernel) milling dialect: reader, writer, reading pipeline, capability table.

ISG is not in the RS274 family: it reads with the ISG/Fagor family's base (``postproc.isg_family``:
lexer, ``$`` statements, P parameters and ``V.`` expressions), with its own variables (``variables``)
and ``#`` commands (``commands``);
its DIN words go through the family's word rules with ISG's table (``codes``), where the codes whose
numbers collide with Fanuc's are told apart.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

from postproc.syntaxes.comments import CommentSyntax
from postproc.geometry.arc_end import NEAREST_CENTRE, ArcEndRule
from postproc.ir.state import MM_PER_INCH
from postproc.dialect import Dialect, Lazy, Reader
from postproc.hookspecs import hookimpl
from postproc.lowering.lazy_step import LazyStep
from postproc.rs274.order_of_execution import stops_before_motion
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory

nest_jumps_keeping_equality = LazyStep("postproc.lowering.structured_jumps:nest_jumps_keeping_equality")

if TYPE_CHECKING:
    from postproc.context import Context


select_tool_data = LazyStep("postproc.isg_family.tool_data:select_tool_data")
resolve_radius_where_d_cannot = LazyStep("postproc.isg_family.tool_data:resolve_radius_where_d_cannot")


absolute_machine_moves = LazyStep("postproc.isg_family.machine_moves:absolute_machine_moves")


class Isg(Dialect):
    NAME = "isg"
    LENGTH_REGISTER_ADDRESS = "D"
    """D selects the tool data, length and radius together [K] (postproc.isg_family.tool_data)."""
    CUTTER_RULES_LACK = ("its start-up and cancel moves (the selection methods G139, its initial state, and G138) "
                         "are given by figures only in the TF5200 programming manual [?]: dialects/isg/cutter_rules.py")
    """Why its compensation is a setting, not a path: the research, tagged, is ``dialects/isg/cutter_rules.py``'s
    docstring (a module no run imports)."""
    STORED_WORK_OFFSETS = True
    """Its zero offset variables write the table, taken at the work system's next selection (the reader's
    ``ZERO_OFFSETS``)."""
    ARC_END = ArcEndRule(metric=2.0, inch=2.0 / MM_PER_INCH, relative=0.05, runs=NEAREST_CENTRE,
                         of_centre_shift=True)
    """G165, the power-on state, moves the programmed centre of an I/J/K arc so that a circle runs from the
    start to the programmed end, and alarms only where the move exceeds both P-CHAN-00059 ``mittelpkt_diff``
    (in 0.1 um whatever the program's units, default 20000: 2 mm) and P-CHAN-00060 ``mittelpkt_faktor`` (in
    0.1 %, default 50: 5 %) times the corrected radius; an R arc is never corrected [V: Beckhoff TF5200
    programming manual "Controlling centre point offset in circle (G164/G165)"; channel parameter pages
    P-CHAN-00059/00060; ISG kernel "Settings for circle centre point correction"]. That the alarm needs both
    limits exceeded (the larger of the two applies) is read from "whether ... and whether ... If this is the
    case" [?]. Where the new centre lies is not stated beyond "the more precise the programmed centre, the
    smaller the move" and "the programmed centre must lie within the permissible move of the corrected one":
    the least move, onto the chord's perpendicular bisector (``NEAREST_CENTRE``), is taken [?]. G164 (a spiral
    within P-CHAN-00171/00172) is not read."""

    @classmethod
    def arc_end_rule(cls, setup: MachineSetup) -> ArcEndRule:
        """``ARC_END`` with the machine's P-CHAN-00059/00060 (``<Controller centreShiftLimit centreShiftShare>``,
        in mm whatever the program's units)."""
        return cls.ARC_END.with_machine(setup.controller.centre_shift_limit, setup.controller.centre_shift_share)

    DESCRIPTION = "Beckhoff TwinCAT CNC (ISG kernel) milling: P parameters, $ control flow, %L subroutines"
    READER = Lazy[type[Reader]](".reader:IsgReader")
    """Imported when a run first reads ISG (``Lazy``), as are the writer and the syntax objects."""
    WRITER = Lazy[type[Writer]](".writer:IsgWriter")
    PIPELINE_FILE = "isg.xml"
    NATIVE_CYCLES = frozenset()
    """G80-G89 are the machine builder's subroutine files, not DIN cycles: every cycle is expanded."""
    PROGRAM_NUMBERS = True
    """``%1001`` names the main program (``%`` is no tape mark here)."""
    SPINDLE_ORIENTATION = True
    """M19 to the machine's angle [?]."""
    TAP_STROKES = True
    """A rigid tap is the strokes ``G331`` (in) and ``G332`` (out, the spindle reversed) [V: TF5200 "Tapping
    (G331/G332)"]: a synchronised tap of another family is written as them (``taps``)."""
    CUTTER_COMPENSATION = True
    """G40/G41/G42."""
    TOOL_LENGTH_OFFSET = True
    """``D<n>`` selects tool data n, length and radius together (``postproc.isg_family.tool_data``): a
    Fanuc ``G43 H``/``G41 D`` is written as the D it needs; a negative offset (G44) is refused."""
    LENGTH_TOGGLES = False
    """No length on/off code: the selected D's length applies [V: TF5200 "Tool offset"]."""
    LENGTH_AT_PROGRAMMED_AXIS = True
    """A D's new length reaches an axis at its next absolute position only; ``D16`` then ``G91 G00 X0``
    moves nothing [V: TF5200 "Tool geometry compensation" (tccncprogramming/15557086347) and
    P-CHAN-00100 (tf5200_channel_parameter/149123467), default 0]."""
    COMMENTS = CommentSyntax(parens=True, nested=True, semicolon=True)
    """``( )`` comments nest, ``;`` runs to the end of the block [V: DIALECTS.md 1.3]; a value in a
    ``#COMMENT BEGIN`` ... ``#COMMENT END`` block is not recognised as commented (refused: the safe side)."""
    PROGRAMS = True
    """P parameters, expressions, $IF/$SWITCH/$FOR/$WHILE/$DO/$REPEAT, $GOTO, %L/LL and L subroutines."""
    LOWERING = (nest_jumps_keeping_equality, stops_before_motion, resolve_radius_where_d_cannot, select_tool_data,
                absolute_machine_moves)
    """A run of moves in machine coordinates or reference returns under G91 is written after one G90, G91 again
    where the program next reads it (``postproc.isg_family.machine_moves``). A spindle stop or coolant off that the source made before its block's motion goes in a block of
    its own before it (ISG acts on M05/M09 after the block's motion, as Fanuc [?]); a G41/G42 whose D
    would bring another length than the one in force becomes the compensated path where the source's
    rules are modelled (``resolve_radius_where_d_cannot``); another family's length and radius
    registers become the D that selects them (``select_tool_data``); another dialect's jumps become the
    ``$IF``/``$BREAK`` they have the shape of, or the program is flattened: ``$GOTO`` may not jump inside a
    loop, and a numbered target needs the label ``N<n>:`` (``postproc.lowering.structured_jumps``)."""

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``isg.xml``, built in Python."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import IsgBlockSyntax
        from .program import IsgProgramSyntax
        return Pipeline(cls.NAME, [IsgProgramSyntax(), IsgBlockSyntax(), CannedCycleResolveSyntax("fanuc"),
                                   ModalStateSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Isg)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("IsgBlockSyntax", f"{__name__}.block_syntax:IsgBlockSyntax")
    factory.register_lazy("IsgProgramSyntax", f"{__name__}.program:IsgProgramSyntax")
