"""The linuxcnc plugin: RS274/NGC lexing, block meaning, lossless round trips, writing, registration.

Expected values are worked out from the RS274/NGC rules (DIALECTS.md §2.1, LinuxCNC's g-code docs)
and, where noted, from what LinuxCNC's interpreter ``rs274`` prints.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest
from lxml import etree

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.ir import Block, Dwell, Motion, SpindleOrientation, ToolLengthOffset
from postproc.plugins import default_registry
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.syntaxes.syntax import load_pipeline
from postproc.simulate.toolpath import toolpath_events
from postproc.xmlio import to_bytes
import postproc_linuxcnc
from postproc_linuxcnc import Linuxcnc
from postproc.rs274.ngc_lexer import lex_block
from tests.support import rs274
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples" / "linuxcnc").glob("*.ngc"))


def read(text: str, setup: MachineSetup | None = None) -> list[Block]:
    return read_program(io.StringIO(text, newline=""), file="t.ngc", dialect="linuxcnc", setup=setup)


def errors(text: str) -> list[str]:
    with pytest.raises(ErrorList) as info:
        read(text)
    return [str(e) for e in info.value.errors]


def events(text: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    lines = io.StringIO(text, newline="")
    return list(toolpath_events(lines, file="t.ngc", dialect="linuxcnc", setup=setup))[1:]


def moves(text: str) -> list[tuple[Any, ...]]:
    return [(e["move"], e["x"], e["y"], e["z"]) for e in events(text) if "move" in e]


def write(text: str, target: str, source: str = "linuxcnc", setup: MachineSetup | None = None,
          on_unsupported: str = "error") -> tuple[str, Diagnostics]:
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text, newline=""), out, file="t.ngc", source=source, target=target, setup=setup,
              on_unsupported=on_unsupported, diagnostics=diagnostics)
    return out.getvalue(), diagnostics


# -- registration ------------------------------------------------------------------------------------

def test_registered_through_its_entry_point_with_its_capabilities() -> None:
    dialect = default_registry().dialect("linuxcnc")
    assert dialect is Linuxcnc
    assert dialect.__module__ == "postproc_linuxcnc"
    caps = dialect.capabilities()
    assert caps["NATIVE_CYCLES"] == sorted(["drill", "drill_dwell", "peck_chip", "peck_deep", "tap", "tap_left",
                                            "bore_feed", "bore_stop", "bore_dwell_feed"])
    assert caps["CYCLE_SEMANTICS"] == "rs274"
    assert not {"fine_bore", "back_bore", "bore_manual"} & set(caps["NATIVE_CYCLES"])


def test_pipeline_xml_loads_and_writes_back_identically() -> None:
    path = Path(postproc_linuxcnc.__file__).with_name("linuxcnc.xml")
    default_registry()
    pipeline = load_pipeline(path)
    assert [type(s).__name__ for s in pipeline.steps] == [
        "LinuxcncProgramSyntax", "PolarSyntax", "NgcBlockSyntax", "CannedCycleResolveSyntax", "ModalStateSyntax"]
    assert pipeline.steps[3].semantics == "rs274"  # type: ignore[attr-defined]
    assert to_bytes(pipeline.make_xml_source()) == to_bytes(etree.fromstring(path.read_bytes()))


# -- lexing ------------------------------------------------------------------------------------------

def test_semicolon_and_paren_comments_and_letter_case_are_kept() -> None:
    block = lex_block("t.ngc", 1, "g0 X1.5 (move) y2 ; rest (of) line", "\n", "linuxcnc")
    assert block.words == [("g", "0"), ("X", "1.5"), ("y", "2")]
    assert block.sections["Comments"].texts == ["move", " rest (of) line"]  # type: ignore[attr-defined]


def test_blanks_inside_a_number_are_ignored_as_in_rs274() -> None:
    block = lex_block("t.ngc", 1, "G1 X 1 0 . 5 Y-2", "\n", "linuxcnc")
    assert block.words == [("G", "1"), ("X", "10.5"), ("Y", "-2")]


SIGNED_SPELLINGS = [("X -1", -1.0), ("X- 1", -1.0), ("X - 1.5", -1.5), ("x-.5", -0.5), ("X - . 5", -0.5),
                    ("X + 1", 1.0), ("X\t-\t1", -1.0), ("X - 1 0 . 2 5", -10.25)]
"""Blanks around a sign, each with the X that rs274 moves to (``G0 <word>`` prints that X)."""


@pytest.mark.parametrize("word, x", SIGNED_SPELLINGS)
def test_blanks_around_the_sign_are_ignored_as_in_rs274(word: str, x: float) -> None:
    assert moves(f"G21 G90\nG0 {word}\nM2\n") == [("rapid", x, 0, 0)]


def test_blanks_around_the_sign_round_trip_byte_for_byte() -> None:
    text = "".join(f"G0 {word} Y - 2 Z- 3 (c)\r\n" for word, _ in SIGNED_SPELLINGS) + "M2\n"
    assert write(text, "linuxcnc")[0] == text


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_blanks_around_the_sign_as_the_interpreter_reads_them() -> None:
    text = "G21 G90\n" + "".join(f"G0 {word} Y - {n}\n" for n, (word, _) in enumerate(SIGNED_SPELLINGS)) + "M2\n"
    theirs = rs274.canonical_moves(rs274.run_rs274(text), start=(0, 0, 0))
    assert [e for e in events(text) if "move" in e] == [dict(e, line=n + 2) for n, e in enumerate(theirs)
                                                        if "move" in e]


def test_a_long_line_is_lexed_in_linear_time() -> None:
    """Blanks and digits by the ten thousand, each line refused or read in well under a second (the
    backtracking regexes this lexer once had took minutes on these)."""
    import time
    n = 50_000
    for line in ("G0 X-" + " " * n + "Y", "G0 X" + " " * n + "-" + " " * n + "Y", "G0 X" + "1" * n + "!",
                 "G0 X " + "1 " * n + ". Y"):
        start = time.perf_counter()
        with pytest.raises(ErrorList):
            read(line + "\n")
        assert time.perf_counter() - start < 1.0, line[:10]


@pytest.mark.parametrize("text, message", [
    ("G0 X -", "t.ngc:1:4: error: malformed word 'X -'"),
    ("G0 X -.", "t.ngc:1:4: error: malformed word 'X -'"),
    ("G0 X .-5", "t.ngc:1:4: error: malformed word 'X .'"),
    ("G0 X 1 - 2", "t.ngc:1:8: error: number without an address at '-'"),
    ("G0 X1 (a (b) c)", "t.ngc:1:10: error: nested comment: '(' inside a comment"),
    ("G0 X1 (open", "t.ngc:1:7: error: unclosed comment"),
    ("o100 foo", "t.ngc:1:6: error: unknown o-word command 'foo'"),
    ("N10 o<x>", "t.ngc:1:5: error: a bare o-word starts a Fanuc-style subprogram and takes a number, not a "
                 "name or an expression"),
    ("G0 X1 o100 sub", "t.ngc:1:7: error: an o-word opens its line (only '/' and N may come before it)"),
    ("G0 X#", "t.ngc:1:6: error: variable number expected after '#'"),
    ("G0 X[1+2", "t.ngc:1:9: error: ']' expected"),
    ("G0 X1+#2", "t.ngc:1:6: error: number without an address at '+#2'"),
    ("#1=1+2", "t.ngc:1:5: error: LinuxCNC reads one value after '=': bracket an expression, #1=[#2+1]"),
    ("G0 X FOO[1]", "t.ngc:1:4: error: address X needs a value"),
    ("G0 X", "t.ngc:1:4: error: address X needs a value"),
    ("G0 X1 %", "t.ngc:1:7: error: '%' must stand alone on its line"),
])
def test_lexical_errors_are_located(text: str, message: str) -> None:
    assert errors(text + "\n") == [message]


@pytest.mark.parametrize("text, line", [("%\nG0 X1\n% (end)\n", 3), ("%;x\nG0 X1\nM2\n", 1), ("%(a @)\nM2\n", 1)])
def test_a_percent_with_a_comment_beside_it_is_refused(text: str, line: int) -> None:
    """rs274 refuses ``% (end)`` ("Bad character '%' used" [V: rs274 2.9 run here]); it was read as a tape mark,
    and a translation wrote ``%``, exit 0."""
    assert errors(text)[0] == (f"t.ngc:{line}:1: error: '%' must stand alone on its line: no comment beside it "
                               "(LinuxCNC: \"Bad character '%' used\")")


def test_block_delete_and_percent_lines() -> None:
    blocks = read("%\n/G0 X1 Y2 Z3\n%\n")
    assert "TapeMark" in blocks[0].sections and "TapeMark" in blocks[2].sections
    assert blocks[1].sections["BlockDelete"].level == 1  # type: ignore[attr-defined]


# -- meaning -----------------------------------------------------------------------------------------

def test_numbers_mean_what_they_say() -> None:
    """X10 is 10 mm in RS274/NGC; on a Fanuc control with default input it is 0.010 mm."""
    block = read("G21 G0 X10 Y.5 Z-2\n")[0]
    assert block.sections["Motion"] == Motion("rapid", {"X": 10.0, "Y": 0.5, "Z": -2.0})


UNIT_FEEDS = ("G21 G90 G94\nG0 X0 Y0 Z0\nG1 X10 F100\nG20 F10 G1 X1\nG1 X2\nG21 F5 G1 X30\nG1 X40\n"
              "G20 G1 X2 F10\nM2\n")
"""F in blocks that change units (rs274 prints ``SET_FEED_RATE(10.0000)`` before
``USE_LENGTH_UNITS(CANON_UNITS_INCHES)``: LinuxCNC sets the feed first, in the old units)."""


def test_f_in_a_block_that_changes_units_is_in_the_old_units() -> None:
    """G20 F10 after G21 is 10 mm/min, G21 F5 after G20 is 5 in/min = 127 mm/min; the rate then
    holds across the next blocks (not 25.4 times too fast or too slow)."""
    assert [e["f"] for e in events(UNIT_FEEDS) if "move" in e] == [100, 10, 10, 127, 127, 10]
    inverse_time = "G21 G90 G93\nG0 X0 Y0 Z0\nG20 G1 X1 F10\nM2\n"  # F is 1/min: no length to convert
    assert [e["f"] for e in events(inverse_time) if "move" in e] == [10]


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_f_in_a_block_that_changes_units_as_the_interpreter_reads_it() -> None:
    ours = [(e["move"], e["x"], e["z"], e.get("f")) for e in events(UNIT_FEEDS) if "move" in e]
    theirs = [(e["move"], e["x"], e["z"], e.get("f"))
              for e in rs274.canonical_moves(rs274.run_rs274(UNIT_FEEDS), start=(0, 0, 0), feeds=True)
              if "move" in e]
    assert ours == theirs


def test_f_in_a_block_that_changes_units_is_written_in_the_old_units() -> None:
    """Fanuc (and grbl) read that F in the new units; LinuxCNC gets it in the old ones, both ways,
    except an inverse-time F, which is no length."""
    fanuc = "G21 G90 G94\nG0 X0. Y0. Z0.\nG20 F10. G1 X1.\nG21 F5. G1 X30.\nM2\n"
    text, _ = write(fanuc, "linuxcnc", source="fanuc")
    assert "G20 G1 X1. F254.\n" in text and "G21 G1 X30. F0.19685039\n" in text
    assert [e["f"] for e in events(text) if "move" in e] == [254, pytest.approx(5, abs=1e-4)]
    text, _ = write(UNIT_FEEDS, "fanuc")
    assert "G20 G01 X1. F0.39370079\n" in text and "G21 G01 X30. F127.\n" in text
    text, _ = write("G21 G90 G93\nG0 X0 Y0 Z0\nG20 G1 X1 F10\nM2\n", "linuxcnc", source="grbl")
    assert "G20 G1 X1. F10.\n" in text


def test_dwell_p_is_seconds() -> None:
    assert read("G4 P0.5\n")[0].sections["Dwell"] == Dwell(0.5)
    assert read("G4 P2\n")[0].sections["Dwell"] == Dwell(2.0)
    assert errors("G4\n") == ["t.ngc:1:1: error: G4 needs a dwell time P (seconds)"]


def test_g80_leaves_no_motion_mode() -> None:
    """rs274: "Cannot use axis values without a g code that uses them"."""
    assert errors("G21 G0 X0 Y0 Z10\nG81 X1 Y1 Z-1 R1 F100\nG80\nX5\n") == [
        "t.ngc:4:1: error: axis words with no motion mode in force (G80 cancels it: program G0 or G1)"]
    assert moves("G21 G0 X0 Y0 Z10\nG80\nG1 X5 F100\nY5\n")[-1] == ("feed", 5, 5, 10)


@pytest.mark.parametrize("text, message", [
    ("G81 X1 Y1 Z-1 R1 K2 F100", "t.ngc:2:18: error: K in a drilling cycle: LinuxCNC counts repeats with L"),
    ("G91 G81 X1 Y1 Z-1 R-1 L0 F100",
     "t.ngc:2:23: error: a canned cycle cannot repeat zero times (L must be 1 or more)"),
    ("G1 X1 L2 F100", "t.ngc:2:7: error: L (repeat count) outside a canned cycle"),
    ("G0 G81 X1 Y1 Z-1 R1 F100", "t.ngc:2:4: error: G codes G0 and G81 are both in one modal group"),
    ("M5 M19", "t.ngc:2:4: error: M codes M5 and M19 are both in one modal group (LinuxCNC runs one of each "
               "group per block)"),
    ("G0 N10 X1", "t.ngc:2:4: error: a block number stands first in its block (LinuxCNC refuses N elsewhere)"),
    ("G1", "t.ngc:2:1: error: G1 with no feed rate in force (program F first)"),
    ("M98 L2", "t.ngc:2:1: error: M98 needs a program number P (rs274: Found 'm98' code with no P-word)"),
    ("G90.1 G2 X1 Y1 I1 F9", "t.ngc:2:1: error: J word missing in an absolute centre arc (G90.1 gives both centre "
                             "coordinates of the plane)"),
    ("G33.1 Z-1", "t.ngc:2:1: error: G33.1 needs K, the distance per spindle revolution"),
    ("G33.1 K1", "t.ngc:2:1: error: G33.1 needs an axis word (the end point of the tap)"),
    ("G10 L1 Z1 R1", "t.ngc:2:1: error: G10 L1 needs the tool number it sets (P1 or more)"),
    ("G44 H1", "t.ngc:2:1: error: unknown G code G44"),
    ("G0 X1 E2", "t.ngc:2:7: error: address E has no meaning in this block"),  # E is G76's taper on a lathe
])
def test_rs274_rules_refuse_with_a_located_error(text: str, message: str) -> None:
    assert errors("G21 G0 X0 Y0 Z10\n" + text + "\n") == [message]


def test_g53_moves_in_the_mode_in_force_which_must_be_g0_or_g1() -> None:
    """rs274: G53 G1 feeds; G53 after G2 is "Must use g0 or g1 with g53"."""
    assert moves("G21 G0 X0 Y0 Z0\nG53 G1 X5 F100\nG53 X7\n") == [("feed", 5, 0, 0), ("feed", 7, 0, 0)]
    assert errors("G21 G0 X0 Y0 Z0\nG2 X2 Y0 I1 J0 F100\nG53 X3\n") == [
        "t.ngc:3:1: error: G53 needs G0 or G1 in force"]


def test_g43_without_h_uses_the_tool_in_the_spindle() -> None:
    blocks = read("T3 M6\nG43 G0 Z10\n")
    assert blocks[1].sections["ToolLengthOffset"] == ToolLengthOffset("positive", 3)
    # [V] rs274: T1 M6 T2 G43 applies tool 1 (the loaded one), not the selected T2; T2 M6 G43 in one block
    # changes the tool first
    assert read("T1 M6\nT2\nG43\n")[2].sections["ToolLengthOffset"] == ToolLengthOffset("positive", 1)
    assert read("T1 M6\nT2 M6 G43\n")[1].sections["ToolLengthOffset"] == ToolLengthOffset("positive", 2)
    assert errors("T2\nG43 G0 Z10\n") == [
        "t.ngc:2:1: error: G43 without H uses the loaded tool, which is not known here: program H"]


def test_m19_takes_its_angle_from_r() -> None:
    assert read("M19 R45\n")[0].sections["SpindleOrientation"] == SpindleOrientation(45.0)


@pytest.mark.parametrize("text, what", [
    ("G10 L1 P1 A1 Z2", "G10 (set offsets (G10 L))"),  # (X and Y are modelled: an A offset is not)
    ("G76 P0.05 Z-1 I-0.075 J0.008 K0.045", "G76 (threading cycle)"),
    ("G87 X1 Y1 Z-1 R1 I0.5 J0 K0.5 F10", "G87 (RS274/NGC back boring (I/J shift, K top))"),
    ("M62 P1", "M62 (digital output on, synchronised)"),
])
def test_codes_without_neutral_meaning_travel_verbatim(text: str, what: str) -> None:
    block = read(text + "\n")[0]
    native = block.sections["NativeCode"]
    assert native.dialect == "linuxcnc" and native.what == what  # type: ignore[attr-defined]
    assert write(text + "\n", "linuxcnc")[0] == text + "\n"
    with pytest.raises(ErrorList, match="has no equivalent in fanuc"):
        write(text + "\n", "fanuc")


# -- cycles under RS274/NGC rules ------------------------------------------------------------------

def test_the_interpreter_starts_in_g99_and_a_modal_g98_returns_to_the_first_old_z() -> None:
    """As rs274 prints it: without G98/G99 the first hole returns to R; a G98 block continuing the same
    cycle returns to the Z the cycle started from (10), not to the R where the tool stands."""
    program = "G21 G0 X0 Y0 Z10\nG81 X1 Y1 Z-1 R1 F100\nG98 G81 X2 Y1 Z-1 R1\nM2\n"
    assert moves(program) == [
        ("rapid", 0, 0, 10),
        ("rapid", 1, 1, 10), ("rapid", 1, 1, 1), ("feed", 1, 1, -1), ("rapid", 1, 1, 1),
        ("rapid", 2, 1, 10), ("rapid", 2, 1, 1), ("feed", 2, 1, -1), ("rapid", 2, 1, 10),
    ]


def test_g98_returns_to_r_when_the_old_z_is_below_it() -> None:
    assert moves("G21 G0 X0 Y0 Z2\nG98 G81 X1 Y1 Z-1 R3 F100\nM2\n") == [
        ("rapid", 0, 0, 2), ("rapid", 0, 0, 3), ("rapid", 1, 1, 3), ("feed", 1, 1, -1), ("rapid", 1, 1, 3)]


def test_start_below_r_rises_to_r_first() -> None:
    assert moves("G21 G0 X0 Y0 Z0\nG81 X1 Y1 Z-3 R2 F100\nM2\n") == [
        ("rapid", 0, 0, 2), ("rapid", 1, 1, 2), ("feed", 1, 1, -3), ("rapid", 1, 1, 2)]


def test_peck_clearances_are_the_interpreter_constant_whatever_the_setup() -> None:
    """rs274 prints the G83 re-approach 0.254 mm above the last bottom (0.010 in)."""
    setup = MachineSetup(cycles=CycleSettings(peck_retract=1.0, peck_clearance=1.0))
    got = [e for e in events("G21 G0 X0 Y0 Z5\nG83 X0 Y0 Z-2 R1 Q1 F100\nM2\n", setup) if "move" in e]
    assert [e["z"] for e in got] == [5, 1, 0, 1, 0.254, -1, 1, -0.746, -2, 1]
    assert setup.cycles.peck_clearance == 1.0  # the caller's set-up is left alone


def test_cycle_dwell_p_is_seconds_and_l_repeats_a_row() -> None:
    got = events("G21 G0 X0 Y0 Z5\nG91 G82 X2 Y0 Z-3 R-4 P1.5 L2 F100\nM2\n")
    assert [e["seconds"] for e in got if e.get("event") == "dwell"] == [1.5, 1.5]
    assert [(e["x"], e["z"]) for e in got if e.get("move") == "feed"] == [(2, -2), (4, -2)]


# -- round trips and writing ------------------------------------------------------------------------

@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_examples_round_trip_byte_for_byte(cli: Any, tmp_path: Path, path: Path) -> None:
    out = tmp_path / path.name
    result = cli("translate", path, "--from", "linuxcnc", "--to", "linuxcnc", "-o", out)
    assert result.status == 0, result.err
    assert out.read_bytes() == path.read_bytes()


def test_examples_exist_and_simulate() -> None:
    assert len(EXAMPLES) >= 2
    for path in EXAMPLES:
        with open(path, encoding="utf-8", newline="") as src:
            got = list(toolpath_events(src, file=str(path), dialect="linuxcnc", setup=with_tools()))
        assert any(e.get("move") == "feed" for e in got), path


@pytest.mark.parametrize("fanuc, linuxcnc", [
    ("G04 X1.5\n", "G4 P1.5\n"),
    ("G04 P250\n", "G4 P0.25\n"),
    ("G55 G00 X1. Y2.\n", "G55 G0 X1. Y2.\n"),
    ("M19\n", "M19 R0.\n"),
    ("O1234 (PART)\n", "(O1234) (PART)\n"),
    ("G91 G28 Z0.\n", "G91 G28 Z0.\n"),
    ("G43 H02 Z50.\n", "G43 H02 G0 Z50.\n"),
])
def test_fanuc_blocks_in_linuxcnc_spelling(fanuc: str, linuxcnc: str) -> None:
    """Every expected line was checked to run in LinuxCNC's interpreter (the fragment has no end: M2)."""
    prefix = "G21 G00 X0. Y0. Z10.\n"
    text, _ = write(prefix + fanuc, "linuxcnc", source="fanuc")
    assert text == "G21 G0 X0. Y0. Z10.\n" + linuxcnc + "M2\n"


@pytest.mark.parametrize("fanuc, message", [
    ("G44 H01 Z5.\n", "t.ngc:2:1: error: the linuxcnc dialect cannot express tool length offset negative"),
    # (G09: written as G61 for its block, tests/test_linuxcnc_exact_stop.py)
    ("/2 G00 X5.\n", "t.ngc:2:1: error: the linuxcnc dialect cannot express block delete level 2 (LinuxCNC has "
                     "one block delete switch)"),
])
def test_what_linuxcnc_lacks_is_a_located_error(fanuc: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        write("G21 G00 X0. Y0. Z10.\n" + fanuc, "linuxcnc", source="fanuc")
    assert [str(e) for e in info.value.errors] == [message]


def test_fanuc_cycles_are_expanded_exactly_for_linuxcnc() -> None:
    """Fanuc's G98 after G99 returns to the first level; LinuxCNC's would not: the motion is written out."""
    text, _ = write("G21 G17 G90\nG00 X0. Y0. Z50.\nG99 G81 X10. Y10. Z-5. R2. F100.\nG98 X20.\nG80\nM30\n",
                    "linuxcnc", source="fanuc")
    code = [line for line in text.splitlines() if not line.startswith("(")]
    assert not any("G81" in line for line in code), text
    # the G98 hole returns to the initial level 50
    assert code[code.index("G0 X20. Y10. Z2."):][:3] == ["G0 X20. Y10. Z2.", "G1 Z-5.", "G0 Z50."], text


def test_linuxcnc_native_cycles_stay_native_when_generated() -> None:
    block_text = "G98 G82 X1 Y1 Z-1 R1 P0.5 F100"
    text, _ = write(f"G21 G0 X0 Y0 Z10\n{block_text}\nM2\n", "linuxcnc", setup=MachineSetup())
    assert text.splitlines()[1] == block_text


def test_an_orientation_angle_is_not_lost_on_the_way_to_fanuc() -> None:
    """Fanuc's M19 orients to the angle its parameters hold (the set-up's orientAngle)."""
    with pytest.raises(ErrorList, match="oriented spindle stop at 90 deg"):
        write("G21 G0 X0 Y0 Z10\nM19 R90\nM2\n", "fanuc")
    text, _ = write("G21 G0 X0 Y0 Z10\nM19 R0\nM2\n", "fanuc")
    assert "M19" in text


@pytest.mark.parametrize("source", ["fanuc", "isg"])
def test_a_feed_move_per_revolution_without_a_spindle_speed_is_refused(source: str) -> None:
    """rs274 refuses G1 under G95 while S is zero, even a G1 that only selects the mode (found by the
    fuzz suite: ``G01 G95 F0.3`` with no S before it was written as ``G95 G1 F0.3``)."""
    with pytest.raises(ErrorList, match=r"t\.ngc:2:1: error: .*feed per revolution \(G95\) with no spindle speed"):
        write("G90 G0 X0. Y0. Z10.\nG01 G95 F0.3\nX5.\n", "linuxcnc", source=source)


def test_a_feed_move_per_revolution_after_a_spindle_speed_is_written() -> None:
    text, _ = write("G21 G90 G0 X0. Y0. Z10.\nS500 M03\nG01 G95 F0.3\nX5.\nG94 F100.\nS0\nX6.\n", "linuxcnc",
                    source="fanuc")
    assert text.splitlines()[2:5] == ["G95 G1 F0.3", "G1 X5.", "G94 F100."], text


# -- negative tool numbers, registers and repeat counts ---------------------------------------------------------

@pytest.mark.parametrize("block, col", [("T-1 M6", 1), ("G43 H-1", 5), ("G41 D-1 G1 X10 F100", 5),
                                         ("G81 X1 Y1 Z-1 R1 L-1 F100", 18)])
def test_a_negative_tool_register_or_count_is_refused_as_rs274_refuses_it(block: str, col: int) -> None:
    text = f"G21 G0 X0 Y0 Z10\n{block}\nM2\n"
    if rs274.available():
        with pytest.raises(rs274.RS274Error):
            rs274.run_rs274(text, tool_table="T1 P1 D0.1 Z0 ;\n")
    found = errors(text)
    assert len(found) == 1 and found[0].startswith(f"t.ngc:2:{col}: error: "), found
    assert "cannot be negative" in found[0], found
