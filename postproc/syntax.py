"""Syntax objects and the pipeline that runs them over a block stream.

A syntax is one processing step (resolve a canned cycle, expand back boring, ...). Its ``build(block,
ctx)`` rewrites the block in place. Steps that need look-ahead (a lathe profile between P and Q, a
subprogram body) override ``process`` and hold only the blocks that construct needs.
A dialect's reading pipeline is an XML file of syntax elements loaded through the factory.
"""

from __future__ import annotations

import abc
import re
from pathlib import Path
from typing import Callable, Iterable, Iterator

from lxml import etree

from .errors import ConfigError, Diagnostics, Location, PostprocError
from .ir import Block
from .setup import MachineSetup
from .source_map import locate
from .state import ModalState
from .xmlio import DEFAULT, XFactory, XmlNode, parse_xml_file, where


class Context:
    """What every step of one run shares: file name, set-up, diagnostics and modal state."""

    __slots__ = ("file", "setup", "diagnostics", "state", "dialect", "on_unsupported", "program_mode")

    def __init__(self, file: str, setup: MachineSetup, diagnostics: Diagnostics, dialect: str) -> None:
        self.file = file
        self.setup = setup
        self.diagnostics = diagnostics
        self.state = ModalState()
        self.dialect = dialect
        self.on_unsupported = "error"
        """'error' or 'warn': what a construct the target cannot express does."""
        self.program_mode = "keep"
        """What the interpreter step does with a program that computes: 'keep' its constructs (for a
        target that has them) or 'execute' them (toolpath, verify, flattening); see ``postproc.interp``."""

    def at(self, block: Block, col: int = 1) -> Location:
        """Where ``block`` (column ``col``) is, through the source map: the one way to locate a block."""
        return locate(self.file, block, col)

    def column_of(self, block: Block, letter: str, number: str | None = None, nth: int = 1) -> int:
        """Column of the ``nth`` word with ``letter`` (and, if given, exactly that number text) in the
        block's text, comments skipped. Computed only when reporting an error."""
        want = letter.upper()
        for col, found, num in word_columns(block.text or ""):
            if found.upper() == want and (number is None or num == number):
                nth -= 1
                if nth == 0:
                    return col
        return 1


_WORD_AT = re.compile(r"([A-Za-z:])[ \t]*([-+]?(?:\d+\.?\d*|\.\d+))")
_COMMENT_AT = re.compile(r"\([^()]*\)|\([^()]*$|;.*$")


def word_columns(text: str) -> list[tuple[int, str, str]]:
    """(1-based column, letter, number text) of every word outside comments."""
    masked = _COMMENT_AT.sub(lambda m: " " * len(m.group(0)), text)
    return [(m.start() + 1, m.group(1), m.group(2)) for m in _WORD_AT.finditer(masked)]


class Syntax(XmlNode, metaclass=abc.ABCMeta):
    """Base of every processing step. Subclasses set ``XNAME`` and implement ``build``."""

    __slots__ = ()

    @abc.abstractmethod
    def build(self, block: Block, ctx: Context) -> None:
        """Rewrite ``block`` in place (its sections, and ``ctx.state`` where the step owns state)."""

    def process(self, blocks: Iterable[Block], ctx: Context) -> Iterator[Block]:
        """Stream form of the step; the default calls ``build`` on each block."""
        build = self.build
        for block in blocks:
            build(block, ctx)
            yield block

    def streams(self) -> bool:
        """True when the step overrides ``process`` (needs look-ahead or emits extra blocks)."""
        return type(self).process is not Syntax.process


class Pipeline(XmlNode):
    """An ordered list of syntax objects. Consecutive per-block steps are fused into one loop."""

    XNAME = "Pipeline"
    __slots__ = ("dialect", "steps")

    def __init__(self, dialect: str, steps: list[Syntax]) -> None:
        self.dialect = dialect
        self.steps = steps

    def _key(self) -> tuple[object, ...]:
        return (self.dialect, tuple(self.steps))

    def __repr__(self) -> str:
        return f"Pipeline({self.dialect!r}, {self.steps!r})"

    @classmethod
    def from_xml(cls, el: etree._Element, factory: XFactory | None = None) -> "Pipeline":
        factory = factory or DEFAULT
        steps = []
        for child in el:
            if not isinstance(child.tag, str):
                continue
            step = factory.create(child)
            if not isinstance(step, Syntax):
                raise ConfigError(f"<{child.tag}> is not a syntax step", where(child))
            steps.append(step)
        return cls(el.get("dialect", ""), steps)

    def make_xml_source(self, base_dir: str = ".", rel_file: str = "", exhibition_only: bool = False) -> etree._Element:
        el = etree.Element(self.XNAME, dialect=self.dialect)
        for step in self.steps:
            el.append(step.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def run(self, blocks: Iterable[Block], ctx: Context) -> Iterator[Block]:
        stream: Iterable[Block] = blocks
        fused: list[Callable[[Block, Context], None]] = []
        for step in self.steps:
            if step.streams():
                if fused:
                    stream = _fused(stream, tuple(fused), ctx)
                    fused = []
                stream = step.process(stream, ctx)
            else:
                fused.append(step.build)
        if fused:
            stream = _fused(stream, tuple(fused), ctx)
        return iter(stream)


def _fused(blocks: Iterable[Block], builds: tuple[Callable[[Block, Context], None], ...],
           ctx: Context) -> Iterator[Block]:
    """Run several per-block steps in one loop; an error in a block is reported and the block kept.

    Pipelines of up to three per-block steps (the usual reading pipeline) call them without an inner
    loop: on a million-block program the loop's overhead is measurable.
    """
    report = ctx.diagnostics.error
    file = ctx.file
    if len(builds) == 3:
        first, second, third = builds
        for block in blocks:
            try:
                first(block, ctx)
                second(block, ctx)
                third(block, ctx)
            except PostprocError as err:
                report(err.located(locate(file, block)))
            yield block
        return
    for block in blocks:
        try:
            for build in builds:
                build(block, ctx)
        except PostprocError as err:
            report(err.located(locate(file, block)))
        yield block


def load_pipeline(path: str | Path, factory: XFactory | None = None) -> Pipeline:
    root = parse_xml_file(path)
    if root.tag != Pipeline.XNAME:
        raise ConfigError(f"expected <Pipeline>, found <{root.tag}>", Location(str(path), root.sourceline or 1, 1))
    return Pipeline.from_xml(root, factory)
