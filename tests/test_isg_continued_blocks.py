"""An ISG block continued with ``\\`` holds several physical lines. The interpreter step reads a program's
blocks again (the keep check, the run before keeping it symbolically, a backward jump's prefix): read as
one line, a continued block lost what followed the backslash, so a P assignment in it was not run (an
unset P it reads went unnoticed) and its words were missing from the check.

Expectations: the same program on separate lines (the manual's reading of a continuation: one block),
and hand-derived moves.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events

CONTINUED = "%1\nG71 G90 G00 X0 Y0 Z10\nP1=1\nG01 X10 F100 \\\nP5=P{p}+1\nG01 X[P5]\nM30\n"


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="c.nc", source="isg", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "fagor"])
def test_an_unset_p_read_in_a_continued_block_is_refused_there(target: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(CONTINUED.format(p=7), target)
    assert [str(e) for e in caught.value.errors] == ["c.nc:4:1: error: P7 is read before it is set"]


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc", "fagor"])
def test_a_continued_assignment_is_run_and_moves_as_written(target: str) -> None:
    """P5 = P1 + 1 = 2: the tool feeds to X10, then back to X2."""
    out = _translate(CONTINUED.format(p=1), target)
    moves = [(e["x"], e["y"], e["z"]) for e in toolpath_events(io.StringIO(out), file="o.nc", dialect=target)
             if "move" in e]
    assert moves == [(0, 0, 10), (10, 0, 10), (2, 0, 10)], out
