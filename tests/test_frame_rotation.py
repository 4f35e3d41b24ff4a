"""Fanuc G68 with an incremental angle (issue #27): parameter 5400#0 RIN = 1 (Haas setting 73), set-up
``<Controller rotationIncremental="true">``: under G91 R turns from the angle of the program's previous G68.

Expected points by hand: (10, 0) turned by a about (0, 0) is (10 cos a, 10 sin a).
"""

from __future__ import annotations

import io
import math
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.groups import ControllerSettings
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

HEAD = "G21 G17 G90 G94\nG00 X0. Y0. Z5.\n"


def _setup(incremental: bool) -> MachineSetup:
    setup = MachineSetup()
    setup.controller = ControllerSettings(rotation_incremental=incremental)
    return setup


def points(text: str, incremental: bool = True) -> list[tuple[float, float]]:
    events = toolpath_events(io.StringIO(HEAD + text + "M30\n", newline=""), file="t.nc", dialect="fanuc",
                             setup=_setup(incremental))
    return [(round(e["x"], 6), round(e["y"], 6)) for e in events if "move" in e][1:]


def _turned(degrees: float) -> tuple[float, float]:
    a = math.radians(degrees)
    return round(10 * math.cos(a), 6) + 0.0, round(10 * math.sin(a), 6) + 0.0


STEPS = ("G00 X0 Y0\nG68 X0 Y0 R30.\nG01 X10. Y0 F100.\nG69\n"
         "G00 X0 Y0\nG91 G68 R15.\nG90 G01 X10. Y0\nG69\n"
         "G00 X0 Y0\nG91 G68 R-60.\nG90 G01 X10. Y0\nG69\n")
"""30, then 30 + 15 = 45, then 45 - 60 = -15. A G68 without a centre turns about the tool's point: the
origin, where the G00 before it (after G69, unturned) leaves the tool."""


def _drawn(text: str, incremental: bool = True) -> list[tuple[float, float]]:
    return [p for p in points(text, incremental) if p != (0.0, 0.0)]


def test_an_incremental_angle_turns_from_the_previous_rotation() -> None:
    assert _drawn(STEPS) == [_turned(30), _turned(45), _turned(-15)]


def test_without_the_parameter_r_is_the_angle_in_g91_too() -> None:
    assert _drawn(STEPS, incremental=False) == [_turned(30), _turned(15), _turned(-60)]


@pytest.mark.parametrize("text, message", [
    ("G91 G68 R15.\n", "an incremental angle needs a rotation before it"),
    ("G68 X0 Y0 R30.\nG69\nG91 G68 X1. Y0 R15.\n", "whether its centre words are increments is not settled"),
])
def test_what_the_manuals_leave_open_is_a_located_error(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        points(text)
    assert message in str(info.value.errors[0])


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_an_incremental_rotation_translates_and_verifies(target: str) -> None:
    source = HEAD + STEPS + "M30\n"
    out = io.StringIO()
    translate(io.StringIO(source), out, file="t.nc", source="fanuc", target=target, setup=_setup(True))
    assert f"X{_turned(45)[0]:.3f}" in out.getvalue()
    report = verify_lines(io.StringIO(source), io.StringIO(out.getvalue()), file_in="t.nc", file_out="o.nc",
                          source="fanuc", target=target, setup=_setup(True))
    assert report.ok, report.summary()
