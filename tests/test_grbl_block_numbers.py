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
from postproc.errors import Diagnostics

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
