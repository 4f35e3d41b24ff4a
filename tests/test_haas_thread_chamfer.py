"""A Haas lathe's G92 pulls out of the thread at 45 degrees while M23 is in force (its power-on default), square
under M24 (``postproc.rs274.lathe_cycles._thread_chamfer_switch``, tagged there).

Derived by hand (inch, the set-up's ``threadChamfer`` 10: one lead, Setting 95's 1.000): from X1.2 Z0.2, ``G92
X0.95 Z-1. F0.0625`` rapids to X0.95, threads along Z to where the thread line is one lead (0.0625) before
Z-1., i.e. to Z-0.9375, then threads at 45 degrees to Z-1. with X out by one lead as a radius (X0.95 + 2 x
0.0625 = X1.075), rapids to X1.2 and back to Z0.2. Under M24 the thread runs to Z-1. at X0.95.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.support.nose_tips import SETUPS
from tests.test_lathe_rs274 import INCH_TOLERANCE, difference, ours, theirs

MM = 25.4
PROGRAM = """%
O1
G00 G18 G20 G40 G80 G99
T0101
G97 S500 M03
G00 X1.2 Z0.2
G92 X0.95 Z-1. F0.0625
X0.93
G00 X2. Z1.
M30
%
"""


def _haas() -> MachineSetup:
    return load_setup(str(SETUPS / "haas_st10_lathe.xml"))


def _moves(text: str, line: int) -> list[tuple[str, float, float]]:
    return [(ev["move"], round(ev["x"] / MM, 6), round(ev["z"] / MM, 6))
            for ev in toolpath_events(io.StringIO(text), file="h.nc", dialect="fanuc", setup=_haas())
            if "move" in ev and ev["line"] == line]


def test_g92_pulls_out_at_45_degrees_by_hand() -> None:
    assert _moves(PROGRAM, 7) == [("rapid", 0.95, 0.2), ("feed", 0.95, -0.9375), ("feed", 1.075, -1.0),
                                  ("rapid", 1.2, -1.0), ("rapid", 1.2, 0.2)]
    assert _moves(PROGRAM, 8)[1:3] == [("feed", 0.93, -0.9375), ("feed", 1.055, -1.0)]


def test_m24_makes_the_exit_square_and_m23_brings_the_chamfer_back() -> None:
    text = PROGRAM.replace("G92 X0.95", "M24\nG92 X0.95").replace("X0.93\n", "X0.93\nM23\nG92 X0.91 Z-1.\n")
    assert _moves(text, 8) == [("rapid", 0.95, 0.2), ("feed", 0.95, -1.0), ("rapid", 1.2, -1.0),
                               ("rapid", 1.2, 0.2)]
    assert _moves(text, 11)[1:3] == [("feed", 0.91, -0.9375), ("feed", 1.035, -1.0)]


def test_a_chamfer_that_would_leave_the_start_point_x_is_refused() -> None:
    text = PROGRAM.replace("G00 X1.2 Z0.2", "G00 X1.0 Z0.2")
    with pytest.raises(ErrorList) as err:
        _moves(text, 7)
    assert "h.nc:7:1: error: G92: threading single cycle: the chamfer 0.0625 pulls out beyond the start point's X" \
        in str(err.value) or "pulls out beyond the start point's X" in str(err.value)


def _translate(target: str) -> tuple[str, object]:
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="h.nc", source="fanuc", target=target, setup=_haas())
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(out.getvalue()), file_in="h.nc", file_out="o.nc",
                          source="fanuc", target=target, setup=_haas())
    return out.getvalue(), report


def test_a_haas_copy_keeps_g92() -> None:
    text, report = _translate("fanuc")
    assert "G92 X0.95 Z-1. F0.0625" in text
    assert report.ok and report.max_deviation == 0.0  # type: ignore[attr-defined]


@pytest.mark.parametrize("target", ["gsk", "linuxcnc"])
def test_another_controller_gets_the_chamfered_passes_as_moves(target: str) -> None:
    """No word of another controller's G92 says this pull-out (Fanuc T's and GSK's chamfer on a machine signal
    or their own M code): the cycle is written as its moves, and verifies at zero deviation."""
    text, report = _translate(target)
    assert not any("G92" in line.split("(")[0] for line in text.splitlines())
    assert ("G33 X1.075 Z-1." if target == "linuxcnc" else "G32 X1.075 Z-1.") in text
    assert report.ok and report.max_deviation == 0.0  # type: ignore[attr-defined]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_linuxcnc_translation_with_the_same_moves() -> None:
    text, _ = _translate("linuxcnc")
    problem = difference(ours(PROGRAM, "fanuc", _haas()), theirs(text), INCH_TOLERANCE)
    assert problem is None, f"{problem}\n\n{text}"
