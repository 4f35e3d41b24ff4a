"""The one XML parser bounds elements, attributes and value sizes before anything reads the tree (issue 8)."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

import postproc.setup.load as setup_load
from postproc import xmlio
from postproc.api import read_program
from postproc.errors import ConfigError
from postproc.commands.program_xml import dump_program, load_program
from postproc.setup.machine_setup import load_setup
from postproc.xmlio import MAX_ATTRIBUTES, MAX_ELEMENTS, MAX_VALUE_CHARS, parse_xml_bytes, parse_xml_file


def test_200000_attributes_are_refused_before_the_setup_reads_them(tmp_path: Path, monkeypatch) -> None:
    """``config check`` took over 60 s: lxml reads attributes in quadratic time."""
    calls = []
    real = setup_load.Merger.read_group
    monkeypatch.setattr(setup_load.Merger, "read_group",
                        lambda self, el, last: calls.append(el.tag) or real(self, el, last))
    attrs = " ".join(f'a{i}="1"' for i in range(200_000))
    path = tmp_path / "m.xml"
    path.write_text(f'<MachineSetup name="t">\n<Input/>\n<Cycles {attrs}/>\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as exc:
        load_setup(path)
    assert str(exc.value) == f"{path}:3:1: error: <Cycles> has more than {MAX_ATTRIBUTES} attributes"
    assert calls == []  # no group was validated at all: the parser stopped it


def test_the_attribute_bound_admits_the_bound(tmp_path: Path) -> None:
    attrs = " ".join(f'a{i}="1"' for i in range(MAX_ATTRIBUTES))
    assert len(parse_xml_bytes(f"<Root {attrs}/>".encode(), "r.xml").attrib) == MAX_ATTRIBUTES


def test_too_many_elements_is_located_at_the_first_one_over() -> None:
    data = ("<MachineSetup>\n" + "<Cycles/>\n" * MAX_ELEMENTS + "</MachineSetup>\n").encode()
    with pytest.raises(ConfigError) as exc:
        parse_xml_bytes(data, "m.xml")
    assert str(exc.value) == f"m.xml:{MAX_ELEMENTS + 1}:1: error: more than {MAX_ELEMENTS} XML elements"


@pytest.mark.parametrize("xml, line", [
    ('<Root>\n<A v="{}"/>\n</Root>', 2),
    ("<Root>\n\n<Header>{}</Header>\n</Root>", 3),
])
def test_a_value_or_text_over_the_bound_is_located(xml: str, line: int) -> None:
    with pytest.raises(ConfigError) as exc:
        parse_xml_bytes(xml.format("x" * (MAX_VALUE_CHARS + 1)).encode(), "v.xml")
    assert str(exc.value) == f"v.xml:{line}:1: error: a value or text longer than {MAX_VALUE_CHARS} characters"


def test_a_dumped_program_may_have_more_elements_than_a_setup(tmp_path: Path) -> None:
    program = "G21 G90\n" + "".join(f"G1 X{i}. F100.\n" for i in range(MAX_ELEMENTS))
    blocks = read_program(io.StringIO(program), file="p.nc", dialect="fanuc")
    path = tmp_path / "p.xml"
    with open(path, "wb") as out:
        dump_program(blocks, out, dialect="fanuc", file="p.nc")
    assert len(load_program(path)[1]) == len(blocks)


def test_a_file_is_read_only_up_to_the_byte_bound(tmp_path: Path, monkeypatch) -> None:
    """A FIFO or /dev/zero named as a set-up was read without end."""
    monkeypatch.setattr(xmlio, "MAX_XML_BYTES", 10)
    path = tmp_path / "big.xml"
    path.write_bytes(b"<Root>" + b"x" * 1000 + b"</Root>")
    with pytest.raises(ConfigError, match="larger than 10 bytes"):
        parse_xml_file(path)
