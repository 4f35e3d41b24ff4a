"""grbl's own lowering steps (``Grbl.LOWERING``): pure block-stream rewrites, each checked on its own
stream and, where the writer's old inline rewrite missed a case, end to end (outputs derived by hand).
grbl lists them fused into one pass (``lower_for_lean_controller``): random programs of what the steps
rewrite, mixed with CAM moves, come out of it as out of the four steps chained."""

from __future__ import annotations

import io

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from postproc.api import read_blocks, translate
from postproc.cycles.lowering import expand_canned_cycles
from postproc.errors import Diagnostics, ErrorLevel
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines
from postproc.rs274.order_of_execution import stops_after_motion
import postproc_grbl
from postproc_grbl import Grbl, drop_resolved_tool_data, resolve_cutter_compensation, write_tool_lengths
from postproc.rs274.lean_controller import (
    cancel_length_offset_first, close_full_circles, lower_for_lean_controller, pause_for_tool_change,
)

FANUC = default_registry().dialect("fanuc")


def fanuc_blocks(text: str) -> tuple[list[Block], Diagnostics]:
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    ctx, blocks = read_blocks(text.splitlines(keepends=True), "t.nc", FANUC, MachineSetup(), diagnostics)
    return list(pause_for_tool_change(cancel_length_offset_first(close_full_circles(
        iter(list(blocks)), ctx, Grbl), ctx, Grbl), ctx, Grbl)), diagnostics


def test_grbl_declares_its_steps() -> None:
    assert Grbl.LOWERING == (write_tool_lengths, resolve_cutter_compensation, drop_resolved_tool_data,
                             postproc_grbl.lower_for_lean_controller)  # lean_controller's, imported when first run
    assert "LOWERING" not in Grbl.capabilities()


def test_tool_change_becomes_a_pause_with_the_spindle_stopped() -> None:
    blocks, diagnostics = fanuc_blocks("T3\nS1000 M03\nM06 (DRILL)\n")
    change = blocks[2]
    assert change.text is None and "ToolChange" not in change.sections
    assert [k for k in change.sections] == ["ToolSelect", "SpindleControl", "ProgramControl", "Comments"]
    assert change.sections["Comments"].texts == ["TOOL CHANGE: LOAD T3, THEN CYCLE START", "DRILL"]  # type: ignore[attr-defined]
    assert [w.message for w in diagnostics.warnings] == [
        "the spindle is running at a tool change: a spindle stop is written before the pause"]


def test_length_offset_cancel_goes_first_also_before_an_arc() -> None:
    """grbl refuses G49 beside any motion word (arcs too): hand-derived from grbl's gcode.c rule."""
    out = io.StringIO()
    translate(io.StringIO("G21 G17 G90\nG00 X10. Y0. Z5.\nG49 G02 X0. Y10. I-10. F100.\n"), out, file="t.nc",
              source="fanuc", target="grbl")
    assert out.getvalue().splitlines()[2:] == ["G49", "G2 X0. Y10. I-10. F100."]


def test_steps_leave_a_grbl_program_to_grbl() -> None:
    diagnostics = Diagnostics(ErrorLevel.RAISE)
    ctx, blocks = read_blocks(["G3 I-7. F100.\n"], "t.gcode", Grbl, MachineSetup(), diagnostics)
    stream = iter(list(blocks))
    assert close_full_circles(stream, ctx, Grbl) is stream


LINES = (
    "G01 X1. Y2. F300.", "X3. Y-1.", "G00 Z5.", "N10 G01 X2.", "G02 X4. Y0. R2.", "G03 I-7.", "G02 J5. Z-1.",
    "G91", "G90", "G17", "G18", "G19", "G03 K2.", "T3", "T7 M06", "M06", "S1000 M03", "M04", "M05", "M19",
    "G01 X1. M05", "G00 Y2. M09", "M08", "G01 Z-1. M05 M09", "G49", "G49 G00 Z10.", "G49 G02 X0. Y10. I-10.",
    "G43 H3 Z20.", "M00", "M01", "G01 X5. M05 M00", "T4 M06 M03 S500", "/ T5 M06", "G04 X1.", "(NOTE)",
    "G81 X1. Y1. Z-2. R1. F100.", "X2.", "G80", "G02 X1. I.5 M05", "N20 T2 M06 (DRILL)",
    "G84 X1. Y1. Z-2. R1. F100.", "N30 Y3. (NEXT)", "G86 X2. Y2. Z-3. R1. F90.",
)


def _lowered(program: list[str], fused: bool, expanded: bool = False) -> tuple[list[Block], list[str]]:
    """The four steps fused or chained, on the blocks as read or with their cycles expanded first (as a
    translation to grbl runs them: an expanded hole is a block of its ``CompoundMotion`` alone)."""
    diagnostics = Diagnostics(ErrorLevel.WARN, warn_stream=io.StringIO())
    ctx, blocks = read_blocks([line + "\n" for line in program], "t.nc", FANUC, MachineSetup(), diagnostics)
    stream = iter(list(blocks))
    if expanded:
        stream = iter(list(expand_canned_cycles(stream, ctx, Grbl)))
    if fused:
        out = list(lower_for_lean_controller(stream, ctx, Grbl))
    else:
        for step in (pause_for_tool_change, cancel_length_offset_first, close_full_circles, stops_after_motion):
            stream = step(stream, ctx, Grbl)
        out = list(stream)
    return out, [w.message for w in diagnostics.warnings]


@pytest.mark.parametrize("expanded", [False, True])
@settings(max_examples=300, deadline=None)
@given(program=st.lists(st.sampled_from(LINES), min_size=1, max_size=14))
@example(program=["G00 X0. Y0. Z10.", "S1000 M03", "G84 X1. Y1. Z-2. R1. F100.", "N30 Y3. (NEXT)", "G80", "T7 M06"])
@example(program=["G00 X0. Y0. Z10.", "S1000 M03", "G86 X2. Y2. Z-3. R1. F90.", "X2.", "G80", "T3", "M06"])
def test_the_fused_pass_is_the_four_steps_chained(program: list[str], expanded: bool) -> None:
    fused, fused_warnings = _lowered(program, fused=True, expanded=expanded)
    chained, chained_warnings = _lowered(program, fused=False, expanded=expanded)
    assert fused == chained
    assert [b.eol for b in fused] == [b.eol for b in chained]
    assert fused_warnings == chained_warnings


def test_the_fused_pass_rewrites_what_each_step_rewrites() -> None:
    """One program that every step changes (so the property above compares rewrites, not copies);
    derived by hand from the steps' rules."""
    program = ["T3", "S1000 M03", "T3 M06", "G49 G00 Z10.", "G03 I-7. F100.", "G01 X1. M05"]
    fused, warnings = _lowered(program, fused=True)
    assert [(b.line, sorted(b.sections)) for b in fused] == [
        (1, ["ToolSelect"]),
        (2, ["SpindleControl", "SpindleSpeed"]),
        (3, ["Comments", "ProgramControl", "SpindleControl", "ToolSelect"]),  # T3 M5 M0 (TOOL CHANGE ...)
        (4, ["ToolLengthOffset"]),  # G49 first
        (4, ["Motion"]),
        (5, ["DistanceMode", "Feed", "Motion"]),  # G91 G3 X0. I-7. F100.
        (5, ["DistanceMode"]),  # G90 again
        (6, ["Motion"]),
        (6, ["SpindleControl"]),  # M5 after the move
    ]
    assert fused[5].sections["Motion"].axes == {"X": 0.0}  # type: ignore[attr-defined]
    assert [b.sections["DistanceMode"].mode for b in fused[5:7]] == ["incremental", "absolute"]  # type: ignore[attr-defined]
    assert warnings == ["the spindle is running at a tool change: a spindle stop is written before the pause"]


def test_a_stopped_spindles_stop_stays_where_the_source_runs_it() -> None:
    """Found by the fuzzer: ``M06 M05 M08 T1`` with the spindle stopped runs tool change, coolant on,
    spindle stop (a Fanuc or mach3 stop acts after the block's other actions). The pause took the block's
    M5, so grbl stopped the spindle before the coolant came on; the M5 now stays with the rest of the
    block (grbl runs ``M5 M8`` without motion as the source runs it: verify agrees). A running spindle's
    M5 still goes with the pause, before the operator reaches for the tool."""
    for source in ("fanuc", "mach3"):
        program = "G21 G90 G0 X0. Y0. Z10.\nM06 M05 M08 T1\n"
        out = io.StringIO()
        translate(io.StringIO(program), out, file="t.nc", source=source, target="grbl")
        assert out.getvalue().splitlines()[1:] == ["T1 M0 (TOOL CHANGE: LOAD T1, THEN CYCLE START)", "M5 M8"]
        report = verify_lines(program.splitlines(keepends=True), out.getvalue().splitlines(keepends=True),
                              file_in="t.nc", file_out="t.gcode", source=source, target="grbl")
        assert report.ok, report.summary()
    out = io.StringIO()
    translate(io.StringIO("G21 G90\nS1000 M03\nM06 M05 M08 T1\n"), out, file="t.nc", source="fanuc", target="grbl")
    assert out.getvalue().splitlines()[2:] == ["T1 M5 M0 (TOOL CHANGE: LOAD T1, THEN CYCLE START)", "M8"]


def test_an_expanded_tap_leaves_the_spindle_running_at_the_next_tool_change() -> None:
    """The pauses follow the spindle through an expansion (``ExpansionItems.spindle``): a G84 ends with its spindle
    forward again (reversed at the bottom, M3 back at R: the expansion's last spindle action), so a tool change after
    it stops the spindle first, with the warning, even where the program stopped it before the cycle; without the
    cycle the stopped spindle needs no stop. Derived from the steps' rules (``_pause``), not from a run."""
    program = ["G00 X0. Y0. Z10.", "M05", "G84 X1. Y1. Z-2. R1. F100.", "G80", "T3 M06"]
    out, warnings = _lowered(program, fused=True, expanded=True)
    pause = out[-1].sections
    assert sorted(pause) == ["Comments", "ProgramControl", "SpindleControl", "ToolSelect"]
    assert pause["SpindleControl"].direction == "stop"  # type: ignore[attr-defined]
    assert warnings == ["the spindle is running at a tool change: a spindle stop is written before the pause"]
    out, warnings = _lowered([program[0], program[1], program[-1]], fused=True, expanded=True)
    assert "SpindleControl" not in out[-1].sections and warnings == []
