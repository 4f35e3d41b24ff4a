"""The word writer's section dispatch is a table built once per writer class (not a method lookup per
section of every block), and it keeps the documented order: ``TRANSFORMS``, then ``<key>_words``, then a
located ``UnsupportedError``."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, UnsupportedError
from postproc.ir import Block, Section
from postproc.plugins import default_registry
from postproc.rs274.writer import WordWriter
from postproc.setup.machine_setup import MachineSetup

PROGRAM = "G21 G90 G0 X0. Y0. Z10.\nG1 X5. F100.\nM30\n"


def _translate(target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(PROGRAM, newline=""), out, file="t.nc", source="fanuc", target=target,
              setup=MachineSetup(), diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def test_one_table_per_writer_class_shared_by_every_run() -> None:
    writer = default_registry().dialect("linuxcnc").WRITER
    assert isinstance(writer, type) and issubclass(writer, WordWriter)
    first = _translate("linuxcnc")
    table = writer.__dict__["_section_writers"]
    assert table["Motion"] is writer.motion_words
    assert _translate("linuxcnc") == first
    assert writer.__dict__["_section_writers"] is table  # the same table, not rebuilt by the second run


def test_a_subclass_gets_its_own_table_and_transforms_come_first() -> None:
    base = default_registry().dialect("linuxcnc").WRITER
    assert isinstance(base, type) and issubclass(base, WordWriter)

    def feed(writer: WordWriter, section: object, block: object) -> list[str]:
        return ["F1."]

    sub = type("FeedOne", (base,), {"TRANSFORMS": {**base.TRANSFORMS, "Feed": feed}})
    assert sub.section_writer("Feed") is feed
    assert sub.section_writer("Motion") is base.motion_words
    assert base.section_writer("Feed") is not feed
    assert sub.section_writer("NoSuchSection") is None


def test_a_section_no_writer_knows_is_a_located_error() -> None:
    dialect = default_registry().dialect("linuxcnc")
    ctx = dialect.context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    writer = dialect.WRITER(ctx, "fanuc", dialect)
    assert isinstance(writer, WordWriter)
    with pytest.raises(UnsupportedError) as info:
        writer.section_words("Mystery", Section(), Block(3, None, "\n"))
    assert str(info.value) == "t.nc:3:1: error: the linuxcnc dialect cannot express Mystery"
    assert type(writer).section_writer("Mystery") is None
