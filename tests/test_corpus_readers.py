"""Readers taking what their controller takes, found by the third-party corpus (tests/corpus/): each
expectation is the controller's own answer (rs274, run here where installed, or the fact cited)."""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList, UnsupportedError
from tests.support import rs274
from tests.support.tools import with_tools

TOOLS = "T1 P1 Z0 D0.1 ;\nT2 P2 Z0 D0.2 ;\n"


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="in.ngc", source="linuxcnc", target=target,
              setup=with_tools(), diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def _rs274_accepts(text: str) -> bool:
    calls = rs274.run_rs274(text, tool_table=TOOLS)
    return any("PROGRAM_END" in call for call in calls)


COMPUTED_D = "g20 f10\n#1=2\ng0 x0 y0\ng41 d#1\ng1 x1 y0\ng1 x1 y1\ng40\ng1 x2\nm2\n"
"""rs274 reads D as a real (interp_read.cc ``read_d``) and wants a whole number only where G41/G42
take a tool number: a computed D of 2 is tool 2."""


def test_a_computed_tool_number_after_g41_is_that_tool() -> None:
    """Mach3 has no variables: D#1 is read as tool 2 (radius 0.1 in here, tool 1's 0.05). Mach3 compensates by
    the NIST rules, not LinuxCNC's, so the path is written as moves, derived by hand under LinuxCNC's: the
    entry move ends square to X1 Y0, cut short where it meets the next move's offset line (an inside corner):
    X0.9 Y0.1; then X0.9 Y1; the exit move to X2 Y1."""
    out = io.StringIO()
    translate(io.StringIO(COMPUTED_D).readlines(), out, file="in.ngc", source="linuxcnc", target="mach3",
              setup=with_tools(radii={1: 0.05 * 25.4, 2: 0.1 * 25.4}),
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    moves = [line for line in out.getvalue().splitlines() if line.startswith("G1")]
    assert moves == ["G1 X0.9000 Y0.1000", "G1 X0.9000 Y1.0000", "G1 X2.0000 Y1.0000"], out.getvalue()


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_takes_the_computed_tool_number_too() -> None:
    assert _rs274_accepts(COMPUTED_D)


def test_a_computed_fraction_after_g41_is_refused_as_rs274_refuses_it() -> None:
    # rs274: "G41 requires D word to be a whole number"
    with pytest.raises(ErrorList) as info:
        _translate(COMPUTED_D.replace("#1=2", "#1=1.5"), "mach3")
    assert [str(e).split("error: ")[1] for e in info.value.errors] == ["address D takes a whole number (D1.5)"]


def test_a_computed_diameter_after_g41_1_is_read_as_a_diameter() -> None:
    # LinuxCNC's tests/interp/inside-corners: G41.1 D#100 with #100 = -.15 (a negative diameter changes
    # sides, rs274 "cutter radius compensation on right"): read, then resolved into the path rs274 cuts,
    # radius .075 on the right of X0 -> X1 (rs274: STRAIGHT_FEED(1.0000, -0.0750, ...)), then the exit move
    text = "g20 f10\n#100=-.15\ng0 x0 y0\ng41.1 d#100\ng1 x1 y0\ng40\ng1 x2\nm2\n"
    assert _translate(text, "mach3").splitlines() == [
        "G20 F10.", "G0 X0.0000 Y0.0000", "G1 X1.0000 Y-0.0750", "G1 X2.0000 Y0.0000", "M2"]
    if rs274.available():
        assert _rs274_accepts(text)
