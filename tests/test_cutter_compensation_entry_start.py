"""Where a compensated stretch starts: the resolver (``postproc.lowering.cutter_compensation``) notes the
plain moves before it in three fields and brings them into its programmed point only when a block needs
it (``ProgrammedPoint._note``/``_settle``, ``lowering.cutter_point``), so the entry move's start point is built from many blocks: absolute
moves naming some of X, Y, Z, incremental moves, unit switches, work offset changes.

The independent check is the source's own simulation: the program translated from Fanuc to grbl (the path
written as moves) and to LinuxCNC (the stretch tried under both rules) must cut the path the Fanuc
simulation cuts, at zero deviation (``verify``); where the translation refuses the stretch, it is with the
located error for a start point it cannot know (a work offset change with no absolute X and Y after it).
"""

from __future__ import annotations

import io
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

SETUP = with_tools(radii={1: 1.0, 2: 2.0})
STRETCH = "G41 D2 G1 X60. F100.\nG91 Y20.\nX-20.\nG40 Y20.\nG90\nM30\n"
"""Entered along +X from wherever the blocks before left the tool (X at most 30: a move of 30 mm or more),
its Y and Z those blocks' (the entry names X only), then two left turns (inner corners) and the cancel, by
increments: every compensated point depends on the start point."""


def _number(value: float) -> str:
    return f"{value:.3f}"


@st.composite
def lead_in(draw: st.DrawFn) -> str:
    """Blocks before the stretch: the start point's ingredients, in random order."""
    lines = ["G21 G90 G17 G0 X5. Y5. Z5."]
    inch = False
    absolute = True
    for _ in range(draw(st.integers(1, 8))):
        kind = draw(st.sampled_from(["absolute", "absolute", "incremental", "units", "offset", "feed only"]))
        coordinate = st.floats(-30, 30, allow_nan=False).map(lambda v: round(v, 3))
        if kind in ("absolute", "incremental"):
            axes = draw(st.lists(st.sampled_from("XYZ"), min_size=1, max_size=3, unique=True))
            words = " ".join(f"{a}{_number(draw(coordinate) / (25.4 if inch else 1.0))}" for a in sorted(axes))
            mode = "G90" if kind == "absolute" else "G91"
            code = draw(st.sampled_from(["G0", "G1"]))
            if (kind == "absolute") != absolute:
                lines.append(f"{mode} {code} {words} F200.")
                absolute = kind == "absolute"
            else:
                lines.append(f"{code} {words} F200.")
        elif kind == "units":
            inch = not inch
            lines.append("G20" if inch else "G21")
        elif kind == "offset":
            lines.append(draw(st.sampled_from(["G55", "G54"])))
        else:
            lines.append("F150.")
    lines.append("G21 G90")  # the stretch in absolute millimetres
    return "\n".join(lines) + "\n"


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.nc", source="fanuc", target=target, setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
@settings(max_examples=40, deadline=None)
@given(head=lead_in())
def test_the_entry_move_starts_where_the_blocks_before_left_the_tool(head: str, target: str) -> None:
    text = head + STRETCH
    try:
        out = _translate(text, target)
    except ErrorList as err:
        messages = [str(e) for e in err.errors]
        assert len(messages) == 1 and "the start point of a compensated move is not known" in messages[0], messages
        assert re.search(r"\bG5[45]\b", head), (head, messages)  # only a changed origin hides the start point
        return
    if target == "grbl":
        assert not re.search(r"\bG4[12]\b", out), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="t.nc", file_out="o", source="fanuc",
                          target=target, setup=SETUP)
    assert report.ok and report.max_deviation == 0, (text, out, report.summary())


def test_a_move_of_one_axis_keeps_the_others_from_earlier_blocks() -> None:
    """Hand-derived: X from the first move (12), Y from the second (7 in = 177.8 mm, read in inches),
    Z from the third; the entry move of tool 2 (radius 2) along +X from (12, 177.8) to (30, 177.8) ends
    square to it on the left: (30, 179.8)."""
    text = ("G21 G90 G17 G0 X12. Y3. Z5.\nG20\nY7.\nG21\nZ1.\nG41 D2 G1 X30. F100.\nX40.\nG40 X50.\nM30\n")
    out = _translate(text, "grbl")
    assert "X30. Y179.8" in out, out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="t.nc", file_out="o", source="fanuc",
                          target="grbl", setup=SETUP)
    assert report.ok and report.max_deviation == 0, report.summary()


def test_after_a_refused_stretch_a_later_one_is_left_to_the_target_writer() -> None:
    """The generic step resolves every G41/G42 for grbl and, after an error, nothing more (its queue no longer
    matches the program); grbl's own step finds nothing left to do (``RESOLVED``), so a later stretch is
    grbl's writer's refusal, not a second resolver's guess."""
    text = ("G21 G90 G17\nT1 M6\nG0 X0 Y0 Z5\nG41 G1 X10 Y0 F100\nY10\nX0\nG40 Y0\n"
            "G41 G1 X10 Y0 D1\nY10\nG40 X0\nM30\n")
    out = io.StringIO()
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(text).readlines(), out, file="t.nc", source="fanuc", target="grbl", setup=SETUP,
                  diagnostics=diagnostics)
    messages = [str(e) for e in info.value.errors]
    assert messages[0].startswith("t.nc:4:1: error: cutter compensation without its register"), messages
    assert all("t.nc:4:" in m or "cannot express cutter radius compensation" in m for m in messages), messages


def test_a_straight_move_after_a_kept_arc_gives_the_start_point() -> None:
    """Hand-derived: the arc (kept by the resolver) ends at (10, 0), the straight move after it (noted past the
    resolver by the lowering loop, ``ProgrammedPoint.passing``) at (12, 3), later, so it wins: the entry move of
    tool 2 (radius 2) along +X from (12, 3) to (30, 3) ends square to it on the left, (30, 5). Then an arc after a
    noted move (20, 8): the arc goes after it, to (25, 13), where the entry to (40, 13) starts: it ends at (40, 15)."""
    text = ("G21 G90 G17 G0 X0. Y0. Z5.\nG2 X10. Y0. I5. J0. F100.\nG1 X12. Y3.\nG41 D2 G1 X30. F100.\nX35.\n"
            "G40 X36.\nG1 X20. Y8.\nG2 X25. Y13. I5. J0.\nG41 D2 G1 X40.\nX45.\nG40 X46.\nM30\n")
    out = _translate(text, "grbl")
    assert "X30. Y5." in out and "X40. Y15." in out, out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="t.nc", file_out="o", source="fanuc",
                          target="grbl", setup=SETUP)
    assert report.ok and report.max_deviation == 0, report.summary()
