"""Tool nose compensation of a Haas lathe outside the cycles: Fanuc T's rules (``cutter_rules.HAAS_T``: the Haas lathe
manual's "Two FANUC compensation types are supported, Type A and Type B", type A the default; the approach
and the departure G00/G01, the departure starting square to the last block), hand-derived toolpaths for every
tip direction over a profile with a chamfer, a concave fillet and a convex round, and translations: GSK and
Fanuc T keep G42 (the same rules), LinuxCNC keeps it where its own rules cut the same path (rs274 the oracle)
and gets the Haas path as moves where they do not, grblHAL gets the path as moves.

The profile (G42, T0101: nose radius r = 0.4, X diameters; below in (Z, X radius)):

    N5  G0 X40. Z2.              start at (2, 20)
    N6  G42 G0 X10. Z2.          approach along -X to (2, 5)
    N7  G1 Z0. F0.1              along -Z to (0, 5)
    N8  X16. Z-3.                a 45 degree chamfer to (-3, 8): an inner corner after N7
    N9  Z-10.                    along -Z to (-10, 8): an outer corner of 135 degrees before it
    N10 G2 X20. Z-12. R2.        a concave fillet about (-10, 10), tangent to N9
    N11 G1 X26.                  face along +X to (-12, 13), tangent to the fillet
    N12 G3 X30. Z-14. R2.        a convex round about (-14, 13), tangent to N11
    N13 G1 Z-20.                 along -Z to (-20, 15), tangent to the round
    N14 G40 G1 X34.              departure to (-20, 17)

The nose centre by hand, one r to the right of the motion (right of -Z is +X; of the chamfer's direction
(-1, 1)/sqrt2 it is (1, 1)/sqrt2; of +X it is +Z), corners at the intersection of the offset paths:

- N6 ends square to N7 at its start (type A): (2, 5 + r);
- N7 ends where X = 5 + r meets the chamfer's offset line Z + X = 5 + r sqrt2: (r (sqrt2 - 1), 5 + r);
- N8 ends where that line meets N9's offset X = 8 + r: (-3 + r (sqrt2 - 1), 8 + r);
- N9 ends at (-10, 8 + r), where the fillet's offset starts (tangent: no corner);
- N10 ends on the circle of radius 2 - r about (-10, 10) (the nose inside it), square to the face: (-12 + r, 10);
- N11 ends at (-12 + r, 13); N12 on the circle of radius 2 + r about (-14, 13): (-14, 15 + r);
- N13 ends square to itself at its end (the departure starts "at a right angle to the last programmed
  block"): (-20, 15 + r); N14 at the programmed (-20, 17).

The machine positions the imaginary tool tip, the centre plus r times the tip's direction from the Haas manual's
table (``tests/support/nose_tips.py``, its words, not ``postproc.compensation.nose``). A taper between two turns
is checked against the Haas manual's own "Tool Radius And Angle Chart" (``HAAS_CHART``).
"""

from __future__ import annotations

import io
import math
from typing import Any

import pytest

from postproc.api import translate
from postproc.rs274.cutter_rules import FANUC_T, FANUC_T_B, HAAS_T, HAAS_T_B, ARC_CORNERS
from postproc.errors import PostprocError
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines
from tests.support.nose_tips import at_tip, controlled, direction, one_tool
from tests.support.rs274 import available, run_rs274

R = 0.4
MM_PER_INCH = 25.4
SQ = math.sqrt(2.0)

PROFILE = """%
O3001 (HAAS TNC PROFILE)
G00 G18 G21 G40 G80 G99
T0101
G97 S800 M03
G00 X40. Z2.
G42 G00 X10. Z2.
G01 Z0. F0.1
X16. Z-3.
Z-10.
G02 X20. Z-12. R2.
G01 X26.
G03 X30. Z-14. R2.
G01 Z-20.
G40 G01 X34.
M30
%
"""
FIRST = 6
"""The line of ``G00 X40. Z2.`` (the start); the profile's blocks follow it."""


def _setup(tip: int | None, name: str = "haas_st10_lathe.xml") -> MachineSetup:
    return one_tool(name, 1, R, tip)


def _centres() -> list[tuple[int, str, tuple[float, float], tuple[float, float] | None]]:
    """The nose centre's end of each compensated move (module docstring), with an arc's centre."""
    k = R * (SQ - 1.0)
    return [
        (FIRST + 1, "rapid", (2.0, 5.0 + R), None),
        (FIRST + 2, "feed", (k, 5.0 + R), None),
        (FIRST + 3, "feed", (-3.0 + k, 8.0 + R), None),
        (FIRST + 4, "feed", (-10.0, 8.0 + R), None),
        (FIRST + 5, "cw", (-12.0 + R, 10.0), (-10.0, 10.0)),
        (FIRST + 6, "feed", (-12.0 + R, 13.0), None),
        (FIRST + 7, "ccw", (-14.0, 15.0 + R), (-14.0, 13.0)),
        (FIRST + 8, "feed", (-20.0, 15.0 + R), None),
    ]


def _expected(tip: int | None) -> list[dict[str, Any]]:
    out: list[dict[str, Any]] = [{"line": FIRST, "move": "rapid", "x": 40.0, "z": 2.0}]
    out += [at_tip(line, move, end, tip, R, centre) for line, move, end, centre in _centres()]
    out.append({"line": FIRST + 9, "move": "feed", "x": 34.0, "z": -20.0})
    return out


def _controlled(text: str, setup: MachineSetup, dialect: str = "fanuc") -> list[dict[str, Any]]:
    return controlled(text, dialect, setup, "t.nc")


def test_the_haas_lathe_rules_are_fanuc_ts() -> None:
    """Every rule but the name: the Haas manual's "Two FANUC compensation types are supported" (cutter_rules.HAAS_T)."""
    assert HAAS_T.cuts_like(FANUC_T) and HAAS_T_B.cuts_like(FANUC_T_B)
    assert not HAAS_T.cuts_like(FANUC_T_B) and not HAAS_T.cuts_like(ARC_CORNERS)
    assert HAAS_T.entry == "perpendicular" and not HAAS_T.arc_after_cancel  # type A; a straight departure


@pytest.mark.parametrize("tip", range(10))
def test_every_tip_direction_by_hand(tip: int) -> None:
    assert _controlled(PROFILE, _setup(tip)) == _expected(tip)


def test_tip_3_touches_the_programmed_diameters_and_faces() -> None:
    """The OD tool (tip 3): along Z and along X its imaginary tip runs on the programmed line."""
    moves = _controlled(PROFILE, _setup(3))
    assert moves[4]["x"] == pytest.approx(16.0) and moves[6]["z"] == pytest.approx(-12.0)
    assert moves[8]["x"] == pytest.approx(30.0)


def test_a_boring_bar_under_g41() -> None:
    """ID boring toward the chuck with G41, tip 2 (the manual's boring bar direction, X+ Z-), r 0.4: the
    approach from (2, 5) down to (2, 3) along -X ends square to the bore after it, the nose centre left of
    -Z, below it: (2, 3 - r); the bore to Z-8 meets the face down to X radius 2 (an inner corner: left of -X
    is -Z): (-8 + r, 3 - r); the face ends square to itself: (-8 + r, 2). Tip 2 adds (-r, +r)."""
    text = ("G00 G18 G21 G40 G99\nT0101\nG97 S800 M03\nG00 X10. Z2.\nG41 G00 X6. Z2.\nG01 Z-8. F0.1\nX4.\n"
            "G40 G01 Z2.\nM30\n")
    expected = [(2.0, 3.0 - R), (-8.0 + R, 3.0 - R), (-8.0 + R, 2.0)]
    moves = _controlled(text, _setup(2))[1:4]
    for move, (z, x) in zip(moves, expected):
        assert move["z"] == pytest.approx(z - R, abs=1e-9) and move["x"] == pytest.approx(2 * (x + R), abs=1e-9)


def test_the_departure_vector_is_refused_by_name() -> None:
    """I and K in a Haas G40 block set where the block before it ends (the manual's overcut remedy): not
    modelled, so refused where it stands rather than run as a plain departure."""
    text = PROFILE.replace("G40 G01 X34.", "G40 G01 X34. I1. K0.")
    with pytest.raises(PostprocError) as err:
        _controlled(text, _setup(3))
    assert "t.nc:15:14: error: I and K in the G40 block (a Haas lathe's departure vector" in str(err.value)


def test_an_arc_as_the_approach_is_an_alarm() -> None:
    """"The approach must be a linear move, that is a G01 or G00" (the Haas manual)."""
    text = PROFILE.replace("G42 G00 X10. Z2.", "G42 G02 X10. Z2. R20. F0.1")
    with pytest.raises(PostprocError, match="cannot start with an arc"):
        _controlled(text, _setup(3))


def test_fanuc_t_runs_the_haas_program_alike() -> None:
    """The same program on a Fanuc 0i-TF set-up (the same offset) moves the same: the Haas form is Fanuc T's."""
    haas = _controlled(PROFILE, _setup(3))
    assert _controlled(PROFILE, _setup(3, "fanuc_0i_tf.xml")) == haas


# -- translations ------------------------------------------------------------------------------------------

def _translate(text: str, target: str, setup: MachineSetup) -> tuple[str, Any]:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source="fanuc", target=target, setup=setup)
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="t.nc", file_out="o.nc",
                          source="fanuc", target=target, setup=setup)
    return out.getvalue(), report


@pytest.mark.parametrize("tip", [3, 8])
def test_gsk_keeps_g42_native_and_runs_the_hand_derived_path(tip: int) -> None:
    setup = _setup(tip)
    out, report = _translate(PROFILE, "gsk", setup)
    assert "G42 G00 X10. Z2." in out and "G40 G01 X34." in out
    assert report.ok and report.max_deviation == 0.0, report
    assert not any("compensation" in note for note in report.ignored), report.ignored
    gsk = _setup(tip, "gsk_980tdc.xml")
    assert _controlled(out, gsk, "gsk")[1:] == _expected(tip)[1:]  # GSK's own reading of what was written


def _moves(ngc: str) -> list[str]:
    return [line for line in ngc.splitlines() if line.startswith(("G0 X", "G1 X", "G2 X", "G3 X"))]


def _words(line: str) -> dict[str, float]:
    return {w[0]: float(w[1:]) for w in line.split()[1:] if w[0] in "XZIK"}


def test_linuxcnc_gets_the_haas_path_as_moves_where_its_rules_differ() -> None:
    """The outer corner N8-N9 LinuxCNC would round with an arc, and its entry ends square to the entry move: the
    stretch is written as the Haas moves (X diameters, G7), the hand-derived points of tip 3."""
    out, report = _translate(PROFILE, "linuxcnc", _setup(3))
    assert "G42" not in out and "G41" not in out
    expected = _expected(3)[1:-1]
    moves = _moves(out)[:len(expected)]
    for line, point in zip(moves, expected):
        words = _words(line)
        assert words["X"] == point["x"] and words["Z"] == point["z"], line
    assert report.ok and report.max_deviation < 1e-6, report


def _table(tip: int) -> str:
    """rs274's tool table (inches): tool 1, its nose diameter and LinuxCNC's orientation (X mirrored: the Haas
    tip 3 is its 2, 8 its 6, 2 its 3 [V: rs274 2.9, ``nose.MIRRORED``])."""
    q = {2: 3, 3: 2, 8: 6}[tip]
    return f"T1 P1 D{2 * R / MM_PER_INCH!r} Q{q} ;\n"


def _rs274_points(ngc: str, tip: int) -> list[tuple[float, float]]:
    """rs274's move ends (Z, X radius), mm, repeated points dropped (and the traverse to where it stands that
    the first line's modal G0 makes)."""
    out: list[tuple[float, float]] = [(0.0, 0.0)]
    for line in run_rs274(ngc, tool_table=_table(tip)):
        for name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED"):
            if f" {name}(" in line:
                nums = [float(t) for t in line.split("(", 1)[1].rstrip(")").split(",")]
                point = (nums[0], nums[1]) if name == "ARC_FEED" else (nums[2], nums[0])
                if math.dist(point, out[-1]) > 1e-9:
                    out.append(point)
    return out[1:]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_resolved_haas_path() -> None:
    """The written moves, run by LinuxCNC's interpreter, put the tip where the Haas rules do (hand-derived)."""
    out, _ = _translate(PROFILE, "linuxcnc", _setup(3))
    theirs = _rs274_points(out, 3)
    ours = [(float(m["z"]), float(m["x"]) / 2.0) for m in _controlled(PROFILE, _setup(3))]
    assert _controlled(PROFILE, _setup(3)) == _expected(3)
    assert len(theirs) == len(ours), (theirs, ours)
    for a, b in zip(theirs, ours):
        assert math.dist(a, b) < 1e-4, (a, b)


TANGENT = """G00 G18 G21 G40 G99
T0101
G97 S800 M03
G00 X10. Z5.
G42 G01 X10. Z2. F0.1
Z-10.
G02 X14. Z-12. R2.
G01 X20.
G03 X24. Z-14. R2.
G01 Z-20.
G40 G01 X30.
M30
"""
"""The approach along -Z into a turn along -Z, then only tangent joins: LinuxCNC's rules cut the Haas path."""


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("tip", [3, 8])
def test_linuxcnc_keeps_g42_where_its_rules_cut_the_same_path_and_rs274_agrees(tip: int) -> None:
    """Kept native as ``G42 D01`` (tool 1's orientation from the tool table): rs274 puts the tip where the Haas
    rules do. By hand (centre, (Z, X radius)): the approach ends at (2, 5 + r), the turn at (-10, 5 + r), the
    fillet on radius 2 - r about (-10, 7) at (-12 + r, 7), the face at (-12 + r, 10), the round on 2 + r about
    (-14, 10) at (-14, 12 + r), the turn at (-20, 12 + r), the departure at (-20, 15)."""
    out, report = _translate(TANGENT, "linuxcnc", _setup(tip))
    assert "G42 D01" in out and report.ok, out
    centres = [(2.0, 5.0 + R), (-10.0, 5.0 + R), (-12.0 + R, 7.0), (-12.0 + R, 10.0), (-14.0, 12.0 + R),
               (-20.0, 12.0 + R)]
    tz, tx = direction(tip)
    by_hand = [(5.0, 5.0)] + [(z + tz * R, x + tx * R) for z, x in centres] + [(-20.0, 15.0)]
    theirs = _rs274_points(out, tip)
    assert len(theirs) == len(by_hand), (theirs, by_hand)
    for a, b in zip(theirs, by_hand):
        assert math.dist(a, b) < 1e-4, (a, b)
    ours = [(float(m["z"]), float(m["x"]) / 2.0) for m in _controlled(TANGENT, _setup(tip))]
    for a, b in zip(ours, by_hand):
        assert math.dist(a, b) < 1e-6, (a, b)


def test_grblhal_gets_the_tip_path_in_diameters() -> None:
    """grblHAL's lathe mode has no nose compensation: the tip's path as moves, X diameters (G7), verified at
    zero deviation, the hand-derived points of tip 3."""
    setup = _setup(3)
    setup.tools["1"] = ToolData(number=1, radius=R, tip=3, x=0.0, z=0.0)
    setup.controller.tool_table = True
    text = PROFILE.replace("G99", "G98").replace("F0.1", "F100.")
    out, report = _translate(text, "grblhal", setup)
    assert "G7" in out and "G42" not in out and "G41" not in out
    expected = _expected(3)[1:-1]
    moves = _moves(out)[:len(expected)]
    assert len(moves) == len(expected), out
    for line, point in zip(moves, expected):
        words = _words(line)
        assert words["X"] == point["x"] and words["Z"] == point["z"], line
    assert report.ok and report.max_deviation < 1e-6, report


HAAS_CHART = {1: (0.0010, 0.0310), 5: (0.0052, 0.0299), 10: (0.0100, 0.0285), 15: (0.0146, 0.0271),
              20: (0.0188, 0.0257), 46: (0.0372, 0.0180), 50: (0.0398, 0.0167), 55: (0.0428, 0.0150),
              60: (0.0458, 0.0132)}
"""The Haas lathe manual's "Tool Radius And Angle Chart (1/32 RADIUS)" [V: Classic Control lathe operator's
manual, "Tool Nose Compensation Geometry", https://staging-diy.haascnc.com/tool-nose-compensation-geometry,
read in this session]: per angle (degrees), Xc (cross, on the part's diameter) and Zc (longitudinal), the
amounts a programmer without compensation moves a taper by for a 1/32 in nose; some of its rows."""


@pytest.mark.parametrize("angle", sorted(HAAS_CHART))
def test_a_compensated_taper_is_shifted_by_the_haas_chart(angle: int) -> None:
    """A taper at ``angle`` to the Z axis (rising toward the chuck, G42, tip 3, nose 1/32 in) between a turn
    before it and a turn after it: both ends of its compensated path lie on the programmed taper moved by the
    chart's Zc along Z, and by its Xc (a diameter) along X, within one unit of the chart's fourth decimal (its
    own rounding: at 1 degree the exact Xc is 0.00108, the chart says .0010; at 20 degrees 0.01874, it says
    .0188)."""
    r, theta, length = 1.0 / 32.0, math.radians(angle), 0.5
    end = (-length * math.cos(theta), 0.5 + length * math.sin(theta))  # (Z, X radius), from (0, 0.5)
    text = (f"G00 G18 G20 G40 G99\nT0101\nG97 S800 M03\nG00 X2. Z0.1\nG42 G01 X1. Z0.1 F0.01\nG01 Z0.\n"
            f"X{2 * end[1]:.6f} Z{end[0]:.6f}\nZ-1.\nG40 G01 X3.\nM30\n")
    moves = _controlled(text, one_tool("haas_st10_lathe.xml", 1, r * MM_PER_INCH, 3))
    taper = [(m["z"] / MM_PER_INCH, m["x"] / MM_PER_INCH / 2.0) for m in moves if m["line"] in (6, 7)]
    xc, zc = HAAS_CHART[angle]
    for z, x in taper:  # the ends of the turn before the taper and of the taper: both on the moved taper
        on_line_z = -(x - 0.5) / math.tan(theta)
        on_line_x = 0.5 - z * math.tan(theta)
        assert abs(on_line_z - z) == pytest.approx(zc, abs=1.1e-4), (z, x)
        assert 2 * abs(on_line_x - x) == pytest.approx(xc, abs=1.1e-4), (z, x)
