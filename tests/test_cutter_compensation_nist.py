"""Cutter radius compensation under the NIST RS274/NGC version 3 rules (``rs274.cutter_rules.NIST_V3``,
Mach3's dialect): the expected points are derived by hand from that interpreter's code as EMC2 imported it
(LinuxCNC commit 6f27a9e96b, interp_convert.cc ``convert_straight_comp1/2``: the entry move ends square to
the line from its end point that touches the tool's circle about its start; an outside corner gets an arc
about the corner, a rapid goes straight; an inside corner is an error). Translations between Mach3 and
LinuxCNC, whose rules differ, carry the source's compensated path as moves; an incremental program from an
unknown start point is resolved by increments, whatever the start."""

from __future__ import annotations

import copy
import io
import math
import re
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parents[1]
HELICAL = ROOT / "tests" / "corpus" / "mach3" / "cncjs_helical_thread_milling.tap"
SETUP = with_tools(radii={1: 1.0, 8: 0.58})


def _moves(text: str, dialect: str = "mach3", setup: MachineSetup = SETUP) -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="t.tap", dialect=dialect, setup=setup)
    return [{**e, **e.get("controlled", {})} for e in events if "move" in e]


def _translate(text: str, source: str, target: str, setup: MachineSetup = SETUP) -> str:
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.tap", source=source, target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str) -> list[str]:
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(text, newline=""), file="t.tap", dialect="mach3", setup=SETUP))
    return [str(e) for e in info.value.errors]


ENTRY = "G21 G90 G0 X0 Y0 Z0\nG42 D1\nG1 X10 Y0 F100\nG1 X20 Y0\n"
"""From X0 Y0 to X10 Y0 on the right, radius 1: the line from the end point touching the circle about the
start leaves at acos(1/10) from the way back, so the tool ends at X10 - cos(acos(0.1)) = 9.9,
Y -sin(acos(0.1)) = -0.994987 (LinuxCNC's rule: X10 Y-1). The move on to X20 then turns by 0.1 rad (more
than the 0.01 rad tolerance) about X10 Y0: an arc to X10 Y-1 first, then the line to X20 Y-1."""


def test_the_entry_move_ends_square_to_the_line_touching_the_start_circle() -> None:
    moves = _moves(ENTRY + "M2\n")
    assert math.dist((moves[0]["x"], moves[0]["y"]), (9.9, -math.sqrt(0.99))) < 1e-6
    assert (moves[1]["move"], moves[1]["x"], moves[1]["y"], moves[1]["cx"], moves[1]["cy"]) == ("ccw", 10, -1, 10, 0)
    assert (moves[2]["move"], moves[2]["x"], moves[2]["y"]) == ("feed", 20, -1)
    linuxcnc = _moves(ENTRY + "M2\n", "linuxcnc")
    assert (linuxcnc[0]["x"], linuxcnc[0]["y"]) == (10, -1)


def test_an_outside_corner_gets_an_arc_about_it() -> None:
    moves = _moves(ENTRY + "G1 X20 Y10\nM2\n")
    assert [m["move"] for m in moves[1:]] == ["ccw", "feed", "ccw", "feed"]
    arc = moves[3]
    assert (arc["x"], arc["y"], arc["cx"], arc["cy"]) == (21, 0, 20, 0)
    assert (moves[4]["x"], moves[4]["y"]) == (21, 10)


def test_a_rapid_around_an_outside_corner_goes_straight_to_its_end() -> None:
    moves = _moves(ENTRY + "G0 X20 Y10\nM2\n")
    assert [(m["move"], m["x"], m["y"]) for m in moves[1:]] == [("ccw", 10, -1), ("feed", 20, -1), ("rapid", 21, 10)]
    linuxcnc = _moves(ENTRY + "G0 X20 Y10\nM2\n", "linuxcnc")
    assert [(m["move"], m["x"], m["y"]) for m in linuxcnc[1:]] == [("feed", 20, -1), ("rapid", 21, 0),
                                                                   ("rapid", 21, 10)]


def test_an_inside_corner_is_a_located_error() -> None:
    errors = _errors(ENTRY + "G1 X20 Y-10\nM2\n")
    assert errors[0].startswith("t.tap:5:1: error: an inside corner under cutter compensation"), errors


def test_an_entry_arc_is_refused_as_not_modelled() -> None:
    errors = _errors("G21 G90 G0 X0 Y0 Z0\nG42 D1\nG2 X10 Y0 I5 J0 F100\nM2\n")
    assert errors[0].startswith("t.tap:3:1: error: an entry arc of cutter compensation cannot be simulated"), errors


def test_compensation_outside_the_xy_plane_is_a_located_error() -> None:
    errors = _errors("G21 G90 G18 G0 X0 Y0 Z0\nG42 D1\nG1 X10 Z-1 F100\nM2\n")
    assert "runs cutter compensation only in the XY plane" in errors[0] and errors[0].startswith("t.tap:2:1"), errors


@pytest.mark.parametrize("source, target", [("mach3", "linuxcnc"), ("linuxcnc", "mach3")])
def test_between_mach3_and_linuxcnc_the_source_path_is_written_as_moves(source: str, target: str) -> None:
    text = ENTRY + "G1 X20 Y10\nG40 G1 X30 Y20\nM2\n"
    out = _translate(text, source, target)
    assert not re.search(r"\bG4[012]\b", out), out
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="t", file_out="o",
                          source=source, target=target, setup=SETUP)
    assert report.ok and report.max_deviation == 0, report.summary()
    assert _moves(out, target)[0]["x"] == _moves(text, source)[0]["x"]  # the source's entry, not the target's


@pytest.mark.parametrize("start", [(0.0, 0.0), (37.5, -12.25)])
def test_an_incremental_program_is_resolved_by_increments_whatever_its_start(start: tuple[float, float]) -> None:
    """The corpus thread milling program moves by increments from wherever the tool stands: its grbl
    translation is all increments (no G90), and it cuts the Mach3 path from any start point."""
    text = HELICAL.read_text()
    out = _translate(text, "mach3", "grbl")
    assert "G90" not in out and not re.search(r"\bG4[012]\b", out), out
    setup = copy.deepcopy(SETUP)
    setup.machine.start_x, setup.machine.start_y = start
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="t", file_out="o",
                          source="mach3", target="grbl", setup=setup)
    assert report.ok and report.max_deviation == 0, report.summary()


FULL_CIRCLE = "G21 G90 G0 X50 Y50 Z0\nG41 D1\nG3 X70 Y50 I10 J0 F100\nG3 I-20\nG3 X50 Y50 I-10 J0\nG40 G1 X40 Y40\nM2\n"
"""A full circle by its centre alone (``G3 I-20``, no end point: gmoccapy's two-tools program): under
compensation it is a move, written with the compensated centre (I-19 from X69, radius 1 inside)."""


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_full_circle_under_compensation_is_resolved_as_rs274_runs_it() -> None:
    out = _translate(FULL_CIRCLE, "linuxcnc", "grbl")
    assert "G3 X69. Y50. I-19. J0." in out, out
    ours = [(m["move"], m["x"], m["y"]) for m in _moves(out, "grbl")]
    table = "T1 P1 D%r Z0 ;\n" % (2.0 / 25.4)
    theirs = [(e["move"], e["x"], e["y"]) for e in canonical_moves(run_rs274(FULL_CIRCLE, tool_table=table),
                                                                   start=(0.0, 0.0, 0.0)) if "move" in e]
    assert len(ours) == len(theirs)
    for a, b in zip(ours, theirs):
        assert a[0] == b[0] and math.dist(a[1:], b[1:]) < 1e-4, (ours, theirs)
