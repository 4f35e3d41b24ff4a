"""Every output valid on its controller (issue 12, item 4).

* The grbl checker (``support/grbl_rules.py``) against cases derived by hand from grbl 1.1's
  ``gcode.c``/``protocol.c``/``serial.c``: each rule refuses what grbl refuses and passes its neighbour.
* The readers refuse what their controller refuses and accept what it accepts: LinuxCNC's checked against
  rs274 itself, grbl's against the grbl checker.
* The writers' fixes: grbl gets no G80, a bare feed motion code with no feed rate is left out, LinuxCNC
  gets no lone closing ``%``.
* The checkers hold every translation the suite makes (``support/output_rules.py``, installed by
  ``conftest.py``): a wrong output fails the test that wrote it.
"""

from __future__ import annotations

import io
import uuid

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from tests.support import output_rules
from tests.support.grbl_rules import grbl_problems
from tests.support.linuxcnc_rules import linuxcnc_problems
from tests.support.rs274 import RS274Error, available, run_rs274

# -- the grbl checker --------------------------------------------------------------------------------

GRBL_REFUSED = [
    ("G80 G0 Z1. M9", "error:21"),  # G80 and G0 are both MODAL_GROUP_G1
    ("M5 M3", "error:21"),
    ("M8 M9", "error:21"),
    ("G90 G91 X1", "error:21"),
    ("G28 G0 X1", "error:24"),  # two axis commands
    ("G49 G0 X1", "error:24"),
    ("G0 X1 X2", "error:25"),
    ("G43 H1", "error:20"),  # only G43.1
    ("G81 X1 Y1 Z-1 R1 F10", "error:20"),
    ("M6", "error:20"),
    ("M7", "error:20"),  # ENABLE_M7 is off in a stock build
    ("M19", "error:20"),
    ("G1 X1 H1 F10", "error:20"),  # H is no grbl word
    ("G4", "error:28"),
    ("G4 P-1", "error:4"),
    ("S-5", "error:4"),
    ("T256", "error:38"),
    ("G1 X1", "error:22"),  # no feed rate yet
    ("G1", "error:22"),  # even with no axis words: the explicit G1 is a motion-mode axis command
    ("G80\nX1", "error:31"),
    ("G80\nG91 G28 Z0.", "error:31"),  # gcode.c: "Even non-modal commands ... will throw this strict error"
    ("G1 X1 F10\nG2 X3", "error:35"),  # no I/J
    ("G1 F10\nG2 Z3 I1", "error:32"),  # nothing in the XY plane
    ("G1 F10\nG2 X4 R1.9", "error:34"),  # R shorter than half the chord of 4
    ("G1 F10\nG2 X4 I2.1", "error:33"),  # the end 0.2 mm off the circle
    ("G1 X1 R2 F10", "error:36"),  # R unused by a line
    ("G0 X1 P1", "error:36"),
    ("G2 X1 Y1 I1 F10\nG53 X0", "error:30"),  # G53 needs G0/G1 in force
    ("%", "error:1"),
    ("(DRILL!)", "error:1"),  # '!' is a feed hold wherever it stands
    ("(SPINDLE ?)", "error:1"),
    ("(\u00d8 8.5 DRILL)", "error:1"),  # non-ASCII: bytes above 0x7F are real-time commands
    ("G1 X1.2.3 F10", "error:1"),
    ("G1 X" + "1" * 80 + " F10", "error:11"),  # 79 characters a line, spaces and comments left out
]

GRBL_ACCEPTED = [
    "G21 G90 G0 X0. Y0. Z10.", "G0", "N10", "N10 (COMMENT)", "G17 G55 G40", "G91 G28 Z0.", "G49",
    "G1 X1 F100\nG1", "G1 X1 F100\nG2 X3 I1", "G1 X1 F100\nG2 X3 R1", "G1 X1 F100\nG3 X5 R-2",
    "T1 M0 (TOOL CHANGE: LOAD T1, THEN CYCLE START)", "G4 P0.5", "S1000 M3\nM8\nM5 M9", "G53 G0 Z0",
    "G80\nG0 X1", "x1 y2 ; lower case and a semicolon comment", "/G0 X1", "G0 X1 (" + "C" * 200 + ")",
    "G20 G1 X1 F10\nG2 X1.2 I0.1",
]


@pytest.mark.parametrize("program, code", GRBL_REFUSED)
def test_the_grbl_checker_refuses_what_grbl_refuses(program: str, code: str) -> None:
    problems = grbl_problems(program)
    assert len(problems) == 1 and f": {code} (" in problems[0], problems


@pytest.mark.parametrize("program", GRBL_ACCEPTED)
def test_the_grbl_checker_accepts_what_grbl_runs(program: str) -> None:
    assert grbl_problems(program) == []


def test_the_grbl_checker_knows_builds_with_m7_and_m19() -> None:
    assert grbl_problems("M7\nM19 R45", m7=True, m19=True) == []


def test_the_grbl_checker_tracks_positions_through_incremental_moves_and_forgets_them_at_g28() -> None:
    assert grbl_problems("G1 X1 F10\nG91 G1 X1\nG90 G2 X4 I1") == []  # from X2: centre X3, radius 1
    assert grbl_problems("G1 X1 F10\nG91 G1 X1\nG90 G2 X4 I0.5") != []
    assert grbl_problems("G28\nG1 F10\nG2 X4 I0.5") == []  # after G28 the start is unknown: not checked


# -- the readers -------------------------------------------------------------------------------------

NGC_HEAD = "G21 G90 G0 X0 Y0 Z10\nS100 M3\n"


def _ngc_errors(dialect: str, line: str) -> list[str]:
    try:
        read_program(io.StringIO(NGC_HEAD + line + "\nM2\n"), file="t.ngc", dialect=dialect)
    except ErrorList as errs:
        return [str(e) for e in errs.errors]
    return []


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("line", ["G10 L1 P2 Z-0.2", "G10 L10 P3 Z1.", "G10 P4 L11 Z2.", "G10L1P5Z0.1"])
def test_the_linuxcnc_checker_gives_the_machine_the_tool_a_table_write_names(line: str) -> None:
    """rs274 refuses a tool table write for a tool its table lacks; the set-up's tools are the shop's (the writer
    refuses a write for a tool the set-up lacks), so the checker's machine holds it, as for a T or an H. The fuzz
    found G10 L1 P2 refused by a table of tool 1 only."""
    tool = int(line.split("P")[1][0])
    with pytest.raises(RS274Error, match=f"Requested tool {tool} not found in the tool table"):
        run_rs274(NGC_HEAD + line + "\nM2\n", tool_table="T1 P1 Z0 D0\n")
    assert linuxcnc_problems(NGC_HEAD + line + "\nM2\n") == []


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_linuxcnc_checker_gives_the_machine_the_user_m_code_files_a_program_names() -> None:
    """A user M code (M100-M199) runs the machine's file of that name, which LinuxCNC's task registers and a
    standalone rs274 never does: rs274 refuses M120 alone, the checker's machine has the file. A code with P or
    Q words and a number past M199 are left to rs274, which refuses them."""
    with pytest.raises(RS274Error, match="Unknown m code used: M120"):
        run_rs274(NGC_HEAD + "N190 M120 (index)\nM2\n")
    assert linuxcnc_problems(NGC_HEAD + "N190 M120 (index M121)\nG0 X1 M0120\nM2\n") == []
    assert "Unknown m code used" in "".join(linuxcnc_problems(NGC_HEAD + "M120 P2\nM2\n"))
    assert "M-code greater than 199" in "".join(linuxcnc_problems(NGC_HEAD + "M200\nM2\n"))


@pytest.mark.parametrize("line", ["G80 G0 Z1. M9", "G0 G80 Z1.", "G0 X1 G80 Y1", "G80 G1 X1 F10",
                                  "G2 G80 X2 R1 F100", "G80 G81 X1 Y1 Z-1 R1 F100", "/N10 G0 X1", "M3 M8 M0",
                                  "M48 M3", "M5 M9", "G1 F10\nG1"])
def test_the_linuxcnc_reader_accepts_what_rs274_runs(line: str) -> None:
    assert _ngc_errors("linuxcnc", line) == []
    if available():
        run_rs274(NGC_HEAD + line + "\nM2\n")


def test_g80_beside_a_motion_code_gives_way_to_it_as_in_rs274() -> None:
    blocks = read_program(io.StringIO(NGC_HEAD + "G80 G0 Z1.\nG0 G80 X2.\nM2\n"), file="t.ngc", dialect="linuxcnc")
    assert [b.sections["Motion"].mode for b in blocks[2:4]] == ["rapid", "rapid"]  # type: ignore[attr-defined]
    assert "CycleCancel" not in blocks[2].sections and "CycleCancel" not in blocks[3].sections


@pytest.mark.parametrize("line, message", [
    ("M5 M19", "M codes M5 and M19 are both in one modal group"),
    ("M7 M8", "M codes M7 and M8 are both in one modal group"),
    ("M70 M3", "M codes M70 and M3 are both in one modal group"),
    ("M0 M60", "M codes M0 and M60 are both in one modal group"),
    ("G0 N10 X1", "a block number stands first in its block"),
    ("(C) N10 G0 X1", "a block number stands first in its block"),
    ("G1", "G1 with no feed rate in force"),
    ("G1 F0", "G1 with no feed rate in force"),
])
def test_the_linuxcnc_reader_refuses_what_rs274_refuses(line: str, message: str) -> None:
    errors = _ngc_errors("linuxcnc", line)
    assert len(errors) == 1 and message in errors[0], errors
    if available():
        with pytest.raises(RS274Error):
            run_rs274(NGC_HEAD + line + "\nM2\n")


def test_the_linuxcnc_reader_refuses_a_lone_closing_percent_as_rs274_does() -> None:
    with pytest.raises(ErrorList) as info:
        read_program(io.StringIO("G0 X1\n%\n"), file="t.ngc", dialect="linuxcnc")
    assert [str(e) for e in info.value.errors] == [
        "t.ngc:2:1: error: '%' closes only a program that opens with '%' on its first line "
        "(LinuxCNC: \"Bad character '%' used\")"]
    for fine in ("%\nG0 X1\n%\n", "G0 X1\nM2\n%\n"):
        read_program(io.StringIO(fine), file="t.ngc", dialect="linuxcnc")
    if available():
        with pytest.raises(RS274Error, match="Bad character"):
            run_rs274("G0 X1\n%\n")


def test_a_feed_mode_code_sets_the_linuxcnc_feed_rate_to_zero_and_the_writer_writes_it_again() -> None:
    assert "G1 with no feed rate in force" in _ngc_errors("linuxcnc", "F100\nG94 G1 Z-3")[0]
    assert "no feed rate" in _ngc_errors("linuxcnc", "F100\nG94\nG1 Z-3")[0]
    assert _ngc_errors("grbl", "F100\nG94\nG1 Z-3") == []  # grbl keeps it (gcode.c, G94 after G94)
    text, _ = _translate("G21 G0 X0 Y0 Z10.\nF100.\nG94 G01 Z-3.\nM30\n", "fanuc", "linuxcnc")
    assert text.splitlines()[2] == "G94 F100. G1 Z-3."
    if available():
        with pytest.raises(RS274Error, match="zero feed rate"):
            run_rs274(NGC_HEAD + "F100\nG94 G1 Z-3\nM2\n")
        run_rs274(text)


@pytest.mark.parametrize("line", ["G80 G0 Z1.", "M5 M3", "M8 M9", "G1"])
def test_the_grbl_reader_refuses_what_grbl_refuses(line: str) -> None:
    assert grbl_problems(NGC_HEAD + line) != []
    assert _ngc_errors("grbl", line) != []


# -- the writers -------------------------------------------------------------------------------------

def _translate(text: str, source: str, target: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text), out, file="t.nc", source=source, target=target, diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def test_grbl_gets_no_g80_which_would_refuse_the_next_g28() -> None:
    text, _ = _translate("G21 G0 X0 Y0 Z10.\nG81 X1. Y1. Z-1. R1. F100.\nG80\nG91 G28 Z0.\nM30\n", "fanuc", "grbl")
    assert "G80" not in text.replace("(G80)", "") and "(G80)\nG91 G28 Z0.\n" in text
    assert grbl_problems(text) == []


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_a_bare_feed_motion_code_with_no_feed_rate_is_left_out(target: str) -> None:
    text, _ = _translate("G21 G0 X0 Y0 Z10.\nG01\nX5. F100.\nG00\nG01\nM30\n", "fanuc", target)
    assert text.splitlines()[1:] == ["(G01)", "G1 X5. F100.", "G0", "G1", "M30"]


def test_grbl_comments_hold_no_realtime_character_and_only_ascii() -> None:
    text, warnings = _translate("G21 G0 X0 Y0 Z10.\n(DRILL \u00d8 8.5 - 90\u00b0 - CHECK DEPTH?!)\n"
                                "(CAF\u00c9 ~ \u2603)\nM30\n", "fanuc", "grbl")
    assert text.splitlines()[1:3] == ["(DRILL DIA 8.5 - 90DEG - CHECK DEPTH__)", "(CAFE _ _)"]
    assert grbl_problems(text) == [] and len(warnings) == 1
    assert _translate("G21 G0 X1.\n(OK)\n", "fanuc", "grbl")[1] == []


@pytest.mark.parametrize("source, program, message", [
    ("fanuc", "G41 D1\nG41 D1\n", 'cutter compensation left while compensation is on (rs274 needs G40 first: '
                                   '"Cannot turn cutter radius comp on when on")'),
    ("fanuc", "G41 D1\nG28\n", 'G28/G30 with cutter compensation on (rs274: "Cannot use g28 or g30 with cutter radius '
                                'comp")'),
    ("grbl", "G91\nG53 Y1.\n", 'a move in machine coordinates in incremental mode (rs274: "Cannot use g53 '
                                'incremental")'),
])
def test_what_rs274_refuses_in_a_translation_is_a_located_error(source: str, program: str, message: str) -> None:
    """Found by ``make fuzz`` with the controllers' rules: Fanuc (grbl: G53 under G91) runs these, rs274 refuses
    them."""
    with pytest.raises(ErrorList) as info:
        _translate("G21 G90 G0 X0 Y0 Z10.\n" + program + "M30\n", source, "linuxcnc")
    assert [str(e) for e in info.value.errors] == [f"t.nc:3:1: error: the linuxcnc dialect cannot express {message}"]
    if available():
        ngc = program.replace("G53 Y1.", "G53 G0 Y1.")
        with pytest.raises(RS274Error):
            run_rs274("G21 G90 G0 X0 Y0 Z10\n" + ngc + "M2\n")


def test_linuxcnc_gets_no_lone_closing_percent() -> None:
    """The lone '%' ended the source program: M2 ends the LinuxCNC one (``test_program_end.py``)."""
    text, warnings = _translate("G21 G0 X1.\n%\n", "fanuc", "linuxcnc")
    assert text == "G21 G0 X1.\nM2\n(%)\n"
    assert warnings == ["t.nc:2:1: warning: the program ends with '%' and no M2/M30, without an opening '%': "
                        "LinuxCNC refuses a lone '%': M2 written for it, the '%' as a comment"]
    for kept in ("%\nG21 G0 X1.\n%\n", "G21 G0 X1.\nM30\n%\n"):
        assert _translate(kept, "fanuc", "linuxcnc")[0] == kept


# -- the hook ----------------------------------------------------------------------------------------

def test_every_translation_to_grbl_is_checked_and_a_refused_one_is_reported() -> None:
    """The hook sees what a translation writes; here the checker is handed a program grbl refuses through
    the same path (``_check``) and must report it, with the program."""
    output_rules.take_violations()
    before = output_rules.checked["grbl"]
    _translate(f"G21 G0 X0 Y0 Z10.\nG01 X5. F100. ({uuid.uuid4().hex.upper()})\n", "fanuc", "grbl")  # never seen
    assert output_rules.checked["grbl"] == before + 1 and output_rules.take_violations() == []
    from postproc.setup.machine_setup import MachineSetup
    output_rules._check("grbl", "G80 G0 Z1.\n", MachineSetup())
    found = output_rules.take_violations()
    assert len(found) == 1 and "error:21" in found[0] and "G80 G0 Z1." in found[0]



def test_a_program_written_without_translate_is_checked_too() -> None:
    """The hook sits on the writers' ``write``: the conformance suite's generated programs (written from a
    neutral IR, no ``translate``) are held to the rules like translations."""
    from postproc.plugins import default_registry
    from postproc.setup.machine_setup import MachineSetup
    from postproc.testing.neutral import NeutralProgram, write_neutral
    before = output_rules.checked["grbl"]
    y = float(uuid.uuid4().int % 1000)  # a program never seen, so it is checked, not found in the cache
    program = NeutralProgram([("rapid", {"X": 1.0, "Y": y}), ("linear", {"X": 2.0}, 100.0)],
                             start={"X": 0.0, "Y": 0.0, "Z": 10.0})
    written = write_neutral(program.blocks(), default_registry().dialect("grbl"), MachineSetup())
    assert not written.errors and output_rules.checked["grbl"] == before + 1
    assert output_rules.take_violations() == []

