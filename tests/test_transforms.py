"""``--transform`` (issue #27 item 3): the transform text, and programs moved by it with toolpaths derived by
hand (rotation, mirror, translation, scaling; arcs, incremental moves, cutter compensation sides, hole
cycles kept native) and the located errors of what cannot be moved exactly."""

from __future__ import annotations

import io
import math
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList, UsageError
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.transforms import parse_transform


def run(text: str, source: str, target: str, transform: str, **kw: Any) -> str:
    out = io.StringIO()
    translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target, transform=transform,
              **kw)
    return out.getvalue()


def moves(text: str, dialect: str) -> list[tuple[Any, ...]]:
    """(move, x, y, z) and for arcs (cx, cy) of every move, rounded to 4 places."""
    out = []
    for e in toolpath_events(io.StringIO(text, newline=""), file="o.nc", dialect=dialect):
        if "move" in e:
            keys = ("x", "y", "z", "cx", "cy") if "cx" in e else ("x", "y", "z")
            out.append((e["move"], *(round(e[k], 4) + 0.0 for k in keys)))
    return out


def refused(text: str, source: str, target: str, transform: str) -> list[str]:
    setup = MachineSetup()
    setup.machine.axes = "XYZA"  # (a machine without A refuses an A word before any transform)
    with pytest.raises(ErrorList) as info:
        run(text, source, target, transform, setup=setup)
    return [str(e) for e in info.value.errors]


# -- the text ------------------------------------------------------------------------------------------
@pytest.mark.parametrize("text, point, expected", [
    ("translate 5,-3", (1, 2, 3), (6, -1, 3)),
    ("translate 5,-3,2", (1, 2, 3), (6, -1, 5)),
    ("rotate 90", (1, 0, 7), (0, 1, 7)),
    ("rotate 90 about 10,20", (10, 25, 0), (5, 20, 0)),  # (0,5) from the centre turns to (-5,0)
    ("rotate 90 in zx", (0, 4, 1), (1, 4, 0)),  # Z toward X: (z, x) = (1, 0) -> (0, 1)
    ("rotate 90 about 1,2 in yz", (0, 1, 2), (0, 1, 2)),  # the centre stays
    ("mirror x", (3, 4, 5), (-3, 4, 5)),
    ("mirror x about 5", (3, 4, 5), (7, 4, 5)),
    ("mirror xy about 5,1", (3, 4, 5), (7, -2, 5)),
    ("scale 2", (1, 2, 3), (2, 4, 6)),
    ("scale 2 about 1,1", (2, 3, 4), (3, 5, 8)),
    ("scale 1,2,0.5 about 0,0,2", (1, 1, 4), (1, 2, 3)),
    ("translate 1,0; rotate 90", (1, 0, 0), (0, 2, 0)),  # in the order written
    ("rotate 90; translate 1,0", (1, 0, 0), (1, 1, 0)),
    ("  Rotate 30 About 0,0 ;  mirror Y ", (2, 0, 0), (math.sqrt(3), -1, 0)),
])
def test_transform_text(text: str, point: tuple[float, float, float], expected: tuple[float, float, float]) -> None:
    got = parse_transform(text).map.point(point)
    assert got == pytest.approx(expected, abs=1e-12)


@pytest.mark.parametrize("text, message", [
    ("", "--transform is empty"),
    ("rotate 30;", "an empty operation"),
    ("spin 30", "unknown operation 'spin'"),
    ("rotate", "rotate needs an angle"),
    ("rotate 30 about 1", "'1' should be 2 comma-separated numbers"),
    ("rotate 30 about 1,2 about 3,4", "unexpected 'about'"),
    ("rotate 30 in xz", "the plane is xy, zx or yz"),
    ("rotate 30 about", "'about' needs a value"),
    ("translate 1", "'1' should be 2 to 3 comma-separated numbers"),
    ("translate 1,2 3", "expected translate"),
    ("translate 1,x", "'x' is not a number"),
    ("translate 1,nan", "'nan' is not a number"),
    ("translate 1,1e400", "out of range"),
    ("translate 1,2;G0 X5", "unknown operation 'G0'"),
    ("mirror q", "mirror takes the axes x, y and z"),
    ("mirror xx", "each once"),
    ("mirror x about 1,2", "'1,2' should be 1 comma-separated numbers"),
    ("scale 0", "a scale factor of 0"),
    ("scale 1,2", "one factor or three"),
])
def test_transform_text_refused(text: str, message: str) -> None:
    with pytest.raises(UsageError, match=message.replace("(", r"\(").replace(".", r"\.")):
        parse_transform(text)


# -- programs moved, toolpaths by hand -----------------------------------------------------------------
FANUC = """G21 G17 G90 G94
G00 X0. Y0. Z5.
G01 Z-1. F100.
G01 X10. Y0.
G02 X20. Y0. I5. J0.
G03 X10. Y0. R5.
G91 G01 X-5. Y5.
G90 G00 Z5.
M30
"""


def test_rotation_about_a_point() -> None:
    """rotate 90 about 10,0: (x, y) -> (10 - y, x - 10); arc centres turn with the points, directions stay."""
    out = run(FANUC, "fanuc", "linuxcnc", "rotate 90 about 10,0")
    assert moves(out, "linuxcnc") == [
        ("rapid", 10.0, -10.0, 5.0),
        ("feed", 10.0, -10.0, -1.0),
        ("feed", 10.0, 0.0, -1.0),
        ("cw", 10.0, 10.0, -1.0, 10.0, 5.0),
        ("ccw", 10.0, 0.0, -1.0, 10.0, 5.0),
        ("feed", 5.0, -5.0, -1.0),  # the increment (-5, 5) turned to (-5, -5)
        ("rapid", 5.0, -5.0, 5.0),
    ]


def test_mirror_turns_arcs_over() -> None:
    """mirror x about 10: x -> 20 - x; G2 becomes G3 and back, the R form keeps its radius."""
    out = run(FANUC, "fanuc", "fanuc", "mirror x about 10")
    assert moves(out, "fanuc") == [
        ("rapid", 20.0, 0.0, 5.0),
        ("feed", 20.0, 0.0, -1.0),
        ("feed", 10.0, 0.0, -1.0),
        ("ccw", 0.0, 0.0, -1.0, 5.0, 0.0),
        ("cw", 10.0, 0.0, -1.0, 5.0, 0.0),
        ("feed", 15.0, 5.0, -1.0),
        ("rapid", 15.0, 5.0, 5.0),
    ]
    assert "G03 X0. Y0. I-5. J0." in out
    assert "G02 X10. Y0. I5. J0." in out  # a half circle's R is written as its centre (NEAR_HALF)


def test_an_r_arc_keeps_its_radius() -> None:
    """A quarter circle R10 from (0, 0) to (10, 10), centre (10, 0) (clockwise), mirrored in y: G3 R10 to
    (10, -10) with its centre at (10, 0)."""
    text = "G21 G90\nG00 X0. Y0. Z0.\nG02 X10. Y10. R10. F100.\nM30\n"
    out = run(text, "fanuc", "fanuc", "mirror y")
    assert "G03 X10. Y-10. R10." in out
    assert moves(out, "fanuc")[-1] == ("ccw", 10.0, -10.0, 0.0, 10.0, 0.0)


def test_translation_and_scaling() -> None:
    """translate 1,2,3 then scale 2 about 0,0,0: p -> 2 (p + (1, 2, 3)); the R radius doubles."""
    out = run(FANUC, "fanuc", "grbl", "translate 1,2,3; scale 2")
    assert moves(out, "grbl") == [
        ("rapid", 2.0, 4.0, 16.0),
        ("feed", 2.0, 4.0, 4.0),
        ("feed", 22.0, 4.0, 4.0),
        ("cw", 42.0, 4.0, 4.0, 32.0, 4.0),
        ("ccw", 22.0, 4.0, 4.0, 32.0, 4.0),
        ("feed", 12.0, 14.0, 4.0),
        ("rapid", 12.0, 14.0, 16.0),
    ]


def test_an_omitted_coordinate_comes_from_the_program_position() -> None:
    """Under a rotation ``X5.`` moves X and Y: the omitted Y is the program's (2)."""
    text = "G21 G90\nG00 X0. Y2. Z0.\nG01 X5. F50.\nM30\n"
    out = run(text, "fanuc", "linuxcnc", "rotate 90")
    assert moves(out, "linuxcnc")[-1] == ("feed", -2.0, 5.0, 0.0)


def test_the_active_work_system_selected_again_keeps_the_position() -> None:
    text = "G21 G90\nG54 G00 X0. Y2. Z0.\nG54\nG01 X5. F50.\nM30\n"
    assert moves(run(text, "fanuc", "linuxcnc", "rotate 90"), "linuxcnc")[-1] == ("feed", -2.0, 5.0, 0.0)


def test_cutter_compensation_side_swaps_under_a_mirror() -> None:
    text = "G21 G90\nG00 X0. Y0. Z0.\nG41 D1 G01 X10. F50.\nG40 G00 X0.\nM30\n"
    out = run(text, "fanuc", "fanuc", "mirror y")
    assert "G42" in out and "G41" not in out
    assert "G41" in run(text, "fanuc", "fanuc", "rotate 45")


def test_a_hole_cycle_stays_a_cycle() -> None:
    """translate 10,0,-2 then rotate 90: the hole (5, 0) -> (0, 15); R and Z levels shift by -2; the peck
    depth Q and the dwell stay; the cycle is still written as G83."""
    text = "G21 G90 G17\nG00 X0. Y0. Z10.\nG99 G83 X5. Y0. Z-10. R2. Q3. F100.\nY5.\nG80\nM30\n"
    out = run(text, "fanuc", "fanuc", "translate 10,0,-2; rotate 90")
    assert "G83 X0. Y15. Z-12. R0. Q3. F100." in out.replace("X-0.", "X0.")
    assert "\nX-5.\n" in out  # the repeat's Y5. moves only X under the quarter turn: (15, 5) -> (-5, 15)
    holes = [m for m in moves(out, "fanuc") if m[0] == "feed" or m[3] == -12.0]
    assert {(m[1], m[2]) for m in holes} == {(0.0, 15.0), (-5.0, 15.0)}


def test_incremental_cycle_levels_scale_without_the_shift() -> None:
    """Under G91 a cycle's R and Z are distances: scaled, not shifted."""
    text = "G21 G90 G17\nG00 X0. Y0. Z10.\nG91 G99 G81 X5. Y0. Z-4. R-8. F100.\nG90 G80\nM30\n"
    out = run(text, "fanuc", "fanuc", "translate 0,0,7; scale 2")
    assert "G81 X10. Y0. Z-8. R-16." in out


@pytest.mark.parametrize("text, transform, message", [
    (FANUC, "scale 1,2,1", "t.nc:5:1: error: an arc in the XY plane cannot be transformed by this map"),
    (FANUC, "rotate 30 in zx", "t.nc:5:1: error: an arc in the XY plane cannot be transformed by this map"),
    ("G21 G90\nG00 X0. Y0. Z10.\nG81 X1. Y1. Z-1. R1. F50.\nG80\nM30\n", "rotate 10 in yz",
     "t.nc:3:1: error: a hole cycle in the XY plane cannot be transformed by a map that tilts or turns over"),
    ("G21 G90\nG00 X0. Y0. Z10.\nG81 X1. Y1. Z-1. R1. F50.\nG80\nM30\n", "mirror z",
     "t.nc:3:1: error: a hole cycle in the XY plane cannot be transformed by a map that tilts or turns over"),
    ("G21 G90\nG00 X0. Y0. Z10.\nG83 X1. Y1. Z-9. R1. Q2. F50.\nG80\nM30\n", "scale 2",
     "t.nc:3:1: error: a peck drilling cycle cannot be transformed by a map that scales its drilling axis Z"),
    ("G21 G90\nG00 X0. Y0. Z0.\nG55\nG01 X5. F50.\nM30\n", "rotate 30",
     "t.nc:4:1: error: this move's X under the transform needs the program's Y, which is not known here"),
    ("G21 G90\nG53 G00 X0. Y0.\nM30\n", "translate 1,0",
     "t.nc:2:1: error: a move to machine coordinates or a reference point on X cannot be transformed"),
    ("G21 G90\nG00 X0. Y0. Z5.\nG91 G28 Z0.\nG90 G01 X5. F50.\nG91 G01 Z-1.\nM30\n", "translate 0,0,-1",
     "t.nc:5:1: error: this move starts from a machine position on Z (the start or a reference return)"),
    ("G21 G90\nG91 G28 Z0.\nG90 G01 X10. F50.\nM30\n", "rotate 30 in zx",
     "t.nc:3:1: error: this move's X under the transform needs the program's Z, which is not known here"),
    ("G21 G90\nG91 G28 Z5.\nM30\n", "translate 0,0,-1",
     "t.nc:2:1: error: this reference return's intermediate point is an increment from a machine position on Z"),
    ("G21 G90\nG00 X0. Y0. Z5.\nG28 X10.\nM30\n", "rotate 30",
     "t.nc:3:1: error: this reference return's intermediate point moves Y under the transform, which it does not "
     "return"),

    ("G21 G90 G00 X0. Y0. A10.\nM30\n", "rotate 5",
     "t.nc:1:1: error: the A axis under a transform that rotates, mirrors or scales cannot be transformed"),
])
def test_refused_at_the_line(text: str, transform: str, message: str) -> None:
    assert any(e.startswith(message) for e in refused(text, "fanuc", "fanuc", transform)), refused(
        text, "fanuc", "fanuc", transform)


def test_the_program_s_own_frames_are_evaluated_first() -> None:
    """Back to its own dialect too: G52 X5. then X1. is work X6., moved by translate 1,0 to X7."""
    text = "G21 G90\nG00 X0. Y0. Z0.\nG52 X5.\nG00 X1. Y1.\nG52 X0.\nM30\n"
    out = run(text, "fanuc", "fanuc", "translate 1,0")
    assert "G52" not in out.replace("(G52 X5. evaluated)", "").replace("(G52 X0. evaluated)", "")
    assert moves(out, "fanuc")[-1] == ("rapid", 7.0, 1.0, 0.0)


def test_a_reference_return_on_an_axis_the_map_leaves_alone_passes() -> None:
    text = "G21 G90\nG00 X1. Y0. Z5.\nG91 G28 Z0.\nM30\n"
    assert "G28 Z0." in run(text, "fanuc", "fanuc", "rotate 30 about 4,4")


def test_a_macro_program_is_flattened() -> None:
    """A loop's computed words cannot be moved symbolically: the target gets the flattened moves."""
    text = "G21 G90 G00 X0. Y0. Z1.\n#1=0\nWHILE [#1 LT 3] DO1\nG01 X[#1*10] F100.\n#1=#1+1\nEND1\nM30\n"
    out = run(text, "fanuc", "linuxcnc", "translate 0,5")
    code = [line for line in out.splitlines() if not line.startswith("(")]
    assert not any("#" in line or "WHILE" in line for line in code)
    assert [m[1:3] for m in moves(out, "linuxcnc")] == [(0.0, 5.0), (10.0, 5.0), (20.0, 5.0)]  # G1 X0 stays put


def test_travel_limits_are_checked_on_the_moved_program() -> None:
    """The VMC's X travels -800..0 with G54 at X-400: the plate fits, moved 900 mm it does not (machine X
    -400 + 15 + 900 = 515); the error names the moved program."""
    from pathlib import Path
    from postproc.setup.machine_setup import load_setup
    root = Path(__file__).resolve().parent.parent
    setup = root / "examples" / "setups" / "fanuc_0i_mf_vmc.xml"
    text = (root / "examples" / "fanuc" / "o1001_plate_drill_tap.nc").read_text()
    run(text, "fanuc", "fanuc", "translate 10,0", setup=load_setup(str(setup)))
    with pytest.raises(ErrorList) as info:
        run(text, "fanuc", "fanuc", "translate 900,0", setup=load_setup(str(setup)))
    assert str(info.value.errors[0]).startswith(
        "t.nc (moved by --transform):13:13: error: X+515.000 mm beyond the limit 0.000")


def test_moved_then_converted() -> None:
    """An inch program moved by 25.4 mm (1 in) in X, then written in mm: X1. -> 2 in = 50.8 mm."""
    text = "G20 G90\nG00 X1. Y0.5 Z0.1\nM30\n"
    out = run(text, "fanuc", "fanuc", "translate 25.4,0", units="mm")
    assert out.splitlines()[:2] == ["G21 G90", "G00 X50.8 Y12.7 Z2.54"]


def test_a_reference_return_stays_and_holds_its_axis_at_the_reference_point() -> None:
    """G91 G28 Z0. under a shift of Z: written as it was (the reference point is a machine position); the XY
    move after it leaves Z there (at the reference point, 0 here: no <Axis home>), the next Z is a program
    point again, moved. By hand: Z50 -> 49; G28 -> Z0; X10 Y0 -> (13, -2) at Z0; Z5 -> 4."""
    text = "G21 G90 G17\nG00 X0. Y0. Z50.\nG91 G28 Z0.\nG90 G00 X10. Y0.\nG00 Z5.\nM30\n"
    out = run(text, "fanuc", "fanuc", "translate 3,-2,-1")
    assert "G91 G28 Z0.\nG90 G00 X13. Y-2.\nG00 Z4." in out, out
    assert moves(out, "fanuc") == [("rapid", 3, -2, 49), ("rapid", 3, -2, 0), ("rapid", 13, -2, 0),
                                   ("rapid", 13, -2, 4)]
    from postproc.simulate.verify import verify_lines
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="fanuc",
                          target="fanuc", transform=parse_transform("translate 3,-2,-1"))
    assert report.ok, report.summary()
    moved = out.replace("G91 G28 Z0.\n", "G90 G00 Z-1.\n")  # a return moved with the program fails verify
    assert not verify_lines(io.StringIO(text), io.StringIO(moved), file_in="a", file_out="b", source="fanuc",
                            target="fanuc", transform=parse_transform("translate 3,-2,-1")).ok
