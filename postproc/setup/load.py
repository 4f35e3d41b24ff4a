"""Loading a set-up: the ``extends`` chain, merging its files, and every problem with its line.

A set-up may ``extends="base.xml"``: a file relative to the extending one, or else a base shipped in
``postproc/setup/bases``. The chain is read base first; each later file overrides single attributes of a group
(``<Cycles peckRetract>``), single entries (an ``<M>`` code, an ``<Axis>``, a template) or root attributes.
Relative paths (``pipeline``, ``<Library path>``) stay relative to the file that wrote them and are
rewritten relative to the extending file. Validation runs on the merged values, and each problem is
located in the file and at the line that wrote the offending value; loading collects them all
(``config check`` prints every one) and raises them together as an ``ErrorList``.
"""

from __future__ import annotations

import os
import stat
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable

from lxml import etree

from ..errors import ConfigError, ErrorList, Location, PostprocError
from .machine import AXIS_LETTERS, CONTAINERS, Entry
from .paths import is_file, join_text, name_text, parent_text
from .validate import Invalid, validate
from ..xmlio import parse_xml_file, path_text, where

if TYPE_CHECKING:
    from pathlib import Path  # annotations only: the loader's paths are text (``postproc.setup.paths``)
    from .record import SetupGroup

BASES = join_text(parent_text(__file__), "bases")
"""The folder of the shipped bases, named by file name in ``extends`` (its path as text: ``postproc.setup.paths``)."""
MAX_CHAIN = 64
"""Files in one inheritance chain (a longer chain is refused: no real set-up comes near it)."""
MAX_SETUP_BYTES = 4 << 20
"""Bytes of one set-up file: its largest honest part is a template, far below this."""
ROOT_ATTRIBUTES = ("name", "dialect", "pipeline", "extends")
Lane = Callable[[type[Any], dict[str, Any]], Any]
"""A shortcut past pydantic a caller may pass (``postproc.fast.setup_values.plain_record``): the record built
from its raw values, or None when pydantic must validate them (``validate``)."""


@dataclass
class Own:
    """What the last file of a chain wrote itself: ``config dump`` without ``--flatten`` writes only this,
    beside ``extends``."""

    root: set[str] = field(default_factory=set)
    groups: dict[str, set[str]] = field(default_factory=dict)
    templates: set[str] = field(default_factory=set)
    library: list[str] = field(default_factory=list)
    codes: set[tuple[str, str]] = field(default_factory=set)
    foreign: set[tuple[str, str]] = field(default_factory=set)
    calls: set[str] = field(default_factory=set)
    entries: dict[str, dict[str, set[str]]] = field(default_factory=dict)
    tool_table: bool = False
    """The file names a LinuxCNC tool table (``<Tools table>``)."""


def resolve_chain(path: str | Path) -> list[etree._Element]:
    """The roots of ``path``'s inheritance chain, base first. A missing base or a cycle is located at the
    ``extends`` that names it."""
    chain: list[etree._Element] = []
    seen: list[str] = []
    """Each file's real path (``Path.resolve``: each was read, so no link loops)."""
    current = path_text(path)
    while True:
        root = parse_xml_file(current, max_bytes=MAX_SETUP_BYTES)
        if root.tag != "MachineSetup":
            raise ConfigError(f"expected <MachineSetup>, found <{root.tag}>", Location(current, root.sourceline or 1, 1))
        chain.append(root)
        seen.append(os.path.realpath(current))
        base = root.get("extends")
        if base is None:
            return chain[::-1]
        here = where(root, current)
        found = find_base(base, parent_text(current))
        if found is None:
            raise ConfigError(f"extends: base {base!r} not found (neither beside {name_text(current)} nor among the "
                              f"shipped bases: {', '.join(shipped_bases()) or 'none'})", here)
        real = os.path.realpath(found)
        if real in seen:
            names = " extends ".join([*seen[seen.index(real):], real])
            raise ConfigError(f"extends: inheritance cycle: {names}", here)
        if len(chain) >= MAX_CHAIN:
            raise ConfigError(f"extends: more than {MAX_CHAIN} set-ups in one chain", here)
        current = found


def irregular(path: str, root: etree._Element) -> str | None:
    """Why ``path`` (relative to ``root``'s file) is no file to read a configuration from: a FIFO, whose
    ``open`` would wait for a writer forever, a device, a folder. None for a regular file, or for nothing
    at all (reading it says so). Only ``os.stat``: nothing is opened."""
    file = root.getroottree().docinfo.URL
    full = join_text(parent_text(file), path) if file and not os.path.isabs(path) else path_text(path)
    try:
        mode = os.stat(full).st_mode
    except (OSError, ValueError):
        return None
    if stat.S_ISREG(mode):
        return None
    kind = ("a directory" if stat.S_ISDIR(mode) else "a FIFO (named pipe)" if stat.S_ISFIFO(mode)
            else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else "not a regular file")
    return f"{path} is {kind}"


def find_base(name: str, folder: str) -> str | None:
    """A local file (relative to the extending file's folder) first, then a shipped base by name."""
    if not name.strip():
        return None
    local = join_text(folder, name)
    if is_file(local):
        return local
    shipped = join_text(BASES, name)
    if "/" not in name and "\\" not in name and is_file(shipped):
        return shipped
    return None


def shipped_bases() -> list[str]:
    from pathlib import Path  # (a message's only: a base not found)
    return sorted(p.name for p in Path(BASES).glob("*.xml"))


class Merger:
    """Merges a chain of ``<MachineSetup>`` roots and validates the result, collecting every problem."""

    def __init__(self, groups: dict[str, type["SetupGroup"]], final_dir: str | None,
                 lane: Lane | None = None) -> None:
        self.groups = groups
        self.final_dir = final_dir
        self.lane = lane
        """Builds a record from plain values without pydantic where it can (``Lane``)."""
        self.problems: list[ConfigError] = []
        self.root: dict[str, str] = {}
        self.raw: dict[str, dict[str, Any]] = {}
        """Group tag -> alias -> raw value (later files win)."""
        self.origin: dict[tuple[str, ...], etree._Element] = {}
        """(tag,) / (tag, alias) / (container, key) / (container, key, alias) -> the element that wrote it."""
        self.templates: dict[str, tuple[str, str, int]] = {}
        """Template name -> (text, file, line)."""
        self.libraries: list[list[str]] = []
        self.codes: dict[tuple[str, str], Any] = {}
        self.foreign: dict[tuple[str, str], Any] = {}
        """(family, code) -> ``<ForeignCodes>`` declaration (later files win)."""
        self.calls: dict[str, str] = {}
        self.entries: dict[str, dict[str, dict[str, Any]]] = {c: {} for c in CONTAINERS}
        self.tool_table: str | None = None
        """The LinuxCNC tool table ``<Tools table>`` names, relative to the last file's folder."""
        self.table_tools: dict[str, Any] = {}
        """Tool number -> the ``ToolData`` the table gives (``postproc.setup.tool_table_file``)."""
        self.own = Own()

    def problem(self, message: str, el: etree._Element) -> None:
        self.problems.append(ConfigError(message, where(el)))

    # -- reading each file ----------------------------------------------------------------------------
    def read(self, root: etree._Element, last: bool) -> None:
        from .groups import code_call_from_xml, library_from_xml, machine_codes_from_xml
        unknown = sorted(set(root.attrib) - set(ROOT_ATTRIBUTES))
        if unknown:
            self.problem(f"<MachineSetup> has unknown attribute(s) {', '.join(unknown)}", root)
        for key in ROOT_ATTRIBUTES:
            value = root.get(key)
            if value is None:
                continue
            if key == "pipeline":
                problem = irregular(value, root)
                if problem is not None:
                    self.problem(f"pipeline: {problem}: a pipeline is read from a file", root)
                    continue
            self.root[key] = self.rebase(value, root) if key == "pipeline" else value
            if last:
                self.own.root.add(key)
        seen: set[str] = set()
        calls_here: set[str] = set()
        library: list[str] = []
        for child in root:
            if not isinstance(child.tag, str):
                continue
            tag = child.tag
            if tag in seen and tag not in ("Library", "CodeCall"):
                self.problem(f"<{tag}> appears twice", child)
                continue
            seen.add(tag)
            try:
                if tag == "Templates":
                    self.read_templates(child, last)
                elif tag == "Library":
                    library.append(self.rebase(library_from_xml(child), root))
                elif tag == "MachineCodes":
                    for declared in machine_codes_from_xml(child, self.lane):
                        self.codes[declared.key()] = declared
                        if last:
                            self.own.codes.add(declared.key())
                elif tag == "ForeignCodes":
                    from .foreign_codes import foreign_codes_from_xml
                    for mapped in foreign_codes_from_xml(child):
                        self.foreign[mapped.key()] = mapped
                        if last:
                            self.own.foreign.add(mapped.key())
                elif tag == "CodeCall":
                    code, file = code_call_from_xml(child)
                    if code in calls_here:
                        raise ConfigError(f"<CodeCall code=\"{code}\"> appears twice", where(child))
                    calls_here.add(code)
                    self.calls[code] = file
                    if last:
                        self.own.calls.add(code)
                elif tag in CONTAINERS:
                    self.read_entries(child, last)
                elif tag in self.groups:
                    self.read_group(child, last)
                else:
                    self.problem(f"unknown element <{tag}> in <MachineSetup>", child)
            except ConfigError as err:
                self.problems.append(err)
        self.libraries.append(library)
        if last:
            self.own.library = library

    def rebase(self, path: str, root: etree._Element) -> str:
        """A path relative to ``root``'s file, made relative to the last file of the chain."""
        file = root.getroottree().docinfo.URL
        if self.final_dir is None or not file or os.path.isabs(path):
            return path
        folder = parent_text(file)
        if os.path.realpath(folder) == os.path.realpath(self.final_dir):
            return path
        return os.path.relpath(join_text(folder, path), self.final_dir)

    def read_group(self, el: etree._Element, last: bool) -> None:
        if len([c for c in el if isinstance(c.tag, str)]):
            raise ConfigError(f"<{el.tag}> takes attributes only", where(el))
        raw = self.raw.setdefault(el.tag, {})
        self.origin[(el.tag,)] = el
        for key, value in el.attrib.items():
            raw[key] = {"true": True, "false": False}.get(value, value)
            self.origin[(el.tag, key)] = el
            if last:
                self.own.groups.setdefault(el.tag, set()).add(key)
        if last:
            self.own.groups.setdefault(el.tag, set())

    def read_templates(self, el: etree._Element, last: bool) -> None:
        from .groups import Templates
        file = el.getroottree().docinfo.URL or "<set-up>"
        if el.attrib:
            self.problem("<Templates> takes no attributes", el)
        seen: set[str] = set()
        for child in el:
            if not isinstance(child.tag, str):
                continue
            name = Templates.TAGS.get(child.tag)
            if name is None:
                self.problem(f"unknown element <{child.tag}> in <Templates>", child)
                continue
            if child.attrib or len([c for c in child if isinstance(c.tag, str)]):
                self.problem(f"<{child.tag}> holds template text only (no attributes or elements)", child)
                continue
            if name in seen:
                self.problem(f"<{child.tag}> appears twice in <Templates>", child)
                continue
            seen.add(name)
            self.templates[name] = (child.text or "", file, child.sourceline or 1)
            if last:
                self.own.templates.add(name)

    def read_entries(self, el: etree._Element, last: bool) -> None:
        kind = CONTAINERS[el.tag]
        if el.tag == "Tools" and set(el.attrib) - {"table"}:
            self.problem("<Tools> takes only the attribute table (a LinuxCNC tool table file), and <Tool> elements", el)
        elif el.tag != "Tools" and el.attrib:
            self.problem(f"<{el.tag}> takes no attributes, only <{kind.TAG}> elements", el)
        if el.tag == "Tools" and el.get("table") is not None:
            self.read_tool_table(el, last)
        entries = self.entries[el.tag]
        here: set[str] = set()
        for child in el:
            if not isinstance(child.tag, str):
                continue
            if child.tag != kind.TAG:
                self.problem(f"unknown element <{child.tag}> in <{el.tag}> (expected <{kind.TAG}>)", child)
                continue
            if len([c for c in child if isinstance(c.tag, str)]):
                self.problem(f"<{child.tag}> takes attributes only", child)
                continue
            key = child.get(kind.KEY)
            if key is None:
                self.problem(f"<{kind.TAG}> needs attribute {kind.KEY!r}", child)
                continue
            if key in here:
                self.problem(f"<{kind.TAG} {kind.KEY}=\"{key}\"> appears twice", child)
                continue
            here.add(key)
            entry = entries.setdefault(key, {})
            self.origin[(el.tag, key)] = child
            for attr, value in child.attrib.items():
                entry[attr] = value
                self.origin[(el.tag, key, attr)] = child
            if last:
                self.own.entries.setdefault(el.tag, {}).setdefault(key, set()).update(child.attrib)

    def read_tool_table(self, el: etree._Element, last: bool) -> None:
        """``<Tools table="tool.tbl">``: the tools of a LinuxCNC tool table file (relative to this file's folder,
        in the machine's units, ``postproc.setup.tool_table_file``), each a whole entry, under the ``<Tool>``
        elements of the same ``<Tools>`` (they override it) and over the bases'."""
        from .tool_table_file import read_tool_table
        from .machine import entry_values
        name = el.get("table") or ""
        root = el.getroottree().getroot()
        problem = irregular(name, root) if name.strip() else "the file name is empty"
        if problem is not None:
            self.problem(f"<Tools table>: {problem}", el)
            return
        file = root.getroottree().docinfo.URL
        path = join_text(parent_text(file), name) if file and not os.path.isabs(name) else path_text(name)
        try:
            found = read_tool_table(path)
        except ErrorList as errors:
            self.problems.extend(e for e in errors.errors if isinstance(e, ConfigError))
            return
        except ConfigError as err:
            self.problems.append(err if err.location is not None else ConfigError(f"<Tools table>: {err.message}",
                                                                                   where(el)))
            return
        entries = self.entries["Tools"]
        self.table_tools = {}
        for _, tool in found:
            key = tool.key()
            entries[key] = dict(entry_values(tool))  # the table's line is the whole tool
            self.origin[("Tools", key)] = el
            self.table_tools[key] = tool
        self.tool_table = self.rebase(name, root)
        if last:
            self.own.tool_table = True

    # -- validating the merged values -------------------------------------------------------------------
    def group(self, cls: type["SetupGroup"]) -> "SetupGroup | None":
        raw = self.raw.get(cls.TAG)
        if raw is None:
            return None
        model = self.validate(cls, raw, f"<{cls.TAG}>", (cls.TAG,))
        return model if isinstance(model, cls) else None

    def validate(self, cls: type[Any], raw: dict[str, Any], name: str, key: tuple[str, ...]) -> Any:
        if self.lane is not None:
            made = self.lane(cls, raw)
            if made is not None:
                return made
        try:
            return validate(cls, raw)
        except Invalid as exc:
            for field_name, msg in exc.problems:
                el = self.origin.get((*key, field_name))
                el = self.origin[key] if el is None else el
                self.problem(f"{name} {field_name}: {msg}" if field_name else f"{name} {msg}", el)
            return None

    def entry_models(self, container: str, axes: str) -> dict[str, Any]:
        kind = CONTAINERS[container]
        models: dict[str, Any] = {}
        for key, raw in self.entries[container].items():
            label = f"<{kind.TAG} {kind.KEY}=\"{key}\">"
            model = self.validate(kind, raw, label, (container, key))
            if not isinstance(model, Entry):
                continue
            letters = [model.key()] if container == "Axes" else [
                a for a in AXIS_LETTERS if getattr(model, a.lower(), None) is not None]
            missing = [a for a in letters if a not in axes]
            if missing:
                self.problem(f"{label}: axis {', '.join(missing)} is not on this machine (axes {axes})",
                             self.origin[(container, key)])
                continue
            models[model.key()] = model
        return models

    def check_pockets(self, tools: dict[str, Any]) -> None:
        """A pocket holds one tool [V: LinuxCNC ``tool_parse.cc`` files a random tool changer's table by pocket, a
        second tool in a pocket replacing the first]."""
        holders: dict[int, str] = {}
        for key, tool in tools.items():
            if tool.pocket is None:
                continue
            first = holders.setdefault(tool.pocket, key)
            if first != key:
                self.problem(f"<Tool number=\"{key}\">: pocket {tool.pocket} holds tool {first} too (a pocket holds one "
                             "tool)", self.origin[("Tools", key)])

    def library(self) -> list[str]:
        """The last file's folders first, then its base's, and so on (each once)."""
        out: list[str] = []
        for folders in reversed(self.libraries):
            out.extend(f for f in folders if f not in out)
        return out

    def build(self, source: str | None, make: Callable[..., Any]) -> Any:
        """The set-up ``make`` (``MachineSetup``) builds from the merged values."""
        from .groups import GROUPS, MachineSettings, Templates
        kwargs: dict[str, Any] = {}
        extra: dict[str, Any] = {}
        for cls in self.groups.values():
            model = self.group(cls)
            if model is None:
                continue
            attr = GROUPS.get(cls)
            if attr is None:
                extra[cls.TAG] = model
            else:
                kwargs[attr] = model
        templates = Templates(**{name: text for name, (text, _, _) in self.templates.items()})
        machine = kwargs.get("machine") or MachineSettings()
        setup = make(
            name=self.root.get("name", "default"), dialect=self.root.get("dialect"),
            pipeline=self.root.get("pipeline"), templates=templates, source=source, library=self.library(),
            machine_codes=list(self.codes.values()), code_calls=dict(self.calls), **kwargs)
        setup.foreign_codes = list(self.foreign.values())
        setup.extends = self.root.get("extends") if "extends" in self.own.root else None
        setup.extra = dict(sorted(extra.items()))
        setup.travel = self.entry_models("Axes", machine.axes)
        setup.work_offsets = self.entry_models("WorkOffsets", machine.axes)
        setup.tools = self.entry_models("Tools", machine.axes)
        setup.tool_table = self.tool_table
        setup.table_tools = dict(self.table_tools)
        self.check_pockets(setup.tools)
        setup.template_lines = {name: line for name, (_, _, line) in self.templates.items()}
        setup.setting_locations = {(key[0], key[1]): where(el) for key, el in self.origin.items()
                                   if len(key) == 2 and key[0] in self.raw}
        setup.template_files = {name: file for name, (_, file, _) in self.templates.items()}
        setup.own = self.own
        return setup


def merge(roots: list[etree._Element], groups: dict[str, type["SetupGroup"]], source: str | None,
          make: Callable[..., Any], lane: Lane | None = None) -> Any:
    """Roots (base first) -> one validated set-up, built by ``make``; every problem found is raised
    together."""
    setup, problems = merge_collect(roots, groups, source, make, lane)
    raise_all(problems)
    return setup


def merge_collect(roots: list[etree._Element], groups: dict[str, type["SetupGroup"]], source: str | None,
                  make: Callable[..., Any], lane: Lane | None = None) -> tuple[Any, list[ConfigError]]:
    """Roots (base first) -> the set-up (a value with a problem left at its default) and the problems."""
    final_dir = parent_text(source) if source else None
    merger = Merger(groups, final_dir, lane)
    for i, root in enumerate(roots):
        merger.read(root, i == len(roots) - 1)
    return merger.build(source, make), merger.problems


def raise_all(problems: list[ConfigError]) -> None:
    """One problem raises itself; several an ``ErrorList``, in file and line order."""
    if len(problems) == 1:
        raise problems[0]
    if problems:
        raise ErrorList(list[PostprocError](_in_file_order(problems)))


def _in_file_order(problems: list[ConfigError]) -> list[ConfigError]:
    def key(err: ConfigError) -> tuple[str, int]:
        loc = err.location
        return ("", 0) if loc is None else (loc.file, loc.line)
    return sorted(problems, key=key)
