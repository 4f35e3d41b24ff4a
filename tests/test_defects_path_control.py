"""Defects: a source that blends (G64) and then asks for an exact stop (G61) translated to grbl/grblHAL wrote
a valid program (G64 as nothing, G61 as grbl's own G61) that ``verify`` then failed ("path control differs"),
with no way out but ``--allow-ignored``.

grbl has one path control mode, G61 the exact path (``gcode.h``: ``CONTROL_MODE_EXACT_PATH // G61 (Default)``;
grblHAL's ``ControlMode_ExactPath``): its planner slows at a corner by the junction deviation but steps along
the programmed lines. So every programmed point a source's exact stop asks for is reached, and a blending mode
only allowed the path to leave them: both verify, and the output names its mode (``G61``) where the source did.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.plugins import default_registry
from postproc.simulate.verify import verify_lines

BLEND_THEN_EXACT = ("G21 G90 G17 G94\nG64\nG0 X0. Y0. Z5.\nG1 Z-1. F100.\nG1 X10.\nG61\nG1 Y10.\nG1 X0.\n"
                    "G0 Z5.\nM30\n")
"""Lines 2 and 6 change the path control; the square's corners are at (10, 0) and (10, 10)."""


def lines(text: str) -> list[str]:
    return text.splitlines(keepends=True)


def translated(source: str, target: str, text: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
@pytest.mark.parametrize("source", ["fanuc", "linuxcnc"])
def test_blending_then_exact_stop_translates_and_verifies_on_grbl(source: str, target: str) -> None:
    if target not in default_registry().dialects or source not in default_registry().dialects:
        pytest.skip(f"the {source} or {target} plugin is not installed")
    out = translated(source, target, BLEND_THEN_EXACT)
    written = out.splitlines()
    assert "G61" in written  # grbl's own mode named where the source asked for an exact stop
    assert "G64" not in out.replace("(G64)", "")  # grbl refuses G64 (error 20): only a trace of it
    report = verify_lines(lines(BLEND_THEN_EXACT), lines(out), file_in="in.nc", file_out="out.nc",
                          source=source, target=target)
    assert report.ok and report.max_deviation == 0, report.summary()
    assert any("path control" in note and "exact path" in note for note in report.ignored), report.ignored


def test_a_path_control_the_target_sets_is_still_compared() -> None:
    """Where the program sets the mode (LinuxCNC), an output that lost the source's exact stop still fails."""
    out = translated("fanuc", "linuxcnc", BLEND_THEN_EXACT)
    dropped = "".join(line for line in lines(out) if line.strip() != "G61")
    report = verify_lines(lines(BLEND_THEN_EXACT), lines(dropped), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target="linuxcnc")
    assert not report.ok and "path control" in report.summary(), report.summary()
