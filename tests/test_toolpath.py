"""Toolpath simulation: hand-computed cases for moves, arcs, units, reference returns and events."""

from __future__ import annotations

import math
from typing import Any

import pytest

from postproc.errors import Diagnostics, ErrorList, ErrorLevel
from postproc.ir import Block, CompoundMotion, Dwell, Feed, Motion, SpindleControl, SpindleOrientation
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup
from postproc.context import Context
from postproc.geometry.arcs import arc_points, arc_sweep, centre_from_radius
from postproc.simulate.toolpath import num, simulate, toolpath_events

HEADER = {"toolpath": 1, "units": "mm", "dialect": "fanuc"}


def run(text: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    lines = [line + "\n" for line in text.strip().splitlines()]
    return list(toolpath_events(lines, file="t.nc", dialect="fanuc", setup=setup))


def body(text: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    events = run(text, setup)
    # lengths are mm whatever the program's units; an inch program's header says it is one
    inch = "G20" in text  # (each program here is in inches from its first move when it has G20)
    assert events[0] == ({**HEADER, "program_units": "inch"} if inch else HEADER), text
    return events[1:]


def errors_of(text: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        run(text, setup)
    return [str(e) for e in info.value.errors]


def same(actual: Any, expected: Any, tol: float = 1e-6) -> bool:
    """Parsed toolpath objects equal, numbers within ``tol``."""
    if isinstance(expected, dict):
        return isinstance(actual, dict) and actual.keys() == expected.keys() and all(
            same(actual[k], expected[k], tol) for k in expected)
    if isinstance(expected, list):
        return isinstance(actual, list) and len(actual) == len(expected) and all(
            same(a, e, tol) for a, e in zip(actual, expected))
    if isinstance(expected, bool) or isinstance(actual, bool):
        return actual is expected
    if isinstance(expected, (int, float)) and isinstance(actual, (int, float)):
        return abs(actual - expected) <= tol
    return bool(actual == expected)


def assert_events(actual: list[dict[str, Any]], expected: list[dict[str, Any]]) -> None:
    assert same(actual, expected), "\n".join(map(str, actual))


# -- straight moves, distance mode, start position ------------------------------------------------

def test_rapid_and_feed_carry_every_axis_and_feed_only_on_feed_moves() -> None:
    assert_events(body("G21 G90\nG00 X10. Y20. Z5.\nG01 Z-1. F150.\nX30."), [
        {"line": 2, "move": "rapid", "x": 10, "y": 20, "z": 5},
        {"line": 3, "move": "feed", "x": 10, "y": 20, "z": -1, "f": 150},
        {"line": 4, "move": "feed", "x": 30, "y": 20, "z": -1, "f": 150},
    ])


def test_incremental_moves_add_to_the_position() -> None:
    assert_events(body("G21 G91\nG01 X10. Y5. F100.\nX10. Y5.\nG90 X0."), [
        {"line": 2, "move": "feed", "x": 10, "y": 5, "z": 0, "f": 100},
        {"line": 3, "move": "feed", "x": 20, "y": 10, "z": 0, "f": 100},
        {"line": 4, "move": "feed", "x": 0, "y": 10, "z": 0, "f": 100},
    ])


def test_start_position_comes_from_the_setup() -> None:
    setup = MachineSetup(machine=MachineSettings(start_x=1.0, start_y=2.0, start_z=100.0))
    assert_events(body("G21 G91\nG00 Z-50.", setup), [{"line": 2, "move": "rapid", "x": 1, "y": 2, "z": 50}])


def test_zero_length_moves_are_dropped() -> None:
    assert_events(body("G21 G90\nG00 X10. Y0. Z5.\nX10.\nG01 X10.0000001 F100.\nG91 X0 Y0"), [
        {"line": 2, "move": "rapid", "x": 10, "y": 0, "z": 5},
    ])


def test_numbers_are_rounded_to_six_places_and_integral_values_are_ints() -> None:
    assert num(50.0) == 50 and isinstance(num(50.0), int)
    assert num(-0.0000001) == 0 and str(num(-0.0000001)) == "0"
    assert num(1 / 3) == 0.333333
    ev = body("G21 G90\nG00 X0.1 Y0.2 Z0.3\nG91 X0.1 Y0.1 Z0.1")
    assert ev[1]["x"] == 0.2 and ev[1]["y"] == 0.3 and ev[1]["z"] == 0.4


def test_extra_machine_axes_are_always_present_and_rotary_axes_are_not_converted() -> None:
    setup = MachineSetup(machine=MachineSettings(axes="XYZA"))
    assert_events(body("G20 G90\nG00 X1. A90.\nZ1.", setup), [
        {"line": 2, "move": "rapid", "x": 25.4, "y": 0, "z": 0, "a": 90},
        {"line": 3, "move": "rapid", "x": 25.4, "y": 0, "z": 25.4, "a": 90},
    ])


def test_an_axis_the_machine_lacks_is_a_located_error() -> None:
    assert errors_of("G21 G90\nG00 X1. A90.") == ["t.nc:2:9: error: axis A is not on this machine (axes XYZ)"]


def test_machine_coordinates_are_absolute_with_zero_work_offsets() -> None:
    assert_events(body("G21 G90 G55\nG00 X10. Y10. Z10.\nG53 Z50.\nG91 X1."), [
        {"line": 2, "move": "rapid", "x": 10, "y": 10, "z": 10},
        {"line": 3, "move": "rapid", "x": 10, "y": 10, "z": 50},
        {"line": 4, "move": "rapid", "x": 11, "y": 10, "z": 50},
    ])


# -- units ------------------------------------------------------------------------------------------

def test_inch_programs_convert_lengths_and_feeds_to_mm() -> None:
    assert_events(body("G20 G90\nG00 X1. Y0.5\nG01 Z-0.1 F8.\nG21 G01 X10."), [
        {"line": 2, "move": "rapid", "x": 25.4, "y": 12.7, "z": 0},
        {"line": 3, "move": "feed", "x": 25.4, "y": 12.7, "z": -2.54, "f": 203.2},
        # the F given in inches stays the same physical feed after G21
        {"line": 4, "move": "feed", "x": 10, "y": 12.7, "z": -2.54, "f": 203.2},
    ])


def test_inch_arc_converts_centre_offsets() -> None:
    assert_events(body("G20 G90 G17\nG00 X1. Y0.\nG02 X0. Y-1. I-1. J0. F10."), [
        {"line": 2, "move": "rapid", "x": 25.4, "y": 0, "z": 0},
        {"line": 3, "move": "cw", "x": 0, "y": -25.4, "z": 0, "cx": 0, "cy": 0, "cz": 0, "plane": "XY", "f": 254},
    ])


def test_per_rev_feed_is_stated_in_the_header() -> None:
    events = run("G21 G90 G95\nS500 M03\nG01 X1. F0.2")
    assert events[0] == {**HEADER, "feed_mode": "per_rev"}
    assert_events(events[1:], [{"line": 2, "event": "spindle", "dir": "cw"}, {"line": 3, "move": "feed", "x": 1, "y": 0, "z": 0, "f": 0.2}])


def test_a_later_feed_mode_change_is_marked_on_the_move() -> None:
    events = run("G21 G90 S500 M03\nG01 X1. F100.\nG95 X2. F0.1")
    assert events[0] == HEADER
    assert events[3]["feed_mode"] == "per_rev" and events[3]["f"] == 0.1


def test_feed_move_without_feed_is_an_error() -> None:
    assert errors_of("G21 G90\nG01 X1.") == ["t.nc:2:1: error: a feed move with no feed rate (program F first)"]


# -- arcs -------------------------------------------------------------------------------------------

def test_ijk_arc_in_g17() -> None:
    assert_events(body("G21 G90 G17\nG00 X10. Y0. Z-1.\nG03 X0. Y10. I-10. J0. F100."), [
        {"line": 2, "move": "rapid", "x": 10, "y": 0, "z": -1},
        {"line": 3, "move": "ccw", "x": 0, "y": 10, "z": -1, "cx": 0, "cy": 0, "cz": -1, "plane": "XY", "f": 100},
    ])


def test_r_arc_short_and_long_way() -> None:
    short = body("G21 G90\nG00 X10. Y0.\nG02 X0. Y10. R10. F100.")[1]
    assert (short["cx"], short["cy"]) == (10, 10)
    long = body("G21 G90\nG00 X10. Y0.\nG02 X0. Y10. R-10. F100.")[1]
    assert (long["cx"], long["cy"]) == (0, 0)
    ccw = body("G21 G90\nG00 X10. Y0.\nG03 X0. Y10. R10. F100.")[1]
    assert (ccw["cx"], ccw["cy"]) == (0, 0)


def test_arc_in_g18_uses_z_and_x_with_i_and_k() -> None:
    expected = {"line": 4, "move": "ccw", "x": 103, "y": 20, "z": -5, "cx": 95, "cy": 20, "cz": -5,
                "plane": "ZX", "f": 1200}
    prog = "G21 G90\nG00 X95. Y20. Z3.\nG18\nG03 X103. Z-5. {} F1200."
    assert_events(body(prog.format("I0. K-8."))[1:], [expected])
    assert_events(body(prog.format("R8."))[1:], [expected])


def test_arc_in_g19_uses_y_and_z_with_j_and_k() -> None:
    expected = {"line": 3, "move": "cw", "x": 5, "y": 10, "z": 0, "cx": 5, "cy": 0, "cz": 0,
                "plane": "YZ", "f": 100}
    prog = "G21 G90\nG00 X5. Y0. Z10.\nG19 G02 Y10. Z0. {} F100."
    assert_events(body(prog.format("J0. K-10."))[1:], [expected])
    assert_events(body(prog.format("R10."))[1:], [expected])


def test_helical_arc_keeps_the_start_level_in_the_centre() -> None:
    ev = body("G21 G90\nG00 X10. Y0. Z0.\nG03 X-10. Y0. Z-2. I-10. J0. F100.")[1]
    assert (ev["cx"], ev["cy"], ev["cz"], ev["z"]) == (0, 0, 0, -2)


def test_full_circle_with_ijk_is_emitted() -> None:
    assert_events(body("G21 G90\nG00 X57. Y50.\nG03 I-7. F900.")[1:], [
        {"line": 3, "move": "ccw", "x": 57, "y": 50, "z": 0, "cx": 50, "cy": 50, "cz": 0, "plane": "XY", "f": 900},
    ])


def test_full_circle_with_r_is_an_error() -> None:
    assert errors_of("G21 G90\nG00 X10. Y0.\nG02 X10. Y0. R5. F100.") == [
        "t.nc:3:14: error: a full circle cannot be programmed with R (use I/J/K)"]


def test_r_too_small_for_the_chord_is_an_error() -> None:
    assert errors_of("G21 G90\nG00 X0. Y0.\nG02 X10. Y0. R4. F100.") == [
        "t.nc:3:14: error: arc radius 4.0000 mm is too small for a chord of 10.0000 mm"]


def test_ijk_arc_whose_end_is_off_the_circle_is_a_located_error() -> None:
    assert errors_of("G21 G90\nG00 X10. Y0.\nG03 X0. Y10.5 I-10. J0. F100.") == [
        "t.nc:3:15: error: arc end point is not on the circle: radius 10.0000 mm at the start, "
        "10.5000 mm at the end (the controller accepts a difference up to 0.01 mm here)"]


def test_ijk_arc_within_the_radius_tolerance_is_accepted() -> None:
    ev = body("G21 G90\nG00 X10. Y0.\nG03 X0. Y10.005 I-10. J0. F100.")[1]
    assert ev["move"] == "ccw" and ev["y"] == 10.005


def test_centre_offset_outside_the_plane_is_an_error() -> None:
    assert errors_of("G21 G90 G17\nG00 X10. Y0.\nG03 X0. Y10. I-10. K1. F100.") == [
        "t.nc:3:20: error: arc centre offset along Z is outside the XY plane"]


def test_arc_geometry_helpers() -> None:
    c = centre_from_radius((10.0, 0.0), (0.0, 10.0), 10.0, clockwise=True)
    assert c == pytest.approx((10.0, 10.0))
    assert arc_sweep((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), clockwise=False) == pytest.approx(math.pi / 2)
    assert arc_sweep((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), clockwise=True) == pytest.approx(1.5 * math.pi)
    assert arc_sweep((10.0, 0.0), (10.0, 0.0), (0.0, 0.0), clockwise=True) == pytest.approx(2 * math.pi)
    pts = list(arc_points((10.0, 0.0, 0.0), (-10.0, 0.0, -2.0), (0.0, 0.0, 0.0), "XY", False, 0.01))
    assert pts[-1] == (-10.0, 0.0, -2.0)
    assert all(abs(math.hypot(x, y) - 10.0) < 1e-9 and y >= -1e-9 for x, y, _ in pts)
    assert all(a[2] >= b[2] for a, b in zip(pts, pts[1:]))
    # chord error: every midpoint between consecutive points is within 0.01 of the circle
    assert all(10.0 - math.hypot((a[0] + b[0]) / 2, (a[1] + b[1]) / 2) <= 0.01 for a, b in zip(pts, pts[1:]))


# -- reference return ---------------------------------------------------------------------------------

def test_g91_g28_z0_goes_straight_up_to_the_reference_point() -> None:
    assert_events(body("G21 G90\nG00 X10. Y20. Z30.\nG91 G28 Z0.\nG90"), [
        {"line": 2, "move": "rapid", "x": 10, "y": 20, "z": 30},
        {"line": 3, "move": "rapid", "x": 10, "y": 20, "z": 0},
    ])


def test_g28_passes_through_the_intermediate_point() -> None:
    assert_events(body("G21 G90\nG00 X10. Y20. Z30.\nG28 X5. Y5.\nG30 Z40."), [
        {"line": 2, "move": "rapid", "x": 10, "y": 20, "z": 30},
        {"line": 3, "move": "rapid", "x": 5, "y": 5, "z": 30},
        {"line": 3, "move": "rapid", "x": 0, "y": 0, "z": 30},
        {"line": 4, "move": "rapid", "x": 0, "y": 0, "z": 40},
        {"line": 4, "move": "rapid", "x": 0, "y": 0, "z": 0},
    ])


def test_g28_footer_with_spindle_stop_and_end() -> None:
    assert_events(body("G21 G90\nG00 X1. Y1. Z25.\nG91 G28 Z0. M05\nG90\nM30"), [
        {"line": 2, "move": "rapid", "x": 1, "y": 1, "z": 25},
        {"line": 3, "move": "rapid", "x": 1, "y": 1, "z": 0},
        {"line": 3, "event": "spindle", "dir": "stop"},
        {"line": 5, "event": "end"},
    ])


# -- machine events -----------------------------------------------------------------------------------

def test_dwell_in_seconds_and_milliseconds() -> None:
    assert_events(body("G21\nG04 X1.5\nG04 P250"), [
        {"line": 2, "event": "dwell", "seconds": 1.5},
        {"line": 3, "event": "dwell", "seconds": 0.25},
    ])


def test_event_order_within_a_block() -> None:
    assert_events(body("G21 G90\nT3 M06\nG00 X10. S1000 M03 M08\nG00 Z5. M05 M09\nM19\nM00\nM01\nM30"), [
        {"line": 2, "event": "tool", "number": 3},
        {"line": 3, "event": "spindle", "dir": "cw"},
        {"line": 3, "event": "coolant", "on": True},
        {"line": 3, "move": "rapid", "x": 10, "y": 0, "z": 0},
        {"line": 4, "move": "rapid", "x": 10, "y": 0, "z": 5},
        {"line": 4, "event": "spindle", "dir": "stop"},
        {"line": 4, "event": "coolant", "on": False},
        {"line": 5, "event": "orient", "angle": 0},
        {"line": 6, "event": "stop", "optional": False},
        {"line": 7, "event": "stop", "optional": True},
        {"line": 8, "event": "end"},
    ])


def test_tool_preselection_emits_nothing_until_the_change() -> None:
    """A tool change stops a turning spindle first (the tool changer does; grbl needs an M5 there)."""
    assert_events(body("G21\nT5\nM04\nM06\nM02"), [
        {"line": 3, "event": "spindle", "dir": "ccw"},
        {"line": 4, "event": "spindle", "dir": "stop"},
        {"line": 4, "event": "tool", "number": 5},
        {"line": 5, "event": "end"},
    ])


def test_a_tool_change_with_the_spindle_stopped_adds_no_stop() -> None:
    assert_events(body("G21\nT5\nM03\nM05\nM06\nM02"), [
        {"line": 3, "event": "spindle", "dir": "cw"},
        {"line": 4, "event": "spindle", "dir": "stop"},
        {"line": 5, "event": "tool", "number": 5},
        {"line": 6, "event": "end"},
    ])


def test_nothing_runs_after_the_program_end() -> None:
    assert_events(body("G21 G90\nM30\nG00 X10.\nG31 X1."), [{"line": 2, "event": "end"}])


def test_block_delete_blocks_are_executed() -> None:
    assert_events(body("G21\n/G04 X3."), [{"line": 2, "event": "dwell", "seconds": 3}])


# -- what cannot be simulated --------------------------------------------------------------------------

def test_native_codes_are_rejected_with_their_location() -> None:
    assert errors_of("G21 G90\nG00 X1.\nN30 G31 X1.") == [
        "t.nc:3:5: error: G31 (skip function) cannot be simulated"]
    # a machine builder's M code is simulated since issue 12 (tests/test_machine_codes.py)


def test_every_error_is_collected_and_the_run_goes_on() -> None:
    errors = errors_of("G21 G90\nG31 X1.\nG01 X1.\nG00 X1. A1.")
    assert [e.split(": error: ")[0] for e in errors] == ["t.nc:2:1", "t.nc:3:1", "t.nc:4:9"]


# -- compound motion (the form expanded canned cycles arrive in) ----------------------------------------

def _ctx(level: ErrorLevel = ErrorLevel.RAISE) -> Context:
    return Context("c.nc", MachineSetup(), Diagnostics(level), "fanuc")


def test_compound_motion_items_are_absolute_and_run_in_order() -> None:
    start = Block(1, "G91 G00 X10. Y10. Z50.")
    from postproc.ir import DistanceMode
    start.add(DistanceMode("incremental"))
    start.add(Motion("rapid", {"X": 10.0, "Y": 10.0, "Z": 50.0}))
    cycle = Block(2, "G84 ...")
    cycle.add(CompoundMotion("tap", [
        Motion("rapid", {"X": 20.0, "Y": 10.0}),
        Motion("rapid", {"Z": 5.0}),
        Feed(750.0),
        Motion("linear", {"Z": -15.0}),
        Dwell(0.3),
        SpindleControl("ccw"),
        Motion("linear", {"Z": 5.0}),
        SpindleOrientation(0.0),
    ]))
    events = list(simulate([start, cycle], _ctx()))
    assert_events(events[1:], [
        {"line": 1, "move": "rapid", "x": 10, "y": 10, "z": 50},
        {"line": 2, "move": "rapid", "x": 20, "y": 10, "z": 50},
        {"line": 2, "move": "rapid", "x": 20, "y": 10, "z": 5},
        {"line": 2, "move": "feed", "x": 20, "y": 10, "z": -15, "f": 750},
        {"line": 2, "event": "dwell", "seconds": 0.3},
        {"line": 2, "event": "spindle", "dir": "ccw"},
        {"line": 2, "move": "feed", "x": 20, "y": 10, "z": 5, "f": 750},
        {"line": 2, "event": "orient", "angle": 0},
    ])


def test_an_unresolved_cycle_is_unsupported() -> None:
    from postproc.ir import CycleCall
    block = Block(3, "G81 X1. Z-1. R1.")
    block.add(CycleCall("drill"))
    ctx = _ctx()
    list(simulate([block], ctx))
    assert [str(e) for e in ctx.diagnostics.errors] == [
        "c.nc:3:1: error: canned cycle 'drill' cannot be simulated: it was not resolved to motion"]


def test_lathe_tool_word_indexes_the_turret() -> None:
    setup = MachineSetup(input=InputSettings(machine_type="lathe"))
    events = run("G21\nT3", setup)
    assert events[0] == {**HEADER, "x_mode": "diameter"}  # a Fanuc T programs X as a diameter
    assert_events(events[1:], [{"line": 2, "event": "tool", "number": 3}])


def test_fanuc_reads_f_in_a_unit_changing_block_in_the_new_units() -> None:
    """Fanuc's manuals want G20/G21 alone at the start of a program and say nothing of an F beside
    it; the reader keeps the modal order (units, then F): G20 F10. is 10 in/min = 254 mm/min.
    LinuxCNC reads the same F in the old units (tests/test_linuxcnc.py)."""
    feeds = [e["f"] for e in body("G21 G90 G94\nG00 X0. Y0. Z0.\nG20 F10. G01 X1.\nG01 X2.\n"
                                  "G21 F127. G01 X60.\n") if "move" in e]
    assert feeds == [254, 254, 127]
