"""grblHAL as a target and a reader (``plugins/grblhal``, issue 29 item 4).

Expected texts and toolpaths are written by hand from grblHAL's source (github.com/grblHAL/core, stored commit
f80fc34): ``gcode.c`` (which codes a build accepts, what a cycle block needs), ``motion_control.c``
``mc_canned_drill`` (how G81/G82 move), ``protocol.h`` (the line buffer); each case names its rule. rs274 is
the oracle where grblHAL's G81/G82 mean what LinuxCNC's do, with the one difference (G98's level) refused.
"""

from __future__ import annotations

import io
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.plugins import default_registry
from postproc.setup.groups import ControllerSettings

from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parents[1]
HEAD = "G21 G00 X0. Y0. Z10.\n"
"""Every Fanuc snippet starts here; it is written for grblHAL as ``OUT_HEAD``."""
OUT_HEAD = "G21 G0 X0. Y0. Z10.\n"
TABLE = MachineSetup(controller=ControllerSettings(tool_table=True))
"""A grblHAL build with a tool table (``N_TOOLS`` > 0)."""


def to_grblhal(fanuc: str, setup: MachineSetup | None = None, source: str = "fanuc", head: str = HEAD) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(head + fanuc, newline=""), out, file="t.nc", source=source, target="grblhal",
              setup=setup, diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    text = out.getvalue()
    assert text.startswith(OUT_HEAD), text
    return text[len(OUT_HEAD):]


def errors_of(run: Any) -> list[str]:
    with pytest.raises(ErrorList) as info:
        run()
    return [str(e) for e in info.value.errors]


def events(text: str, setup: MachineSetup | None = None, dialect: str = "grblhal") -> list[dict[str, Any]]:
    return list(toolpath_events(io.StringIO(text, newline=""), file="t.gcode", dialect=dialect, setup=setup))[1:]


def moves(evs: list[dict[str, Any]]) -> list[tuple[Any, ...]]:
    return [(e["move"], e["x"], e["y"], e["z"]) if "move" in e else ("dwell", e["seconds"])
            for e in evs if "move" in e or e.get("event") == "dwell"]


# -- the dialect -------------------------------------------------------------------------------------

def test_registered_through_its_own_entry_point_on_the_grbl_family_base() -> None:
    from postproc.grbl_family.dialect import GrblFamily
    dialect = default_registry().dialect("grblhal")
    assert dialect.__module__ == "postproc_grblhal" and issubclass(dialect, GrblFamily)
    assert dialect.NATIVE_CYCLES == frozenset({"drill", "drill_dwell"})
    assert not dialect.tool_table(MachineSetup()) and dialect.tool_table(TABLE)


# -- cycles kept native where grblHAL moves as the source ---------------------------------------------

@pytest.mark.parametrize("fanuc, expected", [
    # G99 from the initial level: grblHAL rapids to X/Y at Z10, down to R, feeds, returns to R; the repeat
    # at X20 starts at R (mc_canned_drill), as Fanuc's does. G80 with a cycle in force: G0 (a bare G0
    # ends the cycle and moves nothing; G80 would leave no motion mode for the G0 Z50. after it... it
    # has one, but a later G43.1 Z would not: error 31).
    ("G99 G81 X10. Y10. Z-5. R2. F100.\nX20.\nG80\nG00 Z50.\nM30\n",
     "G99 G81 X10. Y10. Z-5. R2. F100.\nX20.\nG0\nG0 Z50.\nM30\n"),
    # Fanuc's dwell P in milliseconds is grblHAL's P in seconds (gcode.c: canned.dwell = P, mc_dwell(s))
    ("G98 G82 X10. Y10. Z-5. R2. P500 F100.\nY20.\nG80\nM30\n",
     "G98 G82 X10. Y10. Z-5. R2. P0.5 F100.\nY20.\nG0\nM30\n"),
    # Fanuc's K repeats are grblHAL's L (gcode.c: values.l, L <= 0 an error); in G90 the same hole again
    ("G98 G81 X10. Y10. Z-5. R2. K3 F100.\nG80\nM30\n", "G98 G81 X10. Y10. Z-5. R2. L3 F100.\nG0\nM30\n"),
    # a new cycle code needs R and Z again in grblHAL (canned_cycle_change), G82 its P: added from the
    # values Fanuc carried over
    ("G99 G81 X10. Y10. Z-5. R2. F100.\nG82 X20. P250\nG80\nM30\n",
     "G99 G81 X10. Y10. Z-5. R2. F100.\nG82 X20. Z-5. R2. P0.25\nG0\nM30\n"),
    # a cancel beside G28's axis words stands alone first: a bare G0 there would conflict with G28 (error 37)
    ("G99 G81 X10. Y10. Z-5. R2. F100.\nG80 G28 Z10.\nM30\n", "G99 G81 X10. Y10. Z-5. R2. F100.\nG0\nG28 Z10.\nM30\n"),
    # a motion code ends the cycle on both: nothing to cancel
    ("G99 G81 X10. Y10. Z-5. R2. F100.\nG00 X0.\nM30\n", "G99 G81 X10. Y10. Z-5. R2. F100.\nG0 X0.\nM30\n"),
])
def test_cycles_that_move_alike_stay_native(fanuc: str, expected: str) -> None:
    assert to_grblhal(fanuc) == expected


def test_a_cancel_back_to_an_arc_mode_is_a_bare_g0() -> None:
    """A cycle programmed under G2/G3 returns to that mode, but grblHAL refuses a bare G2 (no axis words,
    error 26 [V: gcode.c, as grbl's]): the cancel is a bare G0, and the moves after it carry their own code
    (found by make fuzz: a LinuxCNC full circle, G82, G80 written as a bare G2, exit 0). The G82 has no G98/G99:
    LinuxCNC's own default level is written with it (it retracted to R in the source, to Z10 on grblHAL)."""
    program = "G2 X0 Y0 I2 F100\nG82 X10 Y10 Z-2.5 R2 P0.5\nG80\nG0 X5\nM2\n"
    text = to_grblhal(program, source="linuxcnc", head="G21 G0 X0 Y0 Z10\n")
    lines = text.splitlines()
    assert "G2" not in lines and lines[lines.index("G0 X5.") - 1] == "G0", text
    assert "G99 G82 X10. Y10. Z-2.5 R2. P0.5" in lines, text
    report = verify_lines(io.StringIO("G21 G0 X0 Y0 Z10\n" + program, newline=""), io.StringIO(OUT_HEAD + text),
                          file_in="t.ngc", file_out="t.gcode", source="linuxcnc", target="grblhal")
    assert report.ok, report.summary()


def test_a_straight_move_of_the_fast_lane_ends_the_cycle_too() -> None:
    """A motion code ends a native cycle on grblHAL [V: ``gcode.c``]: a straight block the fast lane writes
    (``postproc.fast``, ``GrblhalWriter.after_block``) as a block the section dispatch writes, so the G80 after
    it has no cycle to cancel (its source as a trace), and the G80 of a cycle still in force is a bare G0."""
    text = to_grblhal("G99 G81 X10. Y10. Z-5. R2. F100.\nG00 X0.\nG80\nG81 X10. Y10. Z-5. R2.\nX20.\nG80\nM30\n")
    assert text == ("G99 G81 X10. Y10. Z-5. R2. F100.\nG0 X0.\n(G80)\nG81 X10. Y10. Z-5. R2.\nX20.\nG0\n"
                    "M30\n")


@pytest.mark.parametrize("fanuc, line", [
    # the tool below R: Fanuc positions at its level, grblHAL rises to R first
    ("G00 Z1.\nG98 G81 X10. Y10. Z-5. R2. F100.\nG80\nM30\n", 3),
    # G98 after G99 holes: Fanuc returns to the initial level (10), grblHAL to the level the block starts at (R)
    ("G99 G81 X10. Y10. Z-5. R2. F100.\nG98 X20.\nG80\nM30\n", 3),
    # G91: grblHAL measures R from the block's start level, Fanuc from the initial level (not modelled)
    ("G91 G99 G81 X10. Y10. Z-7. R-8. F100.\nG90 G80\nM30\n", 2),
    # G83 pecks dwell 0.25 s on grblHAL and feed from the retract level; G85 is parsed and not run
    ("G99 G83 X10. Y10. Z-5. R2. Q2. F100.\nG80\nM30\n", 2),
    ("G99 G85 X10. Y10. Z-5. R2. F100.\nG80\nM30\n", 2),
])
def test_cycles_that_would_move_otherwise_are_expanded(fanuc: str, line: str) -> None:
    text = to_grblhal(fanuc)
    assert f"from line {line}:" in text
    after = text[text.index(f"from line {line}:"):]
    written = " ".join(row for row in after.splitlines()[1:] if not row.startswith("("))
    assert not any(code in written.split() for code in ("G81", "G82", "G83", "G85"))


def test_a_cycle_expanded_once_stays_expanded_to_its_cancel() -> None:
    """The expansion's G0/G1 ended the native cycle on grblHAL, so the holes after it are moves too."""
    text = to_grblhal("G99 G81 X10. Y10. Z-5. R2. F100.\nG98 X20.\nX30.\nG80\nM30\n")
    assert text.count("(drill from line") == 2 and text.splitlines()[0] == "G99 G81 X10. Y10. Z-5. R2. F100."


# -- what a build may lack: the set-up says -----------------------------------------------------------

def test_a_length_offset_is_written_from_the_table_where_the_build_has_one() -> None:
    # G43 with G0 in one block: only G43.1 is an axis command in grblHAL (gcode.c, build 20210513)
    assert to_grblhal("G43 H01 Z20.\nM30\n", with_tools(TABLE, lengths={1: 12.5})) == "G43 H01 G0 Z20.\nM30\n"
    # grblHAL has no G44, table or not: the negated length as G43.1, alone (G43.1 is an axis command)
    assert to_grblhal("G44 H01 Z20.\nM30\n", with_tools(TABLE, lengths={1: 12.5})) == "G43.1 Z-12.5\nG0 Z20.\nM30\n"
    # without a table (N_TOOLS 0, the default), grbl's rule: G43.1 with the register's length, alone
    assert to_grblhal("G43 H01 Z20.\nM30\n", with_tools(lengths={1: 12.5})) == "G43.1 Z12.5\nG0 Z20.\nM30\n"


def test_a_dynamic_length_offset_after_a_cycle_is_accepted() -> None:
    """After G80, grblHAL refuses G43.1 Z (axis words with no motion mode, error 31): the cancel is a bare G0,
    so the translation reads back (the reader keeps grblHAL's rule) and moves as the source."""
    fanuc = HEAD + "G99 G81 X10. Y10. Z-5. R2. F100.\nG80\nT2 M06\nG43 H02 Z20.\nG00 X0.\nM30\n"
    setup = with_tools(lengths={2: 7.5})
    out = io.StringIO(newline="")
    translate(io.StringIO(fanuc), out, file="t.nc", source="fanuc", target="grblhal", setup=setup)
    assert "G0\nT2 M6\nG43.1 Z7.5\n" in out.getvalue()
    report = verify_lines(io.StringIO(fanuc), io.StringIO(out.getvalue()), file_in="t.nc", file_out="t.gcode",
                          source="fanuc", target="grblhal", setup=setup, tolerance=0.0)
    assert report.ok, report.mismatch


def test_a_tool_change_is_m6() -> None:
    """M6 is accepted by every build (gcode.c: $341 asks for a manual change or ignores it; an ATC runs it)."""
    assert to_grblhal("T2 M06\nM30\n") == "T2 M6\nM30\n"


def test_feed_per_revolution_needs_a_spindle_encoder() -> None:
    fanuc = "S500 M03\nG95 G01 X5. F0.1\nM30\n"
    assert errors_of(lambda: to_grblhal(fanuc)) == [
        "t.nc:3:1: error: the grblhal dialect cannot express feed per revolution (G95) on a grblHAL spindle "
        "without an encoder: a set-up with <Controller spindleSync=\"true\"/> has one"]
    synced = MachineSetup(controller=ControllerSettings(spindle_sync=True))
    assert to_grblhal(fanuc, synced) == "S500 M3\nG95 G1 X5. F0.1\nM30\n"


def test_a_line_keeps_256_characters() -> None:
    """protocol.h: LINE_BUFFER_SIZE 257, every character but leading blanks counted, comments included."""
    comment = "C" * 200
    assert to_grblhal(f"G01 X5. F100. ({comment})\nM30\n") == f"G1 X5. F100. ({comment})\nM30\n"
    # 415 characters as written, 413 with its numbers shortest (X5, F100): still too many
    assert errors_of(lambda: to_grblhal(f"G01 X5. F100. ({comment * 2})\nM30\n"))[0].startswith(
        "t.nc:2:1: error: the line keeps 413 characters with its spaces and comments, more than the 256 grblHAL holds")


# -- reading grblHAL ----------------------------------------------------------------------------------

@pytest.mark.parametrize("text, message", [
    ("G84 X10 Y10 Z-5 R2 P1 F100\n", "3:1: error: grblHAL's G84 is experimental"),
    ("G99 G83 X10 Y10 Z-5 R2 Q1 F100\nG98 X20\n", "4:1: error: this grblHAL cycle block moves by rules not modelled"),
    ("G85 X10 Y10 Z-5 R2 F100\n", "3:1: error: grblHAL's parser accepts G85, G86 and G89 but its motion control"),
    ("G43 H1\n", "3:1: error: this grblHAL build has no tool table"),
    ("G95 G1 X10 F0.1\n", "3:1: error: this grblHAL build runs no feed per revolution"),
    ("G7\n", "3:1: error: grblHAL runs G7 in lathe mode only ($32, error 20 otherwise)"),
    ("G65 P100\n", "3:1: error: grblHAL's G65 P1-P7 are its inbuilt macros"),
    ("G99 G81 X10 Y10 Z-5 R2 F100\nG98 X20\n", "4:1: error: this grblHAL cycle block moves by rules not modelled"),
    ("#1=5\n", "3:1: error:"),
])
def test_what_grblhal_refuses_or_this_dialect_does_not_model_is_a_located_error(text: str, message: str) -> None:
    found = errors_of(lambda: read_program(io.StringIO("G21 G90\nG0 X0 Y0 Z10\n" + text + "M2\n"),
                                           file="t.gcode", dialect="grblhal"))
    assert found[0].startswith("t.gcode:" + message), found


def test_g81_and_g82_move_as_mc_canned_drill_does() -> None:
    """Hand-derived from motion_control.c: from Z10 (above R), X/Y at Z10, down to R, feed, dwell P s (G82),
    rapid back to R (G99); the G81 after it (a new code: R and Z given again) positions at R and feeds."""
    text = "G21 G90 G17\nG0 X0 Y0 Z10\nG99 G82 X10 Y5 Z-3 R1 P0.2 F50\nG81 X20 Z-4 R1\nG80\nM2\n"
    assert moves(events(text)) == [
        ("rapid", 0, 0, 10),
        ("rapid", 10, 5, 10), ("rapid", 10, 5, 1), ("feed", 10, 5, -3), ("dwell", 0.2), ("rapid", 10, 5, 1),
        ("rapid", 20, 5, 1), ("feed", 20, 5, -4), ("rapid", 20, 5, 1),
    ]


def test_a_g98_block_that_starts_at_its_clear_level_is_read() -> None:
    """G98 from the initial level (every hole starts there): grblHAL's retract level is that level."""
    text = "G21 G90 G17\nG0 X0 Y0 Z10\nG98 G81 X10 Y5 Z-3 R1 F50\nX20\nG80\nM2\n"
    assert moves(events(text)) == [
        ("rapid", 0, 0, 10),
        ("rapid", 10, 5, 10), ("rapid", 10, 5, 1), ("feed", 10, 5, -3), ("rapid", 10, 5, 10),
        ("rapid", 20, 5, 10), ("rapid", 20, 5, 1), ("feed", 20, 5, -3), ("rapid", 20, 5, 10),
    ]


# -- round trips and examples -------------------------------------------------------------------------

EXAMPLES = sorted((ROOT / "tests" / "conformance" / "grblhal").glob("*.*"))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_grblhal_programs_round_trip_byte_for_byte(path: Path) -> None:
    text = path.read_text()
    setup = load_setup(ROOT / "tests" / "support" / "grblhal_expressions.xml")
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file=path.name, source="grblhal", target="grblhal", setup=setup)
    assert out.getvalue() == text


FANUC_WITH_CYCLES = [ROOT / "examples" / "fanuc" / name for name in (
    "o1004_flange_least_increment.nc", "o1005_bolt_circle_macro.nc")] + [
    ROOT / "tests" / "golden" / "fanuc" / "cycles" / name for name in (
        "g80_cancel_and_g01_cancel.nc", "g81_g98_g99.nc", "g82_dwell.nc")]


@pytest.mark.parametrize("path", FANUC_WITH_CYCLES, ids=lambda p: p.name)
def test_fanuc_cycles_reach_grblhal_shorter_than_grbl_with_the_same_toolpath(path: Path) -> None:
    setup = load_setup(ROOT / "tests" / "support" / "zero_tools.xml")
    source = path.read_text()
    written = {}
    for target in ("grbl", "grblhal"):
        out = io.StringIO(newline="")
        translate(io.StringIO(source, newline=""), out, file=path.name, source="fanuc", target=target, setup=setup,
                  diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
        written[target] = out.getvalue()
        report = verify_lines(io.StringIO(source), io.StringIO(written[target]), file_in=path.name,
                              file_out="out", source="fanuc", target=target, setup=setup, tolerance=0.0)
        assert report.ok and report.max_deviation == 0.0, (target, report.mismatch)
    assert " G81 " in written["grblhal"] or " G82 " in written["grblhal"]
    assert len(written["grblhal"].splitlines()) < len(written["grbl"].splitlines())


# -- rs274 as the oracle ------------------------------------------------------------------------------

def _program(rng: random.Random) -> str:
    """A G81/G82 program grblHAL and LinuxCNC both run: absolute, XY plane, the tool above R at the start."""
    z0 = rng.choice((5.0, 10.0, 25.0))
    lines = ["G21 G17 G90", "F200", f"G0 X0 Y0 Z{z0:g}"]
    for _ in range(rng.randint(1, 4)):
        r = rng.choice((0.5, 1.0, 2.0))
        code = rng.choice(("G81", "G82"))
        words = f"{rng.choice(('G98', 'G99'))} {code} X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} " \
                f"Z{-rng.randint(1, 9)} R{r:g}" + (f" P{rng.choice((0.1, 0.5))}" if code == "G82" else "")
        lines.append(words)
        for _ in range(rng.randint(0, 3)):
            lines.append(" ".join(filter(None, [rng.choice(("", "", "G98", "G99")),
                                                f"X{rng.randint(-20, 20)}",
                                                rng.choice(("", f"L{rng.randint(2, 3)}"))])))
        lines.append("G80")
        lines.append(f"G0 Z{rng.choice((z0, 3.0)):g}")
    return "\n".join(lines + ["M2", ""])


def _ours(text: str) -> list[dict[str, Any]]:
    out = []
    for e in events(text):
        if "move" in e:
            out.append({"move": e["move"], "x": round(e["x"], 3), "y": round(e["y"], 3), "z": round(e["z"], 3)})
        elif e.get("event") == "dwell":
            out.append({"event": "dwell", "seconds": round(e["seconds"], 4)})
    return out


def _theirs(text: str) -> list[dict[str, Any]]:
    out = []
    for e in rs274.canonical_moves(rs274.run_rs274(text), start=(0.0, 0.0, 0.0)):
        if "move" in e:
            out.append({"move": e["move"], "x": round(e["x"], 3), "y": round(e["y"], 3), "z": round(e["z"], 3)})
        elif e.get("event") == "dwell":
            out.append({"event": "dwell", "seconds": round(e["seconds"], 4)})
    return out


def _g98_after_g99(text: str, line: int) -> bool:
    """Read off the program text: the block at ``line`` runs under G98 and the hole before it in the same
    cycle ran under G99, so the tool starts it at R, below the initial level (the generator keeps the tool
    above R at every cycle start): grblHAL returns to that start level, rs274 to the initial level."""
    mode, before = "G98", None  # rs274 and grblHAL both power on in G98 (gcode.h CCRetractMode_Previous)
    for n, words in enumerate(text.splitlines()[:line], start=1):
        if "G80" in words.split():
            before = None
        for code in ("G98", "G99"):
            if code in words.split():
                mode = code
        if n == line:
            return mode == "G98" and before == "G99"
        if words.startswith(("G98", "G99", "X", "G81", "G82")) and "G0" not in words.split():
            before = mode
    return False


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(0, 40, 8))
def test_g81_g82_read_from_grblhal_move_as_rs274_or_are_refused_where_g98_differs(seed: int) -> None:
    """Random programs valid on both: where this dialect reads them, the toolpath is rs274's; where it refuses
    a block, that block is a G98 block after G99 holes of the same cycle (``_g98_after_g99``)."""
    refused = 0
    for n in range(seed, seed + 8):
        text = _program(random.Random(n))
        theirs = _theirs(text)
        try:
            ours = _ours(text)
        except ErrorList as err:
            first = err.errors[0]
            assert "cycle block moves by rules not modelled" in first.message, (n, text, first)
            assert first.location is not None and _g98_after_g99(text, first.location.line), (n, text, first)
            refused += 1
            continue
        assert ours == theirs, (n, text)
    assert refused < 8


# -- parameters, expressions and o-words (a build with NGC_EXPRESSIONS_ENABLE) ---------------------------

EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))
LOOP = """G21 G17 G90
#1 = 0
#<depth> = -2
G0 X0 Y0 Z5
o100 while [#1 LT 3]
  G1 X[#1*10] Y0 Z#<depth> F100
  o101 if [#1 EQ 1]
    G0 Z5
  o101 else
    G1 Y5
  o101 endif
  #1 = [#1 + 1]
o100 endwhile
G0 Z5
M2
"""
"""A LinuxCNC program whose o-words and expressions grblHAL reads alike (ngc_flowctrl.c, ngc_expr.c)."""


def _translate(text: str, source: str, setup: MachineSetup | None) -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(text, newline=""), out, file="t.ngc", source=source, target="grblhal", setup=setup,
              diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def test_o_words_and_expressions_stay_native_on_a_build_with_them() -> None:
    text, warnings = _translate(LOOP, "linuxcnc", EXPRESSIONS)
    assert warnings == []
    assert text == ("G17 G21 G90\n#1=0.\n#<depth>=-2.\nG0 X0. Y0. Z5.\no100 while [#1 LT 3.]\n"
                    "G1 X[#1*10.] Z#<depth> Y0. F100.\no101 if [#1 EQ 1.]\nG0 Z5.\no101 else\nG1 Y5.\n"
                    "o101 endif\n#1=[#1+1.]\no100 endwhile\nG0 Z5.\nM2\n")
    report = verify_lines(io.StringIO(LOOP), io.StringIO(text), file_in="t.ngc", file_out="t.gcode",
                          source="linuxcnc", target="grblhal", setup=EXPRESSIONS, tolerance=0.0)
    assert report.ok and report.moves > 0


def test_without_expressions_the_program_is_flattened_with_a_warning() -> None:
    text, warnings = _translate(LOOP, "linuxcnc", None)
    code = [row for row in text.splitlines() if not row.startswith("(")]
    assert not any("#" in row or row.startswith("o") for row in code)
    assert text.count("(LINE 5: o100 while [#1 LT 3], iteration)") == 3
    assert warnings == ["t.ngc:2:1: warning: the program is flattened (its evaluated motion is written): line 2: "
                        "the grblhal dialect cannot express parameters and o-word flow control on a grblHAL build "
                        "without expressions (NGC_EXPRESSIONS_ENABLE): a set-up with <Controller "
                        "expressions=\"true\"/> has them"]


def test_another_familys_loops_are_flattened() -> None:
    """Fanuc's WHILE .. DO1 reuses its labels and its variables are Macro B's: not written as o-words."""
    fanuc = "G21 G90 G00 X0. Y0. Z5.\n#1=0\nWHILE [#1 LT 2] DO1\nG01 X#1 F100.\n#1=#1+1\nEND1\nM30\n"
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(fanuc), out, file="t.nc", source="fanuc", target="grblhal", setup=EXPRESSIONS,
              diagnostics=diagnostics)
    assert "while" not in out.getvalue() and "G1 X1. F100." in out.getvalue()
    assert "flattened" in str(diagnostics.warnings[0])


def test_reading_o_words_needs_a_build_with_them_and_named_subroutines_are_refused() -> None:
    assert errors_of(lambda: read_program(io.StringIO(LOOP), file="t.gcode", dialect="grblhal"))[0].startswith(
        "t.gcode:2:1: error:")
    sub = "G21\no<probe> sub\nG0 X1\no<probe> endsub\no<probe> call\nM2\n"
    found = errors_of(lambda: read_program(io.StringIO(sub), file="t.gcode", dialect="grblhal", setup=EXPRESSIONS))
    assert found[0].startswith("t.gcode:2:1: error: a named grblHAL subroutine (o<name> sub, o<name> call) is the "
                               "file <name>.macro")


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_o_word_output_runs_in_rs274_as_this_dialect_simulates_it() -> None:
    """grblHAL's o-words and expressions are rs274's (ngc_flowctrl.c, ngc_expr.c are its port): the written
    program, run by rs274, moves as the grblHAL simulation of it does (and as the pocket example does)."""
    text, _ = _translate(LOOP, "linuxcnc", EXPRESSIONS)
    pocket = (ROOT / "tests" / "conformance" / "grblhal" / "pocket_loop.nc").read_text().replace("T1 M6\n", "")
    for program in (text, pocket):
        ours = [e for e in _ours_with(program, EXPRESSIONS) if "move" in e]
        theirs = [e for e in _theirs(program) if "move" in e]
        assert ours == theirs and len(ours) > 5, program


def _ours_with(text: str, setup: MachineSetup) -> list[dict[str, Any]]:
    return [{"move": e["move"], "x": round(e["x"], 3), "y": round(e["y"], 3), "z": round(e["z"], 3)}
            for e in events(text, setup) if "move" in e]


# -- the output checker (tests/support/grblhal_rules.py) holds what it says -----------------------------

@pytest.mark.parametrize("program, problem", [
    ("G21 G90\nG0 X0 Y0 Z10\nG0 Z5\nM2\n", None),
    ("G21\nG80\nG43.1 Z5\nM2\n", "3: axis words while G80 is in force (error 31)"),
    ("G21\nG80 G28 Z5\nG0\nG43.1 Z5\nM2\n", None),
    ("G21\nG0 G28 Z5\nM2\n", "2: axis command conflict (error 24/37)"),
    ("G21\nF100\nG81 X1 Y1 Z-1\nM2\n", "3: G81 newly programmed without R and Z (value word missing)"),
    ("G21\nF100\nG82 X1 Y1 Z-1 R1\nM2\n", "3: G82 newly programmed without P (value word missing)"),
    ("G21\nF100\nG81 X1 Y1 Z-1 R1 L0\nM2\n", "3: a repeat count L of 0 or less (error: non-positive value)"),
    ("G21\nF100\nG85 X1 Y1 Z-1 R1\nM2\n", "3: G85 is parsed but never run by grblHAL's motion control"),
    ("G21\nG1 X1\nM2\n", "2: a feed move with no feed rate (undefined feed rate, error 22)"),
    ("G21\nM19\nM2\n", "2: M19 is no code of grblHAL's (unsupported command, error 20)"),
    ("G21\nG43 H1\nM2\n", "2: G43 without a tool table (unsupported command, error 20)"),
    ("G21\nG0 X1 (what?)\nM2\n", "2: real-time character '?' (status report)"),
    ("G21\n(" + "C" * 255 + ")\nM2\n", "2: line overflow (257 characters kept, 256 fit)"),
])
def test_the_grblhal_checker_finds_what_grblhal_refuses(program: str, problem: str | None) -> None:
    from tests.support.grblhal_rules import grblhal_problems
    assert grblhal_problems(program) == ([] if problem is None else [problem])
