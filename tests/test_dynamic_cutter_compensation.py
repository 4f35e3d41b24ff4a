"""LinuxCNC G41.1/G42.1 (cutter compensation by the diameter D; issue 26, corpus ``inside_corners_trimmed``,
``inverse_time_with_comp``): simulated as rs274 runs them (the controlled points are rs274's, move by
move), kept verbatim for LinuxCNC, and resolved into the compensated path for every other target (its
moves compared with rs274's run of the source). The expected points of
the first program are also derived by hand."""

from __future__ import annotations

import io
import math
from pathlib import Path
import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from postproc.lowering.inverse_time import per_minute
from tests.support.rs274 import RS274Error, available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
CORPUS = ROOT / "tests" / "corpus" / "linuxcnc"
TOLERANCE_MM = 2e-4
needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _controlled(text: str, file: str = "t.ngc") -> list[tuple[str, float, float, float]]:
    out = []
    for e in toolpath_events(io.StringIO(text, newline=""), file=file, dialect="linuxcnc"):
        if "move" in e:
            point = e.get("controlled", e)
            out.append((e["move"], point["x"], point["y"], point["z"]))
    return out


def _theirs(text: str) -> list[tuple[str, float, float, float]]:
    return [(e["move"], e["x"], e["y"], e["z"]) for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0))
            if "move" in e]


def _same(ours: list[tuple[str, float, float, float]], theirs: list[tuple[str, float, float, float]],
          tolerance: float = TOLERANCE_MM) -> None:
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a[0] == b[0] and math.dist(a[1:], b[1:]) <= tolerance, (n, a, b)


SQUARE = """G21 G17 G90 G0 X0 Y0 Z1
G1 Z0 F100
G41.1 D4
G1 X20 Y0
G1 X20 Y20
G3 X0 Y20 R10
G40
G1 X0 Y0
G42.1 D-2
G1 X10 Y-5
G1 X30 Y-5
G40 G1 X40 Y0
M2
"""
"""G41.1 D4 (radius 2 on the left), then G42.1 D-2 (radius 1, the negative diameter puts it on the left)."""

PROGRAMS = {
    "square": SQUARE,
    "right side, o-word diameter": ("G21 G90 G0 X0 Y0 Z1\n#100=6\nG42.1 D#100\nG1 X10 Y0 F100\nG1 X10 Y10\n"
                                    "G1 X0 Y10\nG40 G1 X-5 Y5\nM2\n"),
    "zero diameter": "G21 G90 G0 X0 Y0 Z1\nG41.1 D0\nG1 X10 Y0 F100\nG1 X10 Y10\nG40\nG1 X0 Y0\nM2\n",
    "inch": "G20 G90 G0 X0 Y0 Z0.1\nG41.1 D0.25\nG1 X1 Y0 F10\nG2 X2 Y-1 R1\nG1 Y-2\nG40 G1 X3\nM2\n",
}


def test_the_square_is_compensated_as_derived_by_hand() -> None:
    """Radius 2 on the left: the entry move ends 2 left of the first side at its end corner, offset back
    along the inside corner (X18 Y2); the arc of radius 10 about X10 Y20 becomes one of 8 ending at X2;
    the exit move goes to the programmed point. Then radius 1 left of the X10 Y-5 -> X30 Y-5 side: Y-4."""
    moves = _controlled(SQUARE)
    assert [m[1:3] for m in moves[2:5]] == [(18, 2), (18, 20), (2, 20)]
    assert moves[5][1:3] == (0, 0)
    assert moves[7][2] == -4 and moves[7][1] == 30


@needs_rs274
@pytest.mark.parametrize("name", PROGRAMS)
def test_dynamic_compensation_moves_as_rs274_runs_it(name: str) -> None:
    text = PROGRAMS[name]
    _same(_controlled(text), _theirs(text), 0.0018 if "G20" in text else TOLERANCE_MM)


@needs_rs274
@pytest.mark.parametrize("program", ["inside_corners_trimmed.ngc", "inverse_time_with_comp.ngc"])
def test_the_corpus_programs_move_as_rs274_runs_them(program: str) -> None:
    text = (CORPUS / program).read_text()
    _same(_controlled(text, program), _theirs(text), 0.0018)


TARGETS = ("fanuc", "grbl", "isg", "fagor", "mach3")


def _translated(text: str, target: str, file: str = "t.ngc") -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file=file, source="linuxcnc", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _written(text: str, target: str) -> list[tuple[str, float, float, float]]:
    """The moves a translation programs (no compensation left in it: the programmed point is the tool's)."""
    return [(e["move"], e["x"], e["y"], e["z"])
            for e in toolpath_events(io.StringIO(text, newline=""), file="out", dialect=target) if "move" in e]


def test_linuxcnc_gets_the_block_back() -> None:
    assert _translated(SQUARE, "linuxcnc") == SQUARE


@pytest.mark.parametrize("target", TARGETS)
def test_other_targets_get_the_compensated_path_derived_by_hand(target: str) -> None:
    """No other controller spells G41.1: the path rs274 cuts is written as plain moves (the points of
    ``test_the_square_is_compensated_as_derived_by_hand``), with no compensation code left."""
    out = _translated(SQUARE, target)
    assert not any(code in out for code in ("G41", "G42", "41.1", "42.1")), out
    moves = _written(out, target)
    assert [m[1:3] for m in moves[2:5]] == [(18, 2), (18, 20), (2, 20)]
    assert moves[5][1:3] == (0, 0) and moves[7][1:3] == (30, -4)
    report = verify_lines(io.StringIO(SQUARE, newline=""), io.StringIO(out, newline=""), file_in="t.ngc",
                          file_out="out", source="linuxcnc", target=target)
    assert report.ok and report.max_deviation == 0, report.summary()


def test_a_target_with_g41_keeps_its_own_compensation_beside_a_resolved_one() -> None:
    """G41 D1 by register stays G41 for Fanuc (it has it); only the G41.1 stretch becomes moves."""
    text = ("G21 G90 G0 X0 Y0 Z1\nG41.1 D4\nG1 X20 Y0 F100\nG1 X20 Y20\nG40 G1 X30 Y30\n"
            "G41 D1 G1 X40 Y30\nG1 X50\nG40 G1 X60 Y40\nM2\n")
    lines = _translated(text, "fanuc").splitlines()
    assert sum("G41" in line for line in lines) == 1 and any(line.startswith("G41 D01") for line in lines), lines


@needs_rs274
@pytest.mark.parametrize("target", TARGETS)
@pytest.mark.parametrize("name", PROGRAMS)
def test_the_resolved_path_moves_as_rs274_runs_the_source(name: str, target: str) -> None:
    text = PROGRAMS[name]
    _same(_written(_translated(text, target), target), _theirs(text), 0.0018 if "G20" in text else TOLERANCE_MM)


@needs_rs274
@pytest.mark.parametrize("target", ["fanuc", "grbl", "mach3"])  # ISG refuses its 0.0001 in semicircles: G165
@pytest.mark.parametrize("program", ["inside_corners_trimmed.ngc", "inside_corners_zx_trimmed.ngc"])  # moves them
def test_the_corpus_program_translates_to_the_path_rs274_cuts(program: str, target: str) -> None:
    """A computed diameter in a subprogram called three times (``G41.1 D#100``): the program is flattened,
    each call's path resolved with its own diameter."""
    text = (CORPUS / program).read_text()
    _same(_written(_translated(text, target, program), target), _theirs(text), 0.0018)


INVERSE_EXIT = "g20\ng0x0y0z0\ng42.1d.4\ng93g1x1f30\ny1f20\ng40 x2 y2 f10\nx3 f10\ng94\nm2\n"
"""G93 through the stretch and after it: rs274 runs the compensated moves at F times the programmed length
(30, 20, the corner arc at 20, the exit move from the programmed X1 Y1 at 10 x 1.4142), then X3 at 10."""


def _feeds(text: str, target: str) -> list[tuple[str, float, float, float]]:
    """The moves a translation programs with their feed per minute (mm/min)."""
    events = toolpath_events(io.StringIO(text, newline=""), file="out", dialect=target)
    return [(e["move"], e["x"], e["y"], e.get("f", 0.0)) for e in per_minute(events, {"X": 0, "Y": 0, "Z": 0})
            if "move" in e]


def _their_feeds(text: str) -> list[tuple[str, float, float, float]]:
    return [(e["move"], e["x"], e["y"], e.get("f", 0.0))
            for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0), feeds=True) if "move" in e]


@needs_rs274
@pytest.mark.parametrize("target", TARGETS)
@pytest.mark.parametrize("program", ["inverse_time_with_comp.ngc", "exit"])
def test_inverse_time_under_compensation_runs_at_the_rates_rs274_gives(program: str, target: str) -> None:
    """A compensated G93 move runs at F times its programmed length per minute (the corpus program:
    ``g93 g1 x1 f30`` compensated to X1 Y-.2 at 30 ipm, not 30 x 1.0198): the resolved stretch is written
    per minute with those rates, corner arcs at the next move's, and G93 comes back after it."""
    text = INVERSE_EXIT if program == "exit" else (CORPUS / program).read_text()
    ours, theirs = _feeds(_translated(text, target, "t.ngc"), target), _their_feeds(text)
    assert len(ours) == len(theirs)
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a[0] == b[0] and math.dist(a[1:3], b[1:3]) <= 0.0018 and abs(a[3] - b[3]) <= 0.01, (n, a, b)


def test_g93_comes_back_after_the_resolved_stretch() -> None:
    assert _translated(INVERSE_EXIT, "grbl").splitlines()[2:7] == [
        "G94 G1 X1. Y-0.2 F30.", "G3 X1.2 Y0. I0. J0.2 F20.", "G1 X1.2 Y1. F20.", "G1 X2. Y2. F14.14213562",
        "G93 G1 X3. F10."]


ZX_ENTRY = "G21 G90 G18 G0 X0 Y0 Z0\nG41.1 D2\nG1 X10 Z-1 F100\nG40 G1 X20\nM2\n"
"""In the ZX plane the tool runs left of the path seen from +Y, the plane's points (Z, X): the entry move from
(Z0, X0) to (Z-1, X10) has direction (-1, 10) in (Z, X), its left normal (-10, -1) / sqrt(101), so the tool
ends 1 mm that way from (Z-1, X10): Z -1.995037, X 9.900496 (derived by hand; rs274 agrees below)."""


def test_compensation_by_a_diameter_in_the_zx_plane_is_derived_by_hand() -> None:
    moves = _controlled(ZX_ENTRY)
    root = math.sqrt(101.0)
    assert moves[0][0] == "feed" and math.dist((moves[0][3], moves[0][1]), (-1 - 10 / root, 10 - 1 / root)) < 1e-6


@needs_rs274
def test_compensation_by_a_diameter_in_the_zx_plane_is_rs274s() -> None:
    _same(_controlled(ZX_ENTRY), _theirs(ZX_ENTRY))
    _same(_written(_translated(ZX_ENTRY, "fanuc"), "fanuc"), _theirs(ZX_ENTRY))


def test_compensation_in_the_yz_plane_is_a_located_error_as_in_linuxcnc() -> None:
    """[V] LinuxCNC refuses cutter compensation outside XY and XZ (NCE_RADIUS_COMP_ONLY_IN_XY_OR_XZ)."""
    with pytest.raises(ErrorList) as info:
        _translated("G21 G90 G19 G0 X0 Y0 Z0\nG41.1 D2\nG1 Y10 Z-1 F100\nG40 G1 Y20\nM2\n", "fanuc")
    assert str(info.value.errors[0]).startswith("t.ngc:2:1: error: LinuxCNC runs cutter compensation only in the XY "
                                                "or ZX plane, not in YZ"), str(info.value.errors[0])


REFUSED = {
    "no D": ("G21 G90 G0 X0 Y0\nG41.1\nG1 X1 F10\nM2\n", "t.ngc:2:1: error: G41.1 with no D word"),
    "L outside G18": ("G21 G90 G0 X0 Y0\nG41.1 D1 L2\nG1 X1 F10\nM2\n", "t.ngc:2:10: error: G41.1 with an L word"),
    "on while on": ("G21 G90 G0 X0 Y0\nG41.1 D1\nG1 X1 F10\nG42.1 D1\nG1 X5\nM2\n", "t.ngc:4:"),
}


@pytest.mark.parametrize("name", REFUSED)
def test_what_rs274_refuses_is_a_located_error(name: str) -> None:
    source, message = REFUSED[name]
    with pytest.raises(ErrorList) as info:
        _controlled(source)
    assert str(info.value.errors[0]).startswith(message), str(info.value.errors[0])
    if available():
        with pytest.raises(RS274Error):
            run_rs274(source)


def test_a_block_that_also_moves_is_not_simulated_past() -> None:
    """rs274 runs ``G41.1 D2 G1 X10``; here the whole block stays verbatim, so the simulation refuses it
    rather than lose the move."""
    with pytest.raises(ErrorList) as info:
        _controlled("G21 G90 G0 X0 Y0\nG41.1 D2 G1 X10 F100\nG40 G1 X20\nM2\n")
    assert "t.ngc:2:" in str(info.value.errors[0]) and "cannot be simulated" in str(info.value.errors[0])


@needs_rs274
def test_the_source_simulation_gives_the_rates_rs274_gives() -> None:
    """The simulation of the LinuxCNC source itself (what verify compares a translation with)."""
    text = (CORPUS / "inverse_time_with_comp.ngc").read_text()
    events = ({**e, **e.get("controlled", {})} for e in toolpath_events(io.StringIO(text), file="t.ngc",
                                                                        dialect="linuxcnc"))
    ours = [(e["move"], e["x"], e["y"], e.get("f", 0.0)) for e in per_minute(events, {"X": 0, "Y": 0, "Z": 0})
            if "move" in e]
    theirs = _their_feeds(text)
    assert len(ours) == len(theirs)
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a[0] == b[0] and math.dist(a[1:3], b[1:3]) <= 0.0018 and abs(a[3] - b[3]) <= 0.01, (n, a, b)


SPINDLE_STOP_AT_A_CORNER = """G21 G17 G90 G40
G0 X-5 Y-5 Z5 M3 S1000
G41.1 D4
G1 X0 Y0 F100
X10 M5
Y10 M9
X0
G40 G1 X-5 Y-5
M2
"""
"""``X10 M5`` turns an outside corner: rs274 stops the spindle before the block's motion, and the corner's arc is
that block's motion (its canonical calls: ``STRAIGHT_FEED(-1.4142, 1.4142, ..)``, ``STOP_SPINDLE_TURNING``,
``ARC_FEED(0, 2, ..)``, ``STRAIGHT_FEED(8, 2, ..)``; order of execution: spindle before motion)."""


@pytest.mark.parametrize("target", ["isg", "fagor"])
def test_a_spindle_stop_at_an_outside_corner_goes_before_its_arc(target: str) -> None:
    """An ISG-family target has one resolver, after its own split of stops before motion (the generic step hands
    over to it, ``cutter_compensation.TARGET_RESOLVES``): the M05 comes before the corner's arc, as rs274 runs it.
    Resolved before that split, the arc came first and the spindle stopped one move late."""
    lines = _translated(SPINDLE_STOP_AT_A_CORNER, target).splitlines()
    stop = lines.index("M05")
    arc = next(n for n, line in enumerate(lines) if line.startswith("G02"))
    assert lines[stop - 1].startswith("G01 X-1.414214 Y1.414214") and arc == stop + 1, lines
    assert lines[arc + 1].startswith("G01 X8. Y2."), lines


@needs_rs274
def test_rs274_stops_the_spindle_before_the_corner_arc() -> None:
    """The oracle of the order above."""
    events = canonical_moves(run_rs274(SPINDLE_STOP_AT_A_CORNER), start=(0.0, 0.0, 0.0))
    stop = events.index({"event": "spindle", "dir": "stop"})
    assert events[stop + 1].get("move") == "cw" and events[stop - 1].get("move") == "feed", events[stop - 2:stop + 2]


def test_inverse_time_under_compensation_towards_isg_writes_one_g94() -> None:
    """Towards ISG (no G93) the feeds are per minute before its one resolver runs: the resolved stretch needs no G94
    of its own beside the one that replaces G93 (two were written before)."""
    text = ("G21 G17 G90 G40\nG0 X-5 Y-5 Z5\nG93\nG41.1 D4\nG1 X0 Y0 F2\nX10 F3\nY10 F4\n"
            "G40 G1 X-5 Y-5 F1\nG94\nM2\n")
    lines = _translated(text, "isg").splitlines()
    first_feed = next(n for n, line in enumerate(lines) if line.startswith("G01"))
    assert [line for line in lines[:first_feed + 1] if "G94" in line] == ["G94"], lines
    assert lines[first_feed] == "G01 X-1.414214 Y1.414214 F14.142136", lines
