"""Siemens SINUMERIK 840D sl / 828D milling dialect: reader, writer, reading pipeline, capability table.

SINUMERIK is neither in the RS274 family nor in ISG's: it has its own reader (``reader``: ``=`` forms,
R parameters, ``DEF`` variables, labels, ``IF``/``WHILE``/``FOR``/``REPEAT``/``LOOP`` and ``GOTOF``...) and
expressions (``expressions``), reads its words through the family's word rules with the 840D table
(``codes``, ``block_syntax``) and selects tool data with ``D`` as ISG does
(``postproc.isg_family.tool_data``). ``CYCLE8x`` called once or by ``MCALL`` are read on the neutral cycle IR (``cycles``),
the programmable frame statements (``TRANS``, ``AROT``...) on the neutral frame change (``frames``), ``NAME P3``
as a subprogram call. What the IR does not model (``ROTS`` and computed frames, other cycles, parameters by
reference, ``AC``/``IC`` against the block's mode...) is kept verbatim, named
(``keywords``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

from postproc.syntaxes.comments import CommentSyntax
from postproc.cycle_words import CycleWords
from postproc.geometry.arc_end import SPIRAL, ArcEndRule
from postproc.dialect import Dialect, Lazy, Reader, ResolvedCycle
from postproc.rs274.cycle_semantics import FANUC as FANUC_CYCLES
from postproc.hookspecs import hookimpl
from postproc.lowering.lower import BlockStep, LoweringStep
from postproc.rs274.order_of_execution import stops_before_motion
from postproc.setup.machine_setup import MachineSetup
from postproc.ir.state import MM_PER_INCH
from postproc.syntaxes.syntax import Pipeline
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory

if TYPE_CHECKING:
    from postproc.context import Context


class _SelectToolData(LoweringStep):
    """``postproc.isg_family.tool_data.select_tool_data``, imported when a translation first lowers for
    this dialect."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from postproc.isg_family.tool_data import select_tool_data as step
        return step.start(ctx, target)


class _ResolveRadiusWhereDCannot(LoweringStep):
    """``postproc.isg_family.tool_data.resolve_radius_where_d_cannot``, imported when first used."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from postproc.isg_family.tool_data import resolve_radius_where_d_cannot as step
        return step.start(ctx, target)


class _OrientBeforeTaps(LoweringStep):
    """``tap_strokes.orient_before_taps``, imported when first used."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from .tap_strokes import orient_before_taps as step
        return step.start(ctx, target)


select_tool_data = _SelectToolData()
resolve_radius_where_d_cannot = _ResolveRadiusWhereDCannot()
orient_before_taps = _OrientBeforeTaps()


class Siemens(Dialect):
    NAME = "siemens"
    LENGTH_REGISTER_ADDRESS = "D"
    """D selects the cutting edge, its length and radius together [K: 840D sl Fundamentals, "Tool offset D"]."""
    STORED_WORK_OFFSETS = True
    """Its zero offset variables write the table, taken at the work system's next selection (the reader's
    ``ZERO_OFFSETS``)."""
    DESCRIPTION = "Siemens SINUMERIK 840D sl / 828D milling: R parameters, DEF variables, IF/WHILE/FOR, GOTOF labels"
    READER = Lazy[type[Reader]](".reader:SiemensReader")
    """Imported when a run first reads SINUMERIK (``Lazy``), as are the writer and the syntax objects."""
    WRITER = Lazy[type[Writer]](".writer:SiemensWriter")
    PIPELINE_FILE = "siemens.xml"
    CYCLE_WORDS = CycleWords(names={"drill": "CYCLE81", "drill_dwell": "CYCLE82", "peck_deep": "CYCLE83",
                                    "bore_feed": "CYCLE85", "bore_manual": "CYCLE88", "bore_dwell_feed": "CYCLE89",
                                    "tap": "CYCLE84", "tap_left": "CYCLE84"},
                             return_to_r="RTP=RFP+SDIS", level="R", peck="Q", shift="Q", dwell="P", repeat=("K",))
    """``CYCLE81``/``82``/``83``/``85``/``87``/``88``/``89`` are read as the Fanuc-family words of their meaning
    (``cycles``: R level, Z depth, Q stroke, P dwell in ms, K0 for the modal call that drills nothing);
    ``CYCLE84`` as a rigid ``G84``/``G74`` with its pitch (``tapping``)."""
    NATIVE_CYCLES = frozenset({"drill", "drill_dwell", "peck_deep", "bore_feed", "bore_dwell_feed", "bore_manual",
                               "tap", "tap_left"})
    """Fanuc G81/G82/G83/G85/G89/G88 are written as ``MCALL CYCLE81``/``82``/``83``/``85``/``89``/``88``, a rigid
    G84/G74 (after ``M29 S..``) as ``MCALL CYCLE84``, where they move the same (``moves_like``,
    ``cycle_writing``); every other cycle (a floating tap among them) is expanded for SINUMERIK."""
    RIGID_TAP_CYCLE = True
    """``CYCLE84`` is rigid by itself: Fanuc's ``M29`` before a tap cycle is left out (``cycle_writing``)."""
    CYCLE_SEMANTICS = FANUC_CYCLES.name
    """The cycles read move by Fanuc's rules (the reading pipeline's ``CannedCycleResolveSyntax("fanuc")``)."""
    ARC_END = ArcEndRule(metric=0.01, inch=0.01 / MM_PER_INCH, relative=0.001, runs=SPIRAL)
    """Alarm 14040 (error in end point of circle) when the start and end radii differ by more than MD 21000
    ``CIRCLE_ERROR_CONST`` for small radii, or by more than the radius times MD 21010 ``CIRCLE_ERROR_FACTOR``
    for large ones, i.e. by more than the larger of the two [K: SINUMERIK 840D sl diagnostics manual, alarm
    14040, as copied by helmancnc.com]. The machine data are in mm whatever the program's units; their values
    0.01 mm and 0.001 are the defaults as remembered, not confirmed from a machine data list [?] (the 840C's
    predecessor datum, MD 7, defaulted to 5 units of the input system [K: 840C installation guide 6.2]).

    Path: the same alarm text says a new centre is computed with the start radius on the chord's
    perpendicular bisector (``START_RADIUS``), and that the angle at the start between the programmed and the
    new centre must stay under sqrt(0.001) rad [K]. Not switched on (the simulation draws the spiral through
    the programmed centre [?]), on this evidence: a start-radius centre is ill-conditioned near half a turn,
    where its move is sqrt(2 r delta) for a start radius delta over half the chord. A four-decimal inch
    semicircle (0.0001 in off, tests/corpus/linuxcnc/inside_corners_trimmed.ngc, r 0.2707 in) moves it
    0.13 mm, and even the writer's own rounding (``postproc.numbers.EXACT``, 5e-7 mm) on an exact semicircle of
    6.9 mm moves it sqrt(2 * 6.9 * 1e-6) = 0.0037 mm, past verify's 0.001 mm: switched on, every SINUMERIK
    semicircle this project writes would run elsewhere than it simulates. The cure at the cause is writing
    arcs within reach of half a turn split into pieces of at most about 120 degrees about the exact centre
    (as ``--arcs r`` splits), where the start-radius move stays near the rounding; not done yet."""

    PROGRAM_NUMBERS = True
    """``%_N_NAME_MPF`` names the main program."""
    SPINDLE_ORIENTATION = True
    """``SPOS=<angle>`` stops the spindle at the angle under position control (``reader.spindle_position``);
    M19 is the machine builder's [?]."""
    TAP_STROKES = True
    """A rigid tap is the strokes ``G331`` (in) and ``G332`` (out, the spindle reversed), after ``SPOS=``
    (``tap_strokes``): a synchronised tap of another family is written as them."""
    CUTTER_COMPENSATION = True
    """G40/G41/G42 with the radius of the selected D."""
    TOOL_LENGTH_OFFSET = True
    """``D<n>`` selects cutting edge n, length and radius together (``postproc.isg_family.tool_data``)."""
    LENGTH_TOGGLES = False
    """No length on/off code: the selected D's length applies [K: 840D Fundamentals "Tool offsets"]."""
    LENGTH_AT_PROGRAMMED_AXIS = True
    """[K: SINUMERIK 840D sl Function Manual Basic Functions W1 (11/2006, 6FC5397-0BP10-2BA0) 2.1.1 "Activating
    the tool compensations": tool length compensation is performed on the first traversing motion of the axis
    it acts on (G0/G1)]. Whether an incremental first motion also takes it, as LinuxCNC's rule here does not,
    is not stated [?]."""
    PATH_CONTROL_AT_START = "exact_stop"
    """G60 (exact stop) before a program programs G64: the standard reset value of G group 10 (machine data MD20150
    ``$MC_GCODE_RESET_VALUES[9]``, which a machine builder may set to G64) [K: the SINUMERIK G-group tables mark G60
    as the standard setting of group 10; the page of the 12/2019 programming manual with group 10 was not reached
    here, only its group 1 page (p.1247) and the G60/G9 description (p.293)]. A program read from SINUMERIK that
    moves before it programs G60/G64 is written with an exact stop mode first for a target that powers on in
    continuous path mode, and a program for SINUMERIK from such a source gets ``G64`` first: so the written
    program runs in the source's mode whatever the machine data says (``postproc.lowering.path_at_start``)."""
    MOTION_AT_START = "linear"
    """G1 before a program programs a motion: the standard reset value of G group 1 (machine data MD20150
    ``$MC_GCODE_RESET_VALUES``, which a machine builder may set to G0: the set-up's ``<Controller
    startMotion="rapid"/>``) [V: SINUMERIK ONE NC programming manual 12/2019 6FC5398-2EP40-0BA0 p.1247, "G group
    1", G1 marked in the STD column]. Its moves need a feed rate, as any G1 (alarm 10860)."""
    COMMENTS = CommentSyntax(parens=False, semicolon=True)
    """``;`` to the end of the block [K: 802D manual p.133]; ``(`` is an expression's."""
    PROGRAMS = True
    """Variables and control flow are read, run and written: another dialect's program that computes is kept
    symbolic where every construct has an exact SINUMERIK spelling (``control_writing``: R parameters,
    IF/WHILE/REPEAT/FOR, GOTOF/GOTOB), else flattened with the usual warning."""
    LOWERING = (stops_before_motion, resolve_radius_where_d_cannot, select_tool_data, orient_before_taps)
    """A spindle stop or coolant off that the source made before its block's motion goes in a block of its
    own before it (SINUMERIK acts on M5/M9 after the block's motion, as Fanuc [?]); a G41/G42 whose D would
    bring another length than the one in force (a D carries the edge's length and radius together [K: 840D
    Fundamentals "Tool offsets"]) becomes the compensated path where the source's rules are modelled
    (``resolve_radius_where_d_cannot``, as for ISG); another family's length and radius registers become the
    D that selects them (``select_tool_data``); an in stroke of a rigid tap gets the ``SPOS=`` that puts the
    spindle under position control before it (``orient_before_taps``)."""

    @classmethod
    def moves_like(cls, cycle: ResolvedCycle) -> bool:
        """A Fanuc-family G81/G82 block that ``MCALL CYCLE81``/``CYCLE82`` and a position block drill alike
        (``cycle_writing.writable``); any other is expanded."""
        if not super().moves_like(cycle):
            return False
        from postproc.cycles.section import CannedCycle
        from .cycle_writing import writable
        return isinstance(cycle, CannedCycle) and writable(cycle)

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``siemens.xml``, built in Python."""
        from postproc.cycles.resolve import CannedCycleResolveSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import SiemensBlockSyntax
        from .cycles import SiemensCycleEnd
        from .program import SiemensProgramSyntax
        return Pipeline(cls.NAME, [SiemensProgramSyntax(), SiemensBlockSyntax(), CannedCycleResolveSyntax("fanuc"),
                                   SiemensCycleEnd(), ModalStateSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Siemens)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("SiemensBlockSyntax", f"{__name__}.block_syntax:SiemensBlockSyntax")
    factory.register_lazy("SiemensProgramSyntax", f"{__name__}.program:SiemensProgramSyntax")
    factory.register_lazy("SiemensCycleLevels", f"{__name__}.cycles:CycleLevels")
    factory.register_lazy("SiemensCycleEnd", f"{__name__}.cycles:SiemensCycleEnd")
    factory.register_lazy("SiemensHoles", f"{__name__}.holes:SiemensHoles")
    factory.register_lazy("SiemensArc", f"{__name__}.arcs:SiemensArc")
    factory.register_lazy("SiemensCip", f"{__name__}.arcs:SiemensCip")
    factory.register_lazy("SiemensFixedPoint", f"{__name__}.fixed_point:SiemensFixedPoint")
    factory.register_lazy("SiemensSupa", f"{__name__}.frame_suppression:SiemensSupa")
    factory.register_lazy("SiemensTurn", f"{__name__}.helix:SiemensTurn")
