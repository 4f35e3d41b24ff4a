"""Machine set-up: the parameters of one controller installation, kept as XML.

A set-up file groups parameters in elements (``<Input>``, ``<Output>``, ``<Cycles>``, ``<Templates>``);
attributes use the camelCase aliases of the fields. The groups are plain dataclasses
(``postproc.setup.record``): loading validates them at this boundary with pydantic (with the element's
line in every message, ``postproc.setup.validate``); a run without a set-up file builds the defaults and
never imports it. The per-block path reads plain attributes.
``config dump`` writes a loaded set-up back in canonical form, byte-identical for canonical files.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..errors import ConfigError, Location, UsageError
from .record import SetupGroup, setting, values
from .record import aliases as field_aliases
from ..xmlio import XFactory, XmlNode, lxml_etree, where
from .foreign_codes import ForeignCode as ForeignCode, foreign_codes_to_xml
from .groups import (  # the records, named here as ever
    InputSettings as InputSettings, OutputSettings as OutputSettings, ROUNDED_ADDRESSES as ROUNDED_ADDRESSES,
    parse_address_decimals as parse_address_decimals, CycleSettings as CycleSettings,
    MachineSettings as MachineSettings, LatheCycleSettings as LatheCycleSettings, Limits as Limits,
    ControllerSettings as ControllerSettings, MachineCode as MachineCode, CodeAction as CodeAction,
    Templates as Templates, GROUPS as GROUPS, builtin_groups as builtin_groups,
)

if TYPE_CHECKING:  # lxml is imported where XML is written; the machine's geometry where a set-up file has
    from lxml import etree  # some (postproc.setup.load)
    from pathlib import Path  # annotations only: a start makes no path object (pathlib imports urllib.parse)
    from .machine import AxisTravel, ToolData, WorkOffsetData
    from .load import Lane

__all__ = ["SetupGroup", "setting", "values"]  # the plugin API: a plugin's group is a SetupGroup


class MachineSetup(XmlNode):
    """A controller set-up: dialect, pipeline override and parameter groups."""

    XNAME = "MachineSetup"
    __slots__ = ("name", "dialect", "pipeline", "input", "output", "cycles", "machine", "templates", "source",
                 "template_lines", "limits", "library", "controller", "machine_codes", "foreign_codes", "code_calls",
                 "lathe_cycles",
                 "extends", "extra", "travel", "work_offsets", "tools", "tool_table", "table_tools", "template_files",
                 "own", "setting_locations")

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
        self.foreign_codes: list[ForeignCode] = []
        """What other families' machine-specific M codes become on this machine (``<ForeignCodes>``,
        ``postproc.setup.foreign_codes``)."""
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
        self.setting_locations: dict[tuple[str, str], Location] = {}
        """(element, attribute) -> where the set-up's files last wrote it, e.g. ``("Output", "numberMax")``: a value
        a run refuses (one the target cannot take) is located there; a setting not written has none."""
        self.template_files: dict[str, str] = {}
        """The file each template comes from, where it is not ``source`` (a base the set-up extends)."""
        self.extends: str | None = None
        """The base this set-up's own file names (``extends``); its values are already merged in."""
        self.extra: dict[str, SetupGroup] = {}
        """Groups plugins registered (``postproc_register_setup_groups``), by element name."""
        self.travel: dict[str, AxisTravel] = {}
        """Axis letter -> its travel limits and home (``<Axes>``), machine coordinates, machine units."""
        self.work_offsets: dict[str, WorkOffsetData] = {}
        """Work-system number ('0'-'6') -> its offset as the operator set it (``<WorkOffsets>``)."""
        self.tools: dict[str, ToolData] = {}
        """Tool offset number -> its length or lathe offsets (``<Tools>``)."""
        self.tool_table: str | None = None
        """The LinuxCNC tool table file ``<Tools table>`` names, relative to the set-up file's folder: its tools are
        in ``tools`` (``postproc.setup.tool_table_file``)."""
        self.table_tools: dict[str, ToolData] = {}
        """The tools as the table gives them, before the ``<Tool>`` elements override them (``config dump`` writes
        the table's name and only what the elements change)."""
        self.own: Any = None
        """What the set-up's own file wrote (``setup_load.Own``), when it extends a base."""

    def setting_at(self, element: str, attribute: str) -> Location:
        """Where the set-up wrote ``<element attribute=...>``: its element's line, else the set-up's first line."""
        return self.setting_locations.get((element, attribute)) or Location(self.source or "<set-up>", 1, 1)

    def _key(self) -> tuple[Any, ...]:
        return (self.name, self.dialect, self.pipeline, self.input, self.output, self.cycles,
                self.machine, self.templates, self.limits, tuple(self.library), self.controller,
                tuple(self.machine_codes), tuple(self.foreign_codes), tuple(self.code_calls.items()), self.lathe_cycles,
                tuple(self.extra.items()), tuple(self.travel.items()), tuple(self.work_offsets.items()),
                tuple(self.tools.items()), self.tool_table)

    def group(self, cls: type[SetupGroup]) -> SetupGroup:
        """A plugin's group (its defaults when the set-up does not write it)."""
        found = self.extra.get(cls.TAG)
        return found if isinstance(found, cls) else cls()

    def template_file(self, name: str) -> str | None:
        return self.template_files.get(name, self.source)

    def travel_limited(self) -> bool:
        """The set-up declares travel limits on some axis: motion is checked against them."""
        return any(t.limited() for t in self.travel.values())

    def __repr__(self) -> str:
        return f"MachineSetup(name={self.name!r}, dialect={self.dialect!r})"

    def pipeline_path(self) -> Path | None:
        if self.pipeline is None:
            return None
        from pathlib import Path
        base = Path(self.source).parent if self.source else Path(".")
        return base / self.pipeline

    def library_paths(self) -> list[Path]:
        """The subprogram search path, in order, relative paths resolved from the set-up file's folder."""
        from pathlib import Path
        base = Path(self.source).parent if self.source else Path(".")
        return [base / p for p in self.library]

    @classmethod
    def from_xml(cls, el: etree._Element) -> "MachineSetup":
        """One ``<MachineSetup>`` element with the built-in groups. ``load_setup`` follows ``extends`` and
        knows the plugins' groups; an element alone cannot, so an ``extends`` here is an error."""
        from .load import merge
        if el.get("extends") is not None:
            raise ConfigError("<MachineSetup extends> needs the file it is in: load it with load_setup", where(el))
        return merge([el], builtin_groups(), el.getroottree().docinfo.URL, cls)  # type: ignore[no-any-return]

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False,
                        flatten: bool = False) -> etree._Element:
        """The canonical element. A set-up that extends a base writes ``extends`` and only what its own
        file set; ``flatten`` writes the whole resolved set-up instead, without ``extends``."""
        etree = lxml_etree()
        own = None if flatten or self.extends is None else self.own
        el = etree.Element(self.XNAME, name=self.name)
        if own is not None:
            el.set("extends", self.extends or "")
            if "name" not in own.root:
                del el.attrib["name"]
        for key in ("dialect", "pipeline"):
            value = getattr(self, key)
            if value and (own is None or key in own.root):
                el.set(key, value)
        groups: list[SetupGroup] = [getattr(self, attr) for attr in GROUPS.values()]
        for group in [*groups, *self.extra.values()]:
            if own is None:
                written = values(group, by_alias=True, exclude_defaults=True)
            elif group.TAG in own.groups:
                written = values(group, by_alias=True, include=_fields(group, own.groups[group.TAG]))
            else:
                continue
            if written or own is not None:
                child = etree.SubElement(el, group.TAG)
                for key, value in written.items():
                    child.set(key, _attr_text(value))
        from .machine import entry_values
        for container, entries in (("Axes", self.travel), ("WorkOffsets", self.work_offsets),
                                   ("Tools", self.tools)):
            mine = None if own is None else own.entries.get(container)
            table = container == "Tools" and not flatten and self.tool_table is not None and (
                own is None or own.tool_table)
            if not table and (not entries or (own is not None and not mine)):
                continue
            parent = etree.SubElement(el, container)
            if table:
                parent.set("table", self.tool_table or "")
                if own is not None:
                    mine = mine or {}  # the file's own <Tool> elements only
            for key, entry in entries.items():
                if mine is None or key in mine:
                    written = entry_values(entry, None if mine is None else mine[key])
                    if table and own is None:  # only what the <Tool> elements change in the table's entry
                        given = self.table_tools.get(key)
                        if given is not None:
                            base = entry_values(given)
                            written = {a: v for a, v in written.items() if a == entry.KEY or base.get(a) != v}
                            if len(written) == 1:
                                continue
                    child = etree.SubElement(parent, entry.TAG)
                    for attr, value in written.items():
                        child.set(attr, _attr_text(value))
        texts = [(tag, getattr(self.templates, f)) for tag, f in Templates.TAGS.items()
                 if getattr(self.templates, f) is not None and (own is None or f in own.templates)]
        if texts:
            t = etree.SubElement(el, "Templates")
            for tag, text in texts:
                etree.SubElement(t, tag).text = text
        for path in self.library if own is None else own.library:
            etree.SubElement(el, "Library", path=path)
        codes = [c for c in self.machine_codes if own is None or c.key() in own.codes]
        if codes:
            parent = etree.SubElement(el, "MachineCodes")
            for code in codes:
                child = etree.SubElement(parent, code.letter)
                for key, value in values(code, by_alias=True, exclude_defaults=True, exclude={"letter"}).items():
                    child.set(key, str(value))
        foreign_codes_to_xml(el, [c for c in self.foreign_codes if own is None or c.key() in own.foreign])
        for called, file in self.code_calls.items():
            if own is None or called in own.calls:
                etree.SubElement(el, "CodeCall", code=called, file=file)
        return el


def _fields(group: SetupGroup, aliases: set[str]) -> set[str]:
    """Field names of a group's aliases."""
    return {name for name, alias in field_aliases(type(group)).items() if alias in aliases}


def _attr_text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and value.is_integer():
        return repr(value)
    return str(value)


def check_named_file(path: str | Path) -> None:
    """A set-up file named on the command line (``--machine``, ``config check``) that cannot be opened is
    wrong usage (exit 2), as an input program that cannot be read is (docs/cli.md); a base it
    ``extends`` that cannot be read stays an error of the set-up (exit 1, located in the file naming it)."""
    try:
        with open(path, "rb"):
            pass
    except OSError as exc:
        raise UsageError(f"cannot read {path}: {exc.strerror}") from None


def load_setup(path: str | Path, factory: XFactory | None = None,
               groups: dict[str, type[SetupGroup]] | None = None, lane: Lane | None = None) -> MachineSetup:
    """Load and validate a machine set-up file and the bases it extends. ``groups``: the element name ->
    group class of every group (default: the built-in ones; pass ``default_registry().setup_groups`` for
    those of the installed plugins too, as the command line does); ``lane``: a shortcut past pydantic for
    plain values (the command line passes ``postproc.fast.setup_values.plain_record``). Every problem found
    is raised (one ``ConfigError``, or an ``ErrorList`` of them)."""
    setup, problems = load_setup_collect(path, groups, lane)
    from .load import raise_all
    raise_all(problems)
    return setup


def load_setup_collect(path: str | Path, groups: dict[str, type[SetupGroup]] | None = None,
                       lane: Lane | None = None) -> tuple[MachineSetup, list[ConfigError]]:
    """``load_setup`` that returns the problems (a value with a problem is left at its default) instead of
    raising them, so ``config check`` can go on to the templates; an unreadable file or chain raises."""
    from .load import merge_collect, resolve_chain
    if groups is None:
        groups = builtin_groups()  # the plugins' groups come from the registry, above this module
    setup, problems = merge_collect(resolve_chain(path), groups, str(path), MachineSetup, lane)
    setup.source = str(path)
    return setup, problems
