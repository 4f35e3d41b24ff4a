"""Machine positions in the toolpath's work frame: a move in machine coordinates (G53) and a reference point
are put in the program's coordinates with the work offset of the active system, as LinuxCNC gives them.

rs274 prints canonical points in program coordinates with the work offset apart (``SET_G5X_OFFSET``); its G53
move is the machine position less that offset. The work offsets are the set-up's (``<WorkOffsets>``) on our
side and set by ``G10 L2`` on rs274's (its standalone interpreter has no set-up), so the two toolpaths compare
point for point. Where the program sets the offset itself, the toolpath's frame holds it (its points are
``g5x + p``) and rs274's points are carried there by adding the offset in force.
"""

from __future__ import annotations

import copy
import io
import re
from typing import Any

import pytest

from postproc.errors import ErrorList
from postproc.setup.machine import WorkOffsetData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

OFFSETS = {1: (-100.0, -50.0, -200.0), 2: (-300.0, -60.0, -180.5)}
"""Work systems 1 (G54) and 2 (G55): machine position of each one's zero, mm."""

BODY = ("G54 G0 X10 Y10 Z20\n"
        "G53 G0 Z0\n"              # machine Z0: work Z 200 in G54
        "G1 X30 F100\n"
        "G55 G0 X5 Y5\n"
        "G53 G1 X-250 Y-40 F200\n"  # machine (-250, -40): work (50, 20) in G55
        "G91 G1 X5 Y5\n"           # from there, not from the machine numbers
        "G90 G53 G0 Z-100\n"       # work Z 80.5 in G55
        "G1 Z10\n"
        "G28 Z20\n"                # via work Z20, then to the reference point: machine Z0, work Z 180.5
        "M2\n")


def _g10(offsets: dict[int, tuple[float, float, float]]) -> str:
    return "".join(f"G10 L2 P{n} X{x:g} Y{y:g} Z{z:g}\n" for n, (x, y, z) in offsets.items())


def _setup(offsets: dict[int, tuple[float | None, float | None, float | None]]) -> MachineSetup:
    setup = copy.copy(MachineSetup())
    setup.work_offsets = {str(n): WorkOffsetData(number=n, x=x, y=y, z=z) for n, (x, y, z) in offsets.items()}
    return setup


def _moves(text: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="t.ngc", dialect="linuxcnc", setup=setup)
    return [{k: e[k] for k in ("move", "x", "y", "z")} for e in events if "move" in e]


def _theirs(calls: list[str]) -> list[dict[str, Any]]:
    return [{k: e[k] for k in ("move", "x", "y", "z")} for e in canonical_moves(calls) if "move" in e]


_G5X = re.compile(r"SET_G5X_OFFSET\(\d+,\s*([-\d.]+),\s*([-\d.]+),\s*([-\d.]+)")


def _in_machine_frame(calls: list[str]) -> list[dict[str, Any]]:
    """rs274's moves plus the work offset in force at each (no G92 or rotation in these programs)."""
    out, g5x = [], (0.0, 0.0, 0.0)
    for line in calls:
        m = _G5X.search(line)
        if m:
            g5x = (float(m.group(1)), float(m.group(2)), float(m.group(3)))
            continue
        for e in _theirs([line]):
            out.append({"move": e["move"], "x": round(e["x"] + g5x[0], 6), "y": round(e["y"] + g5x[1], 6),
                        "z": round(e["z"] + g5x[2], 6)})
    return out


def test_machine_positions_are_put_in_the_work_frame_by_hand() -> None:
    ours = _moves("G21 G17 G90 G94\n" + BODY, _setup(OFFSETS))
    assert [(m["x"], m["y"], m["z"]) for m in ours] == [
        (10, 10, 20), (10, 10, 200), (30, 10, 200),
        (5, 5, 180.5),  # machine Z0 in G55 (the machine stays, its number changes)
        (50, 20, 180.5), (55, 25, 180.5), (55, 25, 80.5), (55, 25, 10), (55, 25, 20), (55, 25, 180.5)]


@needs_rs274
def test_machine_positions_match_rs274_with_the_set_ups_offsets() -> None:
    theirs = _theirs(run_rs274("G21 G17 G90 G94\n" + _g10(OFFSETS) + BODY))
    assert _moves("G21 G17 G90 G94\n" + BODY, _setup(OFFSETS)) == theirs


@needs_rs274
def test_machine_positions_match_rs274_with_the_programs_offsets() -> None:
    """The program sets the offsets itself: the frame holds them; the set-up's other values do not count."""
    text = "G21 G17 G90 G94\n" + _g10(OFFSETS) + BODY
    ours = _moves(text, _setup({1: (7.0, 7.0, 7.0), 2: (9.0, 9.0, 9.0)}))
    assert ours == _in_machine_frame(run_rs274(text))
    assert ours[1]["z"] == 0  # the G53 Z0 is the machine's zero in this frame


def test_a_set_up_without_the_active_systems_offset_is_a_located_error() -> None:
    with pytest.raises(ErrorList) as info:
        _moves("G21 G90 G55 G0 X0 Y0 Z10\nG53 G0 Z0\nM2\n", _setup({1: OFFSETS[1]}))
    assert [str(e) for e in info.value.errors] == [
        't.ngc:2:8: error: a machine position cannot be put in work coordinates: the set-up gives work system 2 '
        'no offset for Z (<WorkOffsets><Offset number="2" z=...>) and the program sets none']


def test_a_set_up_without_work_offsets_takes_them_as_zero() -> None:
    """The documented model (docs/toolpath-format.md, "What the simulation assumes")."""
    assert _moves("G21 G90 G0 X1 Y2 Z10\nG53 G0 Z0\nG28 X5\nM2\n") == [
        {"move": "rapid", "x": 1, "y": 2, "z": 10}, {"move": "rapid", "x": 1, "y": 2, "z": 0},
        {"move": "rapid", "x": 5, "y": 2, "z": 0}, {"move": "rapid", "x": 0, "y": 2, "z": 0}]


def test_a_change_to_a_system_the_set_up_lacks_after_a_move_is_a_located_error() -> None:
    """Before the first move the start is a point of the system the program selects (no number changes)."""
    with pytest.raises(ErrorList) as info:
        _moves("G21 G90 G54 G0 X0 Y0 Z10\nG55\nG0 X5\nM2\n", _setup({1: OFFSETS[1], 2: (1.0, 2.0, None)}))
    assert [str(e) for e in info.value.errors] == [
        't.ngc:2:1: error: where the tool stands in the new work coordinates is unknown: the set-up gives work '
        'system 2 no offset for Z (<WorkOffsets><Offset number="2" z=...>) and the program sets none']
