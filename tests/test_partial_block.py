"""``--on-unsupported warn`` drops only what the target refuses (issue #26, item 4;
``postproc.output.partial_block``): the rest of the block is written after a comment of the source line, what
cannot be written without the refused section goes with it and is named, and ``verify`` reports the loss."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

START = "G21 G90 G0 X0 Y0 Z50.\nS1000 M03\n"


def warned(body: str, target: str, lengths: dict[int, float] | None = None) -> tuple[list[str], list[str]]:
    """The translated lines after the start, and the warnings (``lengths``: the set-up's tool lengths)."""
    warnings = io.StringIO()
    out = io.StringIO()
    translate(io.StringIO(START + body + "M30\n"), out, file="t.nc", source="fanuc", target=target,
              on_unsupported="warn", diagnostics=Diagnostics(warn_stream=warnings),
              setup=with_tools(lengths=lengths or {}))
    return out.getvalue().splitlines()[2:-1], warnings.getvalue().splitlines()


NEGATIVE = {"isg": "D adds the tool's length, and no code subtracts it",
            "fagor": "Fagor's G44 cancels the offset, and no code subtracts a length"}
"""Why ISG and Fagor refuse Fanuc's negative tool length offset (a G43 H is written as their D)."""
MACHINE = "motion in machine coordinates"
"""Why SINUMERIK refuses Fanuc's G53 move (its G53 suppresses the frames, not a move in machine coordinates)."""


@pytest.mark.parametrize("target, comment", [("isg", "(UNSUPPORTED LINE 3: G44 H18 Z1. M08)"),
                                             ("fagor", ";UNSUPPORTED LINE 3: G44 H18 Z1. M08")])
def test_a_refused_tool_length_offset_leaves_its_motion_and_coolant(target: str, comment: str) -> None:
    lines, warnings = warned("G44 H18 Z1. M08\n", target)
    assert lines == [comment, "G00 Z1. M08"]
    assert warnings == [f"t.nc:3:1: warning: the {target} dialect cannot express a negative tool length offset "
                        f"(Fanuc G44): {NEGATIVE[target]}; dropped (H18) (the block's motion moves the programmed "
                        "point without the tool's length); the rest of the block is written"]


def test_a_move_in_machine_coordinates_under_a_length_keeps_its_coolant() -> None:
    """SUPA under a tool length was refused (whether it suppresses the length is machine data
    ``$MN_G53_TOOLCORR``); it is now exact with ``D0`` before it and the D again after it
    (``dialects/siemens/writer.py`` ``machine_move``), so nothing is dropped and the coolant stays in its block."""
    lines, warnings = warned("G43 H1 Z50.\nG53 G0 Z0. M09\n", "siemens", {1: 100.0})
    assert lines[1:] == ["D0", "SUPA G0 Z0. M9", "D01"]
    assert warnings == []


def test_a_block_with_nothing_left_is_a_comment() -> None:
    lines, warnings = warned("G44 H18\n", "isg", {18: 100.0})
    assert lines == ["(UNSUPPORTED LINE 3: G44 H18)"]
    assert warnings == [f"t.nc:3:1: warning: the isg dialect cannot express a negative tool length offset (Fanuc "
                        f"G44): {NEGATIVE['isg']}; written as a comment"]


def test_without_warn_the_same_block_is_a_located_error() -> None:
    with pytest.raises(ErrorList, match="t.nc:3:1: error: the isg dialect cannot express a negative tool length"):
        translate(io.StringIO(START + "G44 H18 Z1. M08\nM30\n"), io.StringIO(), file="t.nc", source="fanuc",
                  target="isg")


def test_verify_reports_what_was_lost() -> None:
    program = START + "G44 H18 Z1. M08\nG1 X10. F100.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="t.nc", source="fanuc", target="fagor", on_unsupported="warn",
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="in", file_out="out",
                          source="fanuc", target="fagor", tolerance=0.001, setup=with_tools(lengths={18: 100.0}))
    assert not report.ok
    assert report.max_deviation >= 100.0  # the Z1. without G44 H18's -100 mm
    report.allow_ignored = True
    assert not report.ok  # a measured deviation: nothing accepts it
