"""The grbl plugin: what grbl 1.1 accepts (grbl/gcode.c), how Fanuc constructs are written for it, what
is refused with a located error, and the grbl reader that ``verify`` relies on.

Expected texts were written by hand from grbl 1.1's parser rules (see ``postproc_grbl``'s docstring).
"""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.ir import ToolChange
from postproc.plugins import default_registry
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from postproc_grbl import Grbl
from tests.support.tools import with_tools

HEAD = "G21 G00 X0. Y0. Z10.\n"
"""Every Fanuc snippet starts here; it is written for grbl as ``GRBL_HEAD``."""
GRBL_HEAD = "G21 G0 X0. Y0. Z10.\n"


def to_grbl(fanuc: str, setup: MachineSetup | None = None, on_unsupported: str = "error") -> tuple[str, list[str]]:
    """Translate ``HEAD + fanuc``; returns the text after the head line and the warnings."""
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(HEAD + fanuc, newline=""), out, file="t.nc", source="fanuc", target="grbl",
              setup=setup, on_unsupported=on_unsupported, diagnostics=diagnostics)
    text = out.getvalue()
    assert text.startswith(GRBL_HEAD), text
    return text[len(GRBL_HEAD):], [str(w) for w in diagnostics.warnings]


def grbl_errors(fanuc: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        to_grbl(fanuc, setup)
    return [str(e) for e in info.value.errors]


def grbl_events(text: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    return list(toolpath_events(io.StringIO(text, newline=""), file="t.gcode", dialect="grbl", setup=setup))[1:]


def orientation(mode: str) -> MachineSetup:
    return MachineSetup(cycles=CycleSettings(orientation=mode))


# -- the dialect -------------------------------------------------------------------------------------

def test_registered_through_its_entry_point_as_a_grbl_class_controller() -> None:
    dialect = default_registry().dialect("grbl")
    assert dialect is Grbl and dialect.__module__ == "postproc_grbl"
    caps = dialect.capabilities()
    assert caps["NATIVE_CYCLES"] == []
    assert caps["SPINDLE_ORIENTATION"] is False
    assert caps["TOOL_LENGTH_OFFSET"] is False
    assert caps["DWELL_UNIT"] == "seconds"


# -- writing -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("fanuc, grbl", [
    ("G01 X10. Y5. F200.\n", "G1 X10. Y5. F200.\n"),
    ("G04 X1.5\n", "G4 P1.5\n"),
    ("G04 P250\n", "G4 P0.25\n"),
    ("G02 X10. Y0. R5. F100.\n", "G2 X10. Y0. I5. J0. F100.\n"),  # a semicircle: by its centre, the midpoint
    ("G91 G28 Z0.\n", "G91 G28 Z0.\n"),
    ("G55 G17 G40 G80\n", "G17 G55 G40\n"),  # grbl's G80 would leave no motion mode; no cycle to cancel
    ("S1200 M04\nM08\nM09 M05\n", "S1200 M4\nM8\nM5 M9\n"),
    ("G98 G00 X5.\nG99\n", "G0 X5.\n(G99)\n"),  # G99 means nothing to grbl: a comment, not an empty line
    ("G64 G01 X5. F100.\n", "G1 X5. F100.\n"),
    ("M01\nM30\n", "M1\nM30\n"),
    ("G49 G00 Z50.\n", "G49\nG0 Z50.\n"),
])
def test_fanuc_blocks_in_grbl_spelling(fanuc: str, grbl: str) -> None:
    assert to_grbl(fanuc)[0] == grbl


def test_program_number_and_percent_become_comments() -> None:
    """grbl's parser rejects '%' and the letter O."""
    out = io.StringIO(newline="")
    translate(io.StringIO("%\nO1001 (PLATE)\nG00 X1.\n%\n", newline=""), out, file="t.nc", source="fanuc",
              target="grbl")
    assert out.getvalue() == "(%)\n(O1001) (PLATE)\nG21 G0 X1.\n(%)\n"  # G21: tests/test_units_at_start.py


def test_a_full_circle_gets_an_end_point_in_its_plane() -> None:
    """grbl refuses an arc without an in-plane axis word (no full-circle form): a zero increment in G91."""
    assert to_grbl("G03 I-7. F100.\n")[0] == "G91 G3 X0. I-7. F100.\nG90\n"
    assert to_grbl("G91 G02 J5. F100.\nG90\n")[0] == "G91 G2 X0. J5. F100.\nG90\n"
    assert to_grbl("G18 G03 K-3. F100.\n")[0] == "G18 G91 G3 Z0. K-3. F100.\nG90\n"


def test_a_tool_change_is_a_pause_that_reads_back_as_a_tool_change() -> None:
    text, warnings = to_grbl("T4 M06\nS100 M03\nT5\nM06\n")
    assert text == ("T4 M0 (TOOL CHANGE: LOAD T4, THEN CYCLE START)\nS100 M3\nT5\n"
                    "T5 M5 M0 (TOOL CHANGE: LOAD T5, THEN CYCLE START)\n")
    assert warnings == ["t.nc:5:1: warning: the spindle is running at a tool change: a spindle stop is written before the pause"]
    blocks = read_program(io.StringIO(GRBL_HEAD + text), file="t.gcode", dialect="grbl")
    assert isinstance(blocks[1].sections.get("ToolChange"), ToolChange)
    assert "ProgramControl" not in blocks[1].sections
    assert [e for e in grbl_events(GRBL_HEAD + text) if e.get("event") == "tool"] == [
        {"line": 2, "event": "tool", "number": 4}, {"line": 5, "event": "tool", "number": 5}]


def test_a_plain_pause_stays_a_pause() -> None:
    assert [e.get("event") for e in grbl_events("G21\nM0\nM30\n")] == ["stop", "end"]


# -- what grbl cannot express ------------------------------------------------------------------------

@pytest.mark.parametrize("fanuc, message", [
    ("G43 H01 Z50.\n", "t.nc:2:5: error: the set-up gives tool length register 1 no value: add <Tool "
                       "number=\"1\" length=\"..\"/> to its <Tools>, or write the register in the program"),
    ("G41 D01 G01 X5. F100.\n", "t.nc:2:1: error: the set-up gives tool radius register 1 no value: add <Tool "
                                "number=\"1\" radius=\"..\"/> to its <Tools>, or write the register in the program"),
    ("M19\n", "t.nc:2:1: error: the grbl dialect cannot express an oriented spindle stop (M19); a set-up with "
              "<Cycles orientation=\"stop\"/> pauses for the operator instead"),
    ("/G04 X3.\n", "t.nc:2:1: error: the grbl dialect cannot express block delete '/' (grbl ignores it: the "
                   "block would always run)"),
    ("S500 M03 G95 G01 X5. F0.1\n", "t.nc:2:1: error: the grbl dialect cannot express feed mode per_rev"),
    ("G31 X1.\n", "t.nc:2:1: error: G31 (skip function) from fanuc has no equivalent in grbl"),
])
def test_unsupported_constructs_are_located_errors(fanuc: str, message: str) -> None:
    assert grbl_errors(fanuc) == [message]


def test_warn_mode_keeps_the_motion_of_a_block_and_comments_the_original() -> None:
    text, warnings = to_grbl("N60 M19 G01 X5. F100. M08\n", on_unsupported="warn")
    assert text == "(UNSUPPORTED LINE 2: N60 M19 G01 X5. F100. M08)\nN60 G1 X5. F100. M8\n"
    assert warnings == ["t.nc:2:1: warning: the grbl dialect cannot express an oriented spindle stop (M19); a set-up "
                        "with <Cycles orientation=\"stop\"/> pauses for the operator instead; dropped; the rest of the "
                        "block is written"]


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
def test_a_one_shot_exact_stop_writes_nothing_and_verifies(target: str) -> None:
    """grbl and grblHAL run one mode, the exact path (gcode.h [V]): a G09 block already ends on its point, so the
    block is written without it (it was refused) and verify finds the same path: (0,0,5) -> X5 at F100 -> X10."""
    fanuc = "G21 G90 G00 X0. Y0. Z5.\nN60 G09 G01 X5. F100. M08\nX10.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(fanuc), out, file="t.nc", source="fanuc", target=target)
    assert out.getvalue().splitlines()[1] == "N60 G1 X5. F100. M8"
    report = verify_lines(io.StringIO(fanuc), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source="fanuc", target=target, setup=None, target_setup=None, tolerance=0.0)
    assert report.ok


def test_fanuc_cutter_compensation_is_the_compensated_path_in_grbl() -> None:
    """Fanuc's rules (start-up type A: square to the next move, here on along +X; cancel square to the last
    move): radius 1 on the left of +X is Y1, then the cancel move to its programmed end."""
    text, warnings = to_grbl("N60 G41 D01 G01 X5. F100. M08\nN70 X10.\nN80 G40 X10. Y-5.\n",
                             with_tools(radii={1: 1.0}), on_unsupported="warn")
    assert text == "N60 G1 X5. Y1. F100. M8\nN70 G1 X10. Y1.\nN80 G1 X10. Y-5.\n" and warnings == []


def test_warn_mode_drops_a_motion_with_the_mode_it_needs() -> None:
    """F0.1 per revolution read as per minute would crawl, or race at another spindle speed: the feed and
    the move go with G95, which grbl lacks; the spindle start stays."""
    text, warnings = to_grbl("S500 M03 G95 G01 X5. F0.1\n", on_unsupported="warn")
    assert text == "(UNSUPPORTED LINE 2: S500 M03 G95 G01 X5. F0.1)\nS500 M3\n"
    assert warnings == ["t.nc:2:1: warning: the grbl dialect cannot express feed mode per_rev; dropped, with F0.1 "
                        "(its feed rate) and X5. (the block's motion), which cannot be written without it; the rest "
                        "of the block is written"]


def test_warn_mode_comments_out_a_block_that_has_no_meaning_left() -> None:
    text, warnings = to_grbl("G31 X1.\nG00 X1.\n", on_unsupported="warn")
    assert text == "(UNSUPPORTED LINE 2: G31 X1.)\nG0 X1.\n"
    assert len(warnings) == 1


# -- canned cycles -----------------------------------------------------------------------------------

def test_drilling_cycles_are_expanded_to_plain_moves() -> None:
    text, _ = to_grbl("G99 G81 X5. Y5. Z-3. R2. F100.\nX10.\nG80\n")
    code = [line for line in text.splitlines() if line and not line.startswith("(")]
    # a hole's first move names every axis, the next ones only the axis they move
    assert code == ["F100.", "G0 X5. Y5. Z10.", "G0 Z2.", "G1 Z-3.", "G0 Z2.",
                    "G0 X10. Y5. Z2.", "G1 Z-3.", "G0 Z2."]
    assert text.splitlines()[-1] == "(G80)"  # no cycle ran: nothing to cancel, the line kept as a comment


def test_cycle_dwell_is_written_in_seconds() -> None:
    text, _ = to_grbl("G82 X5. Y5. Z-3. R2. P500 F100.\nG80\n")
    assert "G4 P0.5" in text.splitlines()


def test_tapping_expands_with_spindle_reversal() -> None:
    text, _ = to_grbl("S500 M03\nG99 G84 X5. Y5. Z-10. R2. F750.\nG80\n")
    code = [line for line in text.splitlines() if line and not line.startswith("(")]
    assert code[code.index("G1 Z-10."):][:4] == ["G1 Z-10.", "M4", "G1 X5. Y5. Z2.", "M3"]


FINE_BORING = "S500 M03\nG98 G76 X5. Y5. Z-10. R2. Q0.5 F80.\nG80\n"


def test_cycles_that_orient_the_spindle_fail_clearly_by_default() -> None:
    messages = grbl_errors(FINE_BORING)
    assert messages == ["t.nc:3:1: error: G76 needs an oriented spindle stop, which the grbl dialect cannot make "
                        "(set <Cycles orientation=\"stop\"/> or \"m19\")"]


def test_orientation_stop_pauses_with_the_spindle_stopped() -> None:
    text, _ = to_grbl(FINE_BORING, orientation("stop"))
    code = [line for line in text.splitlines() if line and not line.startswith("(")]
    at = code.index("G1 Z-10.")
    assert code[at - 1:at + 5] == ["G0 Z2.", "G1 Z-10.", "M5", "M0", "G0 X5.5 Y5. Z-10.", "G0 Z10."]
    assert "M19" not in text


def test_orientation_m19_emits_it_and_the_grbl_reader_accepts_it_on_that_machine() -> None:
    setup = orientation("m19")
    text, _ = to_grbl(FINE_BORING, setup)
    assert "M19" in text.splitlines()
    orient = [e for e in grbl_events(GRBL_HEAD + text, setup) if e.get("event") == "orient"]
    assert orient == [{"line": orient[0]["line"], "event": "orient", "angle": 0}]
    with pytest.raises(ErrorList, match="grbl has no oriented spindle stop"):
        grbl_events(GRBL_HEAD + text)


# -- reading grbl ------------------------------------------------------------------------------------

@pytest.mark.parametrize("text, message", [
    ("G81 X1. Y1. Z-1. R1. F100.", "t.gcode:1:1: error: grbl has no canned cycles (G73-G89, G98/G99): "
                                   "translate the program from a dialect that has them"),
    ("T1 M6", "t.gcode:1:4: error: grbl 1.1 rejects M6 (no tool changer)"),
    ("G43 H1", "t.gcode:1:1: error: grbl has no tool table: G43 is not supported (grbl's G43.1 takes the "
               "offset itself)"),
    ("G1 X1. Q2. F100.", "t.gcode:1:8: error: address Q is not used by the grbl dialect"),
    ("M19", "t.gcode:1:1: error: grbl has no oriented spindle stop (M19); a set-up with "
            "<Cycles orientation=\"m19\"/> accepts it"),
])
def test_the_grbl_reader_refuses_what_grbl_refuses(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        read_program(io.StringIO(text + "\n"), file="t.gcode", dialect="grbl")
    assert [str(e) for e in info.value.errors] == [message]


def test_the_grbl_reader_follows_rs274_numbers_and_dwell_seconds() -> None:
    got = grbl_events("G21 G0 X10 Y0 Z5 ; no decimal point needed\nG4 P0.5\nG1 Z-1 F100\nM30\n")
    assert got == [{"line": 1, "move": "rapid", "x": 10, "y": 0, "z": 5},
                   {"line": 2, "event": "dwell", "seconds": 0.5},
                   {"line": 3, "move": "feed", "x": 10, "y": 0, "z": -1, "f": 100},
                   {"line": 4, "event": "end"}]


def test_f_in_a_unit_changing_block_is_in_the_new_units() -> None:
    """grbl converts F by the block's own G20/G21 (gcode.c, "Set feed rate"), unlike LinuxCNC."""
    feeds = [e["f"] for e in grbl_events("G21 G90 G94\nG0 X0 Y0 Z0\nG20 F10 G1 X1\nG21 F127 G1 X60\n")
             if "move" in e]
    assert feeds == [254, 127]


def test_written_text_is_checked_for_every_character_grbl_acts_on() -> None:
    """``_plain_ascii`` (a byte translation) says what ``_REALTIME`` says, for every character in a line."""
    from postproc_grbl.text import _REALTIME, plain_ascii as _plain_ascii
    for code in range(0x180):
        text = f"G1 X1.\n(A{chr(code)}B)\r\n"
        assert _plain_ascii(text) == (text.isascii() and not _REALTIME.search(text)), hex(code)
