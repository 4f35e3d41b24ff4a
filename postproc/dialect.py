"""The dialect base class: one class per controller with a reader, a writer and capabilities.

As in sqlglot, a dialect overrides only what differs; the base never names a concrete dialect.
Capabilities are UPPER_CASE class attributes, each documented, and lowering transforms are chosen
from them (``postproc.lowering.lower``).
"""

from __future__ import annotations

import abc
from typing import TYPE_CHECKING, Callable, ClassVar, Generic, Iterable, Iterator, Mapping, Protocol, TypeVar, cast

from .geometry.arc_end import NEUTRAL_ARC_END, ArcEndRule
from .syntaxes.comments import CommentSyntax
from .errors import Diagnostics
from .output.line_format import LineRule
from .ir import Block
from .setup.machine_setup import MachineSetup
from .context import Context
from .cycle_words import CycleWords
from .syntaxes.syntax import Pipeline, load_pipeline
from .syntaxes.power_on_units import KEY as POWER_ON_UNITS
from .output.writer_base import Writer as Writer

if TYPE_CHECKING:
    from pathlib import Path  # (annotations; imported where a path is made: a start makes none, and pathlib
    # brings urllib.parse and ipaddress)
    from .compensation.rules import CutterRules


class ResolvedCycle(Protocol):
    """What ``Dialect.moves_like`` reads of a resolved hole cycle (``postproc.cycles.section.CannedCycle``,
    which the dialects' base does not import: the cycles build on it)."""

    kind: str
    semantics: str


class Reader(abc.ABC):
    """Turns text into blocks with raw words and source lines (no meaning yet)."""

    BLANKS: ClassVar[str] = ""
    """Characters outside ASCII that this reader reads as blanks (ISG: the no-break space of programs
    copied from web pages). The line check (``postproc.syntaxes.lines``) lets them through; the reader says so."""

    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx

    @abc.abstractmethod
    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        """Yield one block per physical line, in order, with its source location."""


T = TypeVar("T")


class Lazy(Generic[T]):
    """A class attribute imported when it is first read: ``READER = Lazy[type[Reader]](".reader:MyReader")``
    (``module:name`` as an entry point spells it; a module starting with ``.`` is relative to the package
    of the module that defines the class, so a renamed copy of a plugin needs no edit). Reading it gives
    the object, as a plain attribute would.

    Every installed dialect is registered at start-up, but a run reads and writes one or two: a dialect
    whose reader and writer (with their lexers, expression parsers, ...) are lazy costs the others
    nothing but its capability table (a few ms of a short run's start-up per dialect). With
    ``XFactory.register_lazy`` for its syntax objects and ``python_pipeline`` importing their modules
    inside, registering a dialect imports none of them (``tests/test_startup_imports.py``)."""

    __slots__ = ("target", "_module", "_value", "_loaded")

    def __init__(self, target: str) -> None:
        self.target = target
        self._module = ""
        """The module of the class the attribute is set on (relative targets start from its package)."""
        self._value: object = None
        self._loaded = False

    def __set_name__(self, owner: type, name: str) -> None:
        self._module = owner.__module__

    def __get__(self, obj: object, owner: type | None = None) -> T:
        if not self._loaded:
            self._value = self._load()
            self._loaded = True
        return cast(T, self._value)

    def _load(self) -> object:
        import importlib
        import sys
        module, _, names = self.target.partition(":")
        package = None
        if module.startswith("."):
            defining = sys.modules.get(self._module)
            package = getattr(defining, "__package__", None) or self._module.rpartition(".")[0]
        found: object = importlib.import_module(module, package)
        for name in names.split(".") if names else ():
            found = getattr(found, name)
        return found

    def __repr__(self) -> str:
        return f"Lazy({self.target!r})"


class Dialect:
    """A controller dialect. Subclasses set NAME and override what differs."""

    NAME: ClassVar[str] = ""
    DESCRIPTION: ClassVar[str] = ""
    READER: ClassVar[type[Reader] | None] = None
    """Reader class, or None for a write-only dialect (``Lazy`` imports it on first use)."""
    WRITER: ClassVar[type[Writer] | None] = None
    """Writer class, or None for a read-only dialect (``Lazy`` imports it on first use)."""
    PIPELINE_FILE: ClassVar[str | None] = None
    """Name of the reading pipeline XML shipped in the dialect's package (``pipeline_file``); a dialect
    may also declare it in Python (``python_pipeline``)."""
    LOWERING: ClassVar[tuple[Callable[..., Iterator[Block]], ...]] = ()
    """Lowering steps only this dialect needs as a target (``postproc.lowering.lower``), run after the generic
    ones, in order: pure block-stream transforms ``step(blocks, ctx, target)``."""
    CYCLE_WORDS: ClassVar[CycleWords | None] = None
    """Which letters carry the hole-cycle words when this dialect is read, and how it names its
    cycles (None: it reads no canned cycles)."""
    NATIVE_CYCLES: ClassVar[frozenset[str]] = frozenset()
    """Neutral names of the canned cycles the controller runs natively."""
    HOLE_PATTERNS: ClassVar[frozenset[str]] = frozenset()
    """Kinds of hole pattern (``postproc.patterns.HolePattern``: line, parallelogram, grid, circle, arc)
    the controller runs natively, repeating its active canned cycle; a pattern of another kind is
    written as the cycle at every point (``expand_hole_patterns``)."""
    STORED_WORK_OFFSETS: ClassVar[bool] = False
    """The dialect's programs may write a work offset into the controller's table, taken at the work system's
    next selection (``STORED_WORK_OFFSET``: ISG ``V.G.NP[n]``...): a translation from it to a target whose
    setting acts at once moves such a setting to the next selection (``postproc.lowering.stored_offsets``)."""
    INVERSE_TIME_FEED: ClassVar[bool] = False
    """The controller runs G93 inverse-time feed as RS274/NGC does (a move in 1/F minutes); else a
    translation writes each move's feed per minute (``postproc.lowering.inverse_time``)."""
    SPINDLE_ORIENTATION: ClassVar[bool] = True
    """The controller can stop the spindle at an angle (cycles that need it are handled per the set-up's
    ``Cycles orientation`` otherwise)."""
    SYNCHRONISED_TAP: ClassVar[bool] = False
    """The controller writes a rigid tap as one spindle-synchronised move (LinuxCNC's G33.1,
    ``postproc.lowering.synchronised_tap``): a rigid tap cycle of another family is written with it; without it such
    a tap is refused."""
    TAP_STROKES: ClassVar[bool] = False
    """The controller programs a rigid tap as two synchronised strokes, in and out with the spindle reversed
    (ISG's ``G331``/``G332``): a synchronised tap of another family is written as the two strokes
    (``postproc.cycles.rigid_tap_lowering``), and only such a controller writes a lone stroke."""
    RIGID_TAP_CYCLE: ClassVar[bool] = False
    """The controller's tap cycle is rigid by itself, its pitch a parameter (SINUMERIK ``CYCLE84``): another
    family's rigid-tapping code is left out (``postproc.cycles.rigid_tap_lowering``), the tap cycles after it
    written as that cycle or refused."""
    RIGID_TAP_LACK: ClassVar[str] = ""
    """Why the controller gets no synchronised tap (with its source), added where one is refused
    (``postproc.cycles.rigid_tap_lowering``); empty: none said."""
    RIGID_TAP_CODE: ClassVar[str] = ""
    """The machine code that makes the tap cycles after it rigid (Fanuc ``M29 S..``): a synchronised tap of
    another family is written as that code and a tap cycle (``postproc.lowering.synchronised_tap``); '' for none."""
    DWELL_UNIT: ClassVar[str] = "seconds"
    """Unit of the dwell time the writer emits: "seconds" (a decimal number) or "milliseconds" (a whole
    number)."""
    LENGTH_REGISTER_ADDRESS: ClassVar[str] = "H"
    """The address a program names a tool length register by, for messages (``verify``'s account of lost tool
    data, ``postproc.simulate.lost_tool_data``): H on Fanuc-style controllers; D where a D selects the tool's
    length and radius together (ISG, Fagor 8070, SINUMERIK)."""
    CUTTER_COMPENSATION: ClassVar[bool] = True
    """Cutter radius compensation (left/right) exists (the writer refuses it otherwise)."""
    CUTTER_RULES_LACK: ClassVar[str] = ""
    """Why the controller's cutter compensation is not simulated where ``CUTTER_RULES`` is None (its rules not
    confirmed, with the source), said in the verify report beside the compensation compared as a setting; '' for
    none said."""
    CUTTER_RULES: ClassVar[CutterRules | None] = None
    """How the controller compensates the cutter radius (``postproc.compensation.rules``), for the
    simulation; None: compensation is not simulated for this dialect (``verify`` compares the setting)."""
    ARC_END: ClassVar[ArcEndRule] = NEUTRAL_ARC_END
    """How far the controller lets an I/J/K arc's end point lie off the circle through its start, in the
    program's units, and which path it then runs (``postproc.geometry.arc_end``): the reading pipeline and the
    simulator judge each arc by the reading dialect's rule, ``verify`` a translation's by the target's."""
    R_ARC_FLOAT_SLACK: ClassVar[float] = 0.0
    """Where the controller refuses an R arc whose chord exceeds 2R by any amount, reckoned in its own
    floating point: that precision, relative to R (0: the controller has a tolerance, an R arc is written as
    it is). An R arc within reach of 180 degrees, whose centre that rounding moves far (an exact semicircle:
    the chord is 2R), is then written with the centre the source's controller turns about, by I/J/K
    (``postproc.lowering.arcs.settle_arc_ends``)."""
    TOOL_LENGTH_OFFSET: ClassVar[bool] = True
    """Tool length offset from a table exists (the writer refuses it otherwise)."""
    DYNAMIC_TOOL_LENGTH: ClassVar[bool] = False
    """A length given in the program (LinuxCNC's and grbl's ``G43.1 Z..``) can be written; False: the writer
    refuses it, at its own block (``postproc.lowering.length_timing`` leaves it there, never moves it to the
    block where the target would apply it)."""
    PATH_CONTROL_AT_START: ClassVar[str] = "cutting"
    """The path control mode in force before a program programs one ('cutting', 'exact_stop', or grbl's
    'exact_path': ``PathControl``): [K] Fanuc and LinuxCNC power on in G64. A translation between two dialects that start differently writes the source's
    mode before the first move where the program sets none first (``postproc.lowering.path_at_start``), and
    the simulation counts it from the first move (``Simulator.record_settings``)."""
    PATH_CONTROL: ClassVar[str | None] = None
    """The one path control mode the controller runs in, whatever the program says; None: the program sets
    it. ``verify`` accepts a source whose every path control is this mode, and with an exact mode (grbl's
    "exact_path": every programmed point is reached) any source: a blending mode only lets the path leave the
    programmed points the simulation compares."""
    LENGTH_TOGGLES: ClassVar[bool] = True
    """The tool length offset is turned on and off by code (G43/G49, Fagor's G43/G44); False: it applies
    whenever tool data is selected (ISG's ``D``, ``postproc.isg_family.tool_data``)."""
    LENGTH_AT_PROGRAMMED_AXIS: ClassVar[bool] = False
    """A change of the tool length offset moves nothing: axes keep their machine position until the
    length axis is next programmed absolutely, where the new length applies (LinuxCNC, ISG by default,
    grbl's G43.1); the simulator then moves the programmed point instead (``Moves.compensation``).
    False: the new length applies with the next move of any axis (the simulation's Fanuc model); a
    translation across the two rules moves or completes the change (``postproc.lowering.length_timing``,
    ``postproc.isg_family.tool_data``)."""
    LENGTH_AT_AXIS_MOVE: ClassVar[bool] = False
    """With ``LENGTH_AT_PROGRAMMED_AXIS`` False: a change applies only when the length axis itself next moves,
    absolutely or incrementally (Fagor), not with a move of another axis. From a source that applies it at the
    next move of any axis, the change goes beside the next move, which gets the Z the program stands at, as
    towards a target that applies it at the programmed axis (``postproc.lowering.length_timing``)."""
    POSITION_READS: ClassVar[Mapping[str, int]] = {}
    """Per axis, the numbered parameter a block reads the current position of that axis with (program units,
    every offset applied, read when the block is read: before the block's own tool offset change), which the
    target's writer spells as a word value (LinuxCNC's ``#5420``-``#5428``). A lowering writes it where a
    move must keep an axis the program never placed (``postproc.lowering.length_timing``); empty: none."""
    POSITION_READ_RADIUS: ClassVar[bool] = False
    """The X read is a radius in diameter mode while an X word is a diameter (LinuxCNC: ``#5420`` is
    ``current_x``, the radius, and an X word is halved under G7): the read is then doubled."""
    TAPE_MARKS: ClassVar[bool] = False
    """A ``%`` line may open and close a program (Fanuc, GSK, LinuxCNC): ``<Output tapeMarks="always">``."""
    LEADER_TITLE: ClassVar[bool] = False
    """The control skips what follows the ``%`` of a program's first line (its leader): a title read
    there (``TapeMark.title``) is written on that line; otherwise it is written as a comment after it
    (``postproc.lowering.program_frame``)."""
    PROGRAM_NUMBERS: ClassVar[bool] = False
    """The dialect writes a main program's number (Fanuc/GSK ``O``, ISG/Fagor ``%``):
    ``<Output programNumber="1001">``."""
    TOOL_CHANGER: ClassVar[bool] = True
    """An automatic tool changer exists (the writer refuses a tool change otherwise, unless the
    dialect's lowering rewrites it first)."""
    PROGRAMS: ClassVar[bool] = False
    """Variables, expressions and control flow (loops, jumps, subprograms) can be written: a program that
    computes is translated symbolically when every construct has a spelling here, else flattened (its
    evaluated motion). Without it every such program reaches this target flattened."""
    START_RETURN_LEVEL: ClassVar[str] = "initial"
    """The canned-cycle return level in force at program start ("initial": G98, "r": G99), which a cycle
    that programs none returns to (``postproc.rs274.return_level`` writes it where a source assumed the
    other)."""
    FEED_BEFORE_UNITS: ClassVar[bool] = False
    """An F in a block that changes units (``G20 G1 X1. F10.``) is read in the units in force before the
    block: the controller sets the feed rate before the length units (the RS274/NGC order of execution).
    The reader converts such an F into the block's units (the neutral Feed) and the writer back
    (``ctx.feed_before_units``); False: it is in the block's new units (grbl, Fanuc)."""
    WHOLE_SPINDLE_SPEED: ClassVar[bool] = False
    """An S word takes a whole number only (a decimal point is an alarm): the writer rounds a decimal speed
    to the nearest whole one, as the controller rounds a computed S, and warns (``NumberWriter.speed``)."""
    STOPS_BEFORE_MOTION: ClassVar[bool] = False
    """The controller stops the spindle and the coolant before the block's motion (the RS274/NGC order
    of execution), and its reader flags such stops ``before_motion`` (``postproc.ir.event_order``). A
    target that stops after the motion moves them ahead only when the source reads so."""
    FAMILY: ClassVar[str] = ""
    """The controller family whose machine-specific codes (``MachineFunction``: builders' M codes,
    machine G codes) this dialect writes verbatim; '' is a family of its own (the dialect's NAME)."""
    CYCLE_SEMANTICS: ClassVar[str] = ""
    """How the controller moves through its native canned cycles: the name of rules a family base registered
    (``postproc.cycles.semantics``; the RS274 family's 'fanuc' and 'rs274'): a cycle resolved under other rules is expanded for it. Each dialect
    with ``NATIVE_CYCLES`` names its own ('' where it has none: every cycle is expanded for it)."""
    PECK_CLEARANCE_MM: ClassVar[float | None] = None
    """The G73 retract and G83 re-approach clearance of the native peck cycles, mm, where the controller
    fixes it (LinuxCNC: 0.254, whatever the set-up says); None: machine parameters, the set-up's
    ``<Cycles peckRetract peckClearance>``. Reading uses it; a peck cycle read with another clearance is
    expanded for this target (``postproc.cycles.lowering``)."""

    MACHINE_TYPES: ClassVar[frozenset[str]] = frozenset({"mill"})
    """Machine types the dialect reads and writes ("mill", "lathe"); the set-up's ``machineType`` picks
    one where it has both, and a lathe-only dialect reads every program as a lathe's."""
    DIAMETER_PROGRAMMING: ClassVar[bool] = False
    """Lathe X can be programmed as a diameter (the set-up's ``xProgramming``); without it X is a radius
    and a diameter program's X is halved for it (``postproc.cycles.lathe_lowering``)."""
    X_MODE_SWITCH: ClassVar[bool] = False
    """A lathe program may switch how X reads inside it (LinuxCNC's G7/G8, ``XProgramming``): the switches are
    kept (the writer converts the IR's X where the mode differs); without it they go and every X is written
    as the set-up's mode (``postproc.cycles.lathe_lowering``)."""
    LATHE_CYCLES: ClassVar[frozenset[str]] = frozenset()
    """Neutral names of the lathe cycles (G70-G76, G90/G92/G94) the controller runs natively with the
    Fanuc system A/GSK words; others are expanded into their moves."""

    INCREMENTAL_AXES: ClassVar[Mapping[str, str]] = {}
    """On a lathe (``reads_lathe``), the addresses that move an axis by an increment whatever the distance
    mode -> that axis (the RS274 lathe base's ``U``/``W`` for ``X``/``Z``: ``postproc.rs274.lathe_axes``);
    the neutral steps and the simulator read it through ``Context.increments``. Empty: none."""
    LATHE_FEED_AT_START: ClassVar[str] = "per_min"
    """The feed mode a lathe program starts in before it programs one (Fanuc T: per revolution, G99, by
    its default parameter; GSK 980TDc: per minute, G98)."""
    MACRO_ARGUMENTS: ClassVar[Mapping[str, int]] = {}
    """The addresses a macro call passes arguments with -> the local variable each sets (Fanuc ``G65 A30.``:
    ``#1``), so a macro file run on its own (``toolpath``/``verify --arg A=30``) starts with them; empty:
    the dialect has no such arguments."""
    MOTION_AT_START: ClassVar[str | None] = None
    """The motion mode ("rapid", "linear") a program is in before it programs one, for a controller that
    powers on in one (the set-up's ``<Controller startMotion>`` may say the other); None: axis words need
    a motion code first."""
    MIST_COOLANT: ClassVar[bool] = True
    """The controller runs mist coolant in every build; False: only in a build that has it, which the set-up
    says with ``<Controller mistCoolant="true">`` (otherwise mist coolant is refused, never written)."""
    LOWER_CASE: ClassVar[bool] = False
    """The reader takes lower-case addresses (``g1 x10``): the set-up's ``<Output case="lower">`` is
    refused otherwise."""
    COMMENTS: ClassVar[CommentSyntax] = CommentSyntax(parens=False)
    """How the controller writes comments (``postproc.syntaxes.comments``): what text is safe inside one, and where
    a line's comments are. The values a set-up template writes stand only inside a comment
    (``postproc.output.template_values``); the default knows no comment, so a dialect that declares none has
    every such value refused."""
    LINE_RULE: ClassVar[LineRule | None] = None
    """Rules every written line obeys on this controller (``postproc.output.line_format.LineRule``: grbl's line
    buffer and real-time characters), applied to whatever the writer emits; None: no rule."""
    LATHE_TURRET: ClassVar[bool] = True
    """On a lathe, T indexes the turret with its offset (Fanuc-family ``T0101``); False: the control changes a
    lathe tool as a mill's, with ``M6`` (LinuxCNC), and a turret index is written so."""
    LATHE_PATH_CONTROL: ClassVar[bool] = True
    """A lathe program can set a modal path control mode (G61/G64); False where the lathe code table has none
    (Fanuc T, GSK 980TDc: [?], their writers' ``PATH_CONTROL_LACK``): a mode the program sets is refused there
    by name, and a source's power-on exact mode, which the program never asked for, is not written, with a
    warning (``postproc.lowering.path_at_start``)."""
    LATHE_ONE_BLOCK: ClassVar[bool] = False
    """The control reads the one-block forms ``G71 P Q U W D F`` and ``G76 X Z I K D F A P`` (Fanuc
    10/11/15-T) when the set-up's ``latheCycleFormat`` says so; without it every cycle has two blocks."""

    @classmethod
    def writer_class(cls, ctx: Context) -> type[Writer] | None:
        """The writer of a run whose program was read under ``ctx`` (``WRITER``; a dialect with a writer of its
        own for lathe programs picks it here, as LinuxCNC does)."""
        return cls.WRITER

    @classmethod
    def cutter_rules(cls, setup: MachineSetup) -> CutterRules | None:
        """The cutter compensation rules the controller follows under ``setup`` (a parameter may choose
        among the family's, or leave a machine type unsimulated); by default ``CUTTER_RULES``."""
        return cls.CUTTER_RULES

    @classmethod
    def cutter_rules_unknown(cls, setup: MachineSetup) -> str:
        """Why ``cutter_rules`` gives none under ``setup``: what a refusal to resolve the compensation into
        moves names as unknown."""
        return f"the cutter compensation rules of the {cls.NAME} control are not modelled"

    @classmethod
    def reads_lathe(cls, setup: MachineSetup) -> bool:
        """Whether a program is read (and written) with lathe meanings under ``setup``."""
        types = cls.MACHINE_TYPES
        return "lathe" in types and (setup.input.machine_type == "lathe" or "mill" not in types)

    @classmethod
    def capabilities(cls) -> dict[str, object]:
        """The capability table: every UPPER_CASE attribute that describes the controller (not the code that
        runs it: a ``Lazy`` class a dialect loads on use, its writers and reader, is no capability)."""
        skip = {"NAME", "DESCRIPTION", "READER", "WRITER", "LATHE_WRITER", "PIPELINE_FILE", "LATHE_PIPELINE_FILE", "CYCLE_WORDS",
                "LOWERING", "COMMENTS", "LINE_RULE", "MACRO_ARGUMENTS"}
        table: dict[str, object] = {}
        for klass in reversed(cls.__mro__):
            for key, value in vars(klass).items():
                if key == "CUTTER_RULES":
                    table[key] = None if value is None else value.name  # whose rules, by name
                elif key == "ARC_END":
                    table[key] = value.describe()
                elif key.isupper() and key not in skip and not key.startswith("_") and not isinstance(value, Lazy):
                    table[key] = sorted(value) if isinstance(value, frozenset) else \
                        dict(value) if isinstance(value, Mapping) else value
        return table

    @classmethod
    def moves_like(cls, cycle: ResolvedCycle) -> bool:
        """Whether the controller's native cycle of ``cycle.kind`` moves as ``cycle`` does, resolved under its
        source's family rules (``cycle.semantics``): by default when the families are the same
        (``CYCLE_SEMANTICS``). A controller whose cycles follow rules of their own judges each block (grblHAL's
        G98 level); a block judged otherwise is expanded (``postproc.cycles.lowering``)."""
        return cycle.semantics == cls.CYCLE_SEMANTICS

    @classmethod
    def family(cls) -> str:
        """The family machine-specific codes travel in (``FAMILY``, or the dialect alone)."""
        return cls.FAMILY or cls.NAME

    @classmethod
    def pipeline(cls, setup: MachineSetup) -> Pipeline:
        """The reading pipeline: the set-up's override if it names one, else the dialect's own, as it
        declares it in Python (``python_pipeline``) or else from its file (``file_pipeline``)."""
        override = setup.pipeline_path()
        if override is not None:
            return load_pipeline(override)
        declared = cls.python_pipeline(setup)
        return declared if declared is not None else cls.file_pipeline(setup)

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline | None:
        """The pipeline of the dialect's own file (``pipeline_file(setup)``), built in Python: a run then
        reads no XML and imports no XML parser (lxml costs a one-line translation ~5 ms of its start-up).
        None (the default): the file is read. The file stays the definition a set-up's ``pipeline``
        starts from; the conformance suite (``postproc.testing``) checks that the two are the same.
        Import the steps' modules inside the method, so that registering the dialect does not."""
        return None

    @classmethod
    def pipeline_file(cls, setup: MachineSetup) -> str | None:
        """The name of the pipeline XML beside the dialect's module that reads under ``setup``
        (``PIPELINE_FILE``; a dialect with one per machine type picks it here)."""
        return cls.PIPELINE_FILE

    @classmethod
    def file_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """The pipeline read from the dialect's file (``pipeline_file``); one of no steps where it has none."""
        name = cls.pipeline_file(setup)
        if name is None:
            return Pipeline(cls.NAME, [])
        module = cls.__module__
        package = module if _is_package(module) else module.rpartition(".")[0]
        beside = _package_folder(package)
        from pathlib import Path
        if beside is not None:
            return load_pipeline(beside / name)
        from importlib import resources  # a package inside a zip file: its data is extracted
        ref = resources.files(package) / name
        with resources.as_file(ref) as path:
            return load_pipeline(Path(path))

    @classmethod
    def arc_end_rule(cls, setup: MachineSetup) -> ArcEndRule:
        """``ARC_END`` with what the set-up says of this controller's own parameters (a dialect whose limits
        are machine parameters overrides this: ISG, Fagor)."""
        return cls.ARC_END

    @classmethod
    def context(cls, file: str, setup: MachineSetup, diagnostics: Diagnostics) -> Context:
        ctx = Context(file, setup, diagnostics, cls.NAME, cls.CYCLE_WORDS)
        ctx.reader = cls.READER
        ctx.stops_before_motion = cls.STOPS_BEFORE_MOTION
        ctx.feed_before_units = cls.FEED_BEFORE_UNITS
        ctx.cutter_rules = cls.cutter_rules(setup)
        ctx.arc_end = cls.arc_end_rule(setup)
        if ctx.cutter_rules is None:
            ctx.run_data[RULES_UNKNOWN_KEY] = cls.cutter_rules_unknown(setup)
        ctx.length_at_axis = cls.LENGTH_AT_PROGRAMMED_AXIS
        ctx.path_at_start = cls.PATH_CONTROL_AT_START
        ctx.lathe_turret = cls.LATHE_TURRET
        ctx.peck_clearance_mm = cls.PECK_CLEARANCE_MM
        if cls.STORED_WORK_OFFSETS:
            ctx.run_data[STORED_OFFSETS_KEY] = True  # (``postproc.lowering.stored_offsets``)
        if cls.INVERSE_TIME_FEED:
            ctx.run_data[INVERSE_TIME_KEY] = True  # its programs may run in G93 (``postproc.lowering.inverse_time``)
        ctx.lathe = cls.reads_lathe(setup)
        ctx.diameter = ctx.lathe and cls.DIAMETER_PROGRAMMING and setup.input.x_programming == "diameter"
        ctx.one_block = ctx.lathe and cls.LATHE_ONE_BLOCK and setup.input.lathe_cycle_format == "one-block"
        if ctx.lathe:
            ctx.increments = cls.INCREMENTAL_AXES
        if cls.MOTION_AT_START is not None:
            ctx.state.motion = setup.controller.start_motion or cls.MOTION_AT_START
        if setup.controller.start_units is not None:
            ctx.state.units = setup.controller.start_units  # (``postproc.syntaxes.power_on_units``)
            ctx.state.extra[POWER_ON_UNITS] = setup.controller.start_units
        if ctx.lathe:
            ctx.state.plane = "ZX"  # a lathe turns in the ZX plane (G18) from the start
            ctx.state.feed_mode = cls.LATHE_FEED_AT_START
        return ctx


STORED_OFFSETS_KEY = "stored_work_offsets"
"""``ctx.run_data`` key: the reading dialect has ``STORED_WORK_OFFSETS``."""
INVERSE_TIME_KEY = "inverse_time"
"""``Context.run_data`` key, set when the reading dialect has G93 (``Dialect.INVERSE_TIME_FEED``)."""
RULES_UNKNOWN_KEY = "cutter_rules_unknown"
"""``Context.run_data`` key: why the reading dialect's cutter compensation rules are not modelled under the set-up
(``Dialect.cutter_rules_unknown``), set only then."""


def _package_folder(package: str) -> Path | None:
    """The folder of a package imported from files (its data files lie beside its modules), without
    importing ``importlib.resources`` (a tenth of a one-line translation's start-up); None otherwise."""
    import sys
    from pathlib import Path
    mod = sys.modules.get(package)
    paths = list(getattr(mod, "__path__", ()))
    if len(paths) == 1 and Path(paths[0]).is_dir():
        return Path(paths[0])
    return None


def _is_package(module: str) -> bool:
    import sys
    mod = sys.modules.get(module)
    return bool(mod is not None and hasattr(mod, "__path__"))
