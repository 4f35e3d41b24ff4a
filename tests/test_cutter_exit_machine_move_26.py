"""The first move after G40 in machine coordinates, where cutter compensation is resolved into the path
(issue 26, found on LinuxCNC's ``nc_files/mmount.ngc``: its helical-hole sub ends with ``G40`` and the
program goes on with ``G00 G53 Z0``). [V] rs274 runs that G53 move straight from the compensated end of
the last move to the programmed point, X and Y included (the exit move): the resolver used to call it "a
move in machine coordinates with cutter compensation on" (an internal contradiction: compensation was off).
Written as it is, it would keep the compensated X and Y, so it passes only where they are the programmed
ones (a zero radius), and is refused by name otherwise, never written to end elsewhere."""

from __future__ import annotations

import io

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
