"""A flattened program closes its tape as the source did.

The run of a program that computes stops at its M30, before the closing '%' line after it (and after
its subprograms); the written program must still end with that mark: rs274 reports "percent sign
missing from end of file" for a program opened by '%' and never closed, and a tape reader or DNC link
waits for it."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from tests.support import rs274

EXAMPLES = Path(__file__).resolve().parent.parent / "examples" / "fanuc"

LOOP = """%
O1234 (LOOP)
#1 = 0
WHILE [#1 LT 3] DO1
G01 X#1 Y1. F100.
#1 = #1 + 1
END1
M30
%
"""


def _translated(text: str, target: str, **options: object) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source="fanuc", target=target, **options)  # type: ignore[arg-type]
    return out.getvalue()



def test_a_flattened_fanuc_copy_ends_with_its_closing_mark() -> None:
    text = _translated(LOOP, "fanuc", units="inch")  # a unit conversion runs the loop
    lines = text.splitlines()
    assert lines[0] == "%" and lines[-1] == "%" and lines[-2].endswith("M30")
    assert sum(line == "%" for line in lines) == 2


def test_a_program_opened_but_never_closed_gets_no_closing_mark() -> None:
    text = _translated(LOOP.rstrip("%\n") + "\n", "fanuc", units="inch")
    assert text.splitlines()[-1].endswith("M30")
    assert sum(line == "%" for line in text.splitlines()) == 1


def test_a_program_without_marks_gets_none() -> None:
    text = _translated(LOOP.replace("%\n", ""), "fanuc", units="inch")
    assert "%" not in text.splitlines()


@pytest.mark.skipif(not rs274.available(), reason="rs274 not installed")
def test_rs274_reads_the_flattened_bolt_circle_to_its_closing_mark() -> None:
    source = (EXAMPLES / "o1005_bolt_circle_macro.nc").read_text(encoding="utf-8")
    program = _translated(source, "linuxcnc")
    assert program.splitlines()[0] == "%" and program.splitlines()[-1] == "%"
    calls = rs274.run_rs274(program)
    assert not any("percent sign missing" in call for call in calls), calls[-3:]
