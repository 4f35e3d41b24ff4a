"""The plain moves before a compensated stretch are kept, not read, until something asks where the program
stands (``ProgrammedPoint._note``/``_fold``/``_settle``, ``postproc.lowering.cutter_point``): each axis's number
is then the one of the last kept move that names it, and at most ``KEPT`` moves wait (a fold reads them early).

The independent checks: a hand-derived entry point whose Y and Z come from moves many folds before it, and the
source's own simulation (``toolpath_events``), which a copy within Fanuc must refuse as (``Resolver.check``: the
same geometry, at the same line) on random lead-ins of up to three folds' moves, each naming some of X, Y and Z,
with unit switches and moves by increments among them.
"""

from __future__ import annotations

import io

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.lowering.cutter_point import KEPT
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

SETUP = with_tools(radii={1: 1.0, 2: 2.0})

REVERSAL = "G41 D01 G1 X5. Y0. F200.\nX-5.\nG40 G0 X0. Y0.\nM30\n"
"""Entered to (5, 0) from wherever the lead-in left the tool, then straight back along -X: from a start on the X
axis left of X5 the path turns back on itself (the simulation's interference), from (5, 0) the entry has no
length, from elsewhere it is a corner; what the copy says depends on the start point the kept moves give."""

VALUES = ("-10.", "-5.", "0.", "2.", "5.", "10.")
"""Few numbers, so that the lead-in often ends on the X axis, at X5 or left of it."""


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="in.nc", source="fanuc", target=target, setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def _simulated(text: str) -> list[str]:
    """The located errors of the source's simulation (none: it runs)."""
    try:
        list(toolpath_events(io.StringIO(text), file="in.nc", dialect="fanuc", setup=SETUP))
    except ErrorList as err:
        return [str(e) for e in err.errors]
    return []


@st.composite
def lead_in(draw: st.DrawFn) -> str:
    """Up to three folds' plain moves (each naming some of X, Y, Z), with unit switches and moves by increments."""
    lines = ["G21 G90 G17 G0 X-5. Y0. Z5."]
    inch = False
    for _ in range(draw(st.integers(0, 3 * KEPT + 5))):
        kind = draw(st.sampled_from(["move"] * 12 + ["units", "increments"]))
        if kind == "units":
            inch = not inch
            lines.append("G20" if inch else "G21")
            continue
        axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
        words = " ".join(f"{a}{draw(st.sampled_from(VALUES))}" for a in sorted(axes))
        code = draw(st.sampled_from(["G0", "G1", ""]))
        line = f"{code} {words}".strip() + (" F300." if code == "G1" else "")
        lines.append(f"G91 {line}\nG90" if kind == "increments" else line)
    lines.append("G21 G90")  # the stretch in absolute millimetres
    return "\n".join(lines) + "\n"


@settings(max_examples=60, deadline=None)
@given(head=lead_in())
def test_a_copy_refuses_the_stretch_as_the_simulation_does_whatever_the_moves_before_it(head: str) -> None:
    text = head + REVERSAL
    simulated = _simulated(text)
    copied: list[str] = []
    try:
        out = _translate(text, "fanuc")
    except ErrorList as err:
        copied = [str(e) for e in err.errors]
    else:
        assert out == text
    assert copied == simulated[:1], (text, copied, simulated)


def test_the_entry_takes_y_and_z_from_moves_folds_before_it() -> None:
    """Hand-derived: Y from the second block (7 in = 177.8 mm, read in inches), Z from the fourth, then 3 * KEPT
    moves of X alone, the last to X12: the entry move of tool 2 (radius 2) along +X from (12, 177.8) to
    (30, 177.8) ends square to it on the left, (30, 179.8), in the grbl translation (the path written as moves)."""
    xs = "".join(f"X{10 + n % 3}.\n" for n in range(3 * KEPT))  # ... X10. X11. X12. (3 * KEPT is a multiple of 3)
    text = f"G21 G90 G17 G0 X12. Y3. Z5.\nG20\nY7.\nG21\nZ1.\n{xs}G41 D2 G1 X30. F100.\nX40.\nG40 X50.\nM30\n"
    assert xs.endswith("X12.\n")
    out = _translate(text, "grbl")
    assert "X30. Y179.8" in out, out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="o", source="fanuc",
                          target="grbl", setup=SETUP)
    assert report.ok and report.max_deviation == 0, report.summary()


@pytest.mark.parametrize("moves", [KEPT - 1, KEPT, KEPT + 1, 2 * KEPT])
def test_a_copy_refuses_the_reversal_whatever_fold_its_start_came_in(moves: int) -> None:
    """Hand-derived: the last of ``moves`` moves ends at (0, 0), left of X5 on the X axis (its Y from the first
    block, every later move naming X alone): the entry to (5, 0) and the move back along -X turn the path back on
    itself, refused at the move's line (the third line from the end) by the copy as by the simulation. The moves
    before it alternate with X10., right of X5, from where the entry and the move back go one way (no error:
    ``test_from_the_other_side_the_copy_runs``)."""
    xs = "".join(f"X{10 * ((n + 1) % 2)}.\n" for n in range(moves - 1)) + "X0.\n"
    text = "G21 G90 G17 G0 X-5. Y0. Z5.\n" + xs + REVERSAL
    line = text.count("\n") - 2
    expected = f"in.nc:{line}:1: error: a move that turns back on itself under cutter compensation (interference)"
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc")
    assert [str(e) for e in caught.value.errors] == [expected]
    assert _simulated(text)[:1] == [expected]


def test_from_the_other_side_the_copy_runs() -> None:
    """Hand-derived: from (10, 0) the entry to (5, 0) and the move on to (-5, 0) go one way: the copy is the
    program, and the simulation runs it."""
    text = "G21 G90 G17 G0 X-5. Y0. Z5.\n" + "X0.\n" * KEPT + "X10.\n" + REVERSAL
    assert _translate(text, "fanuc") == text
    assert _simulated(text) == []
