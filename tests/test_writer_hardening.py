"""Writer defects the fuzz suite found (``tests/support/fuzzing.py``), each pinned: output the target's own
reader refused, or that ``verify`` rejected. Expected texts are derived by hand from the targets' rules
(RS274/NGC: G80 is a motion code; LinuxCNC: M19 takes R, orients before the block's motion and shares
M5's modal group; grbl: M0 runs last in its block); LinuxCNC outputs also run in the real interpreter.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine_setup import MachineSetup, OutputSettings
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274

HEAD = "G21 G90 G00 X0. Y0. Z10.\n"
HEAD_OUT = "G21 G90 G0 X0. Y0. Z10.\n"


def write(source: str, target: str, program: str, setup: MachineSetup | None = None) -> tuple[str, list[str]]:
    """Translate ``HEAD + program``; the text after the head line, the warnings. The output must be read
    by the target's reader and verify against the source at zero tolerance. A fragment has no end: the
    M2 a LinuxCNC output gets for it (``test_program_end.py``) is checked and left out here."""
    setup = setup or MachineSetup()
    out = io.StringIO(newline="")
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    translate(io.StringIO(HEAD + program, newline=""), out, file="t.nc", source=source, target=target,
              setup=setup, diagnostics=diagnostics)
    text = out.getvalue()
    read_program(io.StringIO(text), file="out.nc", dialect=target, setup=setup)
    report = verify_lines(io.StringIO(HEAD + program), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                          source=source, target=target, setup=setup, tolerance=0.0)
    assert report.ok, report.summary()
    head, _, rest = text.partition("\n")
    assert head.split() == ["G21", "G90", "G0" if source != target else "G00", "X0.", "Y0.", "Z10."], text
    warnings = [str(w) for w in diagnostics.warnings]
    if target == "linuxcnc" and source != target and "M30" not in program and "M02" not in program:
        assert rest.endswith("M2\n") and "the program has no end" in warnings.pop(), (rest, warnings)
        rest = rest[:-len("M2\n")]
    return rest, warnings


def errors(source: str, target: str, program: str) -> list[str]:
    with pytest.raises(ErrorList) as info:
        write(source, target, program)
    return [str(e) for e in info.value.errors]


def rs274_accepts(program: str) -> None:
    if not available():
        pytest.skip("the LinuxCNC interpreter rs274 is not installed")
    run_rs274(HEAD_OUT + program + "M2\n")


# -- G80 beside a motion code (RS274/NGC: one modal group) --------------------------------------------

@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_a_cycle_cancel_with_motion_is_written_as_the_motion_code_alone(target: str) -> None:
    """Fanuc's G80 is its own group; on RS274/NGC G80 and G0 in one block are an error, and the motion
    code ends the cycle by itself."""
    text, _ = write("fanuc", target, "G80 Y2.5\nG80 G00 X3.\nG80 G01 X4. F100.\nG80 G53 X1.\n")
    assert text == "G0 Y2.5\nG0 X3.\nG1 X4. F100.\nG53 G0 X1.\n"


def test_a_cycle_cancel_beside_a_reference_return_stays() -> None:
    """G28 is not a motion-group code: ``G80 G28`` is valid RS274/NGC (rs274 runs it)."""
    text, _ = write("fanuc", "linuxcnc", "G80 G28 Z10.\nX4.\n")
    assert text == "G80 G28 Z10.\nG0 X4.\n"
    rs274_accepts(text)


# -- grbl's manual tool change -------------------------------------------------------------------------

def test_a_tool_change_pause_runs_before_the_rest_of_its_block() -> None:
    """grbl runs M0 after the block's spindle codes, motion and M30: the pause gets a block of its own, first,
    and a running spindle is stopped in it (grbl's M0 leaves it turning)."""
    text, warnings = write("fanuc", "grbl", "S100 M03\nN10 T2 M06 M04 G01 X1. F100.\nT3 M06 M30\n")
    assert text == ("S100 M3\n"
                    "N10 T2 M5 M0 (TOOL CHANGE: LOAD T2, THEN CYCLE START)\n"
                    "G1 X1. F100. M4\n"
                    "T3 M5 M0 (TOOL CHANGE: LOAD T3, THEN CYCLE START)\n"
                    "M30\n")
    assert warnings == [
        "t.nc:3:1: warning: the spindle is running at a tool change: a spindle stop is written before the pause",
        "t.nc:4:1: warning: the spindle is running at a tool change: a spindle stop is written before the pause"]


def test_a_spindle_stop_beside_the_tool_change_goes_into_the_pause() -> None:
    text, warnings = write("fanuc", "grbl", "S100 M03\nT2 M05 M06 (A)\n")
    assert text == "S100 M3\nT2 M5 M0 (TOOL CHANGE: LOAD T2, THEN CYCLE START) (A)\n"
    assert warnings == []


def test_a_tool_change_with_no_tool_selected_is_refused_for_grbl() -> None:
    """A bare ``M0`` reads back as a plain stop: the pause must name the tool, and there is none."""
    assert errors("fanuc", "grbl", "M06\n") == [
        "t.nc:2:1: error: the grbl dialect cannot express a tool change with no tool selected (grbl's manual "
        "tool change, T<n> M0, names the tool to load: program T before M6)"]


# -- LinuxCNC's M19 -------------------------------------------------------------------------------------

def test_m19_goes_after_the_blocks_motion_in_a_block_of_its_own() -> None:
    """LinuxCNC reads M19's R as the angle (so not beside I/J/K or an R arc) and orients before the block's
    motion (rs274 prints ORIENT_SPINDLE before STRAIGHT_TRAVERSE): the neutral order is motion first."""
    text, _ = write("fanuc", "linuxcnc", "G02 X2. I1. F100. M19\nG03 X0. R1. M19\nG00 X2. M19 M09\n")
    assert text == ("G2 X2. I1. F100.\nM19 R0.\n"
                    "G3 X0. R1.\nM19 R0.\n"
                    "G0 X2.\nM19 R0. M9\n")  # coolant off after the move too (order_of_execution), and
    # after the orientation: LinuxCNC runs M19 (group 7) before M9 (group 8), as the simulator orders them
    rs274_accepts(text)


def test_m19_leaves_a_spindle_code_of_its_modal_group() -> None:
    """rs274: 'Two m codes used from same modal group' for ``M5 M19``."""
    text, _ = write("fanuc", "linuxcnc", "S100 M03\nM05 M19\nN5 M19 M30 (END)\n")
    assert text == "S100 M3\nM5\nM19 R0.\nN5 M19 R0. M30 (END)\n"
    rs274_accepts(text.replace("M30", ""))


# -- rounding in incremental mode -------------------------------------------------------------------------

@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_incremental_words_carry_what_rounding_left_so_positions_stay_exact(target: str) -> None:
    """Each -0.0000004 rounds to 0 on its own: three of them must reach -0.000001 (the source is at
    -0.0000012), not stay at 0."""
    text, _ = write("fanuc", target, "G91 G00 X5.\nY-0.0000004\nY-0.0000004\nY-0.0000004 X0.0000004\nG90 X6.\n")
    g = "G0" if target != "fanuc" else "G00"
    assert text == f"G91 {g} X5.\n{g} Y0.\n{g} Y-0.000001\n{g} Y0. X0.\nG90 {g} X6.\n"


def test_normalising_carries_too() -> None:
    setup = MachineSetup(output=OutputSettings(normalize=True))
    text, _ = write("linuxcnc", "linuxcnc", "G91 G0 Y-0.0000004\nY-0.0000004\nY-0.0000004 X0.5\n", setup)
    assert text == "G91 G0 Y0.\nY-0.000001\nY0. X0.5\n"


def test_an_arc_centre_is_measured_from_the_written_start() -> None:
    """The written start X-0.000001 is 0.0000002 beyond the source's X-0.0000008: I1.0000004 alone would round
    to 1. and put the centre 0.0000006 off; from the written start it is I1.000001, the centre exact to 0.0000004."""
    text, _ = write("fanuc", "linuxcnc", "G91 G00 X-0.0000004\nX-0.0000004\nG90 G02 X2. I1.0000004 F100.\n")
    assert text == "G91 G0 X0.\nG0 X-0.000001\nG90 G2 X2. I1.000001 F100.\n"


# -- G53 without a move --------------------------------------------------------------------------------

@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_machine_coordinates_without_a_move_are_not_written(target: str) -> None:
    """G53 alone does nothing on Fanuc; RS274/NGC refuses it unless G0/G1 is in force (rs274: "Must use g0
    or g1 with g53"), which after an arc it is not."""
    text, _ = write("fanuc", target, "G02 X1. Y1. R1. F100.\nG53\nG53 G80\nG00 G53 X1.\n")
    # a line left with no words keeps its source as a comment; grbl writes no G80 (it runs no cycles)
    cancel = "(G53 G80)" if target == "grbl" else "G80"
    assert text == f"G2 X1. Y1. R1. F100.\n(G53)\n{cancel}\nG53 G0 X1.\n"


@pytest.mark.parametrize("dialect", ["linuxcnc", "grbl"])
def test_the_ngc_readers_refuse_g53_alone_under_an_arc_mode(dialect: str) -> None:
    from postproc.simulate.toolpath import toolpath_events
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO("G21 G2 X1. Y1. R1. F100.\nG53\n"), file="t.ngc", dialect=dialect))
    assert [str(e) for e in info.value.errors] == ["t.ngc:2:1: error: G53 needs G0 or G1 in force"]
