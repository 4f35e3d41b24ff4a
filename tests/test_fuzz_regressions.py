"""Programs ``make fuzz`` reduced from failures: each translated with exit 0 into a program that moves
otherwise (or that the toolpath refuses). Each must now be refused with a located error or verify."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.fuzzing import UNKNOWN_MEANING_OUTCOME, check_translation, known_defect, warned_difference
from tests.support.generators.grblhal_targets import check as grblhal_check
from tests.support.generators.macros import as_rs274_prints
from tests.support.rs274 import available as rs274_available, canonical_moves, run_rs274
from tests.support.tools import with_tools

HEAD = "G21 G90 G0 X0. Y0. Z10.\n"

REFUSED = [
    ("fanuc", "linuxcnc", "F0.3 K2 G03\n", "t.nc:2:6: error: arc centre offset along Z is outside the XY plane"),
    ("grbl", "linuxcnc", "G02 G54 R2.\n", "t.nc:2:1: error: G2 with no feed rate in force (program F first)"),
    ("grbl", "linuxcnc", "F10. G02 G54 R2.\n", "t.nc:2:14: error: a full circle cannot be programmed with R (use I/J/K)"),
    ("fanuc", "fanuc", "G53 R2. G03\n", "t.nc:2:5: error: a full circle cannot be programmed with R (use I/J/K)"),
    ("grbl", "fanuc", "X-5 F100. G53 G01\n", "t.nc:2:1: error: the fanuc dialect cannot express a linear move in "
                                            "machine coordinates (its machine-coordinate code moves only rapid)"),
]


@pytest.mark.parametrize("source, target, body, message", REFUSED)
def test_refused_with_a_located_error(source: str, target: str, body: str, message: str) -> None:
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(HEAD + body), io.StringIO(), file="t.nc", source=source, target=target)
    assert [str(e) for e in exc.value.errors] == [message]


ISG_SKIPPED_HEADER = "G90 G0 X0. Y0. Z10.\n/ % R-1 K0\nG1 X1 F100\n"
"""An ISG program header under block delete, once written with the slash after the header ("%_N_R_1_K0_MPF /",
"O0001 (R-1 K0) /", "(R-1 K0) /"), which the siemens reader refused (the fuzz, isg-siemens) and no controller
reads as a skip. What ISG does with "/ %" is in no source found: kept for ISG only."""


@pytest.mark.parametrize("target", ["siemens", "fanuc", "linuxcnc", "grblhal", "mach3"])
def test_an_isg_header_under_block_delete_is_refused_elsewhere(target: str) -> None:
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(ISG_SKIPPED_HEADER), io.StringIO(), file="t.nc", source="isg", target=target)
    assert [str(e) for e in exc.value.errors] == [
        "t.nc:2:1: error: a program header under block delete ('/'): the header names the program, which the block "
        "delete switch cannot skip"]


def test_an_isg_header_under_block_delete_is_copied_to_isg_as_written() -> None:
    out = io.StringIO()
    translate(io.StringIO(ISG_SKIPPED_HEADER), out, file="t.nc", source="isg", target="isg")
    assert out.getvalue() == ISG_SKIPPED_HEADER


def test_a_percent_line_is_no_program_end_for_grbl() -> None:
    """grbl has no tape marks: the move after '%' runs, in the source and in the translation."""
    program = HEAD + "%\nG91 Z5\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="grbl", target="fanuc")
    # (G61 first: grbl's power-on exact path [V: grbl gcode.h], Fanuc's exact stop [K]; ``path_at_start``)
    assert out.getvalue() == "G61 G21 G90 G00 X0. Y0. Z10.\n(%)\nG91 G00 Z5.\n"
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source="grbl", target="fanuc", tolerance=0.0)
    assert report.ok and report.moves == 1, report.summary()


def test_a_spindle_start_keeps_its_place_before_a_coolant_stop_moved_before_the_motion() -> None:
    """make fuzz: grbl runs M4 before M9 (both before the move); the Fanuc output stopped the coolant first."""
    program = HEAD + "M09 X0.0005 M04\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="grbl", target="fanuc")
    assert out.getvalue().splitlines()[-2:] == ["M04 M09", "G00 X0.0005"]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source="grbl", target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()


def test_a_dwell_beside_an_x_move_gets_a_line_of_its_own_in_fanuc() -> None:
    """make fuzz: LinuxCNC 'G1 X5 G4 P1' became Fanuc 'G04 X1. G01 X5.' (X twice: refused by Fanuc)."""
    program = HEAD + "G1 X5 F100 G4 P1\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.ngc", source="linuxcnc", target="fanuc")
    assert out.getvalue().splitlines()[1:3] == ["G04 X1.", "G01 X5. F100."]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.ngc", file_out="b.nc",
                          source="linuxcnc", target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()


def test_a_spindle_stop_comes_before_the_orientation_in_its_own_block() -> None:
    """make fuzz: Fanuc 'Y2.5 M05 M19' (move, stop, orient) became LinuxCNC 'G0 Y2.5', 'M19 R0.', 'M5':
    the orientation ran on a turning spindle and the stop came after it."""
    program = HEAD + "Y2.5 M05 M19\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert out.getvalue().splitlines()[1:] == ["G0 Y2.5", "M5", "M19 R0.", "M2"]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.ngc",
                          source="fanuc", target="linuxcnc", tolerance=0.0)
    assert report.ok, report.summary()


@pytest.mark.parametrize("body, settings, rest", [
    ("G49 T1 G41 D01 G54\n", "G54 G49", "G41 D01 T1"),
    ("S1000 G54 G00 M08 G94 G41 D01\n", "G54", "G94 G41 D01 G0 S1000 M8"),
    ("G99 G21 G41 D01\n", "G99", "G21 G41 D01"),
])
def test_settings_beside_compensation_on_go_before_it_for_linuxcnc(body: str, settings: str, rest: str) -> None:
    """make fuzz: rs274 turns compensation on (order 15) before it changes the tool length offset, the work
    system or the retract mode (16-18), and refuses those under compensation: they go in a block before.
    (The suite's output hook runs every LinuxCNC output through rs274 itself.)"""
    program = HEAD + body
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert out.getvalue().splitlines()[1:] == [settings, rest, "M2"]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.ngc",
                          source="fanuc", target="linuxcnc", tolerance=0.0, allow_ignored=True,
                          setup=with_tools())  # both sides' compensation simulated: the radius is needed
    assert report.ok, report.summary()


_M6_UNDER_COMP = ("a tool change (M6) with cutter compensation on (rs274 changes the tool before it runs the block's "
                  "G40: \"Cannot change tools with cutter radius compensation on\"; program G40 in a block before)")


_M6_SOURCE = "t.nc:3:1: error: a tool change with cutter compensation on cannot be run (cancel it first)"


@pytest.mark.parametrize("body, message", [
    ("G41 D1 G01 X5. F100.\nG49\n", "t.nc:3:1: error: the linuxcnc dialect cannot express a change of tool length "
                                    "offset with cutter compensation on (rs274 refuses it: program G40 first)"),
    ("G41 D01 G28\n", "t.nc:2:1: error: the linuxcnc dialect cannot express G28/G30 with cutter compensation on "
                  "(rs274: \"Cannot use g28 or g30 with cutter radius comp\")"),
    # the simulation's own refusal first (``CutterRadius.tool_change``, which the lowering runs too since
    # issue 26's comp26), then the target's
    ("T1 G41 D01\nM06\n", (_M6_SOURCE, "t.nc:3:1: error: the linuxcnc dialect cannot express " + _M6_UNDER_COMP)),
    ("T1 G41 D01\nG40 M06\n", (_M6_SOURCE, "t.nc:3:1: error: the linuxcnc dialect cannot express " + _M6_UNDER_COMP)),
    ("G41 D01\nG19\n", ("t.nc:3:1: error: the plane cannot change to YZ while cutter compensation is on (cancel it "
                    "first)",  # Fanuc's own alarm (its rules are modelled), then the target's
                    "t.nc:3:1: error: the linuxcnc dialect cannot express a change to the YZ plane with cutter "
                    "compensation on (rs274: \"Cannot change planes with cutter radius compensation on\")")),
    ("G19 G41 D01\n", "t.nc:2:1: error: the linuxcnc dialect cannot express cutter compensation left in the YZ "
                      "plane (rs274: \"Cutter radius compensation allowed only in XY, XZ planes\")"),
    # Fanuc's G41 without D takes the D in force: none is a located error of the source (its rules are
    # modelled), before the target is asked
    ("G19 G41\n", ("t.nc:2:1: error: cutter compensation without its register takes the register programmed last, "
                   "and none was: program D",
                   "t.nc:2:1: error: the linuxcnc dialect cannot express cutter compensation left in the YZ plane "
                   "(rs274: \"Cutter radius compensation allowed only in XY, XZ planes\")")),
])
def test_what_rs274_refuses_under_compensation_is_a_located_error(body: str, message: str | tuple[str, ...]) -> None:
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(HEAD + body), io.StringIO(), file="t.nc", source="fanuc", target="linuxcnc")
    assert [str(e) for e in exc.value.errors] == ([message] if isinstance(message, str) else list(message))


def test_an_isg_dwell_keeps_the_spindle_start_before_it() -> None:
    """make fuzz: LinuxCNC 'T1 Y2.5 X10. M03 G04 P500' (spindle, then dwell, then move) became ISG
    'G04 X500.' then 'G00 Y2.5 X10. T1 M03': the dwell ran before the spindle started."""
    program = HEAD + "T1 Y2.5 X10. M03 G04 P500\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.ngc", source="linuxcnc", target="isg")
    assert out.getvalue().splitlines()[1:4] == ["T1 M03", "G04 X500.", "G00 Y2.5 X10."]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.ngc", file_out="b.nc",
                          source="linuxcnc", target="isg", tolerance=0.0)
    assert report.ok, report.summary()


def test_the_active_work_system_selected_again_keeps_the_arc_checked() -> None:
    """make fuzz: 'R-1 G02 ... G54 X10.' with G54 already active: the translation skipped the arc check
    (a work system change forgets the position) and grbl refused the arc (error 34)."""
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(HEAD + "F0.3\nR-1 G02 Z1234.56789 G90 G54 X10.\n"), io.StringIO(), file="t.ngc",
                  source="linuxcnc", target="grbl")
    assert [str(e) for e in exc.value.errors] == [
        "t.ngc:3:1: error: arc radius 1.0000 mm is too small for a chord of 10.0000 mm"]


def test_machine_coordinates_without_a_move_are_not_written_beside_a_bare_motion_code() -> None:
    """make fuzz: Fanuc 'G01 G53' (no axis words, no feed rate) became LinuxCNC 'G53' alone, which rs274
    refuses ("Must use g0 or g1 with g53"); G53 without a move does nothing, so nothing is written."""
    out = io.StringIO()
    translate(io.StringIO(HEAD + "G01 G53\n"), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert out.getvalue().splitlines()[1] == "(G01 G53)"


def test_a_zero_radius_arc_is_refused_for_linuxcnc() -> None:
    """make fuzz: Fanuc 'G02 F100. I0.' (an arc that does nothing) reached LinuxCNC, which refuses it."""
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(HEAD + "G02 F100. I0.\n"), io.StringIO(), file="t.nc", source="fanuc",
                  target="linuxcnc")
    assert [str(e) for e in exc.value.errors] == [
        "t.nc:2:1: error: the linuxcnc dialect cannot express an arc of zero radius (a controller that runs it "
        "does nothing; rs274 refuses it: \"Zero-radius arc\")"]


PER_REV_STOPPED = [
    ("G95 G01 X5. F0.2\n", "t.nc:2:9: error: a feed-per-revolution move with the spindle stopped: the axes "
                           "would wait for revolutions that never come (start the spindle first, or feed per minute)"),
    ("S500 M03\nG95 G01 X5. F0.2 M05\nG02 X6. I0.5\n",
     "t.nc:4:5: error: a feed-per-revolution move with the spindle stopped: the axes would wait for "
     "revolutions that never come (start the spindle first, or feed per minute)"),
]


@pytest.mark.parametrize("body, message", PER_REV_STOPPED)
@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
def test_a_feed_per_revolution_move_with_the_spindle_stopped_is_refused(body: str, message: str,
                                                                      target: str) -> None:
    """rs274 refuses it ("Spindle not turning in G95"); a Fanuc waits forever: neither is a toolpath."""
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(HEAD + body), io.StringIO(), file="t.nc", source="fanuc", target=target)
    assert [str(e) for e in exc.value.errors] == [message]


def test_a_feed_per_revolution_move_runs_once_the_spindle_turns() -> None:
    """The spindle start in the same block acts before the motion; the stop beside the last cut after it."""
    program = HEAD + "G95 S500 M03 G01 X5. F0.2\nX6. M05\nG00 X0.\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="linuxcnc")
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source="fanuc", target="linuxcnc", tolerance=0.0)
    assert report.ok


def test_a_bare_feed_code_without_feed_is_not_written_for_mach3() -> None:
    """Mach3's reader refuses ``G1`` with no feed rate in force (RS274/NGC): the bare code sets only the
    mode, so it goes (as for LinuxCNC and grbl) and the output reads back."""
    out = io.StringIO()
    translate(io.StringIO(HEAD + "G01\n"), out, file="t.nc", source="fanuc", target="mach3")
    assert out.getvalue() == "G21 G90 G0 X0.0000 Y0.0000 Z10.0000\n(G01)\n"
    translate(io.StringIO(out.getvalue()), io.StringIO(), file="back.nc", source="mach3", target="mach3")


def test_a_fanuc_dwell_split_from_its_move_keeps_the_spindle_start_before_it() -> None:
    """make fuzz: LinuxCNC 'G04 M03 P500 X0.0005' (spindle, dwell, move) became Fanuc 'G04 X500.' then
    'G00 X0.0005 M03': the dwell ran before the spindle started."""
    program = HEAD + "G04 M03 P500 X0.0005\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.ngc", source="linuxcnc", target="fanuc")
    assert out.getvalue().splitlines()[1:4] == ["M03", "G04 X500.", "G00 X0.0005"]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.ngc", file_out="b.nc",
                          source="linuxcnc", target="fanuc", tolerance=0.0)
    assert report.ok, report.summary()


_COMPUTED_REPEAT = HEAD + "#1=5.\nG99 G81 X1. Y1. Z-5. R2. F100.\nX#1 Y2.\nG80\nG02 X7. Y2. R1.\nM30\n"
"""A computed hole repeating a numeric cycle (an internal TypeError in both builds, found by a helper), then
an arc from where that hole leaves the tool (X5 Y2): valid there, impossible from the first hole (X1 Y1)."""


def test_a_computed_hole_repeating_a_cycle_travels_verbatim_to_fanuc() -> None:
    out = io.StringIO()
    translate(io.StringIO(_COMPUTED_REPEAT), out, file="t.nc", source="fanuc", target="fanuc")
    assert out.getvalue() == _COMPUTED_REPEAT  # kept: the hole, and the tool after it, known when it runs


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_a_computed_hole_repeating_a_cycle_is_flattened_where_the_cycle_is_expanded(target: str) -> None:
    out = io.StringIO()
    translate(io.StringIO(_COMPUTED_REPEAT), out, file="t.nc", source="fanuc", target=target)
    assert "X5. Y2." in out.getvalue()  # the computed hole, evaluated
    report = verify_lines(io.StringIO(_COMPUTED_REPEAT), io.StringIO(out.getvalue()), file_in="a.nc",
                          file_out="b.ngc", source="fanuc", target=target, tolerance=0.0)
    assert report.ok, report.summary()


@pytest.mark.parametrize("source, program, expected", [
    # hypothesis (tests/test_isg_fuzz.py): a continued ISG line assigning beside a move became Fanuc
    # '#501=2. G01 X10.', which Fanuc (and our Fanuc reader) refuses: a macro statement stands alone
    ("isg", "G71 G90 G00 X0 Y0 Z10 F100\nP1=1\nG01 X10 \\\nP1=2\n", ["G01 X10.", "#501=2."]),
    # LinuxCNC reads a line's words before it sets its parameters: X#1 is the old #1 (5)
    ("linuxcnc", "G21 G90 G0 X1 Y0 Z10\n#1=5\n#1=2 G1 X#1 F100\nG1 Y#1\nM2\n",
     ["G01 X#1 F100.", "#1=2.", "G01 Y#1"]),
])
def test_an_assignment_beside_words_goes_after_them_on_its_own_fanuc_line(source: str, program: str,
                                                                          expected: list[str]) -> None:
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source=source, target="fanuc")
    lines = out.getvalue().splitlines()
    start = lines.index(expected[0])
    assert lines[start:start + len(expected)] == expected
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source=source, target="fanuc", tolerance=0.0)
    assert report.ok and report.moves >= 2, report.summary()


def test_a_tool_change_that_turns_compensation_on_is_written() -> None:
    """rs274 changes the tool (order 6) before it turns compensation on (15): ``G41 M6`` from off runs."""
    out = io.StringIO()
    translate(io.StringIO(HEAD + "T1 G41 D01 M06\nG40\nM30\n"), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert "G41 D01 T1 M6" in out.getvalue().splitlines()


PAST_END = [
    # make fuzz (isg fragments): the Fanuc output jumped to a block it had commented out after M30
    ("isg", "fanuc", "G71 G90 G00 X0 Y0 Z10 F100\nP1=1\n$GOTO N20\nG70\nM30\nN20: G00 Z5\n",
     "t.nc:3:1: error: '$GOTO N20' jumps to line 6, past the end of the program at line 5: where a controller "
     "runs from there is not modelled"),
    # flattened for LinuxCNC, the run ended at the jump: Fanuc's move to Z5 after M30 went missing
    ("fanuc", "linuxcnc", "G21 G90 G00 X0 Y0 Z10\n#1=1\nGOTO 20\nM30\nN20 G00 Z5\nM30\n",
     "t.nc:3:1: error: 'GOTO 20' jumps to line 5, past the end of the program at line 4: where a controller "
     "runs from there is not modelled"),
]


@pytest.mark.parametrize("source, target, program, message", PAST_END)
def test_a_jump_past_the_program_end_is_a_located_error(source: str, target: str, program: str,
                                                          message: str) -> None:
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source=source, target=target)
    assert [str(e) for e in exc.value.errors] == [message]


@pytest.mark.parametrize("source", ["grbl", "grblhal"])
def test_a_grbl_arc_with_no_axis_word_is_refused_where_it_stands(source: str) -> None:
    """make fuzz (program options): 'G2 I7.5 J7.5' was read by the grbl readers as a full circle and copied to
    the grbl output, where grbl 1.1 refuses it (gcode.c: an arc without axis words, error 26); grblHAL too."""
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(HEAD + "G2 I7.5 J7.5 F100.\nM2\n"), io.StringIO(), file="t.nc", source=source,
                  target=source)
    control = "grbl" if source == "grbl" else "grblHAL"
    assert [str(e) for e in exc.value.errors] == [
        f"t.nc:2:1: error: {control} refuses an arc with no axis word (its centre alone, error 26): program its "
        "end point (the start point, for a full circle)"]
    out = io.StringIO()  # the full circle grbl runs: its end point (the start) programmed
    translate(io.StringIO(HEAD + "G2 X0 I7.5 J7.5 F100.\nM2\n"), out, file="t.nc", source=source, target=source)
    assert "G2 X0 I7.5 J7.5 F100." in out.getvalue()


def test_verify_pairs_compensation_sides_under_a_transform_that_mirrors() -> None:
    """make fuzz (program options): under 'mirror x' translate writes G41 as G42 (the path runs the other way
    round the part); verify compared IN's 'left' with OUT's 'right' and failed the right translation. The
    mirrored output with G41 kept (the wrong side) must still fail."""
    from postproc.transforms.spec import parse_transform
    program = HEAD + "G41 D01 G1 X10. Y-16. F100.\nX20.\nG40 G0 X0. Y0.\nM30\n"
    mirror = parse_transform("mirror x")
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="linuxcnc", target="fagor", transform=mirror)
    text = out.getvalue()
    assert "G42 D01" in text and "G41" not in text, text

    def verified(output: str) -> bool:
        return verify_lines(io.StringIO(program), io.StringIO(output), file_in="a.ngc", file_out="b.nc",
                            source="linuxcnc", target="fagor", tolerance=1e-3, transform=mirror).ok

    assert verified(text)
    assert not verified(text.replace("G42 D01", "G41 D01"))
    rotate = parse_transform("rotate 90")  # no mirror: the side stays
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="linuxcnc", target="fagor", transform=rotate)
    assert "G41 D01" in out.getvalue()
    assert verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.ngc", file_out="b.nc",
                        source="linuxcnc", target="fagor", tolerance=1e-3, transform=rotate).ok


LATHE_SETUP = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"))


@pytest.mark.parametrize("source", ["grbl", "mach3"])
@pytest.mark.parametrize("on_unsupported", ["error", "warn"])
@pytest.mark.parametrize("lathe_source", ["linuxcnc", "grblhal"])
def test_a_mill_program_on_a_lathe_set_up_is_refused_for_fanuc(source: str, on_unsupported: str,
                                                               lathe_source: str) -> None:
    """make fuzz (new words): grbl 'G21 G90 G0 X0. Z10.' on a lathe set-up became Fanuc 'G21 G90 G00 X0. Z10.',
    which Fanuc T (the set-up's reading) takes as a G90 turning cycle; with --on-unsupported warn the line
    'G21 G90' was kept alone. LinuxCNC and grblHAL (its lathe mode) read their own programs with lathe
    meanings, and are still written."""
    program = "G21 G90 G0 X0. Z10.\nG1 X5. F100.\nM30\n"
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source=source, target="fanuc", setup=LATHE_SETUP,
                  on_unsupported=on_unsupported, diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert [str(e) for e in exc.value.errors] == [
        "t.nc:1:1: error: a milling program on a lathe set-up: the fanuc lathe reads its words with lathe meanings "
        "(a mill's distance and feed mode codes are its turning and facing cycles); read it with a dialect that "
        "has lathe meanings, or with a mill set-up"]
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source=lathe_source, target="fanuc", setup=LATHE_SETUP)
    assert out.getvalue() == "G21 G98 G00 X0. Z10.\nG01 X5. F100.\nM30\n"


def test_the_lathe_lowerings_refusals_come_in_the_error_list() -> None:
    """make fuzz (new words): a W move from an unknown Z, towards a target without W, escaped translate as a
    bare UnsupportedError (the first one alone, not an ErrorList); now every such block is reported."""
    program = "G21 G98 G0 X10.\nW-1.\nU2. W-1.\nM30\n"
    with pytest.raises(ErrorList) as exc:
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source="fanuc", target="grbl",
                  setup=LATHE_SETUP)
    assert [str(e) for e in exc.value.errors] == [
        "t.nc:2:1: error: an incremental W move from an unknown position (the target has no W address: program an "
        "absolute Z first)",
        "t.nc:3:1: error: an incremental W move from an unknown position (the target has no W address: program an "
        "absolute Z first)"]


def test_a_percent_after_a_comment_is_no_opening_one_for_linuxcnc() -> None:
    """make fuzz (malformed input, caught by the suite's rs274 check): Fanuc '(C)', '%', ... ends at the '%'
    (the blocks after it are commented); LinuxCNC got '(C)' then '%', which rs274 refuses ("Bad character '%'
    used": a '%' opens a file only on its first line). The program ends there: M2, the '%' as a comment."""
    program = "(C)\n%\nG0 X1.\nM30\n%\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="linuxcnc",
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert out.getvalue().splitlines()[:3] == ["(C)", "M2", "(%)"]
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.ngc",
                          source="fanuc", target="linuxcnc", tolerance=0.0)
    assert report.ok, report.summary()
    out = io.StringIO()  # a '%' on the first line still opens the program
    translate(io.StringIO("%\n(C)\nG0 X1.\nM30\n%\n"), out, file="t.nc", source="fanuc", target="linuxcnc")
    assert out.getvalue() == "%\n(C)\nG21 G0 X1.\nM30\n%\n"  # G21: tests/test_units_at_start.py


def test_a_source_with_cr_line_ends_reaches_linuxcnc_with_lf() -> None:
    """make fuzz (malformed input): a Fanuc file with CR line ends (kept as read) became a LinuxCNC file with
    CR line ends, one long line for rs274 ("Command too long"); CR LF stays CR LF."""
    out = io.StringIO()
    translate(io.StringIO("G21 G90 G0 X0. Y0. Z10.\rG1 X5. F100.\rM30\r", newline=""), out, file="t.nc",
              source="fanuc", target="linuxcnc")
    assert out.getvalue() == "G21 G90 G0 X0. Y0. Z10.\nG1 X5. F100.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO("G21 G90 G0 X0. Y0. Z10.\r\nM30\r\n", newline=""), out, file="t.nc", source="fanuc",
              target="linuxcnc")
    assert out.getvalue() == "G21 G90 G0 X0. Y0. Z10.\r\nM30\r\n"



def test_a_copy_that_fails_to_run_as_its_source_does_is_refused_as_the_simulation_refuses_it() -> None:
    """Hypothesis (mach3 -> mach3): ``G41`` with no register before any tool change (which tool is in the spindle
    is not known). A copy keeps compensation native, and was written as it stands while verify then failed the
    same way on both sides (which the fuzz test excused for a copy, ``same_run_error``); since issue 26's comp26
    the copy computes the compensated path as the simulation does and refuses it with the simulation's error."""
    from tests.support.fuzzing import check_translation

    program = "G21 G90 G0 X0. Y0. Z10.\nG41\nG1 X10. F100.\nM30\n"
    assert check_translation("mach3", "mach3", program, MachineSetup(), False) == "refused"
    with pytest.raises(ErrorList) as simulated:
        list(toolpath_events(io.StringIO(program), file="in.nc", dialect="mach3", setup=MachineSetup()))
    with pytest.raises(ErrorList) as copied:
        translate(io.StringIO(program), io.StringIO(), file="in.nc", source="mach3", target="mach3")
    assert [str(e) for e in copied.value.errors] == [str(simulated.value.errors[0])]


def test_the_options_fuzz_spells_an_isg_dwell_with_x() -> None:
    """make fuzz ('options isg-isg'): the generator's ``G4 P1`` reached ISG as written, where ``P1`` is a parameter
    (ISG dwells with ``G04 X`` [K: DIALECTS.md, the ISG writer's DWELL_WORD]): verify refused the unset read on both
    sides, as every evaluating translation does (located). The generator now spells the dwell in ISG's words; the
    copy of the spelled program verifies, with its one-second dwell (hand-derived)."""
    from tests.support.generators.program_options import spelled

    program = spelled("isg", "G21 G17 G90 G94\nG0 X0. Y0. Z10.\nG4 P1\nM30\n")
    assert program == "G71 G17 G90 G94\nG0 X0. Y0. Z10.\nG04 X1\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="isg", target="isg")
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="a.nc", file_out="b.nc",
                          source="isg", target="isg", tolerance=0.0)
    assert report.ok, report.summary()
    dwells = [e for e in toolpath_events(io.StringIO(program), file="in.nc", dialect="isg") if e.get("event") == "dwell"]
    assert [d.get("seconds") for d in dwells] == [1.0], dwells
    with pytest.raises(ErrorList, match="in.nc:3:1: error: P1 is read before it is set"):
        translate(io.StringIO(program.replace("G04 X1", "G4 P1")), io.StringIO(), file="in.nc", source="isg",
                  target="fanuc")


def test_an_arc_below_rs274s_smallest_radius_is_refused_for_linuxcnc() -> None:
    """make fuzz (fagor patterns, a G163 of radius 0.001 mm): LinuxCNC got G2 .. I0.001 J0., which rs274 refuses
    ("Zero-radius arc": a radius below MIN_CENTER_ARC_RADIUS_TOLERANCE_MM, 0.001, interp_internal.hh [V]); now a
    located error. Its inch twin: 0.00004 in."""
    for units, arc in (("G21", "G2 X20.001 Y0.001 I0.001 J0."), ("G20", "G2 X20.00004 Y0.00004 I0.00004 J0.")):
        program = f"G17 {units} G90\nG0 X20. Y0. Z50.\nF100.\n{arc}\nM30\n"
        with pytest.raises(ErrorList) as exc:
            translate(io.StringIO(program), io.StringIO(), file="t.nc", source="fanuc", target="linuxcnc",
                      diagnostics=Diagnostics(warn_stream=io.StringIO()))
        assert str(exc.value.errors[0]).startswith("t.nc:4:1: error: the linuxcnc dialect cannot express an arc of zero")
    out = io.StringIO()  # twice the smallest radius runs (rs274 accepts I0.002: above its tolerance)
    translate(io.StringIO("G17 G21 G90\nG0 X20. Y0. Z50.\nF100.\nG2 X20.002 Y0.002 I0.002 J0.\nM30\n"), out,
              file="t.nc", source="fanuc", target="linuxcnc", diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert "I0.002" in out.getvalue()


TINY = "G21 G90 G0 X0 Y0 Z5\nG1 X0.9999954 F100\nG1 X1\nG1 X1.0001\nM2\n"
"""A feed of 0.0000046 mm (fuzz, grblhal targets: ``COS[SIN[10]]`` then ``X[0.5+0.5]``), then one of 0.0001 mm."""


@pytest.mark.skipif(not rs274_available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_rs274_comparison_drops_the_moves_rs274_prints_as_standing_still() -> None:
    """rs274 prints 4 decimals: the 0.0000046 mm feed ends where the one before it printed, so ``canonical_moves``
    drops it, and the fuzz's comparison with a toolpath (6 decimals) does too; the 0.0001 mm feed stays on both."""
    theirs = [e for e in canonical_moves(run_rs274(TINY), start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = [e for e in toolpath_events(io.StringIO(TINY), file="t.ngc", dialect="linuxcnc") if "move" in e]
    assert len(ours) == 4 and len(theirs) == 3, (ours, theirs)
    printed = as_rs274_prints(ours)
    assert [(m["move"], round(m["x"], 4)) for m in printed] == [(m["move"], round(m["x"], 4)) for m in theirs] \
        == [("rapid", 0.0), ("feed", 1.0), ("feed", 1.0001)]
    program = ("%\nO0001\nG21 G90 G0 X0 Y0 Z5.\n#26=1\n#101=10.\nG1 X[ABS[#26]*COS[SIN[#101]]] Z-0.5 F200.\n"
               "G1 X[0.5+0.5] Z-0.5 F200.\nM30\n%\n")
    assert grblhal_check("fanuc", program, "everything") == "ok"


def test_a_gsk_program_for_grblhal_on_a_mill_set_up_is_checked_in_lathe_mode() -> None:
    """GSK is a lathe whatever the set-up says (docs/dialects.md), so its grblHAL output runs in grblHAL's lathe
    mode (``G18 G7``), as ``output_rules.problems(source=...)`` and ``verify`` have it; the suite's automatic
    check of every grblHAL output (``output_rules.install``) judged it on the set-up's mill and reported "G7
    outside lathe mode" (a false failure of test_fuzz_generators' malformed input, found in a random run). This
    translation fails at teardown (``_outputs_valid_on_their_controllers``) if that comes back."""
    program = "%\nO0102\nG21 G98\nG28 U0. W0.\nG97 S600 M03\nG00 X52. Z-20.\nG01 X40. F40.\nM30\n%\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="o0102.nc", source="gsk", target="grblhal", setup=with_tools(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert "G18 G7" in out.getvalue()


def test_an_isg_program_header_inside_the_program_is_a_comment_for_linuxcnc_normalized() -> None:
    """make fuzz (pairs, isg-linuxcnc, --normalize): an ISG program header after the first line ("% G87", a
    program named G87) was copied as read, "% G87", which rs274 refuses ("Bad character '%' used": a '%' line
    is only the file's first or last) [V: rs274 2.9]. It is the name as a comment, as without --normalize."""
    program = "G90 G0 X0. Y0. Z10.\nG1 X1 F10\n% G87\nX3\nM30\n"
    setup = MachineSetup()
    written = []
    for normalize in (False, True):
        setup.output.normalize = normalize
        out = io.StringIO()
        translate(io.StringIO(program), out, file="t.nc", source="isg", target="linuxcnc", setup=setup)
        written.append(out.getvalue())
    assert written[1] == written[0] == "G21 G90 G0 X0. Y0. Z10.\nG1 X1. F10.\n(G87)\nG1 X3.\nM30\n"
    if rs274_available():
        run_rs274(written[1])  # raises where rs274 refuses the program


LATHE = with_tools(MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ")))
GRBL_ON_A_LATHE = "G21 G0 X0 Z10\nG1 X1 F100\n"


def test_the_power_on_exact_path_for_a_lathe_without_path_codes_is_warned_of_and_listed_by_verify() -> None:
    """make fuzz (new words, grblhal-gsk, lathe set-up): grblHAL runs in the exact path from power-on [V: grbl
    gcode.h]; a GSK lathe has no path control code [?] (``postproc.lowering.path_at_start``): not written, with a
    warning, and verify lists the difference. The fuzz took that for a defect; it is one the translation warned
    of, as the lathe tool offset a mill control cannot apply."""
    out = io.StringIO()
    warnings = io.StringIO()
    translate(io.StringIO(GRBL_ON_A_LATHE), out, file="t.nc", source="grblhal", target="gsk", setup=LATHE,
              diagnostics=Diagnostics(warn_stream=warnings))
    assert out.getvalue() == "G21 G00 X0. Z10.\nG01 X1. F100.\n"
    assert "t.nc:1:1: warning: the grblhal controller runs this program in the exact path mode from power-on; a " \
           "gsk lathe has no path control code here [?]" in warnings.getvalue()
    report = verify_lines(io.StringIO(GRBL_ON_A_LATHE), io.StringIO(out.getvalue()), file_in="in.nc",
                          file_out="out.nc", source="grblhal", target="gsk", setup=LATHE, tolerance=0.0)
    assert not report.ok and "path control differs: IN exact path (line 1); OUT never set" in report.summary()
    assert check_translation("grblhal", "gsk", GRBL_ON_A_LATHE, LATHE, False) == "warned: lathe path control"


def test_a_path_control_difference_nobody_warned_of_is_a_defect() -> None:
    message = ("translated, but verify says: max deviation 0.0000 mm over 2 moves (IN:1 / OUT:1): settings that "
               "move the tool differ (listed below; --allow-ignored accepts them)\nnot compared:\n"
               "  path control differs: IN exact path (line 2); OUT never set\nG21 G00 X0. Z10.\n")
    warned = "t.nc:2:1: warning: ... a gsk lathe has no path control code here [?]: not written"
    assert warned_difference(message, [warned]) == "lathe path control"
    assert warned_difference(message, ["t.nc:1:1: warning: something else"]) is None
    assert warned_difference(message, []) is None
    other = message.replace("  path control differs", "  work offset differs")
    assert warned_difference(other, [warned]) is None


def test_a_machine_move_under_incremental_distance_of_unknown_meaning_is_kept_by_a_copy_and_refused_elsewhere() -> None:
    """make fuzz (mach3-mach3): Mach3's G53 under G91 is kept verbatim [?] (``MACHINE_MOVE_INCREMENTAL``): the copy
    is byte for byte, and its verify refuses both sides, located at the line (it cannot compare what is not known),
    which the fuzz counts as that outcome, no longer as a listed defect; another target refuses it, located."""
    program = HEAD + "G53 G91 Y2.5\nG90 G1 X5. Y5. F100.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="mach3", target="mach3")
    assert out.getvalue() == program
    with pytest.raises(ErrorList) as verified:
        verify_lines(io.StringIO(program), io.StringIO(program), file_in="in.nc", file_out="out.nc", source="mach3",
                     target="mach3")
    unknown = ("2:1: error: G53 in incremental distance mode (machine positions, increments or ignored: not known for "
               "this controller [?]) cannot be simulated")
    assert [str(e) for e in verified.value.errors] == ["in.nc:" + unknown, "out.nc:" + unknown]
    assert check_translation("mach3", "mach3", program, with_tools(MachineSetup()), False) == UNKNOWN_MEANING_OUTCOME
    assert check_translation("mach3", "mach3", HEAD + "G53 G91 Y2.5\n", with_tools(MachineSetup()),
                             False) == UNKNOWN_MEANING_OUTCOME
    with pytest.raises(ErrorList) as refused:
        translate(io.StringIO(program), io.StringIO(), file="t.nc", source="mach3", target="linuxcnc")
    assert [str(e) for e in refused.value.errors] == [
        "t.nc:2:1: error: G53 in incremental distance mode (machine positions, increments or ignored: not known for "
        "this controller [?]) from mach3 has no equivalent in linuxcnc"]


@pytest.mark.parametrize("word", ["T[1/0]", "T[2+1]"])
def test_a_computed_lathe_t_word_is_refused_by_the_simulator_where_it_stands(word: str) -> None:
    """``make fuzz`` (malformed GSK, 2026-12-01): a GSK lathe program's ``T[1/0]`` reached the simulator's turret
    as an expression and ``toolpath`` and ``info`` ended in an internal error (TypeError), where a translation
    refuses the word ("a computed lathe T word"). The simulator now refuses it too, at the T word."""
    program = f"%\n{word}\nG0 X10. Z5.\n%\n"
    with pytest.raises(ErrorList) as exc:
        for _ in toolpath_events(io.StringIO(program), file="t.nc", dialect="gsk", setup=with_tools(),
                                 diagnostics=Diagnostics(warn_stream=io.StringIO())):
            pass
    assert [str(e) for e in exc.value.errors] == [
        "t.nc:2:1: error: a computed lathe T word cannot be simulated (the tool and offset it selects are known "
        "when the program runs)"]
