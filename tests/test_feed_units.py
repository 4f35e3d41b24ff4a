"""An F in a block that changes units: read in the units before the block where the dialect declares
``FEED_BEFORE_UNITS`` (the RS274/NGC order of execution: set feed rate before set length units; LinuxCNC
[V: rs274], Mach3 [K: its manual's table]), in the new units elsewhere (grbl). Reader, simulation and
writer follow the one flag.

grbl's ``G20 G1 X1. F10.`` feeds at 10 in/min = 254 mm/min (hand-derived): a FEED_BEFORE_UNITS target,
in mm until that block, must say F254.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.plugins import default_registry
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

GRBL = "G21 G90 G0 X0. Y0. Z10.\nG1 X5. F100.\nG20 G1 X1. F10.\nG1 X2.\nG21 G1 X10. F200.\nM30\n"
FEEDS_MM = [100.0, 254.0, 254.0, 200.0]
"""mm/min of the four feed moves (F200 under G21 is 200 mm/min in either order)."""
REGISTRY = default_registry()
BEFORE = sorted(n for n, c in REGISTRY.dialects.items() if c.FEED_BEFORE_UNITS and c.WRITER and c.READER)


def _feeds(text: str, dialect: str) -> list[float]:
    return [round(float(e["f"]), 4) for e in toolpath_events(io.StringIO(text), file="t.nc", dialect=dialect)
            if e.get("move") == "feed"]


def _translate(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source=source, target=target)
    return out.getvalue()


def test_the_dialects_that_read_f_before_units_are_the_rs274_ngc_ones() -> None:
    assert {"linuxcnc", "mach3"} <= set(BEFORE) and "grbl" not in BEFORE


def test_grbl_reads_f_in_the_new_units() -> None:
    assert _feeds(GRBL, "grbl") == FEEDS_MM


@pytest.mark.parametrize("target", BEFORE)
def test_f_in_a_unit_changing_block_is_written_in_the_units_before_it(target: str) -> None:
    text = _translate(GRBL, "grbl", target)
    third = text.splitlines()[2]
    assert third.startswith("G20 G1 X1") and third.endswith(" F254."), text
    assert _feeds(text, target) == FEEDS_MM


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("target", BEFORE)
def test_rs274_feeds_the_rs274_ngc_outputs_as_grbl_does(target: str) -> None:
    """Mach3's output is RS274/NGC too: the interpreter whose order of execution both follow runs it."""
    moves = canonical_moves(run_rs274(_translate(GRBL, "grbl", target)), start=(0.0, 0.0, 0.0), feeds=True)
    assert [round(e["f"], 3) for e in moves if e.get("move") == "feed"] == FEEDS_MM


@pytest.mark.parametrize("target", BEFORE)
def test_back_to_grbl_the_feed_is_in_the_new_units_again(target: str) -> None:
    back = _translate(_translate(GRBL, "grbl", target), target, "grbl")
    assert "G20 G1 X1. F10.\n" in back, back
    assert _feeds(back, "grbl") == FEEDS_MM
