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
from postproc.simulate.toolpath import toolpath_events
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


def _translate(text: str, source: str, target: str, file: str = "t.nc") -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = translate(io.StringIO(text, newline=""), out, file=file, source=source, target=target)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", CASES, ids=lambda p: p.stem)
def test_fanuc_to_linuxcnc_translation_runs_in_rs274_as_the_fanuc_program_moves(path: Path) -> None:
    text, _ = _translate(path.read_text(), "fanuc", "linuxcnc", str(path))
    theirs = [e for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
    _same(_moves(path, "fanuc"), theirs)


def test_a_macro_program_keeps_its_loop_through_linuxcnc_and_back(tmp_path: Path) -> None:
    path = ROOT / "tests" / "golden" / "macro" / "bolt_circle_while.nc"
    ngc, warnings = _translate(path.read_text(), "fanuc", "linuxcnc", str(path))
    assert warnings == []
    assert "o1 while [#10 LT #1]\n" in ngc and "o1 endwhile\n" in ngc
    back, warnings = _translate(ngc, "linuxcnc", "fanuc", "t.ngc")
    assert warnings == []
    assert "WHILE [#10 LT #1] DO1\n" in back and "END1\n" in back and "#11=#3+#10*360./#1\n" in back
    again = tmp_path / "back.nc"
    again.write_text(back)
    _same(_moves(again, "fanuc"), _moves(path, "fanuc"))


SEQUENTIAL = ("%\nG21 G90 G00 X0 Y0 Z5.\n#1=0\nWHILE [#1 LT 2] DO1\nG01 X#1 F100.\n#1=#1+1\nEND1\n"
              "#1=0\nWHILE [#1 LT 2] DO1\nG01 Y#1 F100.\n#1=#1+1\nEND1\nM30\n%\n")


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_loops_that_reuse_do1_get_labels_of_their_own_in_linuxcnc(tmp_path: Path) -> None:
    """LinuxCNC refuses an o-word label opened twice; Fanuc reuses DO1 for every loop at one depth."""
    text, warnings = _translate(SEQUENTIAL, "fanuc", "linuxcnc")
    assert warnings == []
    assert [line for line in text.splitlines() if line.startswith("o")] == [
        "o1 while [#1 LT 2.]", "o1 endwhile", "o2 while [#1 LT 2.]", "o2 endwhile"]
    source = tmp_path / "seq.nc"
    source.write_text(SEQUENTIAL)
    theirs = [e for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
    _same(_moves(source, "fanuc"), theirs)
