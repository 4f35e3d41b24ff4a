"""Syntax objects and the pipeline that runs them over a block stream.

A syntax is one processing step (resolve a canned cycle, expand back boring, ...). Its ``build(block,
ctx)`` rewrites the block in place. Steps that need look-ahead (a lathe profile between P and Q, a
subprogram body) override ``process`` and hold only the blocks that construct needs.
A dialect's reading pipeline is an XML file of syntax elements loaded through the factory.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

import abc
from typing import TYPE_CHECKING, Iterable, Iterator

from ..errors import ConfigError, Location, PostprocError
from ..ir import Block
from ..context import Context
from ..ir.source_map import locate
from ..xmlio import DEFAULT, XFactory, XmlNode, lxml_etree, parse_xml_file, where

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from pathlib import Path  # annotations only: a start makes no path object (pathlib imports urllib.parse)
    from lxml import etree


@mypyc_attr(allow_interpreted_subclasses=True)
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


@mypyc_attr(allow_interpreted_subclasses=True)
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
        etree = lxml_etree()
        el = etree.Element(self.XNAME, dialect=self.dialect)
        for step in self.steps:
            el.append(step.make_xml_source(base_dir, rel_file, exhibition_only))
        return el

    def run(self, blocks: Iterable[Block], ctx: Context) -> Iterator[Block]:
        stream: Iterable[Block] = blocks
        fused: list[Syntax] = []
        for step in self.steps:
            if step.streams():
                if fused:
                    stream = _fused(stream, tuple(fused), ctx)
                    fused = []
                stream = step.process(stream, ctx)
            else:
                fused.append(step)
        if fused:
            stream = _fused(stream, tuple(fused), ctx)
        return iter(stream)


def _fused(blocks: Iterable[Block], steps: tuple[Syntax, ...], ctx: Context) -> Iterator[Block]:
    """Run several per-block steps in one loop; an error in a block is reported and the block kept.

    The steps are called as ``Syntax`` objects, not bound methods: compiled, that is a direct call
    instead of a Python call with its argument parsing. Pipelines of up to three per-block steps (the
    usual reading pipeline) call them without an inner loop: on a million-block program the loop's
    overhead is measurable.
    """
    report = ctx.diagnostics.error
    file = ctx.file
    if len(steps) == 3:
        first, second, third = steps
        for block in blocks:
            try:
                first.build(block, ctx)
                second.build(block, ctx)
                third.build(block, ctx)
            except PostprocError as err:
                report(err.located(locate(file, block)), block.text)
            yield block
        return
    for block in blocks:
        try:
            for step in steps:
                step.build(block, ctx)
        except PostprocError as err:
            report(err.located(locate(file, block)), block.text)
        yield block


def load_pipeline(path: str | Path, factory: XFactory | None = None) -> Pipeline:
    root = parse_xml_file(path)
    if root.tag != Pipeline.XNAME:
        raise ConfigError(f"expected <Pipeline>, found <{root.tag}>", Location(str(path), root.sourceline or 1, 1))
    return Pipeline.from_xml(root, factory)
