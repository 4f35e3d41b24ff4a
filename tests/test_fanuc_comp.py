"""Fanuc cutter compensation C (``rs274.cutter_rules.FANUC_A``/``FANUC_B``, ``compensation.extended_corners``).

Every expected point is derived by hand from the rules of the operator's manual (B-62764EN 15.6: an inner
corner at the intersection of the offset paths, an outer one of 90 degrees or more at their intersection,
an acute outer one extended by the radius along both moves with a straight move between; start-up type
A square to the next move, cancel square to the last), written out in each docstring.
"""

from __future__ import annotations

import io
import math
from typing import Any

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from postproc.compensation.cutter_radius import Segment
from postproc.compensation.geometry_for import cutter_for
from postproc.rs274.cutter_rules import FANUC_A, FANUC_B, FANUC_T, FANUC_T_B, HAAS_A
from postproc.errors import ErrorList, ProgramError, UnsupportedError
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.tools import with_tools

SETUP = with_tools(radii={1: 1.0, 2: 2.0})
HEAD = "G21 G90 G17 G0 X{x} Y{y} Z0\n"


def _moves(text: str, setup: MachineSetup = SETUP) -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="t.nc", dialect="fanuc", setup=setup)
    return [{**e, **e.get("controlled", {})} for e in events if "move" in e]


def _points(text: str) -> list[tuple[float, float]]:
    return [(m["x"], m["y"]) for m in _moves(text)[1:]]


def _close(got: list[tuple[float, float]], expected: list[tuple[float, float]]) -> None:
    assert len(got) == len(expected), got
    for a, b in zip(got, expected):
        assert math.dist(a, b) < 1e-6, (got, expected)


def _errors(text: str) -> list[str]:
    with pytest.raises(ErrorList) as info:
        _moves(text)
    return [str(e) for e in info.value.errors]


POCKET = (HEAD.format(x="10.", y="10.") + "G41 D2 G1 X10. Y0 F100.\nX20.\nY20.\nX0\nY0\nX10.\nG40 X10. Y10.\nM30\n")
"""Left of a counter-clockwise square, radius 2, entered from its centre: every corner is inner. Start-up
(type A): the tool ends square to the next move (+X) at (10, 0): (10, 2). Inner corners at the offset
lines' intersections: y=2 with x=18, x=18 with y=18, then (2, 18), (2, 2). The last move (0,0)->(10,0)
ends square to itself at its end, (10, 2), and the cancel move goes to (10, 10)."""


def test_inner_corners_meet_at_the_intersection_start_up_and_cancel_square() -> None:
    _close(_points(POCKET), [(10, 2), (18, 2), (18, 18), (2, 18), (2, 2), (10, 2), (10, 10)])


TRIANGLE = (HEAD.format(x="0", y="-10.") + "G41 D1 G1 X0 Y0 F100.\nY10.\nX20. Y0\nX0\nY5.\nG40 X-10.\nM30\n")
"""Left of a clockwise triangle (0,0) (0,10) (20,0), radius 1: the tool is outside, every corner outer.

- start-up towards (0,0), the next move goes on along +Y: square to it, (-1, 0);
- (0,10): from t1=(0,1) to t2=(2,-1)/sqrt5, angle 63.4 degrees on the workpiece: acute. The first move is
  extended by r: (0,10)+(-1,0)+(0,1) = (-1, 11); a straight move to (0,10) + r n2 - r t2 with
  n2=(1,2)/sqrt5: (-1/sqrt5, 10+3/sqrt5) = (-0.447214, 11.341641);
- (20,0): from t2 to t3=(-1,0), 26.6 degrees: acute. (20,0) + n2 + t2 = (20+3/sqrt5, 1/sqrt5), then
  (20,0) + (0,-1) - (-1,0) = (21, -1);
- (0,0): from (-1,0) to (0,1), 90 degrees: the intersection of y=-1 and x=-1;
- cancel after the move to (0,5): square to it at its end, (-1, 5), then (-10, 5)."""


def test_acute_outer_corners_are_extended_by_the_radius_and_right_angles_meet() -> None:
    s5 = math.sqrt(5.0)
    _close(_points(TRIANGLE), [(-1, 0), (-1, 11), (-1 / s5, 10 + 3 / s5), (20 + 3 / s5, 1 / s5), (21, -1),
                               (-1, -1), (-1, 5), (-10, 5)])
    moves = _moves(TRIANGLE)
    assert [m["move"] for m in moves[1:]] == ["feed"] * 8  # straight corners: no arc is inserted
    events = toolpath_events(io.StringIO(TRIANGLE, newline=""), file="t.nc", dialect="fanuc", setup=SETUP)
    corner = [e for e in events if "move" in e][3]
    assert (corner["x"], corner["y"], corner["line"]) == (0, 10, 3)  # the extra move: the corner, its block's


ARCS = (HEAD.format(x="-5.", y="0") + "G41 D1 G1 X10. Y0 F100.\nG3 X20. Y0 R5.\nG1 X30.\nG2 X40. Y0 R5.\n"
        "G1 Y-10.\nX0\nG40 Y0\nM30\n")
"""Lines and arcs, left, radius 1.

- start-up towards (10,0); the next move is a counter-clockwise half circle about (15,0) under the line,
  leaving (10,0) along -Y: square to it, (11, 0), on the offset circle of radius 4 (the tool is inside);
- (20,0): the arc arrives along +Y, the line leaves along +X: a right angle, outer; the offset circle
  (radius 4 about (15,0)) meets the offset line y=1 at x = 15 + sqrt(15);
- (30,0): the line meets a clockwise arc about (35,0) leaving along +Y: inner; y=1 meets the offset circle
  of radius 6 at x = 35 - sqrt(35);
- (40,0): the arc arrives along -Y, the line leaves along -Y: no corner, (41, 0);
- (40,-10): a right angle: x=41 meets y=-11; cancel after the move to (0,-10): (0,-11), then (0,0)."""


def test_arcs_meet_lines_at_the_intersection_of_their_offset_paths() -> None:
    _close(_points(ARCS), [(11, 0), (15 + math.sqrt(15), 1), (35 - math.sqrt(35), 1), (41, 0), (41, -11),
                           (0, -11), (0, 0)])
    moves = _moves(ARCS)
    assert [m["move"] for m in moves[1:]] == ["feed", "ccw", "feed", "cw", "feed", "feed", "feed"]
    assert (moves[2]["cx"], moves[2]["cy"], moves[4]["cx"], moves[4]["cy"]) == (15, 0, 35, 0)


def test_one_block_without_motion_in_the_plane_is_looked_past() -> None:
    """A Z move between two moves of a corner: the corner is the same, the Z move made at its point."""
    text = POCKET.replace("Y20.\n", "Y20.\nZ-1.\n")
    moves = _moves(text)
    assert [(m["x"], m["y"]) for m in moves[3:5]] == [(18, 18), (18, 18)] and moves[4]["z"] == -1
    _close([(m["x"], m["y"]) for m in moves[1:] if m is not moves[4]], [(10, 2), (18, 2), (18, 18), (2, 18), (2, 2),
                                                                         (10, 2), (10, 10)])


def test_two_blocks_without_motion_in_the_plane_are_refused_by_name() -> None:
    errors = _errors(POCKET.replace("Y20.\n", "Y20.\nZ-1.\nM08\n"))
    assert errors[0].startswith("t.nc:6:1: error: more than 1 block(s) without motion in the plane"), errors


def test_an_arc_cannot_start_or_cancel_compensation() -> None:
    errors = _errors(HEAD.format(x="0", y="0") + "G41 D1 G2 X10. Y0 R5. F100.\nM30\n")
    assert errors[0].startswith("t.nc:2:1: error: cutter compensation cannot start with an arc"), errors
    errors = _errors(HEAD.format(x="0", y="0") + "G41 D1 G1 X10. F100.\nX20.\nG40 G2 X30. Y0 R5.\nM30\n")
    assert "the move after cutter compensation is cancelled must be straight" in errors[0], errors


def test_a_move_shorter_than_the_radius_allows_is_an_interference_alarm() -> None:
    """Left of a counter-clockwise pocket 3 mm wide with a radius 2 tool: the inner corners' intersections
    cross, the move between them would run backwards."""
    text = HEAD.format(x="1.5", y="10.") + "G41 D2 G1 X1.5 Y0 F100.\nX3.\nY20.\nX0\nY0\nG40 X1.5 Y10.\nM30\n"
    errors = _errors(text)
    assert "interference" in errors[0], errors


def test_an_inner_arc_smaller_than_the_radius_is_an_alarm() -> None:
    text = HEAD.format(x="0", y="0") + "G41 D2 G1 X10. F100.\nG3 X12. Y0 R1.\nG1 X20.\nG40 X20. Y-5.\nM30\n"
    errors = _errors(text)
    assert "the tool radius is not less than the radius of an arc it cuts inside" in errors[0], errors


def _run(rules: Any, side: str, path: list[tuple[float, float]], cancel: bool = False) -> list[tuple[float, float]]:
    out: list[Any] = []
    cutter = cutter_for(rules, out.append)
    cutter.start(side, 1.0)
    for a, b in zip(path, path[1:]):
        cutter.line(Segment("feed", {}, {"X": b[0], "Y": b[1], "Z": 0.0}), a)
    if cancel:
        cutter.cancel()
    elif rules is FANUC_A:
        cutter.stop()
    return [s.xy for s in out]  # type B: what the corners released (a stop is refused)


def test_start_up_type_a_is_square_to_the_next_move_type_b_meets_it() -> None:
    """Right of (0,0)->(10,0), then on along 45 degrees to the left: an outer corner of 135 degrees.
    Type A: square to the next move at (10,0): (10 + 1/sqrt2, -1/sqrt2). Type B: the start-up move's
    offset line y=-1 meets the next move's at x = 10 + tan(22.5 degrees)."""
    path = [(0.0, 0.0), (10.0, 0.0), (20.0, 10.0), (30.0, 20.0)]
    h = math.sqrt(0.5)
    _close(_run(FANUC_A, "right", path)[:1], [(10 + h, -h)])
    _close(_run(FANUC_B, "right", path)[:1], [(10 + math.tan(math.pi / 8), -1)])


def test_start_up_type_b_at_an_acute_corner_extends_both_moves() -> None:
    """Right of (0,0)->(10,0), then back up-left at 135 degrees: an acute outer corner of 45 degrees. Type
    B: (10,0) + (0,-1) + (1,0) = (11,-1), then (10,0) + r n2 - r t2 with n2 = (1,1)/sqrt2 and t2 =
    (-1,1)/sqrt2: (10 + sqrt2, 0)."""
    path = [(0.0, 0.0), (10.0, 0.0), (0.0, 10.0), (-10.0, 20.0)]
    _close(_run(FANUC_B, "right", path)[:2], [(11, -1), (10 + math.sqrt(2), 0)])


def test_what_type_b_leaves_unread_is_refused_by_name() -> None:
    with pytest.raises(UnsupportedError, match="inner corner after the start-up move of start-up type B"):
        _run(FANUC_B, "left", [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0)])
    with pytest.raises(UnsupportedError, match="cancel move of start-up type B"):
        _run(FANUC_B, "right", [(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (20.0, 10.0)], cancel=True)


def test_a_move_that_turns_back_on_itself_is_an_alarm() -> None:
    with pytest.raises(ProgramError, match="turns back on itself"):
        _run(FANUC_A, "left", [(0.0, 0.0), (10.0, 0.0), (20.0, 0.0), (5.0, 0.0)])


# -- properties over random convex contours ---------------------------------------------------------------

def _contour(angles: list[float], clockwise: bool) -> list[tuple[float, float]]:
    """A convex polygon on a circle of radius 20 (corners at ``angles``, degrees), closed, entered from the
    centre and run once round, then on along its first side."""
    corners = [(20 * math.cos(math.radians(a)), 20 * math.sin(math.radians(a))) for a in sorted(set(angles))]
    if clockwise:
        corners.reverse()
    return corners + [corners[0], corners[1]]


def _distance_to_line(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    """Signed: positive on the left of a->b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    return (dx * (p[1] - a[1]) - dy * (p[0] - a[0])) / math.hypot(dx, dy)


def _distance_to_segment(p: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
    dx, dy = b[0] - a[0], b[1] - a[1]
    t = max(0.0, min(1.0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy)))
    return math.dist(p, (a[0] + t * dx, a[1] + t * dy))


def _compensated(path: list[tuple[float, float]], side: str) -> list[tuple[Segment, tuple[float, float]]]:
    """Each released move with the programmed move it belongs to (its end), radius 0.5."""
    out: list[Segment] = []
    cutter = cutter_for(FANUC_A, out.append)
    cutter.start(side, 0.5)
    cutter.line(Segment("feed", {}, {"X": path[0][0], "Y": path[0][1], "Z": 0.0}), (0.0, 0.0))
    for a, b in zip(path, path[1:]):
        cutter.line(Segment("feed", {}, {"X": b[0], "Y": b[1], "Z": 0.0}), a)
    cutter.stop()
    return [(s, (s.end["X"], s.end["Y"])) for s in out]


def _gaps(angles: list[float]) -> list[float]:
    ordered = sorted(angles)
    return [b - a for a, b in zip(ordered, ordered[1:] + [ordered[0] + 360.0])]


ANGLES = st.lists(st.integers(0, 17).map(lambda k: k * 20.0), min_size=3, max_size=18,
                  unique=True).filter(lambda a: max(_gaps(a)) <= 160.0)
"""Corners at least 20 and at most 160 degrees apart on the circle (the centre inside): sides of 6.9 mm or
more, corners of 20 degrees or more. Inside, a side is cut short by r (cot(A/2) + cot(B/2)) at its
corners A and B, at most 11.4 mm per mm of radius: a radius of 0.5 never makes it vanish."""


@settings(max_examples=60, deadline=None)
@given(ANGLES)
def test_inside_a_convex_contour_every_corner_is_at_the_radius_from_both_sides(angles: list[float]) -> None:
    """Left of a counter-clockwise contour (inside): every end of a side's move is the intersection, one
    radius (0.5) inside both sides that meet there."""
    path = _contour(angles, clockwise=False)
    moves = _compensated(path, "left")[1:-1]  # the sides run once round (not the start-up, nor the last)
    assert len(moves) == len(path) - 2
    for k, (seg, end) in enumerate(moves):
        before, after = path[k], path[k + 2]
        assert end == path[k + 1]
        assert seg.xy is not None
        assert _distance_to_line(seg.xy, before, end) == pytest.approx(0.5, abs=1e-9)
        assert _distance_to_line(seg.xy, end, after) == pytest.approx(0.5, abs=1e-9)


@settings(max_examples=60, deadline=None)
@given(ANGLES)
def test_outside_a_convex_contour_the_tool_never_comes_nearer_than_its_radius(angles: list[float]) -> None:
    """Left of a clockwise contour (outside): each side's move ends one radius outside its side (an acute
    corner's extension too), and no point of the path comes nearer the contour than the radius; the moves
    added at acute corners are exactly the corners under 90 degrees. A corner of exactly 90 degrees (its two
    sides span 180 degrees of the circle: hypothesis found 0, 100, 140, 280) is left out: there the extension
    and the intersection are one point, and which construction the rounding picks is not the property."""
    gaps = _gaps(angles)
    assume(all(a + b != 180.0 for a, b in zip(gaps, gaps[1:] + gaps[:1])))
    path = _contour(angles, clockwise=True)
    sides = list(zip(path[:-2], path[1:-1]))
    moves = _compensated(path, "left")[1:]
    for seg, _ in moves:
        assert seg.xy is not None
        assert min(_distance_to_segment(seg.xy, a, b) for a, b in sides) >= 0.5 - 1e-9
    own = [(seg, end) for seg, end in moves if seg.xy is not None]
    acute = sum(1 for k in range(len(path) - 2)
                if (path[k][0] - path[k + 1][0]) * (path[k + 2][0] - path[k + 1][0])
                + (path[k][1] - path[k + 1][1]) * (path[k + 2][1] - path[k + 1][1]) > 0)
    assert len(own) == (len(path) - 1) + acute  # one move per side, plus one at each acute corner


# -- the set-up's start-up type, and translations ----------------------------------------------------------

def test_the_set_up_chooses_start_up_type_b_and_its_unread_cancel_is_refused() -> None:
    from dialects.fanuc import Fanuc
    setup = with_tools(radii={1: 1.0})
    assert Fanuc.cutter_rules(setup) is FANUC_A
    setup.controller.cutter_startup = "B"
    assert Fanuc.cutter_rules(setup) is FANUC_B
    lathe = with_tools()
    lathe.input.machine_type = "lathe"
    assert Fanuc.cutter_rules(lathe) is FANUC_T  # Fanuc T: tool nose radius compensation, by the same SUP
    lathe.controller.cutter_startup = "B"
    assert Fanuc.cutter_rules(lathe) is FANUC_T_B
    haas = with_tools()
    haas.controller.variant = "haas"
    assert Fanuc.cutter_rules(haas) is HAAS_A  # a Haas mill: its settings 43 and 58 (tests/test_haas_cutter_compensation.py)
    text = HEAD.format(x="0", y="0") + "G42 D1 G1 X10. F100.\nX20. Y10.\nX30. Y20.\nG40 X40.\nM30\n"
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(text), file="t.nc", dialect="fanuc", setup=setup))
    assert str(info.value.errors[0]).startswith("t.nc:5:1: error: the cancel move of start-up type B"), info.value


def _translate(text: str, target: str, setup: MachineSetup = SETUP) -> str:
    from postproc.api import translate
    from postproc.errors import Diagnostics, ErrorLevel
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.nc", source="fanuc", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


@pytest.mark.parametrize("text", [TRIANGLE, ARCS, POCKET])
@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "mach3"])
def test_where_the_rules_differ_the_fanuc_path_is_written_as_moves_and_verifies(text: str, target: str) -> None:
    """Towards LinuxCNC and Mach3 (arcs about outer corners, another start-up) and grbl (no compensation)
    the Fanuc path is written as moves: no G41/G42 is left, and verify finds it at zero deviation."""
    import re
    from postproc.simulate.verify import verify_lines
    out = _translate(text, target)
    assert not re.search(r"\bG4[12]\b", out), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="t.nc", file_out="o", source="fanuc",
                          target=target, setup=SETUP)
    assert report.ok and report.max_deviation == 0, report.summary()


ALONG = (HEAD.format(x="5.", y="0") + "G41 D2 G1 X10. Y0 F100.\nX20.\nY20.\nX0\nY0\nX8.\nG40 X8. Y10.\nM30\n")
"""The pocket entered along its first side and left square to its last: start-up (type A: square to the
next move, on along +X) and LinuxCNC's entry (square to the start-up move itself) both end at (10, 2);
every corner is inner (both rules meet there); the cancel leaves from (8, 2) under both."""


def test_where_both_rules_cut_the_same_path_g41_stays_native() -> None:
    """Towards LinuxCNC; not towards Mach3, whose NIST rules stop at an inner corner: there the moves."""
    from postproc.simulate.verify import verify_lines
    out = _translate(ALONG, "linuxcnc")
    assert "G41 D02 G1 X10. Y0. F100." in out, out
    assert "G41" not in _translate(ALONG, "mach3")
    report = verify_lines(io.StringIO(ALONG), io.StringIO(out), file_in="t.nc", file_out="o", source="fanuc",
                          target="linuxcnc", setup=SETUP)
    assert report.ok and report.max_deviation == 0, report.summary()
    _close(_points(ALONG), [(10, 2), (18, 2), (18, 18), (2, 18), (2, 2), (8, 2), (8, 10)])


def test_the_native_stretch_runs_in_rs274_as_fanuc_cuts_it() -> None:
    """The independent check of "the same path": rs274 compensates the G41 kept for LinuxCNC by its own
    rules (tool 2 of 4 mm diameter, 0.15748 in in its standalone table) and cuts the hand-derived Fanuc
    points of ``ALONG``."""
    from tests.support.rs274 import available, canonical_moves, run_rs274
    if not available():
        pytest.skip("the LinuxCNC interpreter rs274 is not installed")
    out = _translate(ALONG, "linuxcnc")
    moves = [e for e in canonical_moves(run_rs274(out, tool_table="T2 P2 D%r Z0 ;\n" % (4.0 / 25.4)),
                                        start=(0.0, 0.0, 0.0)) if "move" in e]
    _close([(m["x"], m["y"]) for m in moves[1:]], [(10, 2), (18, 2), (18, 18), (2, 18), (2, 2), (8, 2), (8, 10)])
