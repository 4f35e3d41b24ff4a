"""G93 inverse-time feed towards targets without it (issue 26, corpus ``inverse_time_with_comp``): each move
gets the feed per minute that takes it the same time, length x F (arcs: arc length, helices with their
rise). Expected feeds are derived by hand and are rs274's own: LinuxCNC's interpreter turns inverse time
into a feed rate per move (SET_FEED_RATE) before it moves."""

from __future__ import annotations

import io
import math

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import Report, verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274

PROGRAM = """G21 G90 G17
G0 X0 Y0 Z0
G93 G1 X30 Y40 F2
G2 X50 Y60 R20 F0.5
G3 X50 Y60 I10 J0 Z-5 F0.25
G91 G1 X-10 F6
G94 G90 G1 X0 Y0 F300
M2
"""
FEEDS = [2 * 50.0, 0.5 * 20 * math.pi / 2, 0.25 * math.hypot(2 * math.pi * 10, 5), 6 * 10.0, 300.0]
"""Hand-derived (mm/min): the 30-40-50 line in 1/2 min; a quarter circle of R20 in 2 min; a full helical
turn of R10 rising 5 in 4 min; 10 mm incremental in 1/6 min; then per minute."""
INCH = PROGRAM.replace("G21", "G20")
INCH_FEEDS = [f for f in FEEDS[:-1]] + [300.0]  # in/min: the same numbers, lengths in inches


def _feeds(text: str, dialect: str) -> list[float]:
    return [e["f"] for e in toolpath_events(io.StringIO(text, newline=""), file="t.nc", dialect=dialect)
            if e.get("move") in ("feed", "cw", "ccw")]


def verify_texts(a: str, b: str, source: str, target: str) -> Report:
    return verify_lines(io.StringIO(a, newline=""), io.StringIO(b, newline=""), file_in="a", file_out="b",
                        source=source, target=target)


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="t.ngc", source="linuxcnc", target=target)
    return out.getvalue()


@pytest.mark.parametrize("target", ["fanuc", "isg", "fagor", "mach3"])
def test_inverse_time_becomes_the_feed_per_minute_of_each_move(target: str) -> None:
    text = _translate(PROGRAM, target)
    assert "G93" not in text.split("(")[0]
    got = _feeds(text, target)
    assert len(got) == len(FEEDS)
    for a, b in zip(got, FEEDS):
        assert math.isclose(a, b, rel_tol=1e-6), (got, FEEDS)


@pytest.mark.parametrize("target", ["fanuc", "mach3"])
def test_inch_feeds_stay_in_inches(target: str) -> None:
    got = _feeds(_translate(INCH, target), target)
    for a, b in zip(got, INCH_FEEDS):
        assert math.isclose(a, b * 25.4, rel_tol=1e-4), (got, INCH_FEEDS)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_hand_derived_feeds_are_rs274s() -> None:
    theirs = [e["f"] for e in canonical_moves(run_rs274(PROGRAM), start=(0.0, 0.0, 0.0), feeds=True)
              if e.get("move") in ("feed", "cw", "ccw")]
    assert len(theirs) == len(FEEDS)
    for a, b in zip(theirs, FEEDS):
        assert abs(a - b) < 1e-4, (theirs, FEEDS)


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_a_target_with_g93_keeps_it(target: str) -> None:
    text = _translate(PROGRAM, target)
    assert "G93" in text
    assert _feeds(text, target)[:4] == [2, 0.5, 0.25, 6]


@pytest.mark.parametrize("target", ["fanuc", "grbl", "isg"])
def test_verify_compares_inverse_time_with_per_minute_feeds(target: str) -> None:
    report = verify_texts(PROGRAM, _translate(PROGRAM, target), "linuxcnc", target)
    assert report.ok, report
    wrong = _translate(PROGRAM, "fanuc").replace("F100.", "F90.")
    assert not verify_texts(PROGRAM, wrong, "linuxcnc", "fanuc").ok


REFUSED = {
    "start unknown": ("G21 G90\nG28 X0 Y0 Z0\nG93 G1 X1 Y1 Z1 F2\nM2\n", "t.ngc:3:1: error: an inverse-time move"),
    "rotary axis": ("G21 G90 G0 X0 Y0 Z0 A0\nG93 G1 X1 A90 F2\nM2\n", "t.ngc:2:1: error: an inverse-time move of a rotary"),
}


ROTARY = MachineSetup()
ROTARY.machine.axes = "XYZA"
"""A machine with the rotary axis A (one without it refuses an A word before anything else)."""


@pytest.mark.parametrize("name", REFUSED)
def test_what_cannot_be_converted_exactly_is_a_located_error(name: str) -> None:
    source, message = REFUSED[name]
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(source, newline=""), io.StringIO(), file="t.ngc", source="linuxcnc", target="fanuc",
                  setup=ROTARY)
    assert str(info.value.errors[0]).startswith(message), str(info.value.errors[0])


INCH_AT_POWER_ON = MachineSetup()
INCH_AT_POWER_ON.controller.start_units = "inch"
"""A machine that powers on in inches (``<Controller startUnits="inch">``): a program without G20/G21 runs in inches."""


@pytest.mark.parametrize(("text", "setup", "feeds"), [
    # G91 before the first block the step changes: 3-4-5 in 1/2 min (10 mm/min), then the same increment in 1 min
    ("G21 G90 G17\nG0 X0 Y0 Z0\nG91\nG93 G1 X3 Y4 F2\nG1 X3 Y4 F1\nM2\n", MachineSetup(), [10.0, 5.0]),
    # G20 and G91 before it: the same numbers in inches (25.4 mm each); back to G90: X0 Y0 from (6, 8) in, 10 in
    # in 1/2 min
    ("G20 G90 G17\nG0 X0 Y0 Z0\nG91\nG93 G1 X3 Y4 F2\nG1 X3 Y4 F1\nG90 G1 X0 Y0 F2\nM2\n", MachineSetup(),
     [254.0, 127.0, 508.0]),
    # the machine's power-on units (the program programs none): inches, 10 in/min
    ("G90 G17\nG0 X0 Y0 Z0\nG93 G1 X3 Y4 F2\nM2\n", INCH_AT_POWER_ON, [254.0]),
])
def test_the_units_and_distance_mode_before_the_converted_move(text: str, setup: MachineSetup,
                                                               feeds: list[float]) -> None:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=setup)
    got = [e["f"] for e in toolpath_events(io.StringIO(out.getvalue(), newline=""), file="t.nc", dialect="fanuc",
                                           setup=setup) if e.get("move") == "feed"]
    assert got == pytest.approx(feeds, rel=1e-9), (got, out.getvalue())
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out.getvalue(), newline=""), file_in="a",
                          file_out="b", source="linuxcnc", target="fanuc", setup=setup)
    assert report.ok, report.summary()
