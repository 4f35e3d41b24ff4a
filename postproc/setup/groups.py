"""The set-up's groups of parameters (``<Input>``, ``<Output>``, ``<Cycles>``, ...), its templates and
machine-specific codes, and the readers of its small elements: the records ``postproc.setup.machine_setup`` assembles
into a ``MachineSetup`` and ``postproc.setup.load`` fills from a chain of files (both import this module,
it imports neither)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, ClassVar, Literal

from ..errors import ConfigError
from ..records import record
from .record import MAX_COORDINATE, SetupGroup, camel, pydantic_config, setting, values
from ..xmlio import where

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree


class InputSettings(SetupGroup):
    TAG = "Input"
    decimal_point: Literal["least-increment", "calculator"] = "least-increment"
    """How a value written without a decimal point is read: Fanuc's least input increment (X10 =
    0.010 mm on IS-B) or calculator-type input (parameter 3401#0 DPI: X10 = 10 mm)."""
    increment_system: Literal["IS-A", "IS-B", "IS-C"] = "IS-B"
    machine_type: Literal["mill", "lathe"] = "mill"
    """What the G codes mean: a mill never reads lathe meanings (G70-G76 lathe cycles, G98/G99 feed
    modes, G50 coordinate setting, U/W incremental) and a lathe never reads mill ones."""
    gcode_system: Literal["A", "B", "C"] = "A"
    """Fanuc lathe G-code system (parameter 3401#6/#7): A numbers G90/G92/G94 as single cycles and G98/G99
    as feed modes; B and C renumber them (DIALECTS.md 1.1). Read on lathes only; GSK is always A."""
    x_programming: Literal["diameter", "radius"] = "diameter"
    """Lathe X (and U) words as diameters (the default) or radii. Arc I and the depths of G71-G76 are
    radii either way."""
    lathe_cycle_format: Literal["two-block", "one-block"] = "two-block"
    """G71-G73 and G76 as two blocks (0i/30i, GSK) or one block (10/11/15-T: ``G71 P Q U W D F``,
    ``G76 X Z I K D F A P``)."""
    repeat_address: Literal["K", "L", "K+L"] = "K"
    """Which address counts canned-cycle repeats (0i/30i: K; 15i and older: L)."""

    def increment(self, units: str) -> float:
        """Least input increment in program units."""
        mm = {"IS-A": 0.01, "IS-B": 0.001, "IS-C": 0.0001}[self.increment_system]
        return mm if units == "mm" else mm / 10.0


class OutputSettings(SetupGroup):
    TAG = "Output"
    normalize: bool = False
    """Write every block from its words with explicit decimal points instead of copying it."""
    decimals: int = setting(3, ge=0, le=6)
    inch_decimals: int = setting(4, ge=0, le=7)
    renumber_start: int = setting(0, ge=0)
    """0 keeps the block numbers as written; otherwise renumber from this value."""
    renumber_step: int = setting(10, ge=1)
    leading_zero: bool = True
    """Write 0.5 rather than .5."""
    # -- line formatting (``postproc.output.line_format``) --
    block_numbers: Literal["keep", "all", "tool-changes", "none"] = "keep"
    """Which lines get a block number: as written, every line with words, only tool changes, none."""
    number_max: int = setting(99999, ge=1, le=99_999_999)
    """The largest block number; the next wraps to ``renumberStart`` (Fanuc 0i, LinuxCNC: five digits)."""
    case: Literal["keep", "upper", "lower"] = "keep"
    """Letter case outside comments (lower only where the target's reader accepts it: ``LOWER_CASE``)."""
    line_ending: Literal["keep", "lf", "crlf"] = "keep"
    """Every line's ending (keep: as read; generated lines LF)."""
    max_line_length: int = setting(0, ge=0, le=1 << 20)
    """Longest line the control takes, line ending excluded (0: no limit); a longer one is an error."""
    # -- decimals per address (``WordWriter.number``) --
    address_decimals: str = ""
    """Places per address in mm programs, e.g. ``XYZ3 F1 S0``: each group of address letters then its
    places (0-6). Such an address is rounded to them (a real rounding: warned once per address when it
    moves a value); the others follow ``decimals``. Implies normalizing."""
    inch_address_decimals: str = ""
    """The same in inch programs (places 0-7)."""
    # -- the program's frame (``postproc.lowering.program_frame``) --
    tape_marks: Literal["keep", "always", "never"] = "keep"
    """``%`` lines: as the source has them, always one opening and one closing the program (a dialect
    with ``TAPE_MARKS``), or none."""
    program_number: Literal["keep", "none"] | int = "keep"
    """The main program's number: as the source has it, none, or this number (1-9999; a dialect with
    ``PROGRAM_NUMBERS``: Fanuc/GSK ``O1001``, ISG/Fagor ``%1001``). A subprogram's number is never changed."""

    def __post_init__(self) -> None:
        number = self.program_number
        if isinstance(number, bool) or not (number in ("keep", "none") or isinstance(number, int)
                                            and 1 <= number <= 9999):
            raise ValueError(f"programNumber {number!r} is not keep, none or a program number (1-9999)")
        parse_address_decimals(self.address_decimals, 6)
        parse_address_decimals(self.inch_address_decimals, 7)

    def address_places(self, inch: bool) -> dict[str, int]:
        """Address letter -> places, in mm or inch programs (empty: ``decimals`` for every address)."""
        if inch:
            return parse_address_decimals(self.inch_address_decimals, 7)
        return parse_address_decimals(self.address_decimals, 6)


ROUNDED_ADDRESSES = "XYZABCUVWIJKRQFS"
"""Addresses whose places ``<Output addressDecimals>`` may set: axes, arc centres, radius and cycle R,
peck Q, feed, spindle speed (the rest are whole numbers or codes)."""


def parse_address_decimals(text: str, most: int) -> dict[str, int]:
    """``"XYZ3 F1 S0"`` -> ``{"X": 3, "Y": 3, "Z": 3, "F": 1, "S": 0}``; a ValueError says what is wrong."""
    places: dict[str, int] = {}
    for entry in text.split():
        letters = entry.rstrip("0123456789")
        digits = entry[len(letters):]
        if not letters or not digits:
            raise ValueError(f"{entry!r}: each entry is address letters then places, e.g. 'XYZ3 F1 S0'")
        count = int(digits)
        if count > most:
            raise ValueError(f"{entry!r}: at most {most} places")
        for letter in letters:
            if letter not in ROUNDED_ADDRESSES:
                raise ValueError(f"{entry!r}: {letter!r} is not one of {ROUNDED_ADDRESSES} (upper case)")
            if letter in places:
                raise ValueError(f"{entry!r}: {letter} is given twice")
            places[letter] = count
    return places


class CycleSettings(SetupGroup):
    TAG = "Cycles"
    peck_retract: float = setting(0.5, gt=0)
    """G73 retract d after each peck, mm (Fanuc parameter 5114)."""
    peck_clearance: float = setting(0.5, gt=0)
    """G83 re-approach clearance d above the previous bottom, mm (Fanuc parameter 5115)."""
    shift_direction: Literal["+X", "-X", "+Y", "-Y"] = "+X"
    """Direction of the G76/G87 tool shift by Q (Fanuc parameters 5101#4/#5)."""
    orient_angle: float = 0.0
    back_boring_levels: Literal["seed", "manual"] = "seed"
    """G87 level convention. 'seed': rapid down to Z (bottom), cut up to R. 'manual' (Fanuc manual):
    rapid down to R (below the part), cut up to Z."""
    expand: str = ""
    """Cycles to expand even where the target runs them natively (comma-separated neutral names or
    'all')."""
    orientation: Literal["error", "m19", "stop"] = "error"
    """How a target without oriented spindle stop handles one: fail, emit M19 anyway, or program stop
    for the operator."""
    fagor_dwell_unit: Literal["seconds", "hundredths"] = "seconds"
    """Unit of the Fagor 8070 cycle dwell K, read and written: seconds (the default; the 8070's unit is
    unconfirmed) or hundredths of a second (the 8055's)."""

    def expanded(self) -> frozenset[str]:
        return frozenset(p.strip() for p in self.expand.split(",") if p.strip())


class MachineSettings(SetupGroup):
    TAG = "Machine"
    axes: str = "XYZ"
    units: Literal["mm", "inch"] = "mm"
    """Unit of the machine's lengths in the set-up: start position, travel and home (``<Axes>``), work
    offsets (``<WorkOffsets>``), tool offsets (``<Tools>``). Cycle parameters stay in mm."""
    start_x: float = setting(0.0, ge=-MAX_COORDINATE, le=MAX_COORDINATE)
    start_y: float = setting(0.0, ge=-MAX_COORDINATE, le=MAX_COORDINATE)
    start_z: float = setting(0.0, ge=-MAX_COORDINATE, le=MAX_COORDINATE)
    """Position (work coordinates, in ``units``) assumed at program start for toolpath simulation."""
    start_tool: int | None = setting(None, ge=0, le=99_999_999)
    """The tool in the spindle when the program starts (``<Machine startTool="3">``), which a LinuxCNC
    ``G41``/``G42`` without D or ``G43`` without H takes before the program's first tool change; None:
    unknown (the machine's, from before the program), and such a block is a located error."""
    tool_lengths: Literal["table", "touched_off"] = "table"
    """Where a tool's length comes from: ``table``, the offset registers (``<Tools>``) that G43 H reads;
    ``touched_off``, nowhere: the work's Z zero is set again with each tool at its change (a router's
    touch-off plate), so the programmed Z is the tool's tip, every length offset is zero, and a
    translation for a controller without a tool table drops the offsets with a note."""

    def mm(self) -> float:
        """mm per unit of the machine's lengths."""
        return 25.4 if self.units == "inch" else 1.0

    def __post_init__(self) -> None:
        bad = set(self.axes) - set("XYZABCUVW")
        if bad or len(set(self.axes)) != len(self.axes):
            raise ValueError(f"axes must be distinct letters from XYZABCUVW, got {self.axes!r}")


class LatheCycleSettings(SetupGroup):
    """The data parameters a lathe cycle takes an omitted word from (GSK 980TDc No.051-060, Fanuc
    5130-5143). A value programmed in a cycle replaces the default for later cycles of the run, as the
    controller rewrites its parameter. Lengths in mm (an inch program reads them converted), radius values."""

    TAG = "LatheCycles"
    rough_depth: float = setting(1.0, gt=0)
    """G71/G72 depth of cut per pass (GSK No.051, Fanuc 5132)."""
    rough_retract: float = setting(1.0, ge=0)
    """G71/G72 retract after each pass (GSK No.052, Fanuc 5133)."""
    pattern_relief_x: float = 1.0
    """G73 total X relief (GSK No.053, Fanuc 5135)."""
    pattern_relief_z: float = 1.0
    """G73 total Z relief (GSK No.054, Fanuc 5136)."""
    pattern_passes: int = setting(1, ge=1, le=9999)
    """G73 number of passes (GSK No.055, Fanuc 5137)."""
    peck_retract: float = setting(1.0, ge=0)
    """G74/G75 retract per peck (GSK No.056, Fanuc 5139)."""
    thread_finish_passes: int = setting(1, ge=1, le=99)
    """G76 finishing passes m (GSK No.057 [?], Fanuc 5142)."""
    thread_chamfer: int = setting(10, ge=0, le=99)
    """G76 pull-out chamfer r in 0.1 x lead (GSK No.058 [?], Fanuc 5130)."""
    thread_angle: int = 60
    """G76 tool angle a in degrees (GSK No.059 [?], Fanuc 5143)."""
    thread_min_depth: float = setting(0.1, gt=0)
    """G76 minimum depth of cut (Fanuc 5140)."""
    thread_allowance: float = setting(0.05, ge=0)
    """G76 finishing allowance d (GSK No.060, Fanuc 5141)."""

    def __post_init__(self) -> None:
        if self.thread_angle not in (0, 29, 30, 55, 60, 80):
            raise ValueError(f"threadAngle must be 0, 29, 30, 55, 60 or 80, got {self.thread_angle}")


class Limits(SetupGroup):
    """Bounds of the interpreter (``postproc.interp``): a program that exceeds one is a located error
    naming the construct, never a hang."""

    TAG = "Limits"
    loop_iterations: int = setting(1_000_000, ge=1)
    """Total loop iterations, jumps, returns to a program's start and subprogram calls of one run."""
    repeated_work: int = setting(1_000_000, ge=1)
    """Blocks the interpreter runs again in one run, and the moves they expand to: the work of its loops,
    jumps and calls, whatever their iteration counts (the first run of each block is not counted, so a
    straight program of any length never reaches it). A million: an endless loop ends in about ten seconds,
    and a parametric program of 20,000 holes in nested loops (make bench: 141k blocks run) passes."""
    call_depth: int = setting(64, ge=1)
    """Nested subprogram and macro calls."""
    kept_prefix: int = setting(100_000, ge=0)
    """Blocks of the straight start of a program kept for a later backward jump into it."""
    moves_per_block: int = setting(100_000, ge=1)
    """Moves (and dwells, spindle actions) one block may expand to: a canned cycle with a huge repeat
    count or a tiny peck is a located error before it fills memory."""
    line_length: int = setting(65_536, ge=1, le=1 << 30)
    """Characters in one program line: a longer line is a located error before it is read (no
    controller accepts anything near the default 64 kB)."""


class ControllerSettings(SetupGroup):
    """Which controller of the dialect's family the machine has: its variant selects the family's
    default machine codes and the variant's word rules (each rule may be set on its own)."""

    TAG = "Controller"
    variant: Literal["fanuc", "haas", "fanuc-0m"] | None = None
    """Which controller of its family the dialect's machine is: None, the one the dialect describes
    (``postproc dialects``; the core has no default family); for the Fanuc family 'fanuc' (0i/30i, as
    None), 'haas' (dwell P with a decimal point in seconds; G103, G187 and Haas M codes), 'fanuc-0m'
    (cutter compensation may take its register from H)."""
    dwell_seconds: bool | None = None
    """A dwell P written with a decimal point is in seconds (G04 P0.5, G82 ... P0.5); without a point it
    stays milliseconds. None: as the variant does (Haas: yes)."""
    cutter_register_h: bool | None = None
    """G41/G42 may take the offset register from H when the block has no D and no tool length
    offset (Fanuc 0M ``G42 H19``). None: as the variant does (0M: yes)."""

    cutter_startup: Literal["A", "B"] = "A"
    """How cutter compensation starts on a Fanuc-family control: start-up type A, the start-up move ends
    square to the next move, or B, it ends as a corner of offset mode would (Fanuc parameter SUP, No.
    5003#0: 0 type A, the default, 1 type B [K: B-62764EN 15.6.2]; on a Haas mill its setting 43, "Cutter Comp
    Type" A or B [K: Haas mill operator's manual, settings]); ``postproc.compensation.rules``."""

    start_motion: Literal["rapid", "linear"] | None = None
    """The motion mode in force at power-on, before a program programs one, on a controller that has one
    (``Dialect.MOTION_AT_START``; Fanuc: G00 or G01 by parameter 3402#0 G01). None: the dialect's
    default. A dialect without a power-on mode (axis words need a motion code first) ignores it."""

    start_units: Literal["mm", "inch"] | None = None
    """The units in force at power-on, before a program programs G20/G21 (Fanuc parameter 0000#2 INI [K], Haas
    Setting 9 [K]): the reading starts in them and the first block that reads a length carries them
    (``postproc.syntaxes.power_on_units``). None: not given, such a program is read in millimetres."""

    mist_coolant: bool | None = None
    """The controller's build runs mist coolant. None: as the dialect says (``Dialect.MIST_COOLANT``: every
    build but grbl's, where it takes ENABLE_M7)."""

    tool_table: bool | None = None
    """The controller's build keeps a tool table, so a length offset from a register is written as such
    (grblHAL with ``N_TOOLS`` above 0 or a tool table plugin). None: as the dialect says (the family's
    ``GrblFamily.tool_table``); a dialect that always or never has one ignores it."""
    expressions: bool | None = None
    """The controller's build runs parameters, expressions and o-word flow control (grblHAL with
    ``NGC_EXPRESSIONS_ENABLE``, the program run from its file system). None: as the dialect says."""
    spindle_sync: bool | None = None
    """The controller's spindle reports its position, so feed per revolution runs (grblHAL: a spindle with
    an encoder). None: as the dialect says."""
    tool_change_with_spindle_on: bool = False
    """The machine's tool change leaves the spindle turning, as a lathe's turret index does: LinuxCNC's
    ``[EMCIO] TOOL_CHANGE_WITH_SPINDLE_ON = 1``, "useful for lathes" [V: LinuxCNC ini-config.adoc; its
    interpreter's convert_tool_change stops every spindle only without it, rs274 run so emits
    STOP_SPINDLE_TURNING before CHANGE_TOOL]. False: a tool change (M6) stops the spindle, which then stays
    stopped until the program starts it; a Fanuc T/GSK turret index with the spindle turning is then refused
    towards a control that changes tools with M6 (``postproc.cycles.lathe_lowering``)."""
    g53_tool_corr: bool | None = None
    """SINUMERIK machine data ``$MN_G53_TOOLCORR``: whether a block without frames (``G53``, ``G153``, ``SUPA``)
    keeps the tool length in force (0, false) or suppresses it too (1, true) [V: SINUMERIK 802D sl/840D ISO Milling
    programming manual 04.07, 3.1.1]. None: not given, and such a block under a tool length is kept verbatim
    (refused elsewhere, naming this attribute)."""
    centre_shift_limit: float | None = setting(None, ge=0)
    """ISG: how far (mm) G165 may move an arc's centre, P-CHAN-00059 ``mittelpkt_diff`` (0.1 um) / 10000.
    None: its default, 2 mm (``dialects/isg`` ``ARC_END``)."""
    centre_shift_share: float | None = setting(None, ge=0)
    """ISG: the share of the corrected radius G165 may move the centre, P-CHAN-00060 ``mittelpkt_faktor``
    (0.1 %) / 1000. None: its default, 0.05."""
    arc_radius_error: float | None = setting(None, ge=0)
    """Fagor 8070: the difference (mm) of an arc's start and end radii it accepts, CIRINERR. None: 0.01 mm
    taken (its default is not documented)."""
    arc_radius_share: float | None = setting(None, ge=0)
    """Fagor 8070: the same as a share of the radius, CIRINFACT (as a fraction, not %). None: none taken."""
    version: str | None = setting(None, pattern=r"^[0-9]{1,3}\.[0-9]{1,3}(\.[0-9]{1,3})?$")
    """The controller software's release, ``major.minor[.patch]`` (``2.9.0``), where a behaviour the dialect models
    changed between releases: LinuxCNC's G70-G72 (``postproc.rs274.ngc_g7x``: a roughing profile short of the
    cycle's X/Z, the pocket walk). None: not given, and such a program is refused where the releases differ."""
    rotation_incremental: bool = False
    """A coordinate rotation's angle R follows G90/G91: under G91 it is added to the angle of the program's
    previous rotation (Fanuc parameter 5400#0 RIN = 1 [V: 0i-A connection manual B-63503EN, 5400];
    Haas setting 73 "G68 incremental R" [K: Haas mill operator's manual, G68]). False: R is absolute."""

    def release(self) -> tuple[int, ...] | None:
        """``version`` as numbers (``(2, 9, 0)``), a missing patch 0; None where not given."""
        if self.version is None:
            return None
        numbers = tuple(int(part) for part in self.version.split("."))
        return numbers if len(numbers) == 3 else numbers + (0,)


CodeAction = Literal["none", "stop", "optional-stop", "spindle-cw", "spindle-ccw", "spindle-stop",
                     "coolant-on", "coolant-off", "gear", "tool-change", "rigid-tap", "thread-chamfer-on",
                     "thread-chamfer-off"]
"""What a machine code does in the simulation (``<M action="...">``)."""


@record(frozen=True)
class MachineCode:
    """One machine-specific code (``<M number="31" action="none" name="part counter"/>``, or ``<G ...>``):
    kept verbatim between controllers of one family, simulated by its action."""

    __pydantic_config__: ClassVar[dict[str, Any]] = pydantic_config(camel)
    letter: Literal["M", "G"]
    number: str = setting(pattern=r"^[0-9]{1,4}(\.[0-9]{1,2})?$")
    """The code's number as a controller reads it (``31``, ``187``, ``5.1``); M numbers are whole."""
    action: CodeAction = "none"
    name: str = ""
    """What the code does, for messages and the toolpath."""
    words: str = setting("", pattern=r"^[A-Z]*$")
    """Address letters the code takes with it (G187 P1 E0.01: 'PE'), kept verbatim beside it."""

    def __post_init__(self) -> None:
        if self.letter == "M" and "." in self.number:
            raise ValueError(f"an M code number is whole, got {self.number!r}")
        if self.action != "none" and self.letter == "G":
            raise ValueError("a machine G code has no action but none (it moves nothing)")

    def key(self) -> tuple[str, str]:
        """``("M", "31")``, ``("G", "5.1")``: numbers compared as a controller reads them."""
        return self.letter, _number_key(self.number)


def _number_key(number: str) -> str:
    whole, _, frac = number.partition(".")
    frac = frac.rstrip("0")
    return f"{int(whole)}.{frac}" if frac else str(int(whole))


@record
class Templates:
    """jinja2 templates (rendered sandboxed, ``postproc.lowering.sequences``) for the program header and footer, and
    for the sequences that replace a block: the tool change, the start of each operation and the program
    end. A template left out leaves its place as the translation writes it."""

    header: str | None = None
    footer: str | None = None
    tool_change: str | None = None
    """Replaces each tool-change block (``T1 M06``)."""
    operation_start: str | None = None
    """Written before each tool change (an operation begins where its tool is loaded)."""
    program_end: str | None = None
    """Replaces the program-end block (``M30``, ``M02``)."""

    TAGS: ClassVar[dict[str, str]] = {"Header": "header", "Footer": "footer", "ToolChange": "tool_change",
                                      "OperationStart": "operation_start", "ProgramEnd": "program_end"}
    """Element name in ``<Templates>`` -> field, in the order ``config dump`` writes them."""

    def defined(self) -> dict[str, str]:
        """field -> template text, for the templates the set-up defines."""
        return {f: t for f in self.TAGS.values() if (t := getattr(self, f))}


GROUPS: dict[type[SetupGroup], str] = {
    InputSettings: "input", OutputSettings: "output", CycleSettings: "cycles", MachineSettings: "machine",
    Limits: "limits", ControllerSettings: "controller", LatheCycleSettings: "lathe_cycles"}
"""The built-in groups, in the order ``config dump`` writes them, and the ``MachineSetup`` attribute of each."""


def builtin_groups() -> dict[str, type[SetupGroup]]:
    return {cls.TAG: cls for cls in GROUPS}


def machine_codes_from_xml(el: etree._Element, lane: Callable[[type[Any], dict[str, Any]], Any] | None = None
                           ) -> list[MachineCode]:
    """``<MachineCodes>`` holds ``<M>`` and ``<G>`` elements; a code declared twice is an error. ``lane``: a
    shortcut past pydantic for plain values (``postproc.setup.load.Lane``)."""
    from .validate import Invalid, validate
    if el.attrib:
        raise ConfigError("<MachineCodes> takes no attributes, only <M> and <G> elements", where(el))
    codes: list[MachineCode] = []
    seen: set[tuple[str, str]] = set()
    for child in el:
        if not isinstance(child.tag, str):
            continue
        if child.tag not in ("M", "G"):
            raise ConfigError(f"unknown element <{child.tag}> in <MachineCodes> (expected <M> or <G>)", where(child))
        if len([c for c in child if isinstance(c.tag, str)]):
            raise ConfigError(f"<{child.tag}> takes attributes only", where(child))
        raw = {"letter": child.tag, **dict(child.attrib)}
        plain = lane(MachineCode, raw) if lane is not None else None
        try:
            code = plain if isinstance(plain, MachineCode) else validate(MachineCode, raw)
        except Invalid as exc:
            field_name, msg = exc.problems[0]
            raise ConfigError(f"<{child.tag}> {field_name}: {msg}" if field_name else f"<{child.tag}> {msg}",
                              where(child)) from None
        if code.key() in seen:
            raise ConfigError(f"{code.letter}{code.number} is declared twice", where(child))
        seen.add(code.key())
        codes.append(code)
    return codes


def library_from_xml(el: etree._Element) -> str:
    path = el.get("path")
    if not path or set(el.attrib) != {"path"} or len([c for c in el if isinstance(c.tag, str)]):
        raise ConfigError("<Library> takes one attribute, path (a folder of subprograms)", where(el))
    return str(path)


def code_call_from_xml(el: etree._Element) -> tuple[str, str]:
    code, file = el.get("code", ""), el.get("file", "")
    if set(el.attrib) != {"code", "file"} or len([c for c in el if isinstance(c.tag, str)]):
        raise ConfigError("<CodeCall> takes two attributes: code (a letter and a number) and file (the "
                          "subprogram it runs)", where(el))
    if not (code[:1].isalpha() and code[:1].isascii() and code[1:].isdigit() and code[1:].isascii()):
        raise ConfigError(f"<CodeCall> code {code!r} is not a letter and a whole number", where(el))
    if not file.strip():
        raise ConfigError("<CodeCall> file is empty", where(el))
    return code[0].upper() + str(int(code[1:])), file
