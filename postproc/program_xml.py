"""A whole program's IR as XML: ``<Program dialect=".." file=".."><Block>..</Block>...</Program>``.

Written incrementally (lxml's ``xmlfile``), so dumping a long program streams like translating it.
"""

from __future__ import annotations

from pathlib import Path
from typing import BinaryIO, Iterable

from lxml import etree

from .errors import ConfigError, Location
from .ir import Block
from .xmlio import DEFAULT, XFactory, parse_xml_file

PROGRAM = "Program"


def dump_program(blocks: Iterable[Block], out: BinaryIO, *, dialect: str, file: str) -> None:
    with etree.xmlfile(out, encoding="UTF-8") as xf:
        xf.write_declaration()
        with xf.element(PROGRAM, dialect=dialect, file=file):
            xf.write("\n")
            for block in blocks:
                el = block.make_xml_source()
                etree.indent(el, space="  ", level=1)
                xf.write("  ", el, "\n")


def load_program(path: str | Path, factory: XFactory | None = None) -> tuple[str, list[Block]]:
    """Load a dumped program: (dialect, blocks). Unknown elements are located errors."""
    root = parse_xml_file(path)
    if root.tag != PROGRAM:
        raise ConfigError(f"expected <{PROGRAM}>, found <{root.tag}>", Location(str(path), root.sourceline or 1, 1))
    blocks = []
    for el in root:
        if not isinstance(el.tag, str):
            continue
        if el.tag != Block.XNAME:
            raise ConfigError(f"unknown element <{el.tag}> in <{PROGRAM}>", Location(str(path), el.sourceline or 1, 1))
        try:
            blocks.append(Block.from_xml(el, factory or DEFAULT))
        except (ValueError, TypeError) as exc:
            raise ConfigError(f"invalid <Block>: {exc}", Location(str(path), el.sourceline or 1, 1)) from None
    return root.get("dialect", ""), blocks
