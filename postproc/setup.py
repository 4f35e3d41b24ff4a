"""Machine set-up: the parameters of one controller installation, validated by pydantic, kept as XML.

A set-up file groups parameters in elements (``<Input>``, ``<Output>``, ``<Cycles>``, ``<Templates>``);
attributes use the camelCase aliases of the pydantic fields. Loading validates at this boundary (with
the element's line in every message); the per-block path then reads plain attributes.
``config dump`` writes a loaded set-up back in canonical form, byte-identical for canonical files.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, ClassVar, Literal

from lxml import etree
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from .errors import ConfigError, Location
from .xmlio import XFactory, XmlNode, parse_xml_file, where


def _camel(name: str) -> str:
    head, *rest = name.split("_")
    return head + "".join(p.title() for p in rest)


class _Group(BaseModel):
    """A group of parameters stored as the attributes of one element."""

    model_config = ConfigDict(alias_generator=_camel, populate_by_name=True, extra="forbid",
                              validate_assignment=True, frozen=False, allow_inf_nan=False)
    """``allow_inf_nan=False``: every float parameter is finite (``nan``/``inf`` are errors)."""
    TAG: ClassVar[str] = ""


class InputSettings(_Group):
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


class OutputSettings(_Group):
    TAG = "Output"
    normalize: bool = False
    """Write every block from its words with explicit decimal points instead of copying it."""
    decimals: int = Field(3, ge=0, le=6)
    inch_decimals: int = Field(4, ge=0, le=7)
    renumber_start: int = Field(0, ge=0)
    """0 keeps the block numbers as written; otherwise renumber from this value."""
    renumber_step: int = Field(10, ge=1)
    leading_zero: bool = True
    """Write 0.5 rather than .5."""


class CycleSettings(_Group):
    TAG = "Cycles"
    peck_retract: float = Field(0.5, gt=0)
    """G73 retract d after each peck, mm (Fanuc parameter 5114)."""
    peck_clearance: float = Field(0.5, gt=0)
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


class MachineSettings(_Group):
    TAG = "Machine"
    axes: str = "XYZ"
    start_x: float = 0.0
    start_y: float = 0.0
    start_z: float = 0.0
    """Position (mm, work coordinates) assumed at program start for toolpath simulation."""

    @model_validator(mode="after")
    def _axes_known(self) -> "MachineSettings":
        bad = set(self.axes) - set("XYZABCUVW")
        if bad or len(set(self.axes)) != len(self.axes):
            raise ValueError(f"axes must be distinct letters from XYZABCUVW, got {self.axes!r}")
        return self


class LatheCycleSettings(_Group):
    """The data parameters a lathe cycle takes an omitted word from (GSK 980TDc No.051-060, Fanuc
    5130-5143). A value programmed in a cycle replaces the default for later cycles of the run, as the
    controller rewrites its parameter. Lengths in mm (an inch program reads them converted), radius values."""

    TAG = "LatheCycles"
    rough_depth: float = Field(1.0, gt=0)
    """G71/G72 depth of cut per pass (GSK No.051, Fanuc 5132)."""
    rough_retract: float = Field(1.0, ge=0)
    """G71/G72 retract after each pass (GSK No.052, Fanuc 5133)."""
    pattern_relief_x: float = 1.0
    """G73 total X relief (GSK No.053, Fanuc 5135)."""
    pattern_relief_z: float = 1.0
    """G73 total Z relief (GSK No.054, Fanuc 5136)."""
    pattern_passes: int = Field(1, ge=1, le=9999)
    """G73 number of passes (GSK No.055, Fanuc 5137)."""
    peck_retract: float = Field(1.0, ge=0)
    """G74/G75 retract per peck (GSK No.056, Fanuc 5139)."""
    thread_finish_passes: int = Field(1, ge=1, le=99)
    """G76 finishing passes m (GSK No.057 [?], Fanuc 5142)."""
    thread_chamfer: int = Field(10, ge=0, le=99)
    """G76 pull-out chamfer r in 0.1 x lead (GSK No.058 [?], Fanuc 5130)."""
    thread_angle: int = 60
    """G76 tool angle a in degrees (GSK No.059 [?], Fanuc 5143)."""
    thread_min_depth: float = Field(0.1, gt=0)
    """G76 minimum depth of cut (Fanuc 5140)."""
    thread_allowance: float = Field(0.05, ge=0)
    """G76 finishing allowance d (GSK No.060, Fanuc 5141)."""

    @model_validator(mode="after")
    def _angle_known(self) -> "LatheCycleSettings":
        if self.thread_angle not in (0, 29, 30, 55, 60, 80):
            raise ValueError(f"threadAngle must be 0, 29, 30, 55, 60 or 80, got {self.thread_angle}")
        return self


class Limits(_Group):
    """Bounds of the interpreter (``postproc.interp``): a program that exceeds one is a located error
    naming the construct, never a hang."""

    TAG = "Limits"
    loop_iterations: int = Field(1_000_000, ge=1)
    """Total loop iterations, jumps, returns to a program's start and subprogram calls of one run."""
    call_depth: int = Field(64, ge=1)
    """Nested subprogram and macro calls."""
    kept_prefix: int = Field(100_000, ge=0)
    """Blocks of the straight start of a program kept for a later backward jump into it."""
    moves_per_block: int = Field(100_000, ge=1)
    """Moves (and dwells, spindle actions) one block may expand to: a canned cycle with a huge repeat
    count or a tiny peck is a located error before it fills memory."""
    line_length: int = Field(65_536, ge=1, le=1 << 30)
    """Characters in one program line: a longer line is a located error before it is read (no
    controller accepts anything near the default 64 kB)."""


class ControllerSettings(_Group):
    """Which controller of the dialect's family the machine has: its variant selects the family's
    default machine codes and the variant's word rules (each rule may be set on its own)."""

    TAG = "Controller"
    variant: Literal["fanuc", "haas", "fanuc-0m"] = "fanuc"
    """'fanuc' (0i/30i), 'haas' (dwell P with a decimal point in seconds; G103, G187 and Haas M
    codes), 'fanuc-0m' (cutter compensation may take its register from H)."""
    dwell_seconds: bool | None = None
    """A dwell P written with a decimal point is in seconds (G04 P0.5, G82 ... P0.5); without a point it
    stays milliseconds. None: as the variant does (Haas: yes)."""
    cutter_register_h: bool | None = None
    """G41/G42 may take the offset register from H when the block has no D and no tool length
    offset (Fanuc 0M ``G42 H19``). None: as the variant does (0M: yes)."""

    def dwell_seconds_rule(self) -> bool:
        return self.variant == "haas" if self.dwell_seconds is None else self.dwell_seconds

    def cutter_h_rule(self) -> bool:
        return self.variant == "fanuc-0m" if self.cutter_register_h is None else self.cutter_register_h


class MachineCode(BaseModel):
    """One machine-specific code (``<M number="31" action="none" name="part counter"/>``, or ``<G ...>``):
    kept verbatim between controllers of one family, simulated by its action."""

    model_config = ConfigDict(alias_generator=_camel, populate_by_name=True, extra="forbid", frozen=True)
    letter: Literal["M", "G"]
    number: str = Field(pattern=r"^[0-9]{1,4}(\.[0-9]{1,2})?$")
    """The code's number as a controller reads it (``31``, ``187``, ``5.1``); M numbers are whole."""
    action: Literal["none", "stop", "optional-stop", "spindle-cw", "spindle-ccw", "spindle-stop",
                    "coolant-on", "coolant-off", "gear", "tool-change"] = "none"
    name: str = ""
    """What the code does, for messages and the toolpath."""
    words: str = Field("", pattern=r"^[A-Z]*$")
    """Address letters the code takes with it (G187 P1 E0.01: 'PE'), kept verbatim beside it."""

    @model_validator(mode="after")
    def _whole_m(self) -> "MachineCode":
        if self.letter == "M" and "." in self.number:
            raise ValueError(f"an M code number is whole, got {self.number!r}")
        if self.action != "none" and self.letter == "G":
            raise ValueError("a machine G code has no action but none (it moves nothing)")
        return self

    def key(self) -> tuple[str, str]:
        """``("M", "31")``, ``("G", "5.1")``: numbers compared as a controller reads them."""
        return self.letter, _number_key(self.number)


def _number_key(number: str) -> str:
    whole, _, frac = number.partition(".")
    frac = frac.rstrip("0")
    return f"{int(whole)}.{frac}" if frac else str(int(whole))


class Templates(BaseModel):
    """jinja2 templates (rendered sandboxed) for the program header and footer."""

    header: str | None = None
    footer: str | None = None


GROUPS: tuple[type[_Group], ...] = (InputSettings, OutputSettings, CycleSettings, MachineSettings, Limits,
                                    ControllerSettings, LatheCycleSettings)


class MachineSetup(XmlNode):
    """A controller set-up: dialect, pipeline override and parameter groups."""

    XNAME = "MachineSetup"
    __slots__ = ("name", "dialect", "pipeline", "input", "output", "cycles", "machine", "templates", "source",
                 "template_lines", "limits", "library", "controller", "machine_codes", "code_calls", "lathe_cycles")

    def __init__(self, name: str = "default", dialect: str | None = None, pipeline: str | None = None,
                 input: InputSettings | None = None, output: OutputSettings | None = None,
                 cycles: CycleSettings | None = None, machine: MachineSettings | None = None,
                 templates: Templates | None = None, source: str | None = None, limits: Limits | None = None,
                 library: list[str] | None = None, controller: ControllerSettings | None = None,
                 machine_codes: list[MachineCode] | None = None, code_calls: dict[str, str] | None = None,
                 lathe_cycles: LatheCycleSettings | None = None) -> None:
        self.name = name
        self.dialect = dialect
        self.pipeline = pipeline
        """Path of a pipeline XML relative to the set-up file's folder, replacing the dialect's own."""
        self.input = input or InputSettings()
        self.output = output or OutputSettings()
        self.cycles = cycles or CycleSettings()
        self.machine = machine or MachineSettings()
        self.templates = templates or Templates()
        self.limits = limits or Limits()
        self.controller = controller or ControllerSettings()
        self.machine_codes = machine_codes if machine_codes is not None else []
        """Machine-specific codes the set-up declares (``<MachineCodes>``), over the family's defaults."""
        self.lathe_cycles = lathe_cycles or LatheCycleSettings()
        self.library = library if library is not None else []
        """Folders searched for subprograms not in the program's file (``<Library path="..."/>``, relative
        to the set-up file's folder; ``--lib DIR`` adds to them)."""
        self.code_calls = code_calls if code_calls is not None else {}
        """Code (as the dialect writes it, upper case, e.g. ISG's implicit subroutine calls) -> the subprogram
        file the machine builder configured it to run (``<CodeCall code="..." file="..."/>``); a dialect
        that reads such codes calls the file, found like any subprogram (``Library``)."""
        self.source = source
        self.template_lines: dict[str, int] = {}
        """Line of the set-up file each template starts on (for located template errors)."""

    def _key(self) -> tuple[Any, ...]:
        return (self.name, self.dialect, self.pipeline, self.input, self.output, self.cycles,
                self.machine, self.templates, self.limits, tuple(self.library), self.controller,
                tuple(self.machine_codes), tuple(self.code_calls.items()), self.lathe_cycles)

    def __repr__(self) -> str:
        return f"MachineSetup(name={self.name!r}, dialect={self.dialect!r})"

    def pipeline_path(self) -> Path | None:
        if self.pipeline is None:
            return None
        base = Path(self.source).parent if self.source else Path(".")
        return base / self.pipeline

    def library_paths(self) -> list[Path]:
        """The subprogram search path, in order, relative paths resolved from the set-up file's folder."""
        base = Path(self.source).parent if self.source else Path(".")
        return [base / p for p in self.library]

    @classmethod
    def from_xml(cls, el: etree._Element) -> "MachineSetup":
        kwargs: dict[str, Any] = {}
        lines: dict[str, int] = {}
        by_tag = {g.TAG: g for g in GROUPS}
        attr_of = {InputSettings: "input", OutputSettings: "output", CycleSettings: "cycles",
                   MachineSettings: "machine", Limits: "limits", ControllerSettings: "controller",
                   LatheCycleSettings: "lathe_cycles"}
        library: list[str] = []
        code_calls: dict[str, str] = {}
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag == "Templates":
                kwargs["templates"] = _templates_from_xml(child)
                lines = {c.tag.lower(): c.sourceline or 1 for c in child if isinstance(c.tag, str)}
                continue
            if child.tag == "Library":
                library.append(_library_from_xml(child))
                continue
            if child.tag == "MachineCodes":
                if "machine_codes" in kwargs:
                    raise ConfigError("<MachineCodes> appears twice", where(child))
                kwargs["machine_codes"] = _machine_codes_from_xml(child)
                continue
            if child.tag == "CodeCall":
                code, file = _code_call_from_xml(child)
                if code in code_calls:
                    raise ConfigError(f"<CodeCall code=\"{code}\"> appears twice", where(child))
                code_calls[code] = file
                continue
            group = by_tag.get(child.tag)
            if group is None:
                raise ConfigError(f"unknown element <{child.tag}> in <MachineSetup>", where(child))
            if attr_of[group] in kwargs:
                raise ConfigError(f"<{child.tag}> appears twice", where(child))
            kwargs[attr_of[group]] = _group_from_xml(group, child)
        unknown = set(el.attrib) - {"name", "dialect", "pipeline"}
        if unknown:
            raise ConfigError(f"<MachineSetup> has unknown attribute(s) {', '.join(sorted(unknown))}", where(el))
        setup = cls(name=el.get("name", "default"), dialect=el.get("dialect"), pipeline=el.get("pipeline"),
                    source=el.getroottree().docinfo.URL, library=library, code_calls=code_calls, **kwargs)
        setup.template_lines = lines
        return setup

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        el = etree.Element(self.XNAME, name=self.name)
        if self.dialect:
            el.set("dialect", self.dialect)
        if self.pipeline:
            el.set("pipeline", self.pipeline)
        for group in (self.input, self.output, self.cycles, self.machine, self.limits, self.controller,
                      self.lathe_cycles):
            values = group.model_dump(by_alias=True, exclude_defaults=True)
            if values:
                child = etree.SubElement(el, group.TAG)
                for key, value in values.items():
                    child.set(key, _attr_text(value))
        if self.templates.header is not None or self.templates.footer is not None:
            t = etree.SubElement(el, "Templates")
            for tag, text in (("Header", self.templates.header), ("Footer", self.templates.footer)):
                if text is not None:
                    etree.SubElement(t, tag).text = text
        for path in self.library:
            etree.SubElement(el, "Library", path=path)
        if self.machine_codes:
            codes = etree.SubElement(el, "MachineCodes")
            for code in self.machine_codes:
                child = etree.SubElement(codes, code.letter)
                for key, value in code.model_dump(by_alias=True, exclude_defaults=True, exclude={"letter"}).items():
                    child.set(key, str(value))
        for called, file in self.code_calls.items():
            etree.SubElement(el, "CodeCall", code=called, file=file)
        return el


def _attr_text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and value.is_integer():
        return repr(value)
    return str(value)


def _group_from_xml(group: type[_Group], el: etree._Element) -> _Group:
    if len([c for c in el if isinstance(c.tag, str)]):
        raise ConfigError(f"<{el.tag}> takes attributes only", where(el))
    raw: dict[str, Any] = {}
    for key, value in el.attrib.items():
        raw[key] = {"true": True, "false": False}.get(value, value)
    try:
        return group.model_validate(raw)
    except ValidationError as exc:
        first = exc.errors()[0]
        msg = first["msg"]
        if first["type"] == "extra_forbidden":
            msg = "unknown parameter"
        elif first["type"] == "value_error":  # our own validators' messages stand alone
            msg = str(first.get("ctx", {}).get("error", msg))
        field_name = ".".join(str(p) for p in first["loc"])
        raise ConfigError(f"<{el.tag}> {field_name}: {msg}" if field_name else f"<{el.tag}> {msg}",
                          where(el)) from None


def _machine_codes_from_xml(el: etree._Element) -> list[MachineCode]:
    """``<MachineCodes>`` holds ``<M>`` and ``<G>`` elements; a code declared twice is an error."""
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
        try:
            code = MachineCode.model_validate({"letter": child.tag, **dict(child.attrib)})
        except ValidationError as exc:
            first = exc.errors()[0]
            msg = "unknown parameter" if first["type"] == "extra_forbidden" else str(
                first.get("ctx", {}).get("error", first["msg"])) if first["type"] == "value_error" else first["msg"]
            field_name = ".".join(str(p) for p in first["loc"])
            raise ConfigError(f"<{child.tag}> {field_name}: {msg}" if field_name else f"<{child.tag}> {msg}",
                              where(child)) from None
        if code.key() in seen:
            raise ConfigError(f"{code.letter}{code.number} is declared twice", where(child))
        seen.add(code.key())
        codes.append(code)
    return codes


def _library_from_xml(el: etree._Element) -> str:
    path = el.get("path")
    if not path or set(el.attrib) != {"path"} or len([c for c in el if isinstance(c.tag, str)]):
        raise ConfigError("<Library> takes one attribute, path (a folder of subprograms)", where(el))
    return str(path)


def _code_call_from_xml(el: etree._Element) -> tuple[str, str]:
    code, file = el.get("code", ""), el.get("file", "")
    if set(el.attrib) != {"code", "file"} or len([c for c in el if isinstance(c.tag, str)]):
        raise ConfigError("<CodeCall> takes two attributes: code (a letter and a number) and file (the "
                          "subprogram it runs)", where(el))
    if not (code[:1].isalpha() and code[:1].isascii() and code[1:].isdigit() and code[1:].isascii()):
        raise ConfigError(f"<CodeCall> code {code!r} is not a letter and a whole number", where(el))
    if not file.strip():
        raise ConfigError("<CodeCall> file is empty", where(el))
    return code[0].upper() + str(int(code[1:])), file


def _templates_from_xml(el: etree._Element) -> Templates:
    values: dict[str, str] = {}
    for child in el:
        if not isinstance(child.tag, str):
            continue
        if child.tag not in ("Header", "Footer"):
            raise ConfigError(f"unknown element <{child.tag}> in <Templates>", where(child))
        values[child.tag.lower()] = child.text or ""
    return Templates(**values)


def load_setup(path: str | Path, factory: XFactory | None = None) -> MachineSetup:
    """Load and validate a machine set-up file."""
    root = parse_xml_file(path)
    if root.tag != MachineSetup.XNAME:
        raise ConfigError(f"expected <MachineSetup>, found <{root.tag}>", Location(str(path), root.sourceline or 1, 1))
    setup = MachineSetup.from_xml(root)
    setup.source = str(path)
    return setup
