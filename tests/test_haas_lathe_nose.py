"""Haas lathe roughing cycles under tool nose radius compensation (G42 in the profile's first block, G40 in
its last: the form of public Haas lathe programs, enier290188/cnc ``src/lathe``), the one-block G75 and
M24 before G76.

Expected values are derived by hand below, not by the code under test: the nose centre one radius
beside each block (right of the motion for G42, looking along it with Z across and X up), every corner
where the offset paths cross (Fanuc T's rules, which a Haas lathe follows: ``cutter_rules.HAAS_T``), the approach
and the departure square to the block after and before them (type A); the imaginary tip the radius away
from the centre in the direction the Haas manual gives each tip number (``tests/support/nose_tips.py``). The end-to-end test
compares the roughing of a compensated profile with the roughing of the same cycle over the tip path
written out by hand, without compensation.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import pytest

from postproc.api import read_program, translate
from postproc.cycles.turning.nose_path import nose_path
from postproc.cycles.turning.profile import Seg
from postproc.rs274.cutter_rules import HAAS_T
from postproc.errors import ErrorList, ProgramError
from postproc.ir import CompoundMotion, CutterCompensation, Motion
from postproc.ir.lathe_sections import LatheCycle
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines
from tests.support.nose_tips import controlled, direction
from tests.support.rs274 import available
from tests.test_lathe_rs274 import INCH_TOLERANCE, difference, ours, theirs

ROOT = Path(__file__).resolve().parents[1]
HAAS_XML = (ROOT / "examples" / "setups" / "haas_st10_lathe.xml").read_text()
TOOLS = """  <Tools>
    <Tool number="1" radius="0.8001" tip="3"/>
  </Tools>
</MachineSetup>"""
"""Tool 1 of the Haas programs: nose radius 0.0315 in (0.8001 mm), tip 3 (their header comments)."""


def _haas(tmp_path: Path):  # type: ignore[no-untyped-def]
    path = tmp_path / "haas.xml"
    path.write_text(HAAS_XML.replace("</MachineSetup>", TOOLS))
    return load_setup(str(path))


def _line(x0: float, z0: float, x1: float, z1: float) -> Seg:
    return Seg("line", x0, z0, x1, z1)


def _points(segs: list[Seg]) -> list[tuple[float, ...]]:
    out: list[tuple[float, ...]] = []
    for s in segs:
        row: tuple[float, ...] = (s.x0, s.z0, s.x1, s.z1)
        if s.kind != "line":
            assert s.cx is not None and s.cz is not None
            row += (s.cx, s.cz)
        out.append(tuple(round(v, 9) for v in row))
    return out


@pytest.mark.parametrize("tip", range(10))
def test_each_tip_direction_moves_the_nose_centre_path(tip: int) -> None:
    """OD turning toward the chuck, then a shoulder up (an inside corner), G42, nose radius 0.8: the centre
    runs at X10.8 (radius) to Z-19.2, where the offset blocks meet, then at Z-19.2 up to X15, where it ends
    square to the shoulder (the departure after it, type A); the tip is the centre moved 0.8 in the tip's
    direction. The approach along -Z and the departure are no part of the path."""
    segs = [_line(10.0, 2.0, 10.0, 0.0), _line(10.0, 0.0, 10.0, -20.0), _line(10.0, -20.0, 15.0, -20.0),
            _line(15.0, -20.0, 16.0, -20.0)]
    sz, sx = direction(tip)  # the Haas manual's words (tests/support/nose_tips.py)
    dx, dz = 0.8 * sx, 0.8 * sz
    centre = [(10.8, 0.0, 10.8, -19.2), (10.8, -19.2, 15.0, -19.2)]
    expected = [tuple(round(v, 9) for v in (a + dx, b + dz, c + dx, d + dz)) for a, b, c, d in centre]
    assert _points(nose_path(segs, "right", 0.8, (int(sz), int(sx)), "G71", HAAS_T)) == expected


def test_g41_on_a_bore_runs_below_it_and_an_outside_corner_meets_where_the_offsets_cross() -> None:
    """ID boring toward the chuck with G41: the centre is below the bore (X5 - 0.5); the face before it,
    cut downward at Z0, is an outside corner of 90 degrees for G41 (the path turns right, the tool is on its
    left): under Fanuc T's rules (a Haas lathe's, ``cutter_rules.HAAS_T``) the offset face (Z0.5) and the offset
    bore (X4.5) meet at (4.5, 0.5), no arc. The approach along -Z ends square to the face: (8, 0.5)."""
    segs = [_line(8.0, 2.0, 8.0, 0.0), _line(8.0, 0.0, 5.0, 0.0), _line(5.0, 0.0, 5.0, -10.0),
            _line(5.0, -10.0, 4.0, -10.0)]
    path = nose_path(segs, "left", 0.5, (0, 0), "G71", HAAS_T)
    assert _points(path) == [(8.0, 0.5, 4.5, 0.5), (4.5, 0.5, 4.5, -10.0)]
    assert [seg.kind for seg in path] == ["line", "line"]


def test_a_profile_with_arcs() -> None:
    """X0.48 Z-0.85 (diameters), a G02 fillet R0.05 to X0.58 Z-0.9, a face to X0.836, a G03 round R0.08 to
    X0.996 Z-0.98, then Z-1.5; radius values, G42, nose 0.0315, tip 3. By hand: the fillet is concave (the
    nose inside it): centre arc radius 0.05 - 0.0315 = 0.0185 about (0.29, -0.85); the round is convex:
    0.08 + 0.0315 = 0.1115 about (0.418, -0.98); every join is tangent. The tip is the centre moved
    (-0.0315, -0.0315)."""
    r = 0.0315
    segs = [_line(0.24, 0.2, 0.24, 0.1), _line(0.24, 0.1, 0.24, -0.85),
            Seg("cw", 0.24, -0.85, 0.29, -0.9, 0.29, -0.85), _line(0.29, -0.9, 0.418, -0.9),
            Seg("ccw", 0.418, -0.9, 0.498, -0.98, 0.418, -0.98), _line(0.498, -0.98, 0.498, -1.5),
            _line(0.498, -1.5, 0.6, -1.5)]
    path = nose_path(segs, "right", r, (-1, -1), "G71", HAAS_T)
    assert [s.kind for s in path] == ["line", "cw", "line", "ccw", "line"]
    expected = [(0.24, 0.0685, 0.24, -0.8815), (0.24, -0.8815, 0.2585, -0.9, 0.2585, -0.8815),
                (0.2585, -0.9, 0.3865, -0.9), (0.3865, -0.9, 0.498, -1.0115, 0.3865, -1.0115),
                (0.498, -1.0115, 0.498, -1.5315)]
    assert _points(path) == [tuple(round(v, 9) for v in row) for row in expected]
    assert math.isclose(math.hypot(path[1].x0 - 0.2585, path[1].z0 + 0.8815), 0.0185, abs_tol=1e-12)
    with pytest.raises(ProgramError, match="G71: the tool radius is not less than the radius of an arc it cuts"):
        nose_path(segs, "right", 0.05, (-1, -1), "G71", HAAS_T)  # the fillet's 0.05 leaves the nose no room


HAAS_TNC = """G00 G18 G20 G40 G80 G99
T0101
G97 S1000 M03
G00 X1.6 Z0.1
G71 P10 Q20 U0.01 W0.005 D0.05 F0.010
N10 G00 G42 X0.48 Z0.1
G01 Z-0.85
G02 X0.58 Z-0.9 R0.05
G01 X0.836
G03 X0.996 Z-0.98 R0.08
G01 Z-1.5
N20 G00 G40 X1.6
M05
M30
"""
"""The profile of ``test_a_profile_with_arcs`` in the Haas programs' form (written here)."""

HAND_TIP_PATH = """G00 G18 G20 G40 G80 G99
T0101
G97 S1000 M03
G00 X1.6 Z0.1
G71 P10 Q20 U0.01 W0.005 D0.05 F0.010
N10 G00 X0.48 Z0.0685
G01 Z-0.8815
G02 X0.517 Z-0.9 I0.0185 K0.
G01 X0.773
G03 X0.996 Z-1.0115 I0. K-0.1115
N20 G01 Z-1.5315
M05
M30
"""
"""The same cycle over the tip path derived by hand (diameters), no compensation: the approach to the path's
start, the path, no departure."""


def _cycle_moves(text: str, setup) -> list[tuple[str, dict[str, float], dict[str, float]]]:  # type: ignore[no-untyped-def]
    blocks = read_program(io.StringIO(text), file="in.nc", dialect="fanuc", setup=setup)
    block = [b for b in blocks if isinstance(b.sections.get("LatheCycle"), LatheCycle)][-1]
    compound = block.sections["CompoundMotion"]
    assert isinstance(compound, CompoundMotion)
    return [(m.mode or "", {a: round(float(v), 9) for a, v in m.axes.items()},  # type: ignore[arg-type]
             {a: round(float(v), 9) for a, v in (m.center or {}).items()})  # type: ignore[arg-type]
            for m in compound.items if isinstance(m, Motion)]


def test_the_roughing_cycle_roughs_to_the_nose_path(tmp_path: Path) -> None:
    setup = _haas(tmp_path)
    compensated = _cycle_moves(HAAS_TNC, setup)
    assert compensated == _cycle_moves(HAND_TIP_PATH, setup)
    first_level = compensated[1:3]  # after the approach to A': infeed to the first level, cut to the shoulder
    assert first_level[1][1]["Z"] == round(-1.5315 + 0.005, 9)  # the tip path's end, plus the Z allowance


def test_the_finishing_cycle_runs_the_profile_compensated(tmp_path: Path) -> None:
    """G70 on the profile: compensation on for the blocks, off for the last (the departure), as programmed."""
    setup = _haas(tmp_path)
    program = HAAS_TNC.replace("M05\n", "G70 P10 Q20\nM05\n")
    blocks = read_program(io.StringIO(program), file="in.nc", dialect="fanuc", setup=setup)
    at = next(i for i, b in enumerate(blocks) if isinstance(b.sections.get("LatheCycle"), LatheCycle)
              and b.sections["LatheCycle"].kind == "turn_finish")  # type: ignore[attr-defined]
    g70, departure = blocks[at], blocks[at + 1]
    on, off = g70.sections["CutterCompensation"], departure.sections["CutterCompensation"]
    assert isinstance(on, CutterCompensation) and (on.mode, on.register) == ("right", None)
    assert isinstance(off, CutterCompensation) and off.mode == "off"
    head = [m.axes for m in g70.sections["CompoundMotion"].items if isinstance(m, Motion)]  # type: ignore[attr-defined]
    tail = [m.axes for m in departure.sections["CompoundMotion"].items if isinstance(m, Motion)]  # type: ignore[attr-defined]
    assert head[0] == {"X": 0.48, "Z": 0.1} and head[-1] == {"X": 0.996, "Z": -1.5}
    assert tail == [{"X": 1.6, "Z": -1.5}, {"X": 1.6, "Z": 0.1}]
    assert _write(program, "fanuc", setup) == program  # its own controller keeps the cycles


def _write(text: str, target: str, setup) -> str:  # type: ignore[no-untyped-def]
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target=target, setup=setup)
    return out.getvalue()


@pytest.mark.parametrize("target", ["gsk", "linuxcnc"])
def test_the_compensated_cycles_translate_expanded_and_verify(tmp_path: Path, target: str) -> None:
    setup = _haas(tmp_path)
    program = HAAS_TNC.replace("M05\n", "G70 P10 Q20\nM05\n")
    out = _write(program, target, setup)
    lines = out.splitlines()
    assert not any(line.startswith(("G71", "G70")) for line in lines)  # another controller's rules: expanded
    # GSK compensates by Fanuc T's rules, which a Haas lathe follows (cutter_rules.HAAS_T): the finishing pass keeps
    # G42/G40; LinuxCNC's rules differ (an arc round outside corners): the pass is written as the tip's path
    kept = sum(1 for line in lines if line.startswith(("G42", "G40")))
    assert kept == (2 if target == "gsk" else 0), out
    report = verify_lines(io.StringIO(program), io.StringIO(out), file_in="in.nc", file_out="out", source="fanuc",
                          target=target, setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_the_expanded_roughing_runs_in_rs274_with_the_same_moves(tmp_path: Path) -> None:
    if not available():
        pytest.skip("rs274 is not installed")
    setup = _haas(tmp_path)
    ngc = _write(HAAS_TNC, "linuxcnc", setup)
    assert difference(ours(HAAS_TNC, "fanuc", setup), theirs(ngc), INCH_TOLERANCE) is None


def test_haas_one_block_g75_reads_i_as_the_peck() -> None:
    """``G75 X1.0 I0.1`` (one-block, I the X peck, radius) cuts as the two-block ``G75 R(e)`` then
    ``G75 X1.0 P(0.1 in least increments)`` with the same retract (the set-up's, 1 mm)."""
    haas = load_setup(str(ROOT / "examples" / "setups" / "haas_st10_lathe.xml"))
    fanuc_t = load_setup(str(ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"))
    head = "G00 G18 G20 G99\nG97 S500 M03\nG00 X1.5 Z-1.\nG01 X1.4 F0.005\n"
    one = _cycle_moves(head + "G75 X1.0 I0.1\nM30\n", haas)
    two = _cycle_moves(head + f"G75 R{1.0 / 25.4:.8f}\nG75 X1.0 P1000\nM30\n", fanuc_t)
    assert [(kind, round(axes["X"], 6)) for kind, axes, _ in one] == [  # by hand: pecks of 0.2 (diameter),
        ("linear", 1.2), ("rapid", round(1.2 + 2.0 / 25.4, 6)), ("linear", 1.0), ("rapid", 1.4)]  # back 1 mm
    assert len(one) == len(two)
    for (kind, axes, _), (kind2, axes2, _) in zip(one, two):  # the R word's inch value rounds at 1e-8
        assert kind == kind2 and all(math.isclose(axes[a], axes2[a], abs_tol=1e-7) for a in axes), (one, two)
    with pytest.raises(ErrorList, match="address P has no meaning in G75"):
        _cycle_moves(head + "G75 X1.0 P1000\nM30\n", haas)


def test_haas_m24_turns_the_g76_pull_out_off_and_m23_back_on() -> None:
    """Haas M24: no angle out of the thread at its end (the weld pin program's G76 after M24 would otherwise
    pull out beyond its start X, refused); M23 brings the set-up's chamfer back."""
    haas = load_setup(str(ROOT / "examples" / "setups" / "haas_st10_lathe.xml"))
    head = "G00 G18 G20 G99\nT0303\nG97 S1000 M03\nG00 X1.5 Z0.1\nG00 X0.6\n"
    g76 = "G76 X0.4069 Z-1.57 K0.043075 D0.01076875 F0.07692308\n"
    with pytest.raises(ErrorList, match="pulls out beyond the start point's X"):
        read_program(io.StringIO(head + g76 + "M30\n"), file="in.nc", dialect="fanuc", setup=haas)
    blocks = read_program(io.StringIO(head + "M24\n" + g76 + "M30\n"), file="in.nc", dialect="fanuc", setup=haas)
    cycle = blocks[6].sections["LatheCycle"]
    assert isinstance(cycle, LatheCycle) and cycle.params["chamfer"] == 0
    moves = [m for m in blocks[6].sections["CompoundMotion"].items if isinstance(m, Motion)]  # type: ignore[attr-defined]
    pulls = [m for before, m in zip(moves, moves[1:]) if m.mode == "thread" and m.axes["X"] != before.axes["X"]]
    assert any(m.mode == "thread" for m in moves) and pulls == []  # every pass along Z only: a square exit
    with pytest.raises(ErrorList, match="pulls out beyond the start point's X"):
        read_program(io.StringIO(head + "M24\nM23\n" + g76 + "M30\n"), file="in.nc", dialect="fanuc", setup=haas)


def test_haas_m24_needs_no_equivalent_elsewhere_the_cycle_carries_it() -> None:
    """Towards LinuxCNC the G76 after M24 is written without its pull-out, and M24 stays as a comment (another
    family has no such code, and needs none); back to Haas it stays M24."""
    haas = load_setup(str(ROOT / "examples" / "setups" / "haas_st10_lathe.xml"))
    program = "G00 G18 G20 G99\nT0303\nG97 S1000 M03\nG00 X1.5 Z0.1\nG00 X0.6\nM24\n" \
              "G76 X0.4069 Z-1.57 K0.043075 D0.01076875 F0.07692308\nM05\nM30\n"
    ngc = _write(program, "linuxcnc", haas)
    assert "(M24: thread pull-out chamfer off, in the threading cycles' words)" in ngc.splitlines()
    report = verify_lines(io.StringIO(program), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=haas, tolerance=1e-5)  # G76's depths: 6 decimals
    assert report.ok, report.summary()
    assert _write(program, "fanuc", haas) == program


R_IN = 0.8001 / 25.4
"""Tool 1's nose radius in the inch program (``TOOLS``)."""

CHAMFER = """G00 G18 G20 G40 G80 G99
T0101
G97 S1000 M03
G00 X0.8 Z0.1
G71 P10 Q20 U0.01 W0.005 D0.05 F0.010
N10 G00 G42 X0.3 Z0.1
G01 Z0.
X0.4
X0.5 Z-0.05
Z-0.5
N20 G00 G40 X0.7
G70 P10 Q20
M05
M30
"""
"""A face up to a 45 degree chamfer, then a turn: an inside corner, then two outside corners of 135 degrees
(written here in the Haas programs' form)."""


def _chamfer_tip_path() -> list[tuple[float, float]]:
    """By hand, (Z, X radius), the nose centre r to the right of the motion (right of -Z is +X, of +X is +Z, of
    the chamfer's (-1, 1)/sqrt2 is (1, 1)/sqrt2), every corner where the offset lines cross (Fanuc T's, a Haas
    lathe's type A): the approach ends square to the turn at (0.1, 0.15 + r); the turn meets the face's offset
    Z = r at (r, 0.15 + r); the face meets the chamfer's offset Z + X = 0.2 + r sqrt2 at (r, 0.2 + r (sqrt2 - 1));
    the chamfer meets the turn's offset X = 0.25 + r at (-0.05 + r (sqrt2 - 1), 0.25 + r); the turn ends square to
    itself at (-0.5, 0.25 + r). Tip 3 moves each by (-r, -r)."""
    r, k = R_IN, R_IN * (math.sqrt(2.0) - 1.0)
    centres = [(0.1, 0.15 + r), (r, 0.15 + r), (r, 0.2 + k), (-0.05 + k, 0.25 + r), (-0.5, 0.25 + r)]
    return [(z - r, x - r) for z, x in centres]


def test_the_roughing_and_the_finishing_take_one_path_at_outside_corners(tmp_path: Path) -> None:
    """G71 roughs to the hand-derived tip path (its cycle over that path written out without compensation makes
    the same moves), and G70 over the same profile runs its blocks to the very same points: one compensation
    (``nose_path`` runs the profile through the rules G70 is simulated with)."""
    setup = _haas(tmp_path)
    tip = _chamfer_tip_path()
    hand = [f"N10 G00 X{2 * tip[0][1]:.10f} Z{tip[0][0]:.10f}", f"G01 X{2 * tip[1][1]:.10f} Z{tip[1][0]:.10f}"]
    hand += [f"X{2 * x:.10f} Z{z:.10f}" for z, x in tip[2:-1]] + [f"N20 Z{tip[-1][0]:.10f}"]
    by_hand = CHAMFER.split("N10")[0] + "\n".join(hand) + "\nM05\nM30\n"
    assert _cycle_moves(CHAMFER.replace("G70 P10 Q20\n", ""), setup) == _cycle_moves(by_hand, setup)
    finish = [m for m in controlled(CHAMFER, "fanuc", setup, "in.nc") if m["line"] == 12]  # events in mm
    assert [m["move"] for m in finish] == ["rapid", "feed", "feed", "feed", "feed", "rapid", "rapid"]
    for move, (z, x) in zip(finish, tip):
        assert move["z"] / 25.4 == pytest.approx(z, abs=1e-5) and move["x"] / 25.4 == pytest.approx(2 * x, abs=1e-5)


CHART_ANGLES = (15, 20, 46, 50, 55, 60)
"""Rows of the Haas manual's "Tool Radius And Angle Chart (1/32 RADIUS)" (``tests/test_haas_nose.HAAS_CHART``,
quoted there with its source) steep enough for a roughing level to end on a taper 0.5 in long."""


@pytest.mark.parametrize("angle", CHART_ANGLES)
def test_a_compensated_taper_in_the_roughing_and_finishing_cycles_is_shifted_by_the_haas_chart(angle: int) -> None:
    """The roughing cycle under compensation against the controller's documented figures (issue 29, "a roughing
    cycle with compensation against the controller's documented example"): a one-block G71 (G42 in its P block,
    G40 in its Q block, U0 W0) and its G70 over a turn at X1.0 (diameter), a taper at ``angle`` to the Z axis
    rising toward the chuck, a turn, with a 1/32 in nose, tip 3. Without allowances every roughing level ends on
    the finishing shape, the compensated taper: the programmed taper moved by the chart's Zc along Z (and by its
    Xc, a diameter, along X); so do the finishing pass's corner before the taper and the taper's end, in G71's
    last pass and in G70. Within one unit of the chart's fourth decimal (its rounding)."""
    from tests.support.nose_tips import one_tool
    from tests.test_haas_nose import HAAS_CHART
    r, theta, length = 1.0 / 32.0, math.radians(angle), 0.5
    top = round(2 * (0.5 + length * math.sin(theta)), 6) / 2  # the taper's end: X (a radius) and Z, as written
    end_z = round(-length * math.cos(theta), 6)
    text = (f"G00 G18 G20 G40 G80 G99\nT0101\nG97 S1000 M03\nG00 X2.2 Z0.1\n"
            f"G71 P10 Q20 U0 W0 D0.05 F0.010\nN10 G42 G00 X1.\nG01 Z0.\nX{2 * top:.6f} Z{end_z:.6f}\nZ-1.\n"
            f"N20 G40 G00 X2.2\nG70 P10 Q20\nM05\nM30\n")
    moves = controlled(text, "fanuc", one_tool("haas_st10_lathe.xml", 1, r * 25.4, 3), "t.nc")
    xc, zc = HAAS_CHART[angle]

    def off_taper(x: float, z: float) -> tuple[float, float]:
        """How far (X as a diameter, Z) the point (X radius, Z) lies from the programmed taper's line."""
        return 2 * abs(x - (0.5 - z * math.tan(theta))), abs(z + (x - 0.5) / math.tan(theta))

    for line in (5, 11):  # G71, G70
        points = [(m["x"] / 25.4 / 2, m["z"] / 25.4) for m in moves if m["line"] == line and m["move"] == "feed"]
        on_taper = [(x, z) for x, z in points if z < 0 and 0.5 - 1e-9 <= x < top - r]  # below the top's corner
        levels = [0.5 + 0.05 * k for k in range(1, 40) if 0.5 + 0.05 * k < top - r] if line == 5 else []
        assert len(on_taper) == len(levels) + 1, (line, points)  # the levels' ends and the corner at X1.0
        assert any(abs(x - top) < 1e-6 for x, _ in points), points  # the taper's end, on the top diameter
        for x, z in on_taper + [(x, z) for x, z in points if abs(x - top) < 1e-6 and z > -1.0 + 1e-6]:
            dx, dz = off_taper(x, z)
            assert dz == pytest.approx(zc, abs=1.1e-4) and dx == pytest.approx(xc, abs=1.1e-4), (line, x, z)
