"""grbl's own lowering steps (``Grbl.LOWERING``): pure block-stream rewrites, each checked on its own
stream and, where the writer's old inline rewrite missed a case, end to end (outputs derived by hand)."""

from __future__ import annotations

import io

from postproc.api import read_blocks, translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.setup import MachineSetup
from postproc.rs274.order_of_execution import stops_after_motion
from postproc_grbl import Grbl
from postproc.rs274.lean_controller import cancel_length_offset_first, close_full_circles, pause_for_tool_change

FANUC = default_registry().dialect("fanuc")


def fanuc_blocks(text: str) -> tuple[list[Block], Diagnostics]:
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    ctx, blocks = read_blocks(text.splitlines(keepends=True), "t.nc", FANUC, MachineSetup(), diagnostics)
    return list(pause_for_tool_change(cancel_length_offset_first(close_full_circles(
        iter(list(blocks)), ctx, Grbl), ctx, Grbl), ctx, Grbl)), diagnostics


def test_grbl_declares_its_steps() -> None:
    assert Grbl.LOWERING == (pause_for_tool_change, cancel_length_offset_first, close_full_circles, stops_after_motion)
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
