"""LinuxCNC o-word programs, checked against LinuxCNC's own interpreter.

Each ``tests/golden/macro/NAME.ngc`` is a hand-written LinuxCNC O-word program (see the folder's
README). rs274 runs it, and so does our LinuxCNC reader and interpreter: the moves must agree.
(Copied from /work/brief/test_macro_oracle.py: the LinuxCNC half of that oracle.)
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from postproc.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
CASES = sorted((ROOT / "tests" / "golden" / "macro").glob("*.nc"))
TOLERANCE_MM = 2e-4
"""rs274 prints 4 decimals (mm programs)."""


def _moves(path: Path, dialect: str) -> list[dict[str, Any]]:
    with open(path, encoding="utf-8", newline="") as src:
        return [e for e in toolpath_events(src, file=str(path), dialect=dialect) if "move" in e]


def _same(ours: list[dict[str, Any]], theirs: list[dict[str, Any]]) -> None:
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in the reference"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_our_linuxcnc_reader_runs_the_oword_equivalent_as_rs274_does(path: Path) -> None:
    ngc = path.with_suffix(".ngc")
    theirs = [e for e in canonical_moves(run_rs274(ngc.read_text()), start=(0.0, 0.0, 0.0)) if "move" in e]
    _same(_moves(ngc, "linuxcnc"), theirs)
