"""A whole program's IR as XML: ``<Program dialect=".." file=".."><Block>..</Block>...</Program>``.

Written incrementally (lxml's ``xmlfile``), so dumping a long program streams like translating it.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import BinaryIO, Iterable

from lxml import etree

from ..errors import ConfigError, Location, UnsupportedError, character_name
from ..ir import Block
from ..xmlio import XFactory, parse_xml_file

PROGRAM = "Program"
PROGRAM_MAX_ELEMENTS = 1 << 24
"""A dumped program may have as many elements as its bytes allow (``MAX_XML_BYTES``); a set-up may not."""


def dump_program(blocks: Iterable[Block], out: BinaryIO, *, dialect: str, file: str) -> None:
    with etree.xmlfile(out, encoding="UTF-8") as xf:
        xf.write_declaration()
        with xf.element(PROGRAM, dialect=dialect, file=file):
            xf.write("\n")
            for block in blocks:
                try:
                    el = block.make_xml_source()
                except ValueError:  # lxml refuses control characters and undecodable bytes (surrogates)
                    raise _not_xml(block, file) from None
                etree.indent(el, space="  ", level=1)
                xf.write("  ", el, "\n")


_NOT_XML = re.compile("[^\t\n\r\x20-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")
"""Characters XML 1.0 cannot hold."""


def _not_xml(block: Block, file: str) -> UnsupportedError:
    m = _NOT_XML.search(block.text or "")
    if m is None:
        return UnsupportedError("the block cannot be written as XML", Location(file, block.line, 1))
    return UnsupportedError(f"{character_name(m.group(0))} cannot be written to the IR XML",
                            Location(file, block.line, m.start() + 1))


def load_program(path: str | Path, factory: XFactory | None = None) -> tuple[str, list[Block]]:
    """Load a dumped program: (dialect, blocks). Unknown elements are located errors.

    Without a ``factory``, the installed plugins' one (their sections may appear in the program)."""
    if factory is None:
        from ..plugins import default_registry  # late: the plugin manager imports the IR
        factory = default_registry().factory
    root = parse_xml_file(path, max_elements=PROGRAM_MAX_ELEMENTS)
    if root.tag != PROGRAM:
        raise ConfigError(f"expected <{PROGRAM}>, found <{root.tag}>", Location(str(path), root.sourceline or 1, 1))
    blocks = []
    for el in root:
        if not isinstance(el.tag, str):
            continue
        if el.tag != Block.XNAME:
            raise ConfigError(f"unknown element <{el.tag}> in <{PROGRAM}>", Location(str(path), el.sourceline or 1, 1))
        try:
            blocks.append(Block.from_xml(el, factory))
        except (ValueError, TypeError) as exc:
            raise ConfigError(f"invalid <Block>: {exc}", Location(str(path), el.sourceline or 1, 1)) from None
    return root.get("dialect", ""), blocks
