"""Program names across families (issue #26, item 5): an ISG or Fagor ``%name`` written for a dialect whose
programs are numbered (Fanuc ``O``) takes the number the set-up or ``--program-number`` gives, else
``O0001`` with a warning naming both, and keeps its name as a comment; a name with spaces (Beckhoff's
streaming-mode sample, ``% TestProgram for streaming mode``) is read and kept byte for byte."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import MachineSetup, OutputSettings
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

BODY = "N10 G01 X10 Y10 F100\nN20 G00 Z5\nM30\n"
STREAMING = "% TestProgram for streaming mode\n" + BODY
"""The first line as Beckhoff's own streaming-mode sample program has it."""


def written(program: str, source: str, target: str, **output: object) -> tuple[str, str]:
    """The translation (read back by the target and verified against the source) and its warnings."""
    warnings = io.StringIO()
    out = io.StringIO()
    setup = MachineSetup(output=OutputSettings(**output))
    translate(io.StringIO(program), out, file="p.nc", source=source, target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=warnings))
    text = out.getvalue()
    translate(io.StringIO(text), io.StringIO(), file="back.nc", source=target, target=target)
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="a", file_out="b", source=source,
                          target=target, tolerance=0.0)
    assert report.ok, report.summary()
    return text, warnings.getvalue()


@pytest.mark.parametrize("source", ["isg", "fagor"])
def test_a_named_program_is_numbered_o0001_with_a_warning_and_keeps_its_name(source: str) -> None:
    text, warnings = written("%PLATE_7\n" + BODY, source, "fanuc")
    assert text.splitlines()[0] == "O0001 (PLATE_7)"
    assert "p.nc:1:1: warning: the program 'PLATE_7' has no number in the fanuc dialect: written as O0001" in warnings
    assert "--program-number" in warnings and "<Output programNumber>" in warnings


def test_the_set_up_number_names_it_without_a_warning() -> None:
    text, warnings = written("%PLATE_7\n" + BODY, "isg", "fanuc", program_number=77)
    assert text.splitlines()[0] == "O0077 (PLATE_7)" and warnings == ""


def test_a_name_with_spaces_is_read_and_kept_byte_for_byte() -> None:
    out = io.StringIO()
    translate(io.StringIO(STREAMING), out, file="p.nc", source="isg", target="isg")
    assert out.getvalue() == STREAMING
    moves = [e for e in toolpath_events(io.StringIO(STREAMING), file="p.nc", dialect="isg") if "move" in e]
    assert [(m["x"], m["y"], m["z"]) for m in moves][-2:] == [(10.0, 10.0, 0.0), (10.0, 10.0, 5.0)]
    text, _ = written(STREAMING, "isg", "fanuc")
    assert text.splitlines()[0] == "O0001 (TestProgram for streaming mode)"


def test_a_subroutine_name_still_takes_no_blanks() -> None:
    from postproc.errors import ErrorList
    with pytest.raises(ErrorList, match="a local subroutine needs a name"):
        translate(io.StringIO("%L my sub\nG01 X1 F100\nM17\n"), io.StringIO(), file="p.nc", source="isg", target="isg")


def test_program_number_on_the_command_line(cli, tmp_path) -> None:  # type: ignore[no-untyped-def]
    program = tmp_path / "named.nc"
    program.write_text("%PLATE_7\n" + BODY)
    done = cli("translate", program, "--from", "isg", "--to", "fanuc", "--program-number", "1234")
    assert done.status == 0 and done.out.decode().splitlines()[0] == "O1234 (PLATE_7)" and done.err == ""
    for bad in ("0", "10000", "12a"):
        refused = cli("translate", program, "--from", "isg", "--to", "fanuc", "--program-number", bad)
        assert refused.status == 2 and "--program-number" in refused.err
    grbl = cli("translate", program, "--from", "isg", "--to", "grbl", "--program-number", "12")
    assert grbl.status == 2 and "the grbl dialect writes no program number" in grbl.err
    batch = cli("translate", program, program, "--from", "isg", "--to", "fanuc", "--program-number", "12",
                "-o", tmp_path / "out")
    assert batch.status == 2 and "not with several inputs" in batch.err


def test_a_second_named_start_is_a_comment_not_a_second_o0001() -> None:
    """ISG runs on through a second ``%name`` (the simulation takes it as nothing); two ``O0001`` lines would be
    two programs of one number, which the Fanuc reader (and control) refuse. Found by the suite's fuzzing."""
    text, warnings = written("%A\nG01 X1 F100\n%B\nG01 X2\nM30\n", "isg", "fanuc")
    assert text.splitlines() == ["O0001 (A)", "G21 G01 X1. F100.", "(B)", "G01 X2.", "M30"]
    assert warnings.count("warning:") == 1
