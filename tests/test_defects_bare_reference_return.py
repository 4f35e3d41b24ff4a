"""Defects found by ``make fuzz`` (fanuc-siemens, linuxcnc-siemens, mach3-siemens; reduced program
``G21 G90 G0 X0. Y0. Z10.`` then ``G28``): a reference return that names no axis.

On a Fanuc it moves no axis: G28 returns the axes it names [K: cncci.com "How the heck does G28 work"]; the
IR's ``Motion("home")`` with no axes moves nothing. But it was written as ``G75 FP=1 `` for SINUMERIK (no axis:
unreadable, verify failed), ``G00`` + ``#SUPPRESS OFFSETS`` for ISG, and a bare ``G28`` for LinuxCNC, grbl and
Mach3, where a bare G28 moves every axis to the stored G28 position [V: rs274 prints a traverse to 0 0 0 in a
fresh run; K: grbl, RS274/NGC v3]. Now nothing moves in the output either; and an NGC-family program's own
bare G28, whose end only the machine knows, is a located error instead of a silent no-op."""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, motions, run_rs274

SEED = "G21 G90 G0 X0. Y0. Z10.\nG28\n"
PROGRAM = "G21 G90 G0 X1. Y2. Z10.\nG28\nG0 X3.\nM30\n"


def written(text: str, source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("target", ["siemens", "isg", "linuxcnc", "grbl", "grblhal", "mach3", "fanuc"])
@pytest.mark.parametrize("text", [SEED, PROGRAM], ids=["seed", "program"])
def test_a_fanuc_return_naming_no_axis_moves_nothing_in_the_output(target: str, text: str) -> None:
    out = written(text, "fanuc", target)
    if target != "fanuc":  # Fanuc keeps its own G28, which moves nothing there too
        assert not re.search(r"^[^;(\n]*\b(G75|G28|#SUPPRESS)", out, re.M), out
    report = verify_lines(io.StringIO(text).readlines(), io.StringIO(out).readlines(), file_in="in.nc",
                          file_out="out", source="fanuc", target=target, tolerance=0.0)
    assert report.ok


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_written_program_as_the_source_moves() -> None:
    out = written(PROGRAM, "fanuc", "linuxcnc")
    theirs = [(m["x"], m["y"], m["z"]) for m in motions(canonical_moves(run_rs274(out)))]
    ours = [(e["x"], e["y"], e["z"]) for e in toolpath_events(io.StringIO(PROGRAM), file="in.nc", dialect="fanuc")
            if "move" in e]
    assert theirs == ours == [(1, 2, 10), (3, 2, 10)]
    # and the bare G28 the old output had would have gone to the stored position, 0 0 0 here
    assert (0, 0, 0) in [(m["x"], m["y"], m["z"]) for m in motions(canonical_moves(run_rs274("G21\nG28\nM2\n")))]


@pytest.mark.parametrize("source", ["linuxcnc", "grbl", "grblhal", "mach3"])
def test_a_bare_return_read_from_the_ngc_family_is_a_located_error(source: str) -> None:
    with pytest.raises(ErrorList) as caught:
        written(PROGRAM, source, "fanuc")
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:2:1: error: G28 with no axis word moves every axis to the position stored on the machine (by G28.1 "
        "or its settings), which the program does not give: name the axes it returns"]


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "mach3"])
def test_a_return_naming_its_axis_is_still_written(target: str) -> None:
    out = written("G21 G90 G0 X1. Y2. Z10.\nG91 G28 Z0.\nG90 G0 X3.\nM30\n", "fanuc", target)
    assert re.search(r"^G91 G28 Z0", out, re.M), out
