"""A computed number too long for any reader (fuzz seed 75822164089876486443380238660552028264, macros -> isg):
``G91 G1 X[EXP[#3]]`` with a large #3 was written as a 40-digit X, which the ISG reader then refused ("a
number with more than 30 digits", ``postproc.syntaxes.lines``). The writer now refuses it at its source line.

The ISG manual's own limit is far lower: numerical inputs within -214 000.0000 mm .. +214 000.0000 mm [K:
Beckhoff TF5200 programming manual, "Measuring systems, input and precision ranges"]; that limit is not
checked by the writer (see the report), only the digits every reader reads.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import read_program, translate
from postproc.errors import ErrorList, ProgramError
from postproc.numbers import MAX_DIGITS, format_decimal
from postproc.syntaxes.lines import MAX_DIGITS as READ_DIGITS

PROGRAM = "G21 G90 G0 X0 Y0 Z5.\n#3=92.\nG91 G1 X[EXP[#3]] F100.\nG90\nM30\n"


@pytest.mark.parametrize("target", ["isg", "grbl"])
def test_a_number_longer_than_any_reader_reads_is_a_located_error(target: str) -> None:
    """exp(92) = 9.0e39 mm: 40 digits. A target that is given the computed word flattened (ISG here, grbl)
    is refused at line 3 (the move), not written."""
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(PROGRAM), io.StringIO(), file="t.nc", source="fanuc", target=target)
    (error,) = info.value.errors
    assert str(error).startswith("t.nc:3:") and f"more than {MAX_DIGITS} digits" in str(error)


def test_a_number_of_thirty_digits_is_written_and_read_back_by_isg() -> None:
    """exp(67) = 1.25e29: 30 digits, the most a reader reads; written, and the ISG reader takes it back."""
    out = io.StringIO()
    translate(io.StringIO(PROGRAM.replace("92.", "67.")), out, file="t.nc", source="fanuc", target="isg")
    line = next(line for line in out.getvalue().splitlines() if "X1" in line)
    assert sum(ch.isdigit() for ch in line.split("X")[1].split()[0]) == 30
    read_program(io.StringIO(out.getvalue()), file="out.nc", dialect="isg")


def test_format_decimal_refuses_past_the_readers_digits() -> None:
    assert READ_DIGITS == MAX_DIGITS
    assert format_decimal(1e29, 3) == "99999999999999991433150857216."  # the float nearest 1e29, 29 digits
    with pytest.raises(ProgramError, match="more than 30 digits"):
        format_decimal(1e30, 3)
    with pytest.raises(ProgramError, match="more than 30 digits"):
        format_decimal(-1.5e30, 0)
