"""Fagor drilling checked against LinuxCNC's own interpreter, rs274.

``tests/golden/fagor/oracle/NAME.nc`` is a Fagor program; beside it ``NAME.ngc`` is written by hand with
LinuxCNC's native cycles (Fagor ``G81 Z I K`` as ``G82 R Z P``, ``G89 Z I K`` as ``G89 R Z P``). rs274
runs the ``.ngc`` with its own cycle code; our Fagor reading of the ``.nc`` must make the same moves.
Every Fagor example and golden is also translated to LinuxCNC (rs274 checks that output through the
conftest hook, and runs it here) and to grbl and Fanuc, each verified at zero deviation.
"""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
CASES = sorted((ROOT / "tests" / "golden" / "fagor" / "oracle").glob("*.nc"))
PROGRAMS = CASES + sorted((ROOT / "examples" / "fagor").glob("*.nc"))
TOLERANCE_MM = 2e-4
"""rs274 prints 4 decimals (mm programs)."""


def _moves(text: str, dialect: str) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect) if "move" in e]


def _same(ours: list[dict[str, Any]], theirs: list[dict[str, Any]]) -> None:
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b)


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fagor", target=target)
    return out.getvalue()


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_fagor_drilling_moves_as_rs274_runs_its_native_cycles(path: Path) -> None:
    theirs = [e for e in canonical_moves(run_rs274(path.with_suffix(".ngc").read_text()), start=(0.0, 0.0, 0.0))
              if "move" in e]
    _same(_moves(path.read_text(encoding="utf-8"), "fagor"), theirs)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", PROGRAMS, ids=lambda p: p.stem)
def test_fagor_translated_to_linuxcnc_moves_as_rs274_runs_it(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    theirs = [e for e in canonical_moves(run_rs274(_translate(text, "linuxcnc")), start=(0.0, 0.0, 0.0))
              if "move" in e]
    _same(_moves(text, "fagor"), theirs)


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "fanuc"])
@pytest.mark.parametrize("path", PROGRAMS, ids=lambda p: p.stem)
def test_fagor_program_translates_with_zero_deviation(path: Path, target: str) -> None:
    text = path.read_text(encoding="utf-8")
    out = _translate(text, target)
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in=str(path), file_out="out.nc",
                          source="fagor", target=target, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out
