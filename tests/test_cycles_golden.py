"""The cycles' CompoundMotion items against the hand-derived golden toolpaths (tests/golden/fanuc/cycles),
and the cycle errors against tests/golden/fanuc/invalid. The simulator's own golden test is separate:
this one checks that the items and those files agree, line by line."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from postproc.api import read_program
from postproc.errors import ErrorList
from postproc.ir import Block, Dwell, Motion, ProgramControl, SpindleControl, SpindleOrientation
from postproc.plugins import default_registry
from postproc.setup.machine_setup import CycleSettings, MachineSetup

GOLDEN = Path(__file__).resolve().parent / "golden" / "fanuc"
CASES = sorted(p.stem for p in (GOLDEN / "cycles").glob("*.nc"))
SETUP = MachineSetup(cycles=CycleSettings(peck_retract=0.5, peck_clearance=0.3))
"""The set-up the golden README prescribes (G73 d = 0.5 mm, G83 d = 0.3 mm, orientation 0 deg, +X shift)."""


def event_rows(rows: list[dict[str, Any]]) -> list[tuple[Any, ...]]:
    out: list[tuple[Any, ...]] = []
    for row in rows:
        if "move" in row:
            out.append((row["move"], round(row["x"], 6), round(row["y"], 6), round(row["z"], 6)))
        elif row["event"] == "spindle":
            out.append(("spindle", row["dir"]))
        elif row["event"] == "dwell":
            out.append(("dwell", row["seconds"]))
        elif row["event"] == "orient":
            out.append(("orient", row["angle"]))
        elif row["event"] == "stop":
            out.append(("stop", row["optional"]))
        else:
            raise AssertionError(f"unexpected event in a cycle: {row}")
    return out


def item_rows(block: Block) -> list[tuple[Any, ...]]:
    out: list[tuple[Any, ...]] = []
    for item in block.sections["CompoundMotion"].items:
        if isinstance(item, Motion):
            a = item.axes
            out.append(("rapid" if item.mode == "rapid" else "feed", round(a["X"], 6), round(a["Y"], 6),
                        round(a["Z"], 6)))
        elif isinstance(item, SpindleControl):
            out.append(("spindle", item.direction))
        elif isinstance(item, Dwell):
            out.append(("dwell", item.seconds))
        elif isinstance(item, SpindleOrientation):
            out.append(("orient", item.angle))
        elif isinstance(item, ProgramControl):
            out.append(("stop", item.kind == "optional_stop"))
        else:
            raise AssertionError(f"unexpected item {item!r}")
    return out


@pytest.mark.parametrize("case", CASES)
def test_items_match_the_golden_toolpath(case: str) -> None:
    default_registry()
    path = GOLDEN / "cycles" / f"{case}.nc"
    blocks = read_program(path.read_text().splitlines(keepends=True), file=str(path), dialect="fanuc", setup=SETUP)
    expected = [json.loads(line) for line in (GOLDEN / "cycles" / f"{case}.jsonl").read_text().splitlines()[1:]]
    cycle_blocks = [b for b in blocks if "CannedCycle" in b.sections]
    assert cycle_blocks, "every golden cycle case has cycle blocks"
    for block in cycle_blocks:
        rows = [r for r in expected if r["line"] == block.line]
        assert item_rows(block) == event_rows(rows), f"line {block.line}: {block.text}"
        feeds = {r["f"] for r in rows if r.get("move") == "feed"}
        assert feeds <= {block.sections["CannedCycle"].feed}


def test_every_golden_case_is_checked() -> None:
    assert len(CASES) == 16


@pytest.mark.parametrize("case", ["cycle_without_z", "g83_without_q", "g87_under_g99"])
def test_cycle_errors_match_the_pinned_messages(case: str) -> None:
    default_registry()
    path = GOLDEN / "invalid" / f"{case}.nc"
    message, where = (GOLDEN / "invalid" / f"{case}.err").read_text().splitlines()[:2]
    with pytest.raises(ErrorList) as caught:
        read_program(path.read_text().splitlines(keepends=True), file=str(path), dialect="fanuc")
    errors = caught.value.errors
    assert len(errors) == 1
    assert errors[0].message == message
    assert errors[0].location is not None
    assert f"{errors[0].location.line}:{errors[0].location.col}" == where
