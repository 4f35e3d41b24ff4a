"""Tool nose radius compensation on a lathe: hand-derived toolpaths for every tip direction, the register a
turret lathe's G41/G42 reads when translated to LinuxCNC, and the lathe cycles refused under it.

The profile (G42, LinuxCNC lathe in G7, X diameters; below in (Z, radius) with nose radius r):

    N3 G0 X60 Z2              start (2, 30)
    N4 G42 G1 X40 Z2          entry along -X to (2, 20)
    N5 G1 Z-10                turn along -Z to (-10, 20): an inside corner after the entry
    N6 G2 X60 Z-20 I10 K0     a quarter arc about (-10, 30), tangent, the tool inside it
    N7 G1 X80                 face along +X to (-20, 40), tangent
    N8 G40 G0 X100 Z5         exit to (5, 50)

Derived by hand (right of the path is +X for a move along -Z; LinuxCNC's entry ends beside its end point,
an inside corner is the intersection of the two offset lines, an arc the tool runs inside keeps its centre
with radius 10 - r): the nose centre ends at (2 - r, 20 + r), (-10, 20 + r), the arc at (-20 + r, 30)
about (-10, 30), the face at (-20 + r, 40). The machine positions the imaginary tool tip: the centre plus
r times the tip's direction, which the Haas lathe manual ("Imaginary Tool Tip and Direction") gives as
1 X+Z+, 2 X+Z-, 3 X-Z-, 4 X-Z+, 5 Z+, 6 X+, 7 Z-, 8 X-, 0 and 9 none. The exit move goes to the
programmed point (LinuxCNC moves no queued exit). The same numbers come out of rs274 with the tool's
orientation Q mirrored (``test_nose_compensation_rs274``).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import PostprocError
from postproc.setup.machine_setup import MachineSetup, load_setup
from tests.support.nose_tips import FINISHING_UNDER_G42, SETUPS, at_tip, controlled, one_tool

R = 0.8

PROFILE = """G18 G21 G7 G90 G94 F100
T1 M6
G0 X60 Z2
G42 G1 X40 Z2
G1 Z-10
G2 X60 Z-20 I10 K0
G1 X80
G40 G0 X100 Z5
M2
"""

def _lathe(tip: int | None) -> MachineSetup:
    return one_tool("linuxcnc_lathe.xml", 1, R, tip)


def _controlled(text: str, setup: MachineSetup) -> list[dict[str, object]]:
    return controlled(text, "linuxcnc", setup, "p.ngc")


def _expected(tip: int) -> list[dict[str, object]]:
    """The module docstring's nose centre ends (Z, radius), moved to the tip."""
    return [
        {"line": 3, "move": "rapid", "x": 60, "z": 2},
        at_tip(4, "feed", (2 - R, 20 + R), tip, R),
        at_tip(5, "feed", (-10, 20 + R), tip, R),
        at_tip(6, "cw", (-20 + R, 30), tip, R, (-10, 30)),
        at_tip(7, "feed", (-20 + R, 40), tip, R),
        {"line": 8, "move": "rapid", "x": 100, "z": 5},
    ]


@pytest.mark.parametrize("tip", range(10))
def test_every_tip_direction_moves_the_controlled_point_by_hand(tip: int) -> None:
    assert _controlled(PROFILE, _lathe(tip)) == _expected(tip)


def test_no_tip_is_the_nose_centre() -> None:
    assert _controlled(PROFILE, _lathe(None)) == _expected(0)


def test_tip_3_turns_the_programmed_diameters_and_faces() -> None:
    """The outside turning tool (tip 3): where the profile runs along Z or along X, its imaginary tip runs on
    the programmed line itself (the nose touches the diameter and the face the tip was set to)."""
    moves = _controlled(PROFILE, _lathe(3))
    turn, face = moves[2], moves[4]
    assert turn["x"] == pytest.approx(40.0) and face["z"] == pytest.approx(-20.0)


# -- a turret lathe's register, towards LinuxCNC -------------------------------------------------------

FANUC_T = """O2010
G21 G18 G40 G99
T0102
G96 S180 M03
G50 S2500
""" + FINISHING_UNDER_G42


def _turret_lathe(tip: int = 3) -> MachineSetup:
    """The Fanuc 0i-TF set-up with offset 02 holding a nose radius of ``R`` and ``tip``."""
    return one_tool("fanuc_0i_tf.xml", 2, R, tip)


def _to_linuxcnc(text: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t.nc", source="fanuc", target="linuxcnc", setup=_turret_lathe())
    return out.getvalue()


def test_turret_offset_is_the_register_of_g42_towards_linuxcnc() -> None:
    """Fanuc T's G42 compensates by the offset T0102 selected (02) [K], written as G43 H02 for its X/Z (on
    the move that applies them). LinuxCNC's own G42 would cut another path around G70's profile (its
    entry, its arcs about outer corners), so the stretch is Fanuc's compensated moves: the profile's first
    move starts it, ending square to the turn after it, nose centre (2, 10 + r), tip 3 at (2 - r, 10): X20
    Z1.2 (``test_fanuc_nose`` keeps ``G42 D02`` where both rules agree)."""
    ngc = _to_linuxcnc(FANUC_T)
    assert "T1 M6" in ngc and "G43 H02 G0 X62. Z2." in ngc  # H02 on the move that applies it (offsets' rule)
    assert "G42" not in ngc and "G0 X20. Z1.2\n" in ngc
    assert "G0 X100. Z50." in ngc


def test_roughing_cycle_under_nose_compensation_is_refused_where_it_stands() -> None:
    text = FANUC_T.replace("G0 X62. Z2.\n", "G42 G0 X62. Z2.\n", 1).replace("G42 G0 X62. Z2.\nG70", "G70")
    with pytest.raises(PostprocError) as err:
        _to_linuxcnc(text)
    assert "t.nc:8:1: error: a lathe cycle (turn rough) under tool nose radius compensation" in str(err.value)


def test_roughing_cycle_under_nose_compensation_stays_only_for_its_own_controller() -> None:
    """Fanuc to Fanuc keeps the cycle as it is (the same controller compensates it); to GSK, whose rules for
    it are not modelled, it is refused at the cycle."""
    text = FANUC_T.replace("G0 X62. Z2.\n", "G42 G0 X62. Z2.\n", 1).replace("G42 G0 X62. Z2.\nG70", "G70")
    setup = load_setup(str(SETUPS / "fanuc_0i_tf.xml"))
    same = io.StringIO()
    translate(io.StringIO(text), same, file="t.nc", source="fanuc", target="fanuc", setup=setup)
    assert "G71 P10 Q20" in same.getvalue()
    with pytest.raises(PostprocError) as err:
        translate(io.StringIO(text), io.StringIO(), file="t.nc", source="fanuc", target="gsk", setup=setup)
    assert "t.nc:8:1: error: a lathe cycle (turn rough) under tool nose radius compensation" in str(err.value)


# -- resolved for a target without compensation (grbl) ------------------------------------------------

def _to_grbl(tip: int) -> tuple[str, object]:
    from postproc.simulate.verify import verify_lines
    setup = _lathe(tip)
    out = io.StringIO()
    translate(io.StringIO(PROFILE), out, file="p.ngc", source="linuxcnc", target="grbl", setup=setup)
    report = verify_lines(io.StringIO(PROFILE), io.StringIO(out.getvalue()), file_in="p.ngc", file_out="p.nc",
                          source="linuxcnc", target="grbl", setup=setup)
    return out.getvalue(), report


@pytest.mark.parametrize("tip", range(10))
def test_grbl_gets_the_imaginary_tip_path_and_verify_agrees(tip: int) -> None:
    """grbl has no G41/G42: it gets the tip's path as plain moves (X a radius), which verify compares with
    LinuxCNC's compensated run of the source at zero deviation."""
    text, report = _to_grbl(tip)
    assert "G41" not in text and "G42" not in text and "G40" not in text
    assert report.ok and report.max_deviation < 1e-5  # type: ignore[attr-defined]


def test_grbl_resolved_turning_tool_by_hand() -> None:
    """Tip 3, r 0.8, the module docstring's points moved by (-r, -r), X a radius: the entry ends at Z 2 - 2r
    on the turned diameter, the turn at Z -10 - r, the arc (about (-10 - r, 30 - r), from the turn's end) at
    the face Z-20 and X 30 - r, the face at X 40 - r."""
    text, _ = _to_grbl(3)
    lines = [line for line in text.splitlines() if line.startswith(("G1 ", "G2 ", "G3 "))]
    assert lines == ["G1 X20. Z0.4", "G1 X20. Z-10.8", "G2 X29.2 Z-20. I9.2 K0.", "G1 X39.2 Z-20."]


# -- kept native between lathe controllers ---------------------------------------------------------------

TURNING = """O2011
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
G40 G0 X100. Z50.
M30
"""


@pytest.mark.parametrize("target,written", [("gsk", "G42 G00 X20. Z2.")])
def test_fanuc_nose_compensation_stays_native_and_verifies(target: str, written: str) -> None:
    """Fanuc T's G42 by offset 02 is GSK's G42 (the same offset columns and rules): verify simulates both
    (LinuxCNC: ``test_fanuc_nose``)."""
    from postproc.simulate.verify import verify_lines
    setup = _turret_lathe()
    out = io.StringIO()
    translate(io.StringIO(TURNING), out, file="t.nc", source="fanuc", target=target, setup=setup)
    assert written in out.getvalue()
    report = verify_lines(io.StringIO(TURNING), io.StringIO(out.getvalue()), file_in="t.nc", file_out="o.nc",
                          source="fanuc", target=target, setup=setup)
    assert report.ok and report.max_deviation == 0.0, report
    assert not any("cutter compensation" in note for note in report.ignored)


def test_a_register_is_no_word_on_a_turret_lathe() -> None:
    """LinuxCNC's G42 D1 towards GSK, on a stretch both rules cut alike (an entry in line with the turn
    after it, then an inner corner): kept as G42, but GSK's G42 reads the offset of the T code, so the D
    is refused where it stands, not written. (Where the rules differ the path is written as moves:
    ``test_fanuc_nose``.)"""
    text = ("G18 G21 G7 G90 G94\nG0 X40 Z10\nG42 D1 G1 X40 Z2 F100\nG1 Z-10\nG1 X60 Z-20\nG40 G0 X100 Z5\n"
            "M2\n")
    with pytest.raises(PostprocError) as err:
        translate(io.StringIO(text), io.StringIO(), file="l.ngc", source="linuxcnc", target="gsk", setup=_lathe(3))
    assert "l.ngc:3:1: error: the gsk dialect cannot express tool nose radius compensation by register 1" in str(err.value)


def test_a_tip_outside_0_to_9_is_a_located_set_up_error(tmp_path: Path) -> None:
    from postproc.errors import ConfigError
    xml = tmp_path / "s.xml"
    xml.write_text('<MachineSetup name="t" dialect="linuxcnc">\n  <Input machineType="lathe"/>\n'
                   '  <Machine axes="XZ"/>\n  <Tools>\n    <Tool number="2" radius="0.4" tip="12"/>\n'
                   '  </Tools>\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as err:
        load_setup(str(xml))
    assert f"{xml}:5:" in str(err.value) and "tip" in str(err.value)
