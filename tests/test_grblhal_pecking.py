"""grblHAL's G73 and G83, read as its motion control runs them.

Expected moves are derived by hand from grblHAL's source (github.com/grblHAL/core, stored commit f80fc34:
``motion_control.c`` ``mc_canned_drill``, ``gcode.c`` ``canned.dwell = 0.25f``, ``config.h``
``DEFAULT_G73_RETRACT`` 0.1 mm), not from the expansion they check.
"""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274
from tests.support.grblhal_rules import grblhal_problems

PECKS = """G21 G17 G90
G0 X0 Y0 Z10
G98 G73 X10 Z-2.5 R1 Q1 F100
G99 G83 X5 Y0 Z-4 R1 Q2
G0 Z10
M2
"""
DWELL = ("dwell", 0.25)
EXPECTED: list[tuple[Any, ...]] = [
    ("rapid", 0, 0, 10),
    # G98 G73 from Z10 (the initial level): X/Y at Z10, down to R, then each peck 1 deeper from R, a 0.25 s
    # dwell, up 0.1 (G73 retract) and on, the bottom's dwell, out to Z10 (the level the block started at)
    ("rapid", 10, 0, 10), ("rapid", 10, 0, 1), ("feed", 10, 0, 0), DWELL, ("rapid", 10, 0, 0.1),
    ("feed", 10, 0, -1), DWELL, ("rapid", 10, 0, -0.9), ("feed", 10, 0, -2), DWELL, ("rapid", 10, 0, -1.9),
    ("feed", 10, 0, -2.5), DWELL, ("rapid", 10, 0, 10),
    # G99 G83: each peck 2 deeper from R, a dwell, out to R, and a feed from R to the next depth
    ("rapid", 5, 0, 10), ("rapid", 5, 0, 1), ("feed", 5, 0, -1), DWELL, ("rapid", 5, 0, 1), ("feed", 5, 0, -3),
    DWELL, ("rapid", 5, 0, 1), ("feed", 5, 0, -4), DWELL, ("rapid", 5, 0, 1),
    ("rapid", 5, 0, 10),
]


def _moves(text: str, dialect: str) -> list[tuple[Any, ...]]:
    out: list[tuple[Any, ...]] = []
    for e in toolpath_events(io.StringIO(text, newline=""), file="t", dialect=dialect):
        if "move" in e:
            out.append((e["move"], round(e["x"], 6), round(e["y"], 6), round(e["z"], 6)))
        elif e.get("event") == "dwell":
            out.append(("dwell", e["seconds"]))
    return out


def _codes(text: str) -> set[str]:
    return {word for row in text.splitlines() if not row.startswith("(") for word in row.split()}


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="t.gcode", source="grblhal", target=target,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def test_g73_and_g83_move_as_mc_canned_drill_does() -> None:
    assert _moves(PECKS, "grblhal") == EXPECTED
    assert grblhal_problems(PECKS) == []


def test_a_grblhal_program_keeps_its_peck_cycles() -> None:
    assert _translate(PECKS, "grblhal") == PECKS


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "grbl"])
def test_towards_another_controller_the_pecks_are_expanded_with_grblhals_moves(target: str) -> None:
    text = _translate(PECKS, target)
    assert not _codes(text) & {"G73", "G83"}
    assert _moves(text, target) == EXPECTED
    report = verify_lines(io.StringIO(PECKS), io.StringIO(text), file_in="t.gcode", file_out="t.out",
                          source="grblhal", target=target, tolerance=0.0)
    assert report.ok, report


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_linuxcnc_expansion_runs_in_rs274_as_grblhal_moves() -> None:
    text = _translate(PECKS, "linuxcnc")
    theirs = []
    for e in rs274.canonical_moves(rs274.run_rs274(text), start=(0.0, 0.0, 0.0)):
        if "move" in e:
            theirs.append((e["move"], round(e["x"], 6), round(e["y"], 6), round(e["z"], 6)))
        elif e.get("event") == "dwell":
            theirs.append(("dwell", round(e["seconds"], 4)))
    assert theirs == EXPECTED


def test_a_fanuc_peck_cycle_is_still_expanded_for_grblhal() -> None:
    """No other family's G73/G83 dwells at each peck and feeds back from the retract level."""
    fanuc = "G21 G90 G00 X0. Y0. Z10.\nG99 G83 X5. Y0. Z-4. R1. Q2000 F100.\nG80\nM30\n"
    out = io.StringIO(newline="")
    translate(io.StringIO(fanuc, newline=""), out, file="t.nc", source="fanuc", target="grblhal",
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert not _codes(out.getvalue()) & {"G83", "G4"}
