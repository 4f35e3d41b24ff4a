"""Fanuc T roughing cycles (G71, G72, type I) under tool nose radius compensation: G41/G42 programmed before
the cycle, G40 after it, none in ns..nf [K: ``cutter_rules.FANUC_T``, the 0i-D/0i-F notes on tool nose radius
compensation in the multiple repetitive cycles]. The cycle roughs to the finishing shape with the
compensation applied: started up at the profile's first block from the start point A, every corner by the
offset mode's rules, the last block ending square to itself (the offset is temporarily cancelled for the
return to A); the move to A ends at A uncompensated; the next move after the cycle starts compensation up
again.

Derived by hand (nose radius r = 0.4, tip 3: the imaginary tip is the nose centre moved by (-r, -r) in
(Z, X); X below as a radius, diameters in the programs):

G71 with G42 from A = (Z 2, X 31): N10 G0 X20. (to (2, 10)), G1 Z-15., X40. Z-25. (a 45 degree taper), N20
G1 X60. (a face along +X). Right of -Z is +X, of the taper's (-1, 1)/sqrt2 it is (1, 1)/sqrt2, of +X it is
+Z. The nose centre:

- N10, the start-up, ends square to the turn after it: (2, 10 + r);
- the turn meets the taper's offset line Z + X = -5 + r sqrt2 (an inner corner) at X = 10 + r:
  (-15 - r + r sqrt2, 10 + r);
- the taper meets the face's offset line Z = -25 + r (an outer corner of 135 degrees: the lines'
  intersection): (-25 + r, 20 - r + r sqrt2);
- N20 ends square to itself: (-25 + r, 30).

The tip: (2 - r, 10), (-15 - 2r + r sqrt2, 10), (-25, 20 - 2r + r sqrt2), (-25, 30 - r). The cycle reaches that
path from A along X, then along Z (type I: ``lathe_expansion.nose_shape``). So the roughing must be the
roughing of the same cycle over that tip path programmed without compensation (``HAND_G71``), and its
last pass runs along the path moved by the finishing allowance (U0.4 W0.1: +0.2 in X as a radius, +0.1 in
Z).

G72 with G41 from A = (2, 31): N30 G0 Z-20. (to (-20, 31)), G1 X40. (a face along -X to (-20, 20)), X20.
Z-10. (a taper to (-10, 10)), N40 G1 Z0. (a turn along +Z). Left of -X is +Z, of the taper's (1, -1)/sqrt2 it
is (1, 1)/sqrt2, of +Z it is +X. The nose centre:

- N30, the start-up, ends square to the face after it: (-20 + r, 31);
- the face meets the taper's offset line Z + X = r sqrt2 (inner) at Z = -20 + r: (-20 + r, 20 - r + r sqrt2);
- the taper meets the turn's offset line X = 10 + r (inner): (-10 - r + r sqrt2, 10 + r);
- N40 ends square to itself: (0, 10 + r).

The tip: (-20, 31 - r), (-20, 20 - 2r + r sqrt2), (-10 - 2r + r sqrt2, 10), (-r, 10) (``HAND_G72``).
"""

from __future__ import annotations

import io
import math
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList, PostprocError
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines
from tests.support.nose_tips import controlled, one_tool

R = 0.4
S2 = math.sqrt(2.0)
TOL = 1.5e-3
"""mm: the hand-written tip paths carry three decimals (their moves' ends then move by as much)."""

HEAD = """O2012
G21 G18 G40 G99 G97 S500 M03
T0102
G0 X100. Z50.
"""

G71 = HEAD + """G42 G0 X62. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G0 X20.
G1 Z-15.
X40. Z-25.
N20 G1 X60.
G70 P10 Q20
G40 G0 X100. Z50.
M30
"""
"""Line 5 reaches A under G42, line 7 roughs, line 12 finishes, line 13 cancels."""

HAND_G71 = HEAD + f"""G0 X62. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G0 X20.
G1 Z{2 - R:.3f}
Z{-15 - 2 * R + R * S2:.3f}
X{2 * (20 - 2 * R + R * S2):.3f} Z-25.
N20 X{2 * (30 - R):.3f}
M30
"""

G72 = HEAD + """G41 G0 X62. Z2.
G72 W2. R0.5
G72 P30 Q40 U0.4 W0.1 F0.25
N30 G0 Z-20.
G1 X40.
X20. Z-10.
N40 G1 Z0.
G40 G0 X100. Z50.
M30
"""

HAND_G72 = HEAD + f"""G0 X62. Z2.
G72 W2. R0.5
G72 P30 Q40 U0.4 W0.1 F0.25
N30 G0 Z-20.
G1 X{2 * (31 - R):.3f}
X{2 * (20 - 2 * R + R * S2):.3f}
X20. Z{-10 - 2 * R + R * S2:.3f}
N40 Z{-R:.3f}
M30
"""


def _setup(name: str = "fanuc_0i_tf.xml") -> MachineSetup:
    return one_tool(name, 2, R, 3)


def _moves(text: str, line: int, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    return [m for m in controlled(text, "fanuc", setup or _setup(), "t.nc") if m["line"] == line]


def _same(ours: list[dict[str, Any]], theirs: list[dict[str, Any]]) -> None:
    assert [m["move"] for m in ours] == [m["move"] for m in theirs]
    for a, b in zip(ours, theirs):
        assert a["x"] == pytest.approx(b["x"], abs=TOL) and a["z"] == pytest.approx(b["z"], abs=TOL), (a, b)


def test_g71_roughs_to_the_compensated_shape_by_hand() -> None:
    ours, hand = _moves(G71, 7), _moves(HAND_G71, 7)
    _same(ours, hand)
    # the last pass: the tip path moved by the allowance (X +0.4 as a diameter, Z +0.1), then back to A
    last = [(m["x"], m["z"]) for m in ours[-7:-3]]
    expected = [(20.4, 2 - R + 0.1), (20.4, -15 - 2 * R + R * S2 + 0.1),
                (2 * (20 - 2 * R + R * S2) + 0.4, -24.9), (2 * (30 - R) + 0.4, -24.9)]
    for (x, z), (ex, ez) in zip(last, expected):
        assert x == pytest.approx(ex, abs=1e-6) and z == pytest.approx(ez, abs=1e-6)
    assert (ours[-1]["x"], ours[-1]["z"]) == (62, 2)


def test_g72_roughs_to_the_compensated_shape_by_hand() -> None:
    ours, hand = _moves(G72, 7), _moves(HAND_G72, 7)
    _same(ours, hand)
    path = [(m["x"], m["z"]) for m in ours if m["move"] == "feed"][-4:]
    expected = [(2 * (31 - R) + 0.4, -19.9), (2 * (20 - 2 * R + R * S2) + 0.4, -19.9),
                (20.4, -10 - 2 * R + R * S2 + 0.1), (20.4, -R + 0.1)]
    for (x, z), (ex, ez) in zip(path, expected):
        assert x == pytest.approx(ex, abs=1e-6) and z == pytest.approx(ez, abs=1e-6)


def test_the_move_to_the_start_point_ends_there_uncompensated() -> None:
    """The G42 block moves to A: start-up and temporary cancel in one, so it ends at A itself. A compensated
    move to A (after a start-up elsewhere) also ends at A, from its compensated start."""
    assert _moves(G71, 5) == [{"line": 5, "move": "rapid", "x": 62, "z": 2}]
    text = G71.replace("G42 G0 X62. Z2.", "G42 G0 X70. Z10.\nG1 X62. Z2. F0.3")
    moves = _moves(text, 6)
    assert [(m["x"], m["z"]) for m in moves] == [(62, 2)]
    start = _moves(text, 5)[0]
    assert (start["x"], start["z"]) != (70, 10)  # the start-up ended offset, square to the move to A


def test_after_the_cycle_the_next_move_starts_compensation_up() -> None:
    """G70's first block is a start-up again: it ends square to the turn after it, (2, 10 + r) as the nose
    centre, the tip at (2 - r, 10) (``tests/test_fanuc_nose.py`` derives the rest of G70's path)."""
    first = _moves(G71, 12)[0]
    assert first["move"] == "rapid"
    assert first["x"] == pytest.approx(20.0, abs=1e-6) and first["z"] == pytest.approx(2 - R, abs=1e-6)


def test_without_compensation_the_same_cycle_roughs_the_programmed_shape() -> None:
    """The control: with G40 in force the last pass runs along the programmed profile plus the allowance."""
    ours = _moves(G71.replace("G42 G0 X62. Z2.", "G0 X62. Z2.").replace("G70 P10 Q20\n", ""), 7)
    assert (ours[-5]["x"], ours[-5]["z"]) == (pytest.approx(40.4), pytest.approx(-24.9))
    assert (ours[-6]["x"], ours[-6]["z"]) == (pytest.approx(20.4), pytest.approx(-14.9))


@pytest.mark.parametrize("text, message", [
    (G71.replace("N10 G0 X20.", "N10 G0 X20. Z2."),
     "t.nc:7:1: error: G71: a type II cycle (its first profile block names both axes) under tool nose radius "
     "compensation: how the controller roughs pockets to the compensated shape is not in our sources"),
    (G71.replace("G42 G0 X62. Z2.\nG71 U2. R0.5", "G0 X62. Z2.\nG42 G71 U2. R0.5"),
     "t.nc:6:1: error: G42 cannot share a block with a lathe cycle (G71)"),
    (G71.replace("G1 Z-15.", "G41 G1 Z-15."), "t.nc:9:1: error: G71: the profile block at line 9 turns tool nose"),
])
def test_what_is_not_known_or_an_alarm_is_refused_where_it_stands(text: str, message: str) -> None:
    with pytest.raises(PostprocError) as err:
        controlled(text, "fanuc", _setup(), "t.nc")
    assert message in str(err.value)


def test_gsk_and_a_haas_lathe_refuse_it_by_name() -> None:
    """GSK 980TDc's roughing under compensation is not in our sources [?] (``cutter_rules.GSK_T``); a Haas lathe
    compensates inside the profile (its own form, ``tests/test_haas_lathe_nose.py``), not before the cycle."""
    with pytest.raises(PostprocError) as err:
        controlled(G71, "gsk", _setup("gsk_980tdc.xml"), "t.nc")
    assert "t.nc:7:1: error: a lathe cycle (turn rough) under tool nose radius compensation" in str(err.value)
    with pytest.raises(PostprocError) as err:
        controlled(G71, "fanuc", _setup("haas_st10_lathe.xml"), "t.nc")
    assert "t.nc:7:1: error: a lathe cycle (turn rough) under tool nose radius compensation" in str(err.value)


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source="fanuc", target=target, setup=_setup())
    return out.getvalue()


def test_a_fanuc_copy_keeps_the_cycle_under_compensation_and_verifies() -> None:
    out = _translate(G71, "fanuc")
    assert "G42 G0 X62. Z2." in out and "G71 P10 Q20 U0.4 W0.1 F0.25" in out
    report = verify_lines(io.StringIO(G71), io.StringIO(out), file_in="t.nc", file_out="o.nc", source="fanuc",
                          target="fanuc", setup=_setup())
    assert report.ok and report.max_deviation == 0.0


@pytest.mark.parametrize("target", ["linuxcnc", "gsk", "grbl"])
def test_another_controller_gets_a_located_refusal(target: str) -> None:
    """No other controller is known to rough so under its compensation (LinuxCNC refuses G71/G72 with it on
    [V: ``interp_g7x.cc``]); writing the moves with compensation off and on around them is not modelled."""
    with pytest.raises(ErrorList) as err:
        _translate(G71, target)
    assert "t.nc:7:1: error: a lathe cycle (turn rough) under tool nose radius compensation: fanuc roughs to the " \
           "compensated shape" in str(err.value)


def test_the_radius_a_g10_wrote_is_the_one_roughed_by() -> None:
    """``G10 P10002 R0.4 Q3`` (the geometry of offset 2: its radius and tip, ``rs274.lathe_offset_input``) before the cycle:
    the roughing reads it as the compensation does, with no ``<Tool>`` for offset 2 in the set-up."""
    setup = one_tool("fanuc_0i_tf.xml", 7, 1.0, 2)
    text = G71.replace("T0102\n", "G10 P10002 R0.4 Q3\nT0102\n")
    ours = [m for m in controlled(text, "fanuc", setup, "t.nc") if m["line"] == 8]
    _same(ours, _moves(HAND_G71, 7))


def test_a_copy_needs_no_radius_for_the_cycle_but_the_simulation_does() -> None:
    setup = one_tool("fanuc_0i_tf.xml", 7, 1.0, 2)
    out = io.StringIO()
    translate(io.StringIO(G71), out, file="t.nc", source="fanuc", target="fanuc", setup=setup)
    assert "G71 P10 Q20 U0.4 W0.1 F0.25" in out.getvalue()
    with pytest.raises(PostprocError) as err:
        controlled(G71, "fanuc", setup, "t.nc")
    assert "t.nc:5:" in str(err.value) and "radius register 2 no value" in str(err.value)


# -- the finishing cycle under the same rules, towards controllers that write its moves ------------------------

FINISH = """O2010
G21 G18 G40 G99
T0102
G97 S500 M03
G0 X62. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G0 X20.
G1 Z-15.
X40. Z-25.
N20 G1 X60.
G42 G0 X62. Z2.
G70 P10 Q20
G40 G0 X100. Z50.
M30
"""
"""G71 without compensation, then G42 (no move: the tool is at A) and G70: its tip path by hand (the module
docstring's G71 shape without the allowance): (2 - r, 10), (-15 - 2r + r sqrt2, 10), (-25, 20 - 2r + r sqrt2),
(-25, 30 - r), then A itself."""


def _finish_points() -> list[tuple[float, float]]:
    return [(20.0, 2 - R), (20.0, -15 - 2 * R + R * S2), (2 * (20 - 2 * R + R * S2), -25.0), (2 * (30 - R), -25.0),
            (62.0, 2.0)]


@pytest.mark.parametrize("target", ["linuxcnc", "grblhal"])
def test_g70_under_compensation_is_written_as_the_tip_path_elsewhere(target: str) -> None:
    """LinuxCNC's own G42 would not cancel the offset for the return (and grblHAL has none): the stretch is
    written as Fanuc's moves, which verify compares at zero deviation."""
    from postproc.setup.groups import ControllerSettings
    setup = _setup()
    if target == "grblhal":
        setup.controller = ControllerSettings(tool_table=True, spindle_sync=True)
    out = io.StringIO()
    translate(io.StringIO(FINISH), out, file="t.nc", source="fanuc", target=target, setup=setup)
    text = out.getvalue()
    assert "G42" not in text and "G41" not in text
    lines = text.split("PROFILE LINE 11")[1].splitlines()[2:7]  # after the G42 block's move to A, written plain
    for line, (x, z) in zip(lines, _finish_points()):
        words = dict((w[0], float(w[1:])) for w in line.split() if w[0] in "XZ")
        assert words["X"] == pytest.approx(x, abs=1e-6) and words["Z"] == pytest.approx(z, abs=1e-6), line
    report = verify_lines(io.StringIO(FINISH), io.StringIO(text), file_in="t.nc", file_out="o.nc", source="fanuc",
                          target=target, setup=setup)
    assert report.ok and report.max_deviation == 0.0


def test_rs274_runs_the_written_finishing_pass_as_simulated() -> None:
    from tests.support.rs274 import available
    from tests.test_lathe_rs274 import difference, theirs
    if not available():
        pytest.skip("the LinuxCNC interpreter rs274 is not installed")
    out = io.StringIO()
    translate(io.StringIO(FINISH), out, file="t.nc", source="fanuc", target="linuxcnc", setup=_setup())
    ours = [{**m, "x": m["x"] / 2.0} for m in controlled(FINISH, "fanuc", _setup(), "t.nc")]
    rs274 = [m for m in theirs(out.getvalue())]
    for m in ours:
        m.pop("line", None)
    problem = difference([dict(m, f=0.0) for m in ours], [dict(m, f=0.0) for m in rs274])
    assert problem is None, f"{problem}\n\n{out.getvalue()}"
