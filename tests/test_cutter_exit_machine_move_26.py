"""The first move after G40 in machine coordinates, where cutter compensation is resolved into the path
(issue 26, found on LinuxCNC's ``nc_files/mmount.ngc``: its helical-hole sub ends with ``G40`` and the
program goes on with ``G00 G53 Z0``). [V] rs274 runs that G53 move straight from the compensated end of
the last move to the programmed point, X and Y included (the exit move): the resolver used to call it "a
move in machine coordinates with cutter compensation on" (an internal contradiction: compensation was off).
Written as it is, it would keep the compensated X and Y, so it passes as it is only where they are the programmed
ones (a zero radius); otherwise each such axis is written as the programmed point's machine position where the
set-up's ``<WorkOffsets>`` give it (comp26), and the move is refused by name where they do not, never written to
end elsewhere."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

PROGRAM = """g21 g17 g40 g90
o100 sub
g0 z#3
g0 x[#1 + 8] y[#2 + 5]
g41 g0 x#1 y[#2 + 3]
g3 x#1 y[#2 + 3] i0 j-3 z-2
g0 z#3
g40
o100 endsub
T4 M6 G43
f250
o100 call [20] [20] [5]
o100 call [40] [20] [5]
G00 G53 Z0
m2
"""


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def to_grbl(radius: float) -> str:
    out = io.StringIO(newline="")
    translate(_lines(PROGRAM), out, file="t.ngc", source="linuxcnc", target="grbl",
              setup=with_tools(lengths={4: 50.0}, radii={4: radius}),
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def test_an_exit_in_machine_coordinates_that_must_move_x_and_y_is_refused_at_its_line() -> None:
    with pytest.raises(ErrorList) as info:
        to_grbl(1.5)
    assert [(e.location.line if e.location else None) for e in info.value.errors] == [14]
    assert "first move after compensation is cancelled" in str(info.value.errors[0])


def test_an_exit_in_machine_coordinates_that_moves_only_z_is_written_as_it_is() -> None:
    gcode = to_grbl(0.0)  # a zero radius: the compensated end is the programmed one
    assert "G53 G0 Z0." in gcode and "G41" not in gcode
    report = verify_lines(_lines(PROGRAM), _lines(gcode), file_in="t.ngc", file_out="t.gcode", source="linuxcnc",
                          target="grbl", setup=with_tools(lengths={4: 50.0}, radii={4: 0.0}))
    assert report.ok, report.summary()


def _with_offsets(radius: float, **offset: float) -> Any:
    from postproc.setup.machine import WorkOffsetData
    setup = with_tools(lengths={4: 50.0}, radii={4: radius})
    setup.work_offsets = {"1": WorkOffsetData(number=1, **offset)}
    return setup


def test_an_exit_in_machine_coordinates_is_written_with_the_set_up_work_offset() -> None:
    """With the set-up's G54 offset (X -400, Y -250) the exit move is written whole: the last hole (centre (40,
    20), the tool inside it on the left of a counter-clockwise helix) ends compensated at (40, 23 - 1.5); the G53
    move goes from there to the programmed point (40, 23): X is already there, Y's machine position is 23 - 250 =
    -227, at machine Z0."""
    setup = _with_offsets(1.5, x=-400.0, y=-250.0, z=-300.0)
    out = io.StringIO(newline="")
    translate(_lines(PROGRAM), out, file="t.ngc", source="linuxcnc", target="grbl", setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    gcode = out.getvalue()
    exit_move = [line for line in gcode.splitlines() if "G53" in line]
    assert exit_move == ["G53 G0 Y-227. Z0."], gcode
    report = verify_lines(_lines(PROGRAM), _lines(gcode), file_in="t.ngc", file_out="t.gcode", source="linuxcnc",
                          target="grbl", setup=setup)
    assert report.ok, report.summary()


def test_an_exit_in_machine_coordinates_without_the_offset_it_needs_names_it() -> None:
    setup = _with_offsets(1.5, x=-400.0)  # no Y for G54
    with pytest.raises(ErrorList) as info:
        translate(_lines(PROGRAM), io.StringIO(), file="t.ngc", source="linuxcnc", target="grbl", setup=setup,
                  diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert [str(e) for e in info.value.errors] == [
        "t.ngc:14:1: error: a move in machine coordinates or a reference return as the first move after compensation "
        "is cancelled cannot be resolved: it also takes Y from the compensated point back to the programmed one, "
        "which needs the work offset: the set-up gives work system 1 no offset for Y (<WorkOffsets><Offset "
        "number=\"1\" y=...>) and the program sets none (or program a move in work coordinates after the cancel "
        "first)"]
