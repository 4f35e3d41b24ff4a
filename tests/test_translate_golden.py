"""Golden translations: ``tests/golden/translate/<src>__<dst>/NAME.<ext>`` translates to
``NAME.expected.<ext>`` byte for byte (``--on-unsupported warn``, as `make run` does). Each pair is also
checked with ``verify`` so an expected file can only be accepted if it moves the tool exactly as its
source: the golden text pins the spelling, the toolpath pins the meaning.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

ROOT = Path(__file__).parent / "golden" / "translate"
SETUP = with_tools(lengths={n: 100.0 + n for n in range(1, 10)})
"""The machine every case runs on: tool n is 100 + n mm long (grbl's G43.1 lengths come from it)."""
CASES = sorted(p for p in ROOT.glob("*__*/*") if ".expected." not in p.name)


def _expected(source: Path) -> Path:
    [match] = source.parent.glob(f"{source.stem}.expected.*")
    return match


def _pair(source: Path) -> tuple[str, str]:
    src, dst = source.parent.name.split("__")
    return src, dst


@pytest.mark.parametrize("source", CASES, ids=[f"{p.parent.name}/{p.name}" for p in CASES])
def test_golden_translation(source: Path) -> None:
    src, dst = _pair(source)
    out = io.StringIO(newline="")
    with source.open(encoding="utf-8", newline="") as lines:
        translate(lines, out, file=str(source), source=src, target=dst, on_unsupported="warn",
                  diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()), setup=SETUP)
    assert out.getvalue() == _expected(source).read_text(encoding="utf-8")


@pytest.mark.parametrize("source", CASES, ids=[f"{p.parent.name}/{p.name}" for p in CASES])
def test_golden_translation_moves_the_tool_as_its_source(source: Path) -> None:
    src, dst = _pair(source)
    expected = _expected(source)
    with source.open(encoding="utf-8", newline="") as a, expected.open(encoding="utf-8", newline="") as b:
        report = verify_lines(a, b, file_in=str(source), file_out=str(expected), source=src, target=dst,
                              allow_ignored=True, setup=SETUP)
    assert report.ok, report.summary()
    # only grbl (no cutter compensation for Fanuc's rules) leaves out settings that move the tool
    assert not report.left_out_moves or dst == "grbl", report.summary()


def test_every_translation_pair_has_cases() -> None:
    assert {p.parent.name for p in CASES} == {"fanuc__grbl", "fanuc__linuxcnc", "linuxcnc__fanuc"}
