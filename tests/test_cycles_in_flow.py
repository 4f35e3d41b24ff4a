"""A canned cycle the target gets as motion, inside a subprogram, a loop or after a jump (issue 26, corpus
``m98m99_*``): the reader resolves a cycle from the state where its block stands in the text, so its
expansion is the motion of one run. Kept symbolically, every call would drill that run's holes (LinuxCNC
``M98 P1 L3`` around ``G91 X1`` + ``G81`` reached Fanuc as the first call's hole three times). Such a
program is flattened instead. Expected holes are derived by hand from the programs and, where rs274 can
run the program, checked against it too."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
CORPUS = ROOT / "tests" / "corpus" / "linuxcnc"
needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _translate(text: str, source: str, target: str) -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target)
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def _moves(text: str, dialect: str) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text, newline=""), file="t.nc", dialect=dialect) if "move" in e]


def _feeds(moves: list[dict[str, Any]]) -> list[tuple[float, float, float]]:
    """(x, y, z) where every feed ends (mm): in these programs only the cycles feed, once a hole."""
    return [(round(m["x"], 4) + 0.0, round(m["y"], 4) + 0.0, round(m["z"], 4) + 0.0) for m in moves
            if m["move"] == "feed"]


# -- LinuxCNC M98 P1 L.. (the corpus programs) towards every target -------------------------------------

BASICS_HOLES = [(1.0, 0.0, -1.0), (2.0, 0.0, -1.0), (3.0, 0.0, -1.0)]
"""m98m99_basics (no G20: millimetres, for rs274 too): from X0, each of three calls jogs G91 X1 and drills
in G90 at the current point."""
LOOPS_HOLES = [(float(k), 0.0, -0.5) for k in range(1, 11)] + [(1.0, 0.0, -0.5), (2.0, 0.0, -0.5)]
"""m98m99_loops: from X0 Z0.25, L10 drills ``G91 G99 G81 X1 Z-1 R0.25`` ten times; L0 none; from X0 Z0.25
again (G0 cancels the cycle), L2 twice. The cycle stays active from call to call (no G80), so its initial
level stays the first call's Z0.25 (rs274 records it where the motion mode becomes the cycle): R 0.5,
bottom 1 below R."""


@pytest.mark.parametrize("target", ["fanuc", "fagor", "isg", "grbl", "mach3"])
@pytest.mark.parametrize("program, holes", [("m98m99_basics.ngc", BASICS_HOLES), ("m98m99_loops.ngc", LOOPS_HOLES)])
def test_a_cycle_in_a_repeated_subprogram_drills_each_call_where_it_runs(
        program: str, holes: list[tuple[float, float, float]], target: str) -> None:
    source = (CORPUS / program).read_text()
    assert _feeds(_moves(source, "linuxcnc")) == holes
    text, _ = _translate(source, "linuxcnc", target)
    assert _feeds(_moves(text, target)) == holes


@needs_rs274
def test_the_hand_derived_holes_are_rs274s() -> None:
    for program, holes in [("m98m99_basics.ngc", BASICS_HOLES), ("m98m99_loops.ngc", LOOPS_HOLES)]:
        theirs = canonical_moves(run_rs274((CORPUS / program).read_text()), start=(0.0, 0.0, 0.0))
        assert _feeds([e for e in theirs if "move" in e]) == holes


def test_the_flattening_names_the_cycle_and_why() -> None:
    _, warnings = _translate((CORPUS / "m98m99_basics.ngc").read_text(), "linuxcnc", "fanuc")
    assert len(warnings) == 1
    assert "flattened" in warnings[0] and "line 11: the cycle in 'G90 G99 G81 Z-1.0 R0.25" in warnings[0]
    assert "control flow" in warnings[0]


# -- Fanuc towards LinuxCNC (its G81 moves by other rules, so it is expanded) ------------------------------

FANUC_SUB = """%
O0001
G21 G17 G40 G80 G90
G90 G00 X0. Y0. Z5.
M98 P1000 L3
G80 G90 G00 Z20.
M30
O1000
G91 G98 G81 X10. Z-8. R-3. F100.
M99
%
"""
"""Each call: G91 X10 from where the last left the tool, R 3 below the initial level 5 (R2), the bottom 8
below R (-6), back to the initial level (G98)."""
FANUC_SUB_HOLES = [(10.0, 0.0, -6.0), (20.0, 0.0, -6.0), (30.0, 0.0, -6.0)]

FANUC_WHILE = """%
O0002
G21 G17 G90 G00 X0. Y0. Z5.
#1=0
WHILE [#1 LT 3] DO1
G91 G98 G81 Y5. Z-8. R-3. F100.
G80
#1=#1+1
END1
G90 G00 Z20.
M30
%
"""
FANUC_WHILE_HOLES = [(0.0, 5.0, -6.0), (0.0, 10.0, -6.0), (0.0, 15.0, -6.0)]

FANUC_GOTO = """%
O0003
G21 G17 G90 G00 X0. Y0. Z5.
#1=0
N10 G91 G98 G81 X-4. Z-8. R-3. F100.
G80
#1=#1+1
IF [#1 LT 2] GOTO10
G90 G00 Z20.
M30
%
"""
"""The cycle comes before the backward jump that repeats it: the jump, not a statement before it, makes
the second run."""
FANUC_GOTO_HOLES = [(-4.0, 0.0, -6.0), (-8.0, 0.0, -6.0)]


@pytest.mark.parametrize("source, holes", [(FANUC_SUB, FANUC_SUB_HOLES), (FANUC_WHILE, FANUC_WHILE_HOLES),
                                           (FANUC_GOTO, FANUC_GOTO_HOLES)], ids=["M98 L3", "WHILE", "GOTO back"])
@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "isg", "fagor", "mach3"])
def test_a_fanuc_cycle_in_control_flow_drills_each_run_where_it_runs(
        source: str, holes: list[tuple[float, float, float]], target: str) -> None:
    assert _feeds(_moves(source, "fanuc")) == holes
    text, _ = _translate(source, "fanuc", target)
    assert _feeds(_moves(text, target)) == holes
    if target == "linuxcnc" and available():
        theirs = [e for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]
        assert _feeds(theirs) == holes


def test_a_cycle_before_any_control_flow_stays_exact_and_symbolic() -> None:
    """Straight code before the first construct is the same on every run: its expansion is written
    there while the subprogram stays a subprogram."""
    source = FANUC_SUB.replace("M98 P1000 L3", "G98 G81 X-5. Z-6. R2. F100.\nG80\nM98 P1000 L3").replace(
        "G91 G98 G81 X10. Z-8. R-3. F100.", "G91 G00 X10.")
    text, warnings = _translate(source, "fanuc", "linuxcnc")
    assert warnings == [] and "M98 P1000 L3" in text
    assert _feeds(_moves(text, "linuxcnc")) == [(-5.0, 0.0, -6.0)]


def test_a_forced_expansion_in_a_subprogram_kept_as_is_is_a_located_error() -> None:
    """Back to its own dialect a program is never flattened: an expansion the set-up forces inside a
    subprogram cannot be exact, so it is refused where the cycle is."""
    setup = MachineSetup()
    setup.cycles.expand = "all"
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(FANUC_SUB, newline=""), io.StringIO(), file="t.nc", source="fanuc",
                  target="fanuc", setup=setup)
    assert str(info.value.errors[0]).startswith("t.nc:9:1: error: the cycle in 'G91 G98 G81")
