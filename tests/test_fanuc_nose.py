"""Tool nose radius compensation of Fanuc T and GSK, by Fanuc's rules (``cutter_rules.FANUC_T``: start-up type A,
straight corners, type A cancel; the radius and the tip of the offset the T code selected): hand-derived
toolpaths for every tip direction, the finishing cycle under compensation, and translations that keep it
native (GSK; LinuxCNC where its own rules cut the same path, run by rs274 as the oracle) or write the
compensated path as moves (LinuxCNC where the rules differ, grbl).

The profile (G42, offset 02: nose radius r = 0.8, X diameters; below in (Z, X radius)):

    N7  G42 G0 X20. Z2.     start-up from (2, 31) to (2, 10)
    N8  G1 Z-15.            turn along -Z to (-15, 10)
    N9  X40. Z-25.          a 45 degree taper to (-25, 20): an inner corner after the turn
    N10 G2 X50. Z-30. R5.   a quarter arc about (-25, 25): an outer (135 degree) corner before it
    N11 G1 X60.             face along +X to (-30, 30), tangent to the arc
    N12 Z-40.               turn along -Z to (-40, 30): an outer 90 degree corner
    N13 G40 G0 X100. Z50.   cancel, to (50, 50)

Derived by hand, the nose centre one r to the right of the path (right of -Z is +X; of the taper's
direction (-1, 1)/sqrt2 it is (1, 1)/sqrt2; of +X it is +Z), at the intersection of the offset paths for
inner corners and for outer corners of 90 degrees or more (Fanuc's offset mode figures):

- N7 ends square to the next move at its start (type A): (2, 10 + r);
- N8 ends where X = 10 + r meets the taper's offset line Z + X = -5 + r sqrt2: Z = -15 - r + r sqrt2;
- N9 ends where that line meets the arc's offset circle (inside it: radius 5 - r about (-25, 25)), the
  intersection nearest the corner: u + v = c, u^2 + v^2 = (5 - r)^2 with u = Z + 25, v = X - 25,
  c = -5 + r sqrt2, u = (c + sqrt(2 (5 - r)^2 - c^2)) / 2;
- N10 ends at (-30 + r, 25) about (-25, 25);
- N11 ends at the offset lines' intersection (-30 + r, 30 + r);
- N12 ends square to itself at its end (type A cancel): (-40, 30 + r); N13 at the programmed (50, 50).

The machine positions the imaginary tool tip: the centre plus r times the tip's direction, from the Haas
lathe manual's table ("Imaginary Tool Tip and Direction": 1 X+Z+, 2 X+Z-, 3 X-Z-, 4 X-Z+, 5 Z+, 6 X+,
7 Z-, 8 X-, 0 and 9 none), written out as words in ``tests/support/nose_tips.py``, not taken from
``postproc.compensation.nose``.
"""

from __future__ import annotations

import io
import math
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import PostprocError
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.nose_tips import FINISHING_UNDER_G42, SETUPS, at_tip, controlled, direction, one_tool
from tests.support.rs274 import available, run_rs274

R = 0.8
MM_PER_INCH = 25.4

PROFILE = """O2011
G21 G18 G40 G99
T0102
G96 S180 M03
G50 S2500
G0 X62. Z2.
G42 G0 X20. Z2.
G1 Z-15. F0.2
X40. Z-25.
G2 X50. Z-30. R5.
G1 X60.
Z-40.
G40 G0 X100. Z50.
M30
"""

def _setup(tip: int | None, name: str = "fanuc_0i_tf.xml") -> MachineSetup:
    return one_tool(name, 2, R, tip)


def _centres() -> list[tuple[int, str, tuple[float, float], tuple[float, float] | None]]:
    """The nose centre's end of each compensated move (module docstring), with an arc's centre."""
    c = -5.0 + R * math.sqrt(2.0)
    u = (c + math.sqrt(2.0 * (5.0 - R) ** 2 - c * c)) / 2.0
    return [
        (7, "rapid", (2.0, 10.0 + R), None),
        (8, "feed", (-15.0 - R + R * math.sqrt(2.0), 10.0 + R), None),
        (9, "feed", (u - 25.0, c - u + 25.0), None),
        (10, "cw", (-30.0 + R, 25.0), (-25.0, 25.0)),
        (11, "feed", (-30.0 + R, 30.0 + R), None),
        (12, "feed", (-40.0, 30.0 + R), None),
    ]


def _expected(tip: int | None) -> list[dict[str, Any]]:
    """Every move's controlled point, X a diameter: the tip on the compensated path, the rest programmed."""
    out: list[dict[str, Any]] = [{"line": 6, "move": "rapid", "x": 62.0, "z": 2.0}]
    out += [at_tip(line, move, end, tip, R, centre) for line, move, end, centre in _centres()]
    out.append({"line": 13, "move": "rapid", "x": 100.0, "z": 50.0})
    return out


def _controlled(text: str, dialect: str, setup: MachineSetup, file: str = "t.nc") -> list[dict[str, Any]]:
    return controlled(text, dialect, setup, file)


@pytest.mark.parametrize("tip", range(10))
def test_every_tip_direction_by_hand(tip: int) -> None:
    assert _controlled(PROFILE, "fanuc", _setup(tip)) == _expected(tip)


def test_no_tip_is_the_nose_centre() -> None:
    assert _controlled(PROFILE, "fanuc", _setup(None)) == _expected(None)


@pytest.mark.parametrize("tip", [2, 3, 8])
def test_gsk_runs_the_same_rules(tip: int) -> None:
    """GSK's G42 by the offset of its T code, as Fanuc T's ([?] its manual's figures: see ``cutter_rules.FANUC_T``)."""
    assert _controlled(PROFILE, "gsk", _setup(tip, "gsk_980tdc.xml")) == _expected(tip)


def test_tip_3_cuts_the_programmed_diameters_and_faces() -> None:
    """The outside turning tool (tip 3): on the turn along Z and the face along X its imaginary tip runs on
    the programmed line (the nose touches the diameter and the face it was set to)."""
    moves = _controlled(PROFILE, "fanuc", _setup(3))
    assert moves[2]["x"] == pytest.approx(20.0) and moves[5]["z"] == pytest.approx(-30.0)
    assert moves[6]["x"] == pytest.approx(60.0)


def test_g42_takes_the_offset_of_the_t_code() -> None:
    """T0102: offset 02's radius; without an offset number (T0100) there is no radius to compensate by."""
    setup = _setup(3)
    setup.tools["5"] = ToolData(number=5, radius=2 * R, tip=3)
    other = _controlled(PROFILE.replace("T0102", "T0105"), "fanuc", setup)
    assert other[1]["x"] == pytest.approx(2 * (10.0 + 2 * R - 2 * R))  # tip 3 on the start-up's X
    assert other[1]["z"] == pytest.approx(2.0 - 2 * R)
    with pytest.raises(PostprocError) as err:
        _controlled(PROFILE.replace("T0102", "T0100"), "fanuc", setup)
    assert "t.nc:7:1: error: tool nose radius compensation takes the radius of the offset the T code" in str(err.value)


# -- the finishing cycle under compensation ------------------------------------------------------------

CYCLE = """O2010
G21 G18 G40 G99 G97 S500 M03
T0102
""" + FINISHING_UNDER_G42


def test_finishing_cycle_runs_its_profile_compensated_by_hand() -> None:
    """G42 before G70 and G40 after it [K: Fanuc T, see ``cutter_rules.FANUC_T``]: G70 runs ns..nf compensated, the
    offset temporarily cancelled on the return to A = (2, 31). The G42 block does not move, so the profile's
    first move (to (2, 10)) starts compensation, ending square to the turn after it: (2, 10 + r). The turn
    meets the taper as in the module docstring; the taper meets the face (+X, nose centre at Z = -25 + r) at
    X = -5 + r sqrt2 - (-25 + r); the face, the last compensated block, ends square to itself: (-25 + r, 30)
    (right of +X is +Z). Tip 3 moves each by (-r, -r). The return ends with the tip on A itself (X62 Z2)."""
    centres = [
        (2.0, 10.0 + R),
        (-15.0 - R + R * math.sqrt(2.0), 10.0 + R),
        (-25.0 + R, -5.0 + R * math.sqrt(2.0) + 25.0 - R),
        (-25.0 + R, 30.0),
    ]
    moves = [m for m in _controlled(CYCLE, "fanuc", _setup(3)) if m["line"] == 12]
    assert [m["move"] for m in moves] == ["rapid", "feed", "feed", "feed", "rapid"]
    for move, (z, x) in zip(moves, centres):
        assert move["z"] == pytest.approx(z - R, abs=1e-6) and move["x"] == pytest.approx(2 * (x - R), abs=1e-6)
    assert (moves[-1]["x"], moves[-1]["z"]) == (62, 2)


def test_pattern_repeating_cycle_under_compensation_is_refused() -> None:
    """G73's passes under compensation are not in our sources [?] (G71/G72 type I are modelled:
    ``tests/test_fanuc_nose_roughing.py``): refused at the cycle, not run uncompensated."""
    text = CYCLE.replace("G0 X62. Z2.\nG71 U2. R0.5\nG71 P10 Q20", "G42 G0 X62. Z2.\nG73 U2. W1. R3\nG73 P10 Q20") \
        .replace("G42 G0 X62. Z2.\nG70", "G70")
    with pytest.raises(PostprocError) as err:
        _controlled(text, "fanuc", _setup(3))
    assert "t.nc:6:1: error: a lathe cycle (pattern repeat) under tool nose radius compensation" in str(err.value)


# -- translations ------------------------------------------------------------------------------------------

def _translate(text: str, source: str, target: str, setup: MachineSetup) -> tuple[str, Any]:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source=source, target=target, setup=setup)
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="t.nc", file_out="o.nc",
                          source=source, target=target, setup=setup)
    return out.getvalue(), report


@pytest.mark.parametrize("text", [PROFILE, CYCLE])
def test_gsk_keeps_g42_native_and_verify_simulates_both(text: str) -> None:
    """GSK compensates by the same rules: its G42 stays, and verify compares the two simulated paths (the
    compensation is no longer a setting it sets aside)."""
    out, report = _translate(text, "fanuc", "gsk", _setup(3))
    assert "G42 G00 X" in out and "G40 G00 X100. Z50." in out
    assert report.ok and report.max_deviation == 0.0, report
    assert not any("cutter compensation" in note for note in report.ignored)


def _moves(ngc: str) -> list[str]:
    return [line for line in ngc.splitlines() if line.startswith(("G0 X", "G1 X", "G2 X", "G3 X"))]


def test_linuxcnc_gets_the_fanuc_path_as_moves_in_diameters() -> None:
    """LinuxCNC's own G42 would cut another path here (its entry ends square to the entry move, it rolls an
    arc around outer corners), so the stretch is written as Fanuc's moves, X diameters (G7), an arc's I a
    radius: the hand-derived points of tip 3."""
    out, report = _translate(PROFILE, "fanuc", "linuxcnc", _setup(3))
    assert "G42" not in out and "G40" not in out.split("T1 M6")[1]
    expected = _expected(3)[1:-1]
    moves = _moves(out)[:-1]
    assert len(moves) == len(expected), moves
    for line, point in zip(moves, expected):
        words = dict((w[0], float(w[1:])) for w in line.split()[1:] if w[0] in "XZ")
        assert words["X"] == point["x"] and words["Z"] == point["z"], line
    arc = next(line for line in moves if line.startswith("G2"))
    words = dict((w[0], float(w[1:])) for w in arc.split()[1:])
    start = expected[2]  # the taper's end, where the arc starts
    assert words["I"] == pytest.approx((25.0 - R) - start["x"].expected / 2.0, abs=1e-6)  # a radius
    assert words["K"] == pytest.approx((-25.0 - R) - start["z"].expected, abs=1e-6)
    assert report.ok and report.max_deviation < 1e-6, report


def _table(tip: int) -> str:
    """rs274's tool table: tool 1 in the spindle, entry 2 the offset G42 D02 reads (diameter in inches,
    Q the tip in LinuxCNC's numbers, X mirrored: Fanuc's 3 is its 2 [V: ``nose.MIRRORED``, rs274 run])."""
    q = {0: 0, 1: 4, 2: 3, 3: 2, 4: 1, 5: 5, 6: 8, 7: 7, 8: 6, 9: 9}[tip]
    return f"T1 P1 ;\nT2 P2 D{2 * R / MM_PER_INCH!r} Q{q} ;\n"


def _rs274_moves(ngc: str, tip: int) -> list[tuple[str, float, float]]:
    """rs274's moves of a LinuxCNC program: (kind, Z, X radius), mm."""
    out = []
    for line in run_rs274(ngc, tool_table=_table(tip)):
        for name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED"):
            if f" {name}(" in line:
                nums = [float(t) for t in line.split("(", 1)[1].rstrip(")").split(",")]
                if name == "ARC_FEED":
                    out.append(("arc", nums[0], nums[1]))
                else:
                    out.append(("line", nums[2], nums[0]))
    return out


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_runs_the_resolved_path_as_fanuc_simulates_it() -> None:
    """The written moves, run by LinuxCNC's interpreter, put the tip where Fanuc T's rules do (4 decimals)."""
    out, _ = _translate(PROFILE, "fanuc", "linuxcnc", _setup(3))
    theirs = [(z, x) for _, z, x in _rs274_moves(out, 3)]
    ours = [(float(p["z"]), float(p["x"]) / 2.0) for p in
            [{"z": m["z"], "x": m["x"]} for m in _controlled(PROFILE, "fanuc", _setup(3))]]
    deduped = [p for n, p in enumerate(theirs) if n == 0 or math.dist(p, theirs[n - 1]) > 1e-9]
    assert len(deduped) == len(ours)
    for a, b in zip(deduped, ours):
        assert math.dist(a, b) < 1e-4, (a, b)


COLLINEAR = """O2012
G21 G18 G40 G99
T0102
G97 S500 M03
G0 X20. Z10.
G42 G1 X20. Z2. F0.2
G1 Z-15.
X40. Z-25.
X60.
G40 G0 X100. Z50.
M30
"""
"""Entry along -Z into a turn along -Z, then only inner corners: LinuxCNC's rules cut Fanuc's path here."""


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("tip", [3, 2, 8])
def test_linuxcnc_keeps_g42_where_its_rules_cut_the_same_path_and_rs274_agrees(tip: int) -> None:
    """Kept native as ``G42 D02`` (the offset of T0102): rs274, with entry 2's nose radius and orientation,
    compensates it to the points Fanuc T's rules give (by hand for tip 3, the nose centre moved by (-r, -r): the
    entry to (2, 10 + r), the turn to Z = -15 - r + r sqrt2, the taper to Z = -25 + r on its offset line
    Z + X = -5 + r sqrt2, the face to (-25 + r, 30), square to it at its end)."""
    out, report = _translate(COLLINEAR, "fanuc", "linuxcnc", _setup(tip))
    assert "G42 D02 G1 X20. Z2." in out and report.ok
    theirs = [(z, x) for _, z, x in _rs274_moves(out, tip)]
    ours = [(float(m["z"]), float(m["x"]) / 2.0) for m in _controlled(COLLINEAR, "fanuc", _setup(tip))]
    deduped = [p for n, p in enumerate(theirs) if n == 0 or math.dist(p, theirs[n - 1]) > 1e-9]
    assert len(deduped) == len(ours), (deduped, ours)
    for a, b in zip(deduped, ours):
        assert math.dist(a, b) < 1e-4, (a, b)
    if tip == 3:
        by_hand = [(2.0 - R, 10.0), (-15.0 - R + R * math.sqrt(2.0) - R, 10.0),
                   (-25.0, -5.0 + R * math.sqrt(2.0) + 25.0 - R - R), (-25.0, 30.0 - R)]
        for a, b in zip(ours[1:5], by_hand):
            assert math.dist(a, b) < 1e-6, (a, b)  # events carry 6 decimals


@pytest.mark.parametrize("tip", [3, 6])
def test_grbl_gets_the_tip_path_as_moves(tip: int) -> None:
    """grbl has no G41/G42: the tip's path, X a radius, which verify compares at zero deviation."""
    setup = _setup(tip)
    setup.tools["2"] = ToolData(number=2, radius=R, tip=tip, x=0.0, z=0.0)  # grbl takes the offset in its moves
    out, report = _translate(PROFILE.replace("G99", "G98").replace("G96 S180 M03\nG50 S2500\n", "S800 M03\n")
                             .replace("F0.2", "F100."), "fanuc", "grbl", setup)
    assert "G41" not in out and "G42" not in out
    assert report.ok and report.max_deviation < 1e-6, report
    tz, tx = direction(tip)
    z, x = _centres()[0][2]
    words = dict((w[0], float(w[1:])) for w in _moves(out)[0].split()[1:] if w[0] in "XZ")
    assert words["X"] == pytest.approx(x + tx * R) and words["Z"] == pytest.approx(z + tz * R)  # a radius


def test_grblhal_in_diameter_mode_gets_the_tip_path_in_diameters() -> None:
    """grblHAL's lathe mode (G7) has no nose compensation here: the tip's path as moves, X diameters and an
    arc's I a radius [V: grblHAL ``gcode.c`` halves the X word only], the hand-derived points of tip 3."""
    setup = _setup(3)
    setup.tools["2"] = ToolData(number=2, radius=R, tip=3, x=0.0, z=0.0)
    setup.controller.tool_table = True  # a build with a tool table takes the offset as G43 H02
    out, report = _translate(PROFILE.replace("G99", "G98").replace("G96 S180 M03\nG50 S2500\n", "S800 M03\n")
                             .replace("F0.2", "F100."), "fanuc", "grblhal", setup)
    assert "G7" in out and "G42" not in out
    moves = _moves(out)[:-1]
    for line, point in zip(moves, _expected(3)[1:-1]):
        words = dict((w[0], float(w[1:])) for w in line.split()[1:] if w[0] in "XZ")
        assert words["X"] == point["x"] and words["Z"] == point["z"], line
    assert report.ok and report.max_deviation < 1e-6, report


def test_linuxcnc_g42_by_register_becomes_gsk_moves() -> None:
    """LinuxCNC's G42 D1 cuts another path than GSK's G42 would (its entry ends square to the entry move):
    GSK gets LinuxCNC's path as moves. By hand (tip 3, r 0.8): the entry from (2, 30) to (2, 20) along -X
    ends with the nose centre to its right, (2 - r, 20), the tip at (2 - 2r, 20 - r): X38.4 Z0.4."""
    text = "G18 G21 G7 G90 G94\nG0 X60 Z2\nG42 D1 G1 X40 Z2 F100\nG40 G0 X100 Z5\nM2\n"
    setup = load_setup(str(SETUPS / "linuxcnc_lathe.xml"))
    setup.tools = {"1": ToolData(number=1, radius=R, tip=3)}
    out, report = _translate(text, "linuxcnc", "gsk", setup)
    assert "G42" not in out and "G01 X38.4 Z0.4 F100." in out
    assert report.ok and report.max_deviation < 1e-6, report


def test_start_up_type_b_ends_as_an_outer_corner() -> None:
    """``<Controller cutterStartup="B">`` (parameter SUP = 1): the start-up move (along +X from X radius 5 to
    10 at Z2) ends as the outer 90 degree corner with the turn after it would, where the offset lines
    meet: Z = 2 + r (right of +X), X = 10 + r (right of -Z); type A would end at Z2. Tip 3: (2, 10). The
    type B cancel is not modelled: refused where it stands."""
    text = PROFILE.replace("G0 X62. Z2.\n", "G0 X10. Z2.\n").replace("G42 G0 X20. Z2.", "G42 G1 X20. Z2. F0.2")
    setup = _setup(3)
    setup.controller.cutter_startup = "B"
    moves: list[dict[str, Any]] = []
    with pytest.raises(PostprocError) as err:
        for ev in toolpath_events(io.StringIO(text), file="t.nc", dialect="fanuc", setup=setup):
            if "move" in ev:
                moves.append({**ev, **ev.get("controlled", {})})
    assert moves[1]["line"] == 7
    assert moves[1]["z"] == pytest.approx(2.0 + R - R) and moves[1]["x"] == pytest.approx(2 * (10.0 + R - R))
    assert "t.nc:13:1: error: the cancel move of start-up type B" in str(err.value)
