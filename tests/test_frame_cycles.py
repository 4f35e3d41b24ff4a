"""Hole cycles under Fanuc scaling (issue #27): the hole positions scale as any point, a negative factor
mirrors them; the Z moves are those of the unscaled cycle when only X and Y scale (Haas scales no Z move of a
cycle, Fanuc never Q or d: the controllers agree there). A Z factor other than 1 is refused by name, and so is a boring cycle's shift under any frame that turns,
scales or mirrors (it follows the spindle's oriented stop, fixed to the machine).

Expected toolpaths: the holes carried by hand (``x' = cx + f (x - cx)``), drilled by the same cycle written
at those points without a frame.
"""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

HEAD = "G21 G17 G90 G94\nG00 X0. Y0. Z5.\n"


def moves(text: str) -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(HEAD + text + "M30\n", newline=""), file="t.nc", dialect="fanuc")
    return [{k: v for k, v in e.items() if k != "line"} for e in events if "move" in e]


@pytest.mark.parametrize("scaled, by_hand", [
    # X doubled about X10, Y mirrored about Y0: (15, 5) -> (20, -5), (20, 10) -> (30, -10)
    ("G51 X10. Y0. I2000 J-1000\nG99 G81 X15. Y5. Z-3. R2. F100.\nX20. Y10.\nG80\nG50\n",
     "G99 G81 X20. Y-5. Z-3. R2. F100.\nX30. Y-10.\nG80\n"),
    # a peck cycle: its Q and clearance are Z moves, unscaled; the holes halved about (0, 0)
    ("G51 X0 Y0 I500 J500\nG98 G83 X20. Y-8. Z-10. R1. Q3. F80.\nX-6. Y4.\nG80\nG50\n",
     "G98 G83 X10. Y-4. Z-10. R1. Q3. F80.\nX-3. Y2.\nG80\n"),
    # an incremental hole: its increment scales (X +10 doubled: +20 from the scaled first hole; G91 makes R
    # and Z increments too, on both sides)
    ("G51 X0 Y0 I2000 J2000\nG99 G81 X5. Y5. Z-2. R1. F100.\nG91 X10.\nG90 G80\nG50\n",
     "G99 G81 X10. Y10. Z-2. R1. F100.\nG91 X20.\nG90 G80\n"),
])
def test_a_hole_cycle_under_scaling_drills_the_scaled_holes(scaled: str, by_hand: str) -> None:
    assert moves(scaled) == moves(by_hand)


@pytest.mark.parametrize("text, message", [
    ("G51 X0 Y0 Z0 P2000\nG00 Z5.\nG81 X5. Y5. Z-2. R1. F100.\nG80\nG50\n", "a canned cycle under a scaling of Z"),
    ("G51 X0 Y0 I2000 J2000\nG76 X5. Y5. Z-2. R1. Q0.5 F100.\nG80\nG50\n",
     "a boring cycle with a shift under coordinate rotation, scaling or a mirror"),
    ("G68 X0 Y0 R30.\nG87 X5. Y5. Z-8. R-2. Q0.5 F100.\nG80\nG69\n",
     "a boring cycle with a shift under coordinate rotation, scaling or a mirror"),
    ("G51.1 X0\nG76 X5. Y5. Z-2. R1. Q0.5 F100.\nG80\nG50.1 X0\n",
     "a boring cycle with a shift under coordinate rotation, scaling or a mirror"),
])
def test_what_the_controllers_scale_differently_is_refused(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as info:
        moves(text)
    assert message in str(info.value.errors[0])


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_a_scaled_peck_cycle_translates_and_verifies(target: str) -> None:
    source = HEAD + "G51 X0 Y0 I1500 J-1500\nG98 G83 X20. Y-8. Z-10. R1. Q3. F80.\nX-6. Y4.\nG80\nG50\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(source), out, file="t.nc", source="fanuc", target=target)
    assert not [line for line in out.getvalue().splitlines() if "G51" in line and not line.startswith("(")]
    report = verify_lines(io.StringIO(source), io.StringIO(out.getvalue()), file_in="t.nc", file_out="o.nc",
                          source="fanuc", target=target)
    assert report.ok, report.summary()
