"""A Fanuc program's first line ``%<title>`` (issue 26, held-out ``gcodeworkshop_tokarka_lathe_trimmed.nc``):
the control reads the ``%`` and skips the rest of the line, the leader, where a title may stand [V: Fanuc
16i/18i-TB operator's manual B-63524EN/01, memory card file format; Data Server manual B-64014EN/03,
``% TITLE ;``]. The reader keeps it as the tape mark's title; a copy is byte for byte, a Fanuc target keeps it
on its ``%`` line, any other target gets it as a comment after the ``%`` (LinuxCNC refuses text after its
``%``: checked below with rs274). A later ``%`` with text stays an error."""

from __future__ import annotations

import io
import string

import pytest
from hypothesis import given, settings, strategies as st

from postproc.api import read_program, translate
from postproc.commands.program_xml import dump_program, load_program
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup, OutputSettings
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import RS274Error, available, run_rs274
from tests.support.tools import with_tools

FUZZ = settings(max_examples=100, deadline=None)

BODY = "G21 G90\nG0 X0 Y0 Z10\nG1 X5 F100.\nM30\n%\n"
TOKARKA = "%O1200(TOKARKA)\r\n"
"""The held-out program's first line, as written (CR LF)."""


def lex(text: str) -> list:
    fanuc = default_registry().dialect("fanuc")
    ctx = fanuc.context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE))
    return list(fanuc.READER(ctx).read(io.StringIO(text, newline="")))


def translated(program: str, target: str, **output: object) -> str:
    out = io.StringIO()
    translate(io.StringIO(program, newline=""), out, file="p.nc", source="fanuc", target=target,
              setup=MachineSetup(output=OutputSettings(**output)))
    return out.getvalue()


def test_the_first_line_is_the_tape_mark_with_its_title():
    block = lex(TOKARKA + BODY)[0]
    assert list(block.sections) == ["TapeMark"]  # the O number and comment are the leader's: skipped
    assert block.sections["TapeMark"].title == "O1200(TOKARKA)"
    assert block.words == []
    assert (block.text, block.eol) == ("%O1200(TOKARKA)", "\r\n")


@pytest.mark.parametrize("line, title", [
    ("%", None), ("  %  ", None), ("% TITLE ;", "TITLE ;"), ("%\tO0001 (PART)\t", "O0001 (PART)"),
    ("%%", "%"), ("\ufeff%TITLE", "TITLE")])
def test_titles(line, title):
    block = lex(line + "\n" + BODY)[0]
    assert list(block.sections) == ["TapeMark"]
    assert block.sections["TapeMark"].title == title
    assert block.text == line


@pytest.mark.parametrize("program, col", [
    ("G21\n%END\n", 1),  # a '%' with text after the first line
    ("%\n%TITLE\n", 1),  # the second '%' line
    ("\n%TITLE\n", 1),  # not the first line
    ("G21 %TITLE\n", 5),  # not at the start of the line
])
def test_a_percent_with_text_elsewhere_stays_an_error(program, col):
    with pytest.raises(ErrorList) as info:
        read_program(io.StringIO(program), file="t.nc", dialect="fanuc")
    messages = [str(e) for e in info.value.errors]
    assert any("'%' must stand alone on its line" in m and f":{col}: " in m for m in messages), messages


_TITLE = st.builds(str.__add__, st.sampled_from(["", "O1200", " O0001 ", "1"]),
                   st.text(st.sampled_from([c for c in string.printable if c not in string.digits + "\r\n\x0b\x0c"]),
                           max_size=30))
"""ASCII (a program is, outside comments: ``postproc.syntaxes.lines.line_problem``) with short numbers."""


@FUZZ
@given(_TITLE, st.sampled_from(["\n", "\r\n"]))
def test_any_title_is_read_and_copied_byte_for_byte(title, eol):
    program = "%" + title + eol + BODY.replace("\n", eol)
    block = lex(program)[0]
    assert block.sections["TapeMark"].title == (title.strip(" \t") or None)
    assert block.text == "%" + title
    assert translated(program, "fanuc") == program


def test_a_fanuc_target_keeps_the_title_on_its_percent_line_when_normalising():
    assert translated(TOKARKA + BODY, "fanuc", normalize=True).startswith("%O1200(TOKARKA)\r\n")


@pytest.mark.parametrize("target, opening", [
    ("linuxcnc", "%\n(O1200[TOKARKA])\n"),
    ("mach3", "%\n(O1200[TOKARKA])\n"),
    ("isg", "%\n(O1200[TOKARKA])\n"),
    ("siemens", ";%\n;O1200(TOKARKA)\n"),
    ("fagor", ";%\n;O1200(TOKARKA)\n"),
    ("grbl", "(%)\n(O1200[TOKARKA])\n"),
])
def test_another_target_gets_the_title_as_a_comment(target, opening):
    program = TOKARKA.replace("\r\n", "\n") + BODY
    text = translated(program, target)
    assert text.startswith(opening)
    translate(io.StringIO(text), io.StringIO(), file="back", source=target, target=target)  # reads back
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="a", file_out="b", source="fanuc",
                          target=target, tolerance=0.0, setup=with_tools())
    assert report.ok, report.summary()


@pytest.mark.parametrize("target, opening", [("fanuc", "(O1200[TOKARKA])\nG21"), ("linuxcnc", "(O1200[TOKARKA])\nG21")])
def test_without_percent_lines_the_title_stays_as_a_comment(target, opening):
    text = translated(TOKARKA.replace("\r\n", "\n") + BODY, target, tape_marks="never")
    assert text.startswith(opening)
    assert "%" not in text


@pytest.mark.skipif(not available(), reason="rs274 not installed")
def test_linuxcnc_refuses_a_title_on_its_percent_line_and_runs_the_translation():
    """Why LinuxCNC gets a comment: its interpreter refuses text after the opening '%'."""
    with pytest.raises(RS274Error, match="Bad character '%' used"):
        run_rs274("%O1200(TOKARKA)\nG0 X1\nM2\n%\n")
    calls = run_rs274(translated(TOKARKA.replace("\r\n", "\n") + BODY, "linuxcnc"))
    assert any("STRAIGHT_FEED" in call for call in calls)


def test_the_title_survives_the_ir_xml(tmp_path):
    blocks = read_program(io.StringIO(TOKARKA + BODY, newline=""), file="p.nc", dialect="fanuc")
    path = tmp_path / "ir.xml"
    with open(path, "wb") as out:
        dump_program(blocks, out, dialect="fanuc", file="p.nc")
    _, loaded = load_program(path)
    assert loaded == blocks
    assert loaded[0].sections["TapeMark"].title == "O1200(TOKARKA)"
