"""What follows a program's end is never live code in another dialect (``postproc.lowering.program_end``), and
``verify`` compares it: grbl is streamed to and runs whatever follows M30, while both simulators stop
at the end."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.interp.control import Return, SubStart
from postproc.context import Context
from postproc.dialect import Dialect
from postproc.errors import Diagnostics
from postproc.ir import Block, Motion, ProgramControl, ProgramStart
from postproc.lowering.program_end import comment_after_end
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available as rs274_available, run_rs274

AFTER_M30 = "G21 G90\nG0 X1.\nM30\nG0 X100. (CRASH)\nG1 Y5. F10.\n"


def _translate(program: str, source: str, target: str) -> tuple[str, Diagnostics]:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    translate(io.StringIO(program), out, file="p.nc", source=source, target=target, diagnostics=diagnostics)
    return out.getvalue(), diagnostics


def _verify(a: str, b: str, source: str, target: str) -> tuple[bool, str]:
    report = verify_lines(io.StringIO(a), io.StringIO(b), file_in="in", file_out="out", source=source,
                          target=target)
    return report.ok, report.mismatch or ""


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_blocks_after_m30_are_written_as_comments(target: str) -> None:
    text, diagnostics = _translate(AFTER_M30, "fanuc", target)
    tail = text.splitlines()[-2:]
    assert tail == ["(AFTER PROGRAM END, LINE 4: G0 X100. [CRASH])", "(AFTER PROGRAM END, LINE 5: G1 Y5. F10.)"]
    assert [str(w) for w in diagnostics.warnings] == [
        "p.nc:4:1: warning: blocks after the program end are written as comments (a controller that is "
        "streamed to would run them)"]


def test_blocks_after_a_closing_percent_are_written_as_comments() -> None:
    text, _ = _translate("%\nG21 G90\nG0 X1.\n%\nG0 X100.\n", "fanuc", "grbl")
    assert text.splitlines()[-1] == "(AFTER PROGRAM END, LINE 5: G0 X100.)"
    moves = [e for e in toolpath_events(io.StringIO("%\nG21 G90\nG0 X1.\n%\nG0 X100.\n"), file="p.nc",
                                        dialect="fanuc") if "move" in e]
    assert [m["x"] for m in moves] == [1]  # the simulator stops at the closing % too


def test_same_dialect_keeps_the_program_as_it_is() -> None:
    text, diagnostics = _translate(AFTER_M30, "fanuc", "fanuc")
    assert text == AFTER_M30 and diagnostics.warnings == []


def test_verify_reports_live_blocks_after_the_end_in_the_translation_only() -> None:
    """The old grbl output (live G0 X100. after M30) verified ok; now it is a mismatch. Dead code after the
    source's end written as comments is the safe translation: it verifies."""
    live = "G21 G90\nG0 X1.\nM30\nG0 X100.\n"
    assert _verify("G21 G90\nG0 X1.\nM30\n", live, "fanuc", "grbl") == (
        False, "OUT has live blocks after the program end (from line 4), IN has none (a controller that is "
        "streamed to would run them)")
    assert _verify(AFTER_M30, AFTER_M30, "fanuc", "fanuc") == (True, "")
    commented, _ = _translate(AFTER_M30, "fanuc", "grbl")
    assert _verify(AFTER_M30, commented, "fanuc", "grbl") == (True, "")


def _block(line: int, *sections: object) -> Block:
    b = Block(line, f"LINE{line}", "\n")
    for s in sections:
        b.add(s)  # type: ignore[arg-type]
    return b


class _Programs(Dialect):
    NAME = "with-programs"
    PROGRAMS = True


class _Flat(Dialect):
    NAME = "flat"


@pytest.mark.parametrize("target, kept", [(_Programs, True), (_Flat, False)])
def test_subprograms_after_the_end_are_kept_where_the_target_runs_them(target: type[Dialect], kept: bool) -> None:
    """A Fanuc O2000 ... M99 or a LinuxCNC o<x> sub after the main program: live code only where the
    target has no subprograms of its own; a stray block between them is commented either way."""
    blocks = [_block(1, Motion("rapid", {"X": 1.0})), _block(2, ProgramControl("end_rewind")),
              _block(3, ProgramStart(2000, None)), _block(4, Motion("rapid", {"X": 2.0})), _block(5, Return()),
              _block(6, Motion("rapid", {"X": 3.0})),
              _block(7, SubStart("s")), _block(8, Motion("rapid", {"X": 4.0}))]
    ctx = Context("p.nc", MachineSetup(), Diagnostics(warn_stream=io.StringIO()), "source")
    out = list(comment_after_end(iter(blocks), ctx, target))
    commented = [b.line for b in out if list(b.sections) == ["Comments"]]
    assert commented == ([6] if kept else [3, 4, 5, 6, 7, 8])


# -- a program with no end, written for LinuxCNC ----------------------------------------------------

NO_END = "p.nc:{}:1: warning: the program has no end (M2/M30): M2 written after its last block, as LinuxCNC " \
         "refuses a program that runs out"


@pytest.mark.parametrize("program, expected, warning", [
    ("G21 G90\nG0 X1.\n", "G21 G90\nG0 X1.\nM2\n", NO_END.format(2)),
    ("%\nG21 G90\nG0 X1.\n", "%\nG21 G90\nG0 X1.\nM2\n%\n", NO_END.format(3)),
    ("G21 G90\nG0 X1.\n%\n", "G21 G90\nG0 X1.\nM2\n(%)\n",
     "p.nc:3:1: warning: the program ends with '%' and no M2/M30, without an opening '%': LinuxCNC refuses a "
     "lone '%': M2 written for it, the '%' as a comment"),
    ("(ONLY A COMMENT)\n", "(ONLY A COMMENT)\nM2\n", NO_END.format(1)),
    # ends rs274 accepts as they are: no M2, no warning about the end
    ("%\nG21 G90\nG0 X1.\n%\n", "%\nG21 G90\nG0 X1.\n%\n", None),
    ("G21 G90\nG0 X1.\nM02\n", "G21 G90\nG0 X1.\nM2\n", None),
    ("G21 G90\nG0 X1.\nM30\n%\n", "G21 G90\nG0 X1.\nM30\n%\n", None),
    # a Fanuc's opening '%' after a blank line (read so by the Fanuc reader: the program runs from it) opens the
    # program, it does not end it (issue 26: CadeKiely's Haas programs start with a blank line, then '%'); off
    # rs274's first line it can only be a comment, and the closing '%' then closes nothing
    ("\n%\nG21 G90\nG0 X1.\nM30\n%\n", "\n(%)\nG21 G90\nG0 X1.\nM30\n%\n", None),
    ("\n%\nG21 G0 X1.\n%\n", "\n(%)\nG21 G0 X1.\nM2\n(%)\n",
     "p.nc:4:1: warning: the program ends with '%' and no M2/M30, without an opening '%': LinuxCNC refuses a "
     "lone '%': M2 written for it, the '%' as a comment"),
    ("\n%\nG21 G0 X1.\n", "\n(%)\nG21 G0 X1.\nM2\n", NO_END.format(3)),
])
def test_linuxcnc_gets_an_end_where_the_source_has_none(program: str, expected: str, warning: str | None) -> None:
    """rs274 refuses a file that runs out with neither M2/M30 nor a closing '%' after an opening one ("File
    ended with no percent sign or program end"), and a lone closing '%' ("Bad character '%' used"): the
    program ends where it runs out, so M2 says so. The output is checked by rs274 (``output_rules``), and
    verifies against its source: a program that runs out and one that ends there are the same program."""
    text, diagnostics = _translate(program, "fanuc", "linuxcnc")
    assert text == expected
    ends = [str(w) for w in diagnostics.warnings if "M2" in str(w)]
    assert ends == ([warning] if warning else [])
    assert _verify(program, text, "fanuc", "linuxcnc") == (True, "")
    if rs274_available():
        run_rs274(text)  # raises when rs274 refuses it


@pytest.mark.parametrize("source, program", [
    ("gsk", "G0 X10. Z2.\nG1 Z-5. F0.2\n"),
    ("isg", "N10 G0 X10. Y2.\nN20 G1 Y-5. F100\n"),
    ("fagor", "G0 X10 Y2\nG1 Y-5 F100\n"),
    ("grbl", "G21 G90\nG0 X1\nG1 Y2 F100\n"),
])
def test_every_source_dialect_without_an_end_gets_m2(source: str, program: str) -> None:
    text, _ = _translate(program, source, "linuxcnc")
    assert text.endswith("M2\n")
    if rs274_available():
        run_rs274(text)


def test_linuxcnc_written_back_to_itself_stays_as_it_is() -> None:
    """Lossless: a LinuxCNC file without an end is the user's own (rs274 would refuse the source too)."""
    assert _translate("G0 X1\n", "linuxcnc", "linuxcnc")[0] == "G0 X1\n"


def test_verify_takes_an_end_where_the_source_runs_out_as_the_same_program() -> None:
    """Not the other way round: M2/M30 stop the spindle and coolant, a program that runs out does not
    (``test_verify.py``: a missing end is a mismatch)."""
    assert _verify("G21 G0 X1.\n", "G21 G0 X1.\nM30\n", "fanuc", "fanuc") == (True, "")
    assert _verify("G21 G0 X1.\nM30\n", "G21 G0 X1.\n", "fanuc", "fanuc")[0] is False
    ok, why = _verify("G21 G0 X1.\n", "G21 G0 X1.\nM30\nG0 X2.\n", "fanuc", "grbl")
    assert not ok  # an end that is not the last thing is no end where the program runs out


@pytest.mark.parametrize("setup_expressions", [False, True])
def test_a_numbered_subprogram_after_m30_is_no_live_code_on_grblhal(setup_expressions: bool) -> None:
    """grblHAL reads o-word subs only [V ngc_flowctrl.c]: an uncalled Fanuc O2000 .. M99 after M30 was
    written as '(O2000)' and a live 'G0 X90.' after the end, which a streamed grblHAL runs."""
    from postproc.setup.groups import ControllerSettings
    program = "O1\nG21 G90 G17\nG0 X1. Y1. Z5.\nM30\nO2000\nG00 X90.\nM99\n"
    out = io.StringIO()
    setup = MachineSetup(controller=ControllerSettings(expressions=setup_expressions))
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="grblhal", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    lines = out.getvalue().splitlines()
    assert lines[lines.index("M30") + 1:] and all(line.startswith("(") for line in lines[lines.index("M30") + 1:])
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="in", file_out="out",
                          source="fanuc", target="grblhal", setup=setup)
    assert report.ok, report.summary()
