"""A program's moves and dwells, and an exact verification of a translation: the helpers tests/test_fagor.py
and tests/test_siemens.py each wrote out, for dialect tests that hold a program to a hand-derived toolpath."""

from __future__ import annotations

import io

from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines


def moves_and_dwells(text: str, dialect: str, setup: MachineSetup | None = None,
                     file: str = "in.nc") -> list[tuple[object, ...]]:
    """(move, x, y, z) of each motion and ("dwell", seconds) of each dwell of the program ``file``."""
    out: list[tuple[object, ...]] = []
    for e in toolpath_events(io.StringIO(text), file=file, dialect=dialect, setup=setup):
        if "move" in e:
            out.append((e["move"], e["x"], e["y"], e["z"]))
        elif e.get("event") == "dwell":
            out.append(("dwell", e["seconds"]))
    return out


def assert_verifies_exactly(a: str, b: str, source: str, target: str, setup: MachineSetup | None = None) -> None:
    """``b`` (in ``target``) moves the tool as ``a`` (in ``source``) does, to the last digit, under one set-up."""
    report = verify_lines(io.StringIO(a), io.StringIO(b), file_in="a", file_out="b", source=source,
                          target=target, setup=setup, target_setup=setup, tolerance=0.0)
    assert report.ok, report.summary() + "\n--- a\n" + a + "--- b\n" + b
