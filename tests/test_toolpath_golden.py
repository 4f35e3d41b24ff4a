"""Golden toolpaths: tests/golden/fanuc/cycles/*.nc against the hand-written *.jsonl beside them, and
the example programs, which must simulate without errors (their arcs are consistent)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.tools import with_tools

ROOT = Path(__file__).parent
CYCLES = sorted((ROOT / "golden" / "fanuc" / "cycles").glob("*.nc"))
EXAMPLES = ROOT.parent / "examples" / "fanuc"
GOLDEN_SETUP = MachineSetup(cycles=CycleSettings(peck_retract=0.5, peck_clearance=0.3, orient_angle=0.0,
                                                 shift_direction="+X"))
"""The set-up tests/golden/fanuc/cycles/README.md prescribes."""


def same(actual: Any, expected: Any, tol: float = 1e-6) -> bool:
    """Parsed objects equal with the same keys, numbers within ``tol`` (10 equals 10.0), as README.md says."""
    if isinstance(expected, dict):
        return isinstance(actual, dict) and actual.keys() == expected.keys() and all(
            same(actual[k], expected[k], tol) for k in expected)
    if isinstance(expected, bool) or isinstance(actual, bool):
        return actual is expected
    if isinstance(expected, (int, float)) and isinstance(actual, (int, float)):
        return abs(actual - expected) <= tol
    return bool(actual == expected)


def first_difference(actual: list[dict[str, Any]], expected: list[dict[str, Any]]) -> str | None:
    for i, (a, e) in enumerate(zip(actual, expected)):
        if not same(a, e):
            return f"event {i}: got {a}, expected {e}"
    if len(actual) != len(expected):
        return f"got {len(actual)} events, expected {len(expected)}"
    return None


def events_of(path: Path, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    with open(path, encoding="utf-8", newline="") as f:
        return list(toolpath_events(f, file=str(path), dialect="fanuc", setup=setup or with_tools()))


def test_there_are_golden_cycle_cases() -> None:
    assert len(CYCLES) >= 16


@pytest.mark.parametrize("case", CYCLES, ids=[p.stem for p in CYCLES])
def test_cycle_golden(case: Path) -> None:
    expected = [json.loads(line) for line in case.with_suffix(".jsonl").read_text().splitlines() if line.strip()]
    actual = events_of(case, GOLDEN_SETUP)
    assert actual[0] == expected[0]
    assert first_difference(actual[1:], expected[1:]) is None, first_difference(actual[1:], expected[1:])


def test_example_without_cycles_simulates() -> None:
    events = events_of(EXAMPLES / "o1003_pocket_and_edge.nc")
    moves = [e for e in events if "move" in e]
    assert len(moves) == 40
    assert sum(1 for m in moves if m["move"] == "ccw") == 7
    assert events[-1] == {"line": 62, "event": "end"}


@pytest.mark.parametrize("name", ["o1001_plate_drill_tap.nc", "o1002_bracket_inch.nc",
                                  "o1004_flange_least_increment.nc"])
def test_examples_with_cycles_simulate(name: str) -> None:
    events = events_of(EXAMPLES / name)
    assert events[-1]["event"] == "end"
    assert any(e.get("move") == "feed" for e in events)


def test_inch_example_profile_arcs() -> None:
    """O1002's profile (lines 12-27) is cycle-free: run just that part, in inches converted to mm."""
    lines = (EXAMPLES / "o1002_bracket_inch.nc").read_text().splitlines(keepends=True)[:27]
    events = list(toolpath_events(lines, file="o1002.nc", dialect="fanuc", setup=with_tools()))
    arcs = [e for e in events if e.get("move") == "cw"]
    assert len(arcs) == 4
    first = arcs[0]
    assert first["line"] == 19
    assert (first["x"], first["y"], first["cx"], first["cy"], first["f"]) == pytest.approx(
        (6.35, 69.85, 6.35, 57.15, 406.4))
