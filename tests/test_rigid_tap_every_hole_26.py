"""A Fanuc rigid tap cycle stays rigid at every hole (issue 26, found translating to ISG): the next-hole lane
(``postproc.fast.holes``) copied the cycle record without its pitch, so from the third hole of a row on
the tap was expanded as a floating tap, feed moves with the spindle reversed, on both sides of a
translation (``verify`` passed); and it remembered the pitch across a spindle speed change, which in feed
per minute changes it (F/S [V: Fanuc 0i connection manual B-63833EN-1/02, rigid tapping]). Expected values
hand-derived from the program text."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events

ROW = "G21\nG90 G17 {mode}\nG0 X0. Y0. Z10. S500 M3\nM29 S500\nG99 G84 X1. Y1. Z-5. R2. {feed}\nX2.\nX3.\nX4.\nG80\nM30\n"


def taps(text: str) -> list[tuple[Any, ...]]:
    events = toolpath_events(io.StringIO(text, newline="").readlines(), file="t.nc", dialect="fanuc",
                             setup=MachineSetup())
    return [(e["line"], e["x"], e["z"], e["f"]) for e in events if e.get("move") in ("tap", "feed")]


@pytest.mark.parametrize("mode, feed", [("G94", "F500."), ("G95", "F1.")])
def test_every_hole_of_a_row_is_tapped_rigidly(mode: str, feed: str) -> None:
    # pitch 1 mm: F500 / S500 per minute, F1 per revolution; in to Z-5 and back to R2 at each of 4 holes
    assert taps(ROW.format(mode=mode, feed=feed)) == [
        (line, x, z, 1) for line, x in ((5, 1), (6, 2), (7, 3), (8, 4)) for z in (-5, 2)]


def test_a_new_spindle_speed_between_holes_changes_the_pitch_per_minute() -> None:
    text = ROW.format(mode="G94", feed="F500.").replace("X3.\n", "S250\nX3.\n")
    # from S250 on: F500 / 250 = 2 mm per revolution
    assert taps(text) == [(5, 1, -5, 1), (5, 1, 2, 1), (6, 2, -5, 1), (6, 2, 2, 1),
                          (8, 3, -5, 2), (8, 3, 2, 2), (9, 4, -5, 2), (9, 4, 2, 2)]
