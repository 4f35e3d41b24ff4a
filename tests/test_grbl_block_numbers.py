"""A block number grbl refuses is dropped with a located warning, never written (found this session: a Fanuc
``N20000000`` was written to grbl unchanged, exit 0, and grbl answered ``error:27``).

Facts: grbl 1.1 ``gcode.c`` ``MAX_LINE_NUMBER 10000000``, a larger N is error 27 [V]; grblHAL core ``gcode.c``
the same constant and error [V]; LinuxCNC's ``read_n_number`` (``interp_read.cc``) has its 99999 check
commented out, so any number ``%d`` reads runs (rs274 runs ``N99999999999``) [V]. The block number is only a
label on these controllers, so the block is written without it; the checker that judges the output
(``tests/support/grbl_rules.py``) is written from grbl's source, independently of the writer."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList

from tests.support.grbl_rules import grbl_problems

PROGRAM = "G21 G90 G17\nN20000000 G1 X1. Y2. F100.\nN10000000 X2.\nN30000000 G2 X4. Y2. I1. J0.\nN40 G1 X5.\nM30\n"
"""Above the limit on a straight block (the fast lane's) and an arc, at the limit, and a small one."""


def _translate(program: str, source: str, target: str) -> tuple[str, list[str]]:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    translate(io.StringIO(program), out, file="in.nc", source=source, target=target, diagnostics=diagnostics)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


@pytest.mark.parametrize("source", ["fanuc", "linuxcnc"])
@pytest.mark.parametrize("target", ["grbl", "grblhal"])
def test_a_block_number_above_grbls_limit_is_dropped_with_a_warning(source: str, target: str) -> None:
    text, warnings = _translate(PROGRAM, source, target)
    assert grbl_problems(text) == []
    lines = text.splitlines()
    assert lines[1].startswith("G1 X1") and lines[2].startswith("N10000000 ") and lines[3].startswith("G2 ")
    assert lines[4].startswith("N40 ")
    assert len(warnings) == 1 and warnings[0].startswith("in.nc:2:1: warning: block number N20000000 is above 10000000")


def test_linuxcnc_keeps_a_large_block_number() -> None:
    text, warnings = _translate(PROGRAM, "fanuc", "linuxcnc")
    assert text.splitlines()[1].startswith("N20000000 G1 ") and warnings == []


@pytest.mark.parametrize("source", ["grbl", "grblhal"])
@pytest.mark.parametrize("target", ["grbl", "grblhal", "linuxcnc"])
def test_a_grbl_source_with_a_block_number_above_the_limit_is_refused_where_it_stands(source: str, target: str) -> None:
    """grbl's ``gc_execute_line`` refuses the whole line (error 27) before running any of it: the source is invalid
    on its own controller, so the copy cannot be byte for byte and valid; the reader says so, located."""
    program = "G21 G90\nN10000000 G1 X1. F100.\n  N10000001 X2.\nM30\n"
    assert grbl_problems(program) == ["3: error:27 (invalid line number):   N10000001 X2."]  # the checker agrees
    with pytest.raises(ErrorList) as info:
        _translate(program, source, target)
    (error,) = info.value.errors
    assert str(error).startswith("in.nc:3:3: error: block number N10000001 is above 10000000, the largest the ")
    assert "it refuses the line" in str(error)


@pytest.mark.parametrize("source", ["grbl", "grblhal"])
def test_a_grbl_source_at_the_limit_is_copied_byte_for_byte(source: str) -> None:
    program = "G21 G90\nN10000000 G1 X1. F100.\nM30\n"
    assert _translate(program, source, source) == (program, [])


def test_renumbering_past_the_limit_is_refused_at_the_block_it_would_number() -> None:
    """``--renumber START,STEP`` has no maximum: the block it would number past grbl's limit is a located error,
    reported once (the numbers before it are valid: N10000000 is the largest)."""
    from postproc.setup.machine_setup import MachineSetup, OutputSettings
    program = "G21 G90\nG1 X1. F100.\nX2.\nX3.\nM30\n"
    setup = MachineSetup(output=OutputSettings(renumber_start=9_999_990, renumber_step=10))
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(program), out, file="in.nc", source="grbl", target="grbl", setup=setup,
                  diagnostics=diagnostics)
    (error,) = info.value.errors
    assert str(error).startswith("in.nc:3:1: error: --renumber numbers this block N10000010, above 10000000")
    setup = MachineSetup(output=OutputSettings(renumber_start=9_999_960, renumber_step=10))
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="grbl", target="grbl", setup=setup)
    assert out.getvalue().splitlines()[-1] == "N10000000 M30" and grbl_problems(out.getvalue()) == []
