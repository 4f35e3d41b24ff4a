"""Defects: ``postproc info`` counted one hole per SINUMERIK ``HOLES1``/``HOLES2`` block, which makes the whole
row or circle in one block with the first hole's cycle record. Now it counts the pattern's holes (NUM of
each call), by hand: HOLES1 NUM 5 and HOLES2 NUM 4 make 9; checked against the toolpath too (one feed to
the bottom per hole), for a plain drill, a dwell drill and a bore that feeds out (its two feeds per hole
arrive at the bottom once)."""

from __future__ import annotations

import io

import pytest

from postproc.commands.info import program_info
from postproc.simulate.toolpath import toolpath_events

PROGRAM = ("G17 G90 G71\nG0 X0 Y0 Z10\nF100 S1000 M3\nMCALL {cycle}\nHOLES1(0,0,0,0,10,5)\n"
           "HOLES2(50,50,20,0,90,4)\nMCALL\nG0 X0 Y0\nM30\n")
CYCLES = {"CYCLE81(10,0,2,-5)": "drill", "CYCLE82(10, 0, 2, -5, , 0.5)": "drill_dwell",
          "CYCLE85(10, 0, 2, -5, , 0.5, 100, 100)": "bore_dwell_feed"}


@pytest.mark.parametrize("cycle", sorted(CYCLES))
def test_info_counts_every_hole_of_holes1_and_holes2(cycle: str) -> None:
    text = PROGRAM.format(cycle=cycle)
    report = program_info(text.splitlines(True), file="p.mpf", dialect="siemens", targets=False)
    assert report["holes"] == 5 + 4
    assert report["cycles"] == {CYCLES[cycle]: 1}
    bottoms = [ev for ev in toolpath_events(io.StringIO(text), file="p.mpf", dialect="siemens")
               if ev.get("move") == "feed" and ev["z"] == -5]
    assert len(bottoms) == 9


def test_a_single_hole_call_and_a_fanuc_repeat_still_count_as_before() -> None:
    one = PROGRAM.format(cycle="CYCLE81(10,0,2,-5)").replace("HOLES1(0,0,0,0,10,5)", "HOLES1(0,0,0,0,10,1)")
    assert program_info(one.splitlines(True), file="p.mpf", dialect="siemens", targets=False)["holes"] == 1 + 4
    fanuc = "G21 G90 G0 X0 Y0 Z10\nG91 G81 X10. Z-7. R-8. K3 F100.\nG80\nM30\n"
    assert program_info(fanuc.splitlines(True), file="p.nc", dialect="fanuc", targets=False)["holes"] == 3
