"""A native cycle that leaves its return level to the controller's start: LinuxCNC starts in G99 [V: rs274
returns to R], Mach3 in G98 (the dialect's reading): written for the other, the cycle gets its G98/G99.

Expected paths are hand-derived (drill at X5 Y5 and X10 Y5 from Z10, R2, to Z-2) and checked against
rs274 where the program is LinuxCNC's.
"""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

CYCLE = "G21 G90 G0 X0 Y0 Z10\nG81 X5 Y5 Z-2 R2 F100\nX10\nG80\nM2\n"


def _holes(back: float) -> list[tuple[Any, ...]]:
    """The moves of the two holes, each returning to Z ``back``."""
    return [("rapid", 0.0, 0.0, 10.0), ("rapid", 5.0, 5.0, 10.0), ("rapid", 5.0, 5.0, 2.0), ("feed", 5.0, 5.0, -2.0),
            ("rapid", 5.0, 5.0, back), ("rapid", 10.0, 5.0, back)] + \
        ([("rapid", 10.0, 5.0, 2.0)] if back != 2.0 else []) + [("feed", 10.0, 5.0, -2.0), ("rapid", 10.0, 5.0, back)]


AT_R = _holes(2.0)
AT_INITIAL = _holes(10.0)


def _path(text: str, dialect: str) -> list[tuple[Any, ...]]:
    return [(e["move"], round(e["x"], 4), round(e["y"], 4), round(e["z"], 4))
            for e in toolpath_events(io.StringIO(text), file="r.nc", dialect=dialect) if "move" in e]


def _rs274(text: str) -> list[tuple[Any, ...]]:
    return [(e["move"], round(e["x"], 4), round(e["y"], 4), round(e["z"], 4))
            for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]


def _translate(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="r.nc", source=source, target=target)
    return out.getvalue()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_starts_in_g99() -> None:
    assert _rs274(CYCLE) == AT_R == _path(CYCLE, "linuxcnc")


def test_a_linuxcnc_cycle_left_to_its_default_is_written_with_g99_for_mach3() -> None:
    mach3 = _translate(CYCLE, "linuxcnc", "mach3")
    assert mach3.splitlines()[1].startswith("G99 G81 "), mach3
    assert _path(mach3, "mach3") == AT_R
    assert _path(CYCLE, "mach3") == AT_INITIAL  # the same text on Mach3 returns to the initial level


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_mach3_cycle_left_to_its_default_is_written_with_g98_for_linuxcnc() -> None:
    ngc = _translate(CYCLE, "mach3", "linuxcnc")
    assert ngc.splitlines()[1].startswith("G98 G81 "), ngc
    assert _rs274(ngc) == AT_INITIAL


def test_a_level_the_program_sets_is_not_written_twice() -> None:
    program = CYCLE.replace("G81", "G98 G81")
    mach3 = _translate(program, "linuxcnc", "mach3")
    assert mach3.count("G98") == 1 and "G99" not in mach3, mach3
    assert _path(mach3, "mach3") == AT_INITIAL
