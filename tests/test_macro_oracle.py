"""Programs that compute, checked against LinuxCNC's own interpreter.

Each ``tests/golden/macro/NAME.nc`` is a Fanuc Custom Macro B program; beside it ``NAME.ngc`` is a
hand-written LinuxCNC O-word program making the same moves (see the folder's README). rs274 runs the
``.ngc``; our interpreter runs the ``.nc`` (and the ``.ngc`` through our LinuxCNC reader): the moves must
agree, and so must the flattened grbl translation of the Fanuc program.
"""

from __future__ import annotations

import io
import math
import re
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
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
def test_fanuc_macro_program_moves_as_rs274_runs_its_oword_equivalent(path: Path) -> None:
    theirs = [e for e in canonical_moves(run_rs274(path.with_suffix(".ngc").read_text()), start=(0.0, 0.0, 0.0))
              if "move" in e]
    _same(_moves(path, "fanuc"), theirs)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_our_linuxcnc_reader_runs_the_oword_equivalent_as_rs274_does(path: Path) -> None:
    ngc = path.with_suffix(".ngc")
    theirs = [e for e in canonical_moves(run_rs274(ngc.read_text()), start=(0.0, 0.0, 0.0)) if "move" in e]
    _same(_moves(ngc, "linuxcnc"), theirs)


@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_flattened_grbl_translation_makes_the_same_moves(tmp_path: Path, path: Path) -> None:
    out = io.StringIO(newline="")
    with open(path, encoding="utf-8", newline="") as src:
        translate(src, out, file=str(path), source="fanuc", target="grbl")
    text = out.getvalue()
    code = re.sub(r"\([^)]*\)", "", text)
    assert "#" not in code and "WHILE" not in code and "GOTO" not in code and "M98" not in code, text
    flat = tmp_path / "flat.nc"
    flat.write_text(text, encoding="utf-8")
    _same(_moves(flat, "grbl"), _moves(path, "fanuc"))
