"""ISG programs that compute, checked against LinuxCNC's own interpreter.

Each ``tests/golden/isg/oracle/NAME.nc`` is an ISG program; beside it ``NAME.ngc`` is a hand-written
LinuxCNC O-word program making the same moves (P<n> written as ``#[500+n]``, ``$FOR`` as a counted
``while``, ``$SWITCH`` as ``if``/``elseif``, ``$REPEAT .. $UNTIL c`` as ``do .. while [not c]``). rs274
runs the ``.ngc``; our interpreter runs the ``.nc``: the moves must agree, and so must the flattened grbl
translation and the LinuxCNC translation of the ISG program (each verified at zero deviation).
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
CASES = sorted((ROOT / "tests" / "golden" / "isg" / "oracle").glob("*.nc"))
TOLERANCE_MM = 2e-4
"""rs274 prints 4 decimals (mm programs)."""


def _moves(path: Path) -> list[dict[str, Any]]:
    with open(path, encoding="utf-8", newline="") as src:
        return [e for e in toolpath_events(src, file=str(path), dialect="isg") if "move" in e]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_isg_program_moves_as_rs274_runs_its_oword_equivalent(path: Path) -> None:
    theirs = [e for e in canonical_moves(run_rs274(path.with_suffix(".ngc").read_text()), start=(0.0, 0.0, 0.0))
              if "move" in e]
    ours = _moves(path)
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b)


@pytest.mark.parametrize("target", ["grbl", "linuxcnc", "fanuc"])
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_isg_program_translates_with_zero_deviation(path: Path, target: str) -> None:
    text = path.read_text(encoding="utf-8")
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file=str(path), source="isg", target=target)
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in=str(path), file_out="out.nc",
                          source="isg", target=target, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out.getvalue()


TRANSLATED = [ROOT / "tests/golden/isg/oracle/subroutine_for_if_while.nc", ROOT / "examples/isg/prof_contour_xy.nc"]
"""Programs whose every construct LinuxCNC spells ($SWITCH and $REPEAT have no o-word: flattened)."""


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", TRANSLATED, ids=lambda p: p.stem)
def test_isg_program_translated_to_linuxcnc_runs_in_rs274_as_it_runs_here(path: Path) -> None:
    """The translation kept symbolically (o-word subprogram, while loops, #501.. for P1..) is run by
    LinuxCNC's own interpreter, and moves as our interpreter moves the ISG source."""
    text = path.read_text(encoding="utf-8")
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file=str(path), source="isg", target="linuxcnc")
    assert "while" in out.getvalue()  # kept symbolically, not flattened
    theirs = [e for e in canonical_moves(run_rs274(out.getvalue()), start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = _moves(path)
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b)
