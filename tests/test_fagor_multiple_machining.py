"""Fagor multiple machining words (``dialects/fagor/multiple_machining.py``), read from real Fagor
programs: every pattern's points and moves from its words, I and K forms alike, skipped points, and a
pinned located error for each word combination the controller or the reference does not define.

The active cycle comes from the Fagor drilling block of ``PRELUDE`` (a G81 at X20 Y0 from Z50, reference
plane Z2, depth I-5, F100, G98), so each hole below is: rapid to the point at Z50, rapid to Z2, feed to
Z-5, rapid to Z50. The pattern block is line 9 of the program.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from dialects.fagor.multiple_machining import pattern_words
from postproc.api import read_blocks, translate
from postproc.output.bounded import run_bounded
from postproc.errors import Diagnostics, PostprocError
from postproc.ir import Block, Feed, Motion
from postproc.plugins import default_registry
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

PRELUDE = ["%1000", "; multiple machining after a drilling cycle", "G71 G90 G17", "G00 X0 Y0 Z50", "M03 S1000",
           "; the pattern's point 1: the cycle drills X20 Y0", "; (reference plane Z2, depth I-5, back to Z50)",
           "G81 G98 X20 Y0 Z2 I-5 F100"]
"""Eight lines: the pattern block is line 9."""
R3 = 3 ** 0.5


def read(lines: list[str]) -> tuple[list[Block], Diagnostics]:
    """A Fagor program read through the Fagor dialect: (its blocks, the diagnostics collected)."""
    diagnostics = Diagnostics()
    _, blocks = read_blocks([line + "\n" for line in lines], "t.nc", default_registry().dialect("fagor"),
                            MachineSetup(), diagnostics)
    return list(blocks), diagnostics


def run(text: str, prelude: list[str] = PRELUDE) -> Block:
    """The pattern block ``text``, line 9 of a Fagor program after ``prelude``; its first located error is
    raised."""
    assert len(prelude) == 8
    blocks, diagnostics = read(prelude + [text])
    if diagnostics.errors:
        raise diagnostics.errors[0]
    return blocks[-1]


def holes(block: Block) -> list[tuple[float, float]]:
    """The plane points where the tool feeds down (one feed to the bottom per hole)."""
    return [(round(m.axes["X"], 6), round(m.axes["Y"], 6)) for m in block.sections["CompoundMotion"].items
            if isinstance(m, Motion) and m.mode == "linear" and m.axes["Z"] == -5.0]


def drill(x: float, y: float) -> list[Motion]:
    return [Motion("rapid", {"X": x, "Y": y, "Z": 50.0}), Motion("rapid", {"X": x, "Y": y, "Z": 2.0}),
            Motion("linear", {"X": x, "Y": y, "Z": -5.0}), Motion("rapid", {"X": x, "Y": y, "Z": 50.0})]


def test_bolt_circle_by_count_is_the_cycle_at_every_further_point():
    # start (20, 0), centre 20 to the left (0, 0): K4 = 90 deg steps counter-clockwise
    block = run("G163 X-20 Y0 K4")
    items = block.sections["CompoundMotion"].items
    assert items == drill(0.0, 20.0) + drill(-20.0, 0.0) + drill(0.0, -20.0)
    assert block.sections["HolePattern"].split == (4, 4, 4)


def test_the_tool_ends_at_the_last_point_of_the_pattern():
    # the toolpath of the program: the cycle's own hole at (20, 0), the pattern's three, then an
    # incremental move of X5 from the last point (0, -20) at the initial level Z50
    lines = [line + "\n" for line in PRELUDE + ["G163 X-20 Y0 K4", "G80", "G91 G01 X5 F200", "M30"]]
    moves = [(e["line"], e["move"], e["x"], e["y"], e["z"]) for e in toolpath_events(lines, file="t.nc", dialect="fagor")
             if "move" in e]
    assert moves[-1] == (11, "feed", 5, -20, 50)
    assert [m[2:] for m in moves if m[1] == "feed" and m[4] == -5] == [(20, 0, -5), (0, 20, -5), (-20, 0, -5),
                                                                      (0, -20, -5)]


@pytest.mark.parametrize("text", ["G163 X-20 Y0 I90", "G163 X-20 K4", "G163 X-20. Y0. I90."])
def test_i_and_k_forms_give_the_same_points(text):
    assert holes(run(text)) == [(0, 20), (-20, 0), (0, -20)]


def test_negative_step_turns_clockwise():
    assert holes(run("G163 X-20 I-90")) == [(0, -20), (-20, 0), (0, 20)]


def test_skipped_points_are_not_machined():
    # K6 from (20, 0) around (0, 0): 60 deg steps; points 3 (-10, 10 sqrt3) and 5 (-10, -10 sqrt3) skipped
    block = run("G163 X-20 K6 P3 Q5")
    assert holes(block) == [(10, round(10 * R3, 6)), (-20, 0), (10, round(-10 * R3, 6))]


def test_clockwise_arcs_between_points_at_their_feed():
    # C2: clockwise whatever I's sign, F500 between the points, F100 again for the cycle; the arc to
    # point 4 passes over the skipped point 3
    block = run("G163 X-20 I90 C2 F500 P3")
    items = block.sections["CompoundMotion"].items
    assert items[:3] == [Feed(500.0), Motion("cw", {"X": 0.0, "Y": -20.0, "Z": 50.0}, center={"X": -20.0, "Y": 0.0}),
                         Feed(100.0)]
    assert items[3:6] == drill(0.0, -20.0)[1:]  # already over the point: no rapid in the plane
    assert items[6:9] == [Feed(500.0), Motion("cw", {"X": 0.0, "Y": 20.0, "Z": 50.0}, center={"X": 0.0, "Y": 20.0}),
                          Feed(100.0)]
    assert items[9:] == drill(0.0, 20.0)[1:]


def test_linear_moves_between_points():
    items = run("G163 X-20 K2 C1 F300").sections["CompoundMotion"].items
    assert items == [Feed(300.0), Motion("linear", {"X": -20.0, "Y": 0.0, "Z": 50.0}), Feed(100.0)] + drill(-20.0, 0.0)[1:]


def test_arc_pattern_by_step_and_by_count():
    # start (20, 0), centre (0, 0), B90: 45 deg steps give points at 45 and 90 deg
    h = round(20 * 2 ** 0.5 / 2, 6)
    assert holes(run("G164 X-20 B90 I45")) == [(h, h), (0, 20)]
    assert holes(run("G164 X-20 B90 K3")) == [(h, h), (0, 20)]


@pytest.mark.parametrize("text", ["G160 A90 X30 I10", "G160 A90 X30 K4", "G160 A90 I10 K4"])
def test_line_any_two_of_length_step_and_count(text):
    assert holes(run(text)) == [(20, 10), (20, 20), (20, 30)]


def test_parallelogram_and_grid():
    # from (20, 0): side 1 along X, 2 points 10 apart; side 2 along Y, 3 points 5 apart
    assert holes(run("G161 I10 K2 J5 D3")) == [(30, 0), (30, 5), (30, 10), (20, 10), (20, 5)]
    assert holes(run("G162 X10 K2 Y10 D3")) == [(30, 0), (30, 5), (20, 5), (20, 10), (30, 10)]


def test_pattern_words_read_back_to_the_same_pattern():
    for text in ("G163 X-20 Y0 K6 P3", "G163 X-20 Y0 I-60 C2 F500", "G164 X-20 Y0 B90 I45 C1 F200",
                 "G160 A30 I10 K4", "G162 A15 B60 I10 K3 J5 D2 P4"):
        block = run(text)
        pattern = block.sections["HolePattern"]
        again = run(" ".join(pattern_words(pattern, lambda v: repr(float(v)))))
        assert again.sections["HolePattern"] == pattern, text


@pytest.mark.parametrize("text, message", [
    ("G163 X-20 I90 K4", "t.nc:9:15: error: G163 takes either the angular step I or the number of points K, not both"),
    ("G163 X-20", "t.nc:9:1: error: G163 needs the angular step I or the number of points K"),
    ("G163 X-20 I35", "t.nc:9:11: error: G163 angular step I35 does not close the full circle (360 degrees): the "
                      "total angular movement must be a whole number of steps"),
    ("G163 X-20 I0", "t.nc:9:11: error: G163 angular step I cannot be 0"),
    ("G163 X-20 I360", "t.nc:9:11: error: G163 angular step I360 leaves no point but the first"),
    ("G163 X-20 K1", "t.nc:9:11: error: G163 K must be at least 2 (point 1 included)"),
    ("G163 X-20 K4.5", "t.nc:9:11: error: G163 K4.5 must be a whole number"),
    ("G163 K4", "t.nc:9:1: error: G163 needs X or Y: the distance from the first point to the centre"),
    ("G163 X-20 K4 C4", "t.nc:9:14: error: G163 C4 is not a way to move between points (C0 rapid, C1 feed, "
                        "C2 clockwise, C3 counterclockwise)"),
    ("G163 X-20 K4 C1", "t.nc:9:14: error: G163 C1 needs the feed F of the moves between points"),
    ("G163 X-20 K4 F100", "t.nc:9:14: error: G163 F is the feed between points, which C0 (rapid) does not use"),
    ("G163 X-20 K4 P1", "t.nc:9:14: error: G163 P1: point 1 is machined by the cycle's own block and cannot be "
                        "skipped"),
    ("G163 X-20 K4 Q5", "t.nc:9:1: error: G163: the circle has 4 points: point 5 cannot be skipped"),
    ("G163 X-20 K4 Z3", "t.nc:9:14: error: G163 takes no Z word (its words: X Y I K C F P Q R S T U V)"),
    ("G163 X-20 K4 X3", "t.nc:9:14: error: address X appears twice in one block"),  # the lexer's
    ("G163 G91 X-20 K4", "t.nc:9:6: error: G163 takes no other G code (G91): program it in a block of its own"),
    ("G164 X-20 I45", "t.nc:9:1: error: G164 needs B, the angle of the arc"),
    ("G164 X-20 B360 I45", "t.nc:9:11: error: G164 B360 must be more than 0 and less than 360 degrees"),
    ("G164 X-20 B100 I45", "t.nc:9:16: error: G164 angular step I45 does not close the arc B100: the total "
                           "angular movement must be a whole number of steps"),
    ("G160 X30 I10 K4", "t.nc:9:14: error: G160 needs exactly two of X (length), I (step) and K (number of "
                        "points), not 3"),
    ("G160 X30", "t.nc:9:1: error: G160 needs exactly two of X (length), I (step) and K (number of points), not 1"),
    ("G160 X25 I10", "t.nc:9:10: error: G160 length X25 is not a whole number of steps I10"),
    ("G160 X-30 I10", "t.nc:9:6: error: G160 X must be positive (the angle gives the direction)"),
    ("G161 I10 K2 J5", "t.nc:9:1: error: G161 needs exactly two of Y (length), J (step) and D (number of points), "
                       "not 1"),
    ("G162 B180 I10 K2 J5 D2", "t.nc:9:6: error: G162 angle B180 between the sides makes no parallelogram"),
])
def test_bad_words_are_located_errors(text, message):
    with pytest.raises(PostprocError) as info:
        run(text)
    assert str(info.value) == message


@pytest.mark.parametrize("text, what", [
    ("G163 X-20 K4 P2.005", "G163 P2.005: a range of points to skip (its notation is unverified)"),
    ("G165 X-20 A30 C10", "G165 (multiple machining along a chord, whose words the reference leaves unverified)"),
])
def test_what_the_reference_leaves_open_is_kept_verbatim_for_fagor_and_refused_elsewhere(text, what):
    program = [*PRELUDE, text, "G80", "M30"]
    assert translated(text, "fagor", after=("G80", "M30")) == "\n".join(program) + "\n"
    for target in ("fanuc", "linuxcnc", "grbl"):
        with pytest.raises(PostprocError) as info:
            translated(text, target, after=("G80", "M30"))
        assert str(info.value) == f"t.nc:9:1: error: {what} from fagor has no equivalent in {target}"
    with pytest.raises(PostprocError) as info:
        list(toolpath_events([line + "\n" for line in program], file="t.nc", dialect="fagor"))
    assert str(info.value) == f"t.nc:9:1: error: {what} cannot be simulated"


def test_a_pattern_needs_an_active_cycle():
    with pytest.raises(PostprocError) as info:
        run("G163 X-20 K4", PRELUDE[:-2] + [PRELUDE[-1], "G80"])
    assert str(info.value) == "t.nc:9:1: error: G163 repeats the active canned cycle, and no canned cycle is active"


@pytest.mark.parametrize("text, message", [
    # a hundred million points (or a grid of K x D, or 360 / 0.0001 steps): each machined point makes at
    # least one move, so the count alone passes the bound of 100,000 moves a block
    ("G163 X-20 K99999999", "G163: the pattern machines 99999998 points"),
    ("G163 X-20 I0.0001", "G163: the pattern machines 3599999 points"),
    ("G160 A0 I1 K99999999", "G160: the pattern machines 99999998 points"),
    ("G162 I1 K99999 J1 D99999", "G162: the pattern machines 9999800000 points"),
    ("G161 I1 K99999999 J1 D99999999", "G161: the pattern machines 399999991 points"),
    ("G164 X-20 B359 I0.0001", "G164: the pattern machines 3590000 points"),
])
def test_a_huge_pattern_is_refused_before_its_points_are_made(text, message):
    def refused() -> str:
        try:
            run(text)
        except PostprocError as err:
            return str(err)
        return "no error"

    found = run_bounded(refused, seconds=20, memory=128 << 20)  # the points as a list: gigabytes
    assert found.failure is None, found.failure
    assert found.value == (f"t.nc:9:1: error: {message}, which make more than 100000 moves in one block (the "
                           "set-up's <Limits movesPerBlock>)")


def test_a_pattern_that_passes_the_bound_midway_says_at_which_point():
    # 100,000 points of 4 moves each (drill()): points 2 to 25001 make 100,000 moves, point 25002 passes
    with pytest.raises(PostprocError) as info:
        run("G163 X-20 K100000")
    assert str(info.value) == ("t.nc:9:1: error: G163: the pattern makes more than 100000 moves in one block by its "
                               "point 25002 of 100000 (the set-up's <Limits movesPerBlock>)")


def test_outside_g17_is_refused():
    with pytest.raises(PostprocError) as info:
        run("G163 X-20 K4", PRELUDE[:-3] + [PRELUDE[-1], "G80", "G18"])
    assert str(info.value) == ("t.nc:9:1: error: G163 outside the G17 plane is not supported (which axes its X "
                               "and Y name in G18 and G19 is unverified)")


def test_a_pattern_with_computed_words_travels_verbatim_between_fagor_programs():
    program = PRELUDE[:-1] + ["P1=6", "G163 X-20 K[P1]", "G80", "M30"]
    out = io.StringIO()
    translate([line + "\n" for line in program], out, file="t.nc", source="fagor", target="fagor")
    assert out.getvalue().splitlines() == program


def translated(text: str, target: str, after: tuple[str, ...] = (), prelude: list[str] = PRELUDE) -> str:
    """The Fagor program ``prelude``, the pattern block ``text`` (line 9) and ``after``, translated to
    ``target``."""
    out = io.StringIO()
    translate([line + "\n" for line in prelude + [text, *after]], out, file="t.nc", source="fagor", target=target)
    return out.getvalue()


def test_a_target_without_patterns_gets_the_modal_cycle_at_every_point():
    # Fagor's G81 without a dwell K drills with none (K0: Fagor 8055-M manual p.162): Fanuc's G81 with R, Z
    out = translated("G163 X-20 K4", "fanuc")
    assert out.endswith("G98 G81 X20. Y0. Z-5. R2. F100.\nX0. Y20.\nX-20. Y0.\nX0. Y-20.\n"), out


def test_incremental_points_are_written_from_point_to_point():
    # G91 in force: each repeat is the step from the previous point, (20,0) -> (0,20) -> (-20,0) -> (0,-20)
    out = translated("G163 X-20 K4", "fanuc", prelude=PRELUDE[:-2] + [PRELUDE[-1], "G91"])
    assert out.endswith("G91\nX-20. Y20.\nX-20. Y-20.\nX20. Y-20.\n"), out


def test_arcs_between_points_are_written_as_motion_and_so_is_the_rest_of_the_cycle():
    out = translated("G163 X-20 K4 C3 F500 P3", "fanuc", after=("X50 Y50",))
    tail = out[out.index("(drill from line 9"):]
    assert tail.splitlines() == [
        "(drill from line 9: G163 X-20 K4 C3 F500 P3)",
        "F500.", "G03 X0. Y20. Z50. I-20. J0.", "F100.",
        "G00 X0. Y20. Z2.", "G01 Z-5.", "G00 Z50.",  # a move names only the axes it changes
        "(drill from line 9: G163 X-20 K4 C3 F500 P3)",
        # the arc to point 4 passes over the skipped point 3
        "F500.", "G03 X0. Y-20. Z50. I0. J-20.", "F100.",
        "G00 X0. Y-20. Z2.", "G01 Z-5.", "G00 Z50.",
        # the G03 cancelled the cycle on the target: a later hole of the same cycle is motion too
        "(drill from line 10: X50 Y50)",
        "G00 X50. Y50. Z50.", "G00 Z2.", "G01 Z-5.", "G00 Z50.",
    ], out


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_arcs_between_points_reach_linuxcnc_and_grbl_as_arcs(target):
    # LinuxCNC's output is run by rs274 (the conftest hook); the arcs turn counter-clockwise around (0, 0)
    out = translated("G163 X-20 K4 C3 F500 P3", target)
    arcs = [line for line in out.splitlines() if line.startswith(("G3", "G03"))]
    assert arcs == ["G3 X0. Y20. Z50. I-20. J0.", "G3 X0. Y-20. Z50. I0. J-20."], out


def test_grbl_gets_the_motion_of_every_point():
    out = translated("G163 X-20 K2", "grbl")
    assert out.splitlines()[-5:] == ["(drill from line 9: G163 X-20 K2)", "G0 X-20. Y0. Z50.",
                                     "G0 Z2.", "G1 Z-5.", "G0 Z50."], out


@pytest.mark.parametrize("text", ["G163 X-20 Y0 K6 P3 Q5", "G163 X-20 I-60 C2 F500", "G164 X-20 B90 I45 C1 F200",
                                  "G160 A30 I10 K4", "G161 X20 K3 Y10 D2", "G162 A15 B60 I10 K3 J5 D2 P4",
                                  "  G163   X-20.000  K4 ; a comment"])
def test_fagor_to_fagor_keeps_the_pattern_byte_for_byte(text):
    program = [*PRELUDE, text, "G80", "M30"]
    assert translated(text, "fagor", after=("G80", "M30")) == "\n".join(program) + "\n"


def test_a_pattern_block_generated_from_its_section_reads_back_to_the_same_pattern():
    # a pattern block marked rewritten (as a transformation would) is written from its HolePattern
    # section; read back, it is the same pattern
    from postproc.lowering.lower import lower_for

    program = [*PRELUDE, "N90 G163 X-20 Y0 I-60 C2 F500 P3", "G80", "M30"]
    fagor = default_registry().dialect("fagor")
    ctx, blocks = read_blocks([line + "\n" for line in program], "t.nc", fagor, MachineSetup(), Diagnostics())

    def rewritten(stream):
        for block in stream:
            if "HolePattern" in block.sections:
                block.changed()
            yield block

    out = io.StringIO()
    assert fagor.WRITER is not None
    fagor.WRITER(ctx, "fagor", fagor).write(lower_for(rewritten(blocks), ctx, fagor, "error"), out)
    lines = out.getvalue().splitlines()
    assert lines[:8] + lines[9:] == program[:8] + program[9:]
    assert lines[8] == "N90 G163 X-20. Y0. I-60. C2 F500. P3"
    assert run(lines[8]).sections["HolePattern"] == run(program[8]).sections["HolePattern"]


def test_a_cycle_the_set_up_expands_takes_its_pattern_with_it():
    # Fagor to Fagor with <Cycles expand="drill"/> (a G81 without K drills without a dwell: Fagor 8055-M
    # manual p.162): the G81 is written as motion, so no cycle is
    # active on the controller for a G163 to repeat; the pattern is written as the motion of its holes
    out = io.StringIO()
    setup = MachineSetup(cycles=CycleSettings(expand="drill"))
    translate([line + "\n" for line in [*PRELUDE, "G163 X-20 K2", "G80", "M30"]], out, file="t.nc",
              source="fagor", target="fagor", setup=setup)
    lines = out.getvalue().splitlines()
    assert not any("G163" in line and not line.startswith(";") for line in lines), lines
    assert lines[-7:] == [";drill from line 9: G163 X-20 K2", "G00 X-20. Y0. Z50.", "G00 Z2.",
                          "G01 Z-5.", "G00 Z50.", "G80", "M30"]


EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "fagor"


@pytest.mark.parametrize("args", [
    ("bolt_circle.nc", "fanuc/o1401_bolt_circle_points.nc", "--from", "fagor", "--to", "fanuc"),
    ("fanuc/o1401_bolt_circle_points.nc", "bolt_circle.nc", "--from", "fanuc", "--to", "fagor"),
])
def test_a_fanuc_bolt_circle_hole_by_hole_verifies_against_fagor_g81_g163_both_ways(cli, args):
    # the Fanuc file's coordinates are 40 sin 60 = 34.641016 rounded to 6 places: under 1e-6 mm off
    first, second, *dialects = args
    result = cli("verify", EXAMPLES / first, EXAMPLES / second, *dialects, "--tolerance", "0.000001")
    assert result.status == 0, result.err
    assert result.out.decode().startswith("max deviation 0.0000 mm over 24 moves (IN:7 / OUT:7): ok"), result.out


@pytest.mark.parametrize("source, target", [("fagor", "fanuc"), ("fanuc", "fagor")])
def test_a_bolt_circle_on_the_axes_verifies_at_exactly_zero_both_ways(tmp_path, source, target):
    # K4 around (50, 50) from (70, 50): 90 deg steps, the points (50, 70), (30, 50), (50, 30) exactly
    programs = {
        "fagor": ["%1404", "G71 G90 G17", "G00 X0 Y0 Z30", "M03 S1000", "G00 X70 Y50",
                  "G81 G98 Z2 I-10 F150", "G163 X-20 Y0 K4", "G80", "M30"],
        "fanuc": ["O1404", "G90 G17 G21", "G00 X0 Y0 Z30.", "M03 S1000", "G00 X70. Y50.",
                  "G98 G81 Z-10. R2. F150.", "X50. Y70.", "X30. Y50.", "X50. Y30.", "G80", "M30"],
    }
    report = verify_lines([line + "\n" for line in programs[source]], [line + "\n" for line in programs[target]],
                          file_in="in.nc", file_out="out.nc", source=source, target=target, tolerance=0.0)
    assert report.ok, report.summary()
    assert report.max_deviation == 0.0
