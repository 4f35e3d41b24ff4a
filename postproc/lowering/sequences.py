"""Sequences from the set-up's templates: where the translation calls each one, with what context.

* ``header`` after the opening tape mark, ``footer`` before the closing one (``Writer.write``).
* ``operation_start`` before each tool change: an operation begins where its tool is loaded (CAM posts
  write one tool change per operation and name the operation in a comment line just before it; that
  comment is the template's ``name``).
* ``tool_change`` replaces each tool-change block; the block may hold only the tool change, its tool
  number, a block number and comments (anything else would be lost: a located error).
* ``program_end`` replaces the program-end block (``M30``, ``M02``), with the same rule.

Tool change and operation start are placed before lowering (so a target whose lowering rewrites a tool
change, grbl's pause, gets the set-up's sequence instead); the program end after it (lowering finds the
end to comment out what follows it). Every rendered text is read back by the target dialect's reader:
a template whose output the target cannot read, or that leaves a modal setting (units, distance mode,
plane, motion mode, work offset, feed mode, a canned cycle) other than it found it, is a located error at
the template's line in the set-up. ``tools`` (every tool with the source line of its first use) needs the
whole program: only when a template names it is the block stream buffered, otherwise it streams.
"""

from __future__ import annotations

import copy
import io
import keyword
import os
import re
from typing import TYPE_CHECKING, Any, ClassVar, Iterable, Iterator

from ..errors import ConfigError, Diagnostics, ErrorLevel, Location, PostprocError, UsageError
from ..ir import Block, Section
from ..ir.state import ModalState
from ..xmlio import XAttr

if TYPE_CHECKING:
    from ..context import Context
    from ..dialect import Dialect
    from ..setup.machine_setup import MachineSetup

def path_stem(path: str) -> str:
    """``pathlib.PurePath(path).stem`` (the file's name without its last suffix: the ``program`` a template reads),
    on the path's text where paths are POSIX ones: every run makes it, and ``pathlib`` (with ``urllib.parse`` and
    ``ipaddress``, which it imports) is no module a start needs otherwise. ``tests/test_start_paths.py`` holds it to
    ``PurePath`` on random paths."""
    if os.name != "posix":  # (drives and two separators: PurePath's own parsing)
        from pathlib import PurePath
        return PurePath(path).stem
    parts = [part for part in path.split("/") if part not in ("", ".")]
    name = parts[-1] if parts else ""
    dot = name.rfind(".")
    return name[:dot] if 0 < dot < len(name) - 1 else name


BLOCK_TEMPLATES = ("tool_change", "operation_start", "program_end")
"""Templates the translation renders at blocks (the others, header and footer, once each)."""
BUILTIN = frozenset({"program", "source_file", "source_dialect", "target_dialect", "machine", "units", "date",
                     "setup", "tools", "tool", "previous_tool", "operation", "name", "line", "first_use"})
"""Names the translation passes; ``--define`` may not take them (except ``date``, for reproducible output)."""
_NAME = r"[A-Za-z_][A-Za-z0-9_]{0,63}\Z"
"""Compiled where first used (``--define``), not at every start."""
_KEEPS = ("Sequence", "ToolSelect", "ToolChange", "Comments", "ProgramControl")
"""What a replaced block may hold besides what the template writes."""
_MODAL = ("units", "distance", "plane", "feed_mode", "work_offset", "return_level", "cycle", "motion")
"""Modal settings a template must leave as it found them (the next source block relies on them)."""


class GeneratedText(Section):
    """Text a set-up template wrote in place of a block (or before it): written as it is, and marked
    generated in the output map (``postproc.ir.source_map.OutputMap``)."""

    XNAME = KEY = "Generated"
    __slots__ = ("text", "template")
    XATTRS = (XAttr("text", str), XAttr("template", str))
    text: str
    template: str

    def __init__(self, text: str, template: str) -> None:
        self.text = text
        self.template = template


def parse_defines(items: Iterable[str]) -> dict[str, str]:
    """``--define NAME=VALUE`` (repeatable) -> {NAME: VALUE}; a malformed, reserved or repeated name is
    wrong usage."""
    defines: dict[str, str] = {}
    for item in items:
        name, eq, value = item.partition("=")
        if not eq:
            raise UsageError(f"--define takes NAME=VALUE, got {item!r}")
        if not re.match(_NAME, name) or keyword.iskeyword(name) or name in ("true", "false", "none", "True",
                                                                         "False", "None", "loop", "self"):
            raise UsageError(f"--define {name!r}: a name is a letter or '_' then letters, digits or '_' "
                             "(at most 64, not a keyword)")
        if name in BUILTIN and name != "date":
            raise UsageError(f"--define {name}: the translation sets {name} itself")
        if name in defines:
            raise UsageError(f"--define {name} is given twice")
        defines[name] = value
    return defines


def today() -> str:
    """The date templates see: ``SOURCE_DATE_EPOCH`` (reproducible builds) if set, else today (UTC)."""
    import datetime  # here: a translation without templates never asks the date
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    if epoch is not None and epoch.strip().isdigit():
        return datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc).date().isoformat()
    return datetime.datetime.now(datetime.timezone.utc).date().isoformat()


def setup_values(ctx_setup: Any) -> dict[str, Any]:
    """The set-up as templates see it, by its XML spelling: ``setup.name``, ``setup.Cycles.peckRetract``."""
    from ..setup.machine_setup import GROUPS
    from ..setup.record import values as record_values
    values: dict[str, Any] = {"name": ctx_setup.name, "dialect": ctx_setup.dialect}
    for group in GROUPS:
        attr = {"Input": "input", "Output": "output", "Cycles": "cycles", "Machine": "machine", "Limits": "limits",
                "Controller": "controller", "LatheCycles": "lathe_cycles"}.get(group.TAG)
        if attr is not None and hasattr(ctx_setup, attr):
            values[group.TAG] = record_values(getattr(ctx_setup, attr), by_alias=True)
    return values


def names_used(text: str) -> frozenset[str]:
    """The free names a template reads (jinja2 parses it; nothing runs; imported here, only where a set-up
    has templates)."""
    from jinja2 import TemplateSyntaxError, meta

    from ..output.templates import _ENV
    try:
        return frozenset(meta.find_undeclared_variables(_ENV.parse(text)))
    except TemplateSyntaxError:
        return frozenset()  # rendering reports it at its line


class Sequences:
    """The set-up's templates for one translation: the fixed context, the per-block state (tool loaded,
    operation count) and the rendering and checking of every output."""

    DISABLED: ClassVar["Sequences | None"] = None

    def __init__(self, ctx: "Context", source_dialect: str, target: type["Dialect"] | None,
                 defines: dict[str, str] | None = None, enabled: bool = True) -> None:
        self.ctx = ctx
        setup = ctx.setup
        self.target = target
        self.texts = setup.templates.defined() if enabled else {}
        self.per_block = any(name in self.texts for name in BLOCK_TEMPLATES)
        self.needs_tools = any("tools" in names_used(text) for text in self.texts.values())
        self.base: dict[str, Any] = {
            "program": path_stem(ctx.file), "source_file": ctx.file, "source_dialect": source_dialect,
            "target_dialect": target.NAME if target is not None else source_dialect, "machine": setup.name,
            "date": today() if self.texts else "", "setup": setup_values(setup)}
        self.base.update(defines or {})
        self.tools: list[dict[str, Any]] | None = None
        self.state = ModalState()
        """The program's modal state where it stands (for checking what a template leaves in force)."""
        self.selected: int | None = None
        self.loaded: int | None = None
        self.operation = 0
        self.comment = ""
        self.seen: set[int] = set()

    # -- rendering -----------------------------------------------------------------------------------
    def variables(self, extra: dict[str, Any] | None = None) -> dict[str, Any]:
        values = dict(self.base)
        values["units"] = self.state.units if self.per_block else self.ctx.state.units
        if self.tools is not None:
            values["tools"] = self.tools
        if extra:
            values.update(extra)
        return values

    def render(self, name: str, extra: dict[str, Any] | None = None, block: Block | None = None) -> str:
        """Render ``name`` (or '' when the set-up has none), read its output back as the target does."""
        text = self.texts.get(name)
        if not text:
            return ""
        from ..output.templates import render
        setup = self.ctx.setup
        first = setup.template_lines.get(name, 1)
        file = setup.template_file(name)
        comments = self.target.COMMENTS if self.target is not None else None
        out = render(name, text, self.variables(extra), file, first, comments)
        if out and self.target is not None:
            check_output(name, out, self.target, setup, Location(file or "<set-up>", first, 1),
                         self.state if name != "header" else None, name not in ("footer", "program_end"))
        return out

    # -- the block stream ------------------------------------------------------------------------------
    def before_lowering(self, blocks: Iterator[Block]) -> Iterator[Block]:
        """Collect the tools (only when a template asks: that buffers the program), then put the tool
        change and operation start sequences in place."""
        stream: Iterable[Block] = blocks
        if self.needs_tools:
            stream = list(blocks)
            self.tools = tools_used(stream)
        if "tool_change" not in self.texts and "operation_start" not in self.texts:
            return iter(stream)
        return self._tool_changes(stream)

    def _tool_changes(self, blocks: Iterable[Block]) -> Iterator[Block]:
        for block in blocks:
            sections = block.sections
            if "ToolChange" not in sections:
                self._follow(block)
                yield block
                continue
            select = sections.get("ToolSelect")
            tool = getattr(select, "number", self.selected) if select is not None else self.selected
            if not isinstance(tool, int):
                raise ConfigError("a tool-change template needs the tool's number; here it is "
                                  + ("computed" if tool is not None else "not selected before the change"),
                                  self.ctx.at(block))
            self.operation += 1
            extra = {"tool": tool, "previous_tool": self.loaded, "operation": self.operation, "line": block.line,
                     "name": self.comment, "first_use": tool not in self.seen}
            start = self.render("operation_start", extra, block)
            if start:
                yield _generated(block, start, "operation_start")
            self.seen.add(tool)
            self.loaded = self.selected = tool
            self.comment = ""
            if "tool_change" in self.texts:
                _only_replaceable(block, "tool_change", self.ctx)
                yield _generated(block, self.render("tool_change", extra, block), "tool_change")
                self.state.tool = tool
            else:
                self._follow(block)
                yield block

    def _follow(self, block: Block) -> None:
        """Keep the modal state, the selected tool and the last comment line (an operation's name)."""
        sections = block.sections
        self.state.apply(sections)
        select = sections.get("ToolSelect")
        if select is not None:
            number = getattr(select, "number", None)
            self.selected = number if isinstance(number, int) else None
        comments = sections.get("Comments")
        if comments is not None and not block.words and len(sections) == 1:
            self.comment = " ".join(getattr(comments, "texts", ())).strip()

    def after_lowering(self, blocks: Iterator[Block]) -> Iterator[Block]:
        """Replace the program-end block with the ``program_end`` sequence."""
        if "program_end" not in self.texts:
            return blocks
        return self._program_end(blocks)

    def _program_end(self, blocks: Iterator[Block]) -> Iterator[Block]:
        done = False
        for block in blocks:
            control = block.sections.get("ProgramControl")
            if not done and control is not None and getattr(control, "kind", "") in ("end", "end_rewind"):
                _only_replaceable(block, "program_end", self.ctx)
                done = True
                yield _generated(block, self.render("program_end", {"line": block.line}, block), "program_end")
                continue
            yield block


def _generated(block: Block, text: str, template: str) -> Block:
    out = Block(block.line, None, "\n")
    out.sections = {"Generated": GeneratedText(text, template)}
    return out


def _only_replaceable(block: Block, template: str, ctx: "Context") -> None:
    extra = [k for k in block.sections if k not in _KEEPS]
    if extra:
        raise ConfigError(f"the {template} template replaces this whole block, which also programs "
                          f"{', '.join(extra)}: put the {template.replace('_', ' ')} in a block of its own",
                          ctx.at(block))


def tools_used(blocks: list[Block]) -> list[dict[str, Any]]:
    """Every tool selected, in order of first use, with the source line of that use."""
    tools: list[dict[str, Any]] = []
    seen: set[int] = set()
    for block in blocks:
        select = block.sections.get("ToolSelect")
        if select is not None:
            number = getattr(select, "number", None)
            if isinstance(number, int) and number not in seen:
                seen.add(number)
                tools.append({"number": number, "line": block.line})
    return tools


def check_output(name: str, text: str, target: type["Dialect"], setup: Any, where: Location,
                 state: ModalState | None, keep_modal: bool) -> None:
    """Read a template's output as ``target`` reads it; an error in it, or a modal setting it leaves
    changed (``keep_modal``), is a ``ConfigError`` at the template."""
    from ..reading import read_blocks
    if target.READER is None:
        return
    diagnostics = Diagnostics(ErrorLevel.RAISE, max_errors=1_000_000, warn_stream=io.StringIO())
    fragment = f"<template {name}>"
    try:
        fctx, blocks = read_blocks(io.StringIO(text), fragment, target, setup, diagnostics)
        if state is not None:
            fctx.state = copy.deepcopy(state)
        start = copy.deepcopy(fctx.state)
        for _ in blocks:
            pass
    except PostprocError as refused:
        diagnostics.errors.append(refused)
    if diagnostics.errors:
        err = diagnostics.errors[0]
        line = err.location.line if err.location is not None else 1
        shown = text.splitlines()[line - 1] if 0 < line <= len(text.splitlines()) else ""
        raise ConfigError(f"template {name}: the {target.NAME} reader refuses its output, line {line} "
                          f"{shown!r}: {err.message}", where)
    if keep_modal:
        fields = _MODAL if state is not None else _MODAL[:-1]  # a header: nothing moves before it
        changed = [f for f in fields if getattr(fctx.state, f) != getattr(start, f)]
        if changed:
            raise ConfigError(f"template {name} leaves {', '.join(changed)} changed (from "
                              f"{', '.join(str(getattr(start, f)) for f in changed)} to "
                              f"{', '.join(str(getattr(fctx.state, f)) for f in changed)}); the program "
                              "after it relies on what it found: set it back", where)


SAMPLE_PROGRAM = "o1001"
"""The program name ``config check`` renders with (the writer passes the input file's stem)."""


def check_templates(setup: "MachineSetup", defines: dict[str, str] | None = None, collect: bool = False,
                    target: type["Dialect"] | None = None) -> list[ConfigError]:
    """Render the set-up's templates with sample values (metric and inch), as ``config check`` does, and
    read each output back with ``target`` (the set-up's dialect, when it names an installed one). The
    first failure is raised, or with ``collect`` every template's failure is returned."""
    from ..output.templates import render_all
    problems: list[ConfigError] = []
    for name, text in setup.templates.defined().items():
        first = setup.template_lines.get(name, 1)
        file = setup.template_file(name)
        try:
            outputs = render_all(name, text, sample_variables(setup, name, defines), file, first,
                                 target.COMMENTS if target is not None else None)
            if target is not None:
                for out in outputs:
                    if out:
                        check_output(name, out, target, setup, Location(file or "<set-up>", first, 1), None,
                                     name not in ("footer", "program_end"))
        except ConfigError as err:
            if not collect:
                raise
            problems.append(err)
    return problems


def sample_variables(setup: "MachineSetup", name: str = "header",
                     defines: dict[str, str] | None = None) -> list[dict[str, Any]]:
    """The variables a translation passes (``postproc.lowering.sequences``), with sample values, once per unit
    system; the block templates also get a sample tool change (tool 1 after none, operation 1)."""
    dialect = setup.dialect or "unknown"
    base: dict[str, Any] = {"program": SAMPLE_PROGRAM, "source_file": SAMPLE_PROGRAM + ".nc",
                            "source_dialect": dialect, "target_dialect": dialect, "machine": setup.name,
                            "date": "2000-01-01", "setup": setup_values(setup),
                            "tools": [{"number": 1, "line": 10}, {"number": 2, "line": 40}]}
    if name in ("tool_change", "operation_start"):
        base.update(tool=1, previous_tool=None, operation=1, line=10, name="SAMPLE OPERATION", first_use=True)
    elif name == "program_end":
        base.update(line=99)
    base.update(defines or {})
    return [{**base, "units": units} for units in ("mm", "inch")]
