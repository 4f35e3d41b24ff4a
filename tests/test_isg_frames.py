"""ISG (Beckhoff TwinCAT CNC) ``G68 R.. X.. Y..`` / ``G69``: the contour rotation in G17, G18 and G19, read on the
neutral frame change under the ``isg`` rules (``postproc/frames/lowering.py`` ``isg_rotate``) [V: TF5200
programming manual, "Rotate the coordinate system in the plane (G68/G69)"; K: the sense in G18/G19, from the
plane's first main axis toward its second].

Expected points by hand: program (x, y) turned by a about (cx, cy) is
(cx + (x-cx) cos a - (y-cy) sin a, cy + (x-cx) sin a + (y-cy) cos a), with (x, y) the plane's first and second
main axes (G18: Z, X; G19: Y, Z). The LinuxCNC translations are run by rs274.
"""

from __future__ import annotations

import io
import math
import random
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.frame_programs import centre_arc, radius_arc
from tests.support.rs274 import assert_same_moves, available, canonical_moves, run_rs274

HEAD = "N1 G71 G90 G17 G00 X0 Y0 Z0\n"


def _translate(text: str, target: str, warnings: io.StringIO | None = None) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="isg", target=target,
              diagnostics=Diagnostics(warn_stream=warnings or io.StringIO()))
    return out.getvalue()


def _errors(text: str, target: str = "linuxcnc") -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, target)
    return [str(e) for e in caught.value.errors]


def _events(text: str) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect="isg") if "move" in e]


def _points(body: str) -> list[tuple[Any, ...]]:
    return [(e["move"], round(e["x"], 6) + 0.0, round(e["y"], 6) + 0.0) for e in _events(HEAD + body + "M30\n")]


def _turned(x: float, y: float, a: float, cx: float, cy: float) -> tuple[float, float]:
    c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
    return round(cx + (x - cx) * c - (y - cy) * s, 6) + 0.0, round(cy + (x - cx) * s + (y - cy) * c, 6) + 0.0


def test_g68_turns_the_programmed_points_about_its_centre() -> None:
    # R90 about (10, 0): (20, 0) -> (10, 10); G91 X5: the increment turned, (0, 5) -> (10, 15); G69: (20, 0) as written
    assert _points("G68 R90 X10 Y0\nG01 X20 Y0 F100\nG91 X5\nG90 G69\nG01 X20 Y0\n") == [
        ("feed", 10, 10), ("feed", 10, 15), ("feed", 20, 0)]


def test_a_second_g68_replaces_the_angle_and_r_is_absolute() -> None:
    # R30 about (0, 0), then R45 about (0, 0): the second is 45 degrees, not 75
    assert _points("G68 R30 X0 Y0\nG01 X10 Y0 F100\nG68 R45 X0 Y0\nG01 X10 Y0\n") == [
        ("feed", *_turned(10, 0, 30, 0, 0)), ("feed", *_turned(10, 0, 45, 0, 0))]


def test_an_omitted_centre_is_the_current_position_and_r_omitted_is_zero() -> None:
    # the tool at (5, 5): G68 R60 turns about it; G68 X0 Y0 without R: 0 degrees
    assert _points("G01 X5 Y5 F100\nG68 R60\nG01 X15 Y5\nG68 X0 Y0\nG01 X15 Y5\n") == [
        ("feed", 5, 5), ("feed", *_turned(15, 5, 60, 5, 5)), ("feed", 15, 5)]


def test_an_arc_keeps_its_centre_and_direction() -> None:
    # R90 about (0, 0): G02 from (10, 0) to (0, -10) about (0, 0) becomes G02 from (0, 10) to (10, 0) about (0, 0)
    arcs = [(e["move"], round(e["x"], 6) + 0.0, round(e["y"], 6) + 0.0, round(e["cx"], 6) + 0.0,
             round(e["cy"], 6) + 0.0) for e in _events(HEAD + "G01 X10 Y0 F100\nG68 R90 X0 Y0\nG01 X10 Y0\n"
                                                         "G02 X0 Y-10 I-10 J0\nM30\n") if e["move"] == "cw"]
    assert arcs == [("cw", 10, 0, 0, 0)]


def test_a_plane_change_ends_the_rotation_with_a_warning() -> None:
    warnings = io.StringIO()
    text = HEAD + "G68 R90 X0 Y0\nG01 X10 Y0 F100\nG18\nG17\nG01 X10 Y0\nM30\n"
    out = _translate(text, "linuxcnc", warnings)
    assert "the plane change ends the coordinate rotation" in warnings.getvalue()
    assert _points("G68 R90 X0 Y0\nG01 X10 Y0 F100\nG18\nG17\nG01 X10 Y0\n") == [("feed", 0, 10), ("feed", 10, 0)]
    _verify(text, out, "linuxcnc")


def test_what_is_not_settled_or_not_allowed_is_refused() -> None:
    assert "Z belongs in the next block" in _errors(HEAD + "G68 R30 X0 Y0 Z5\nM30\n")[0]
    assert "Y belongs in the next block" in _errors(HEAD + "G18\nG68 R30 Z0 X0 Y1\nM30\n")[0]
    assert "program Z and X" in _errors(HEAD + "G18\nG68 R30 Z0 X0\nG68 R40 Z1\nM30\n")[0]
    assert "without its centre while a rotation is on" in _errors(HEAD + "G68 R30 X0 Y0\nG68 R40\nM30\n")[0]
    assert "with cutter compensation on" in _errors(
        HEAD + "D1\nG41 G01 X10 Y0 F100\nG68 R30 X0 Y0\nG01 X20\nG40 G01 X0 Y0\nM30\n")[0]


def _plane_points(body: str) -> list[tuple[Any, ...]]:
    return [(e["move"], *(round(e[k], 6) + 0.0 for k in ("x", "y", "z"))) for e in _events(HEAD + body + "M30\n")]


def test_g68_in_g18_turns_from_z_toward_x() -> None:
    # R90 about (Z0, X0): (Z10, X0) -> (Z0, X10); (Z10, X5) -> (Z-5, X10); G91 Z5 turned: X + 5; G69: as written
    assert _plane_points("G18\nG68 R90 Z0 X0\nG01 Z10 X0 F100\nZ10 X5\nG91 Z5\nG90\nG69\nG01 Z10 X0\n") == [
        ("feed", 10, 0, 0), ("feed", 10, 0, -5), ("feed", 15, 0, -5), ("feed", 0, 0, 10)]
    # R30 about (Z2, X4): (Z12, X4) -> Z 2 + 10 cos 30, X 4 + 10 sin 30
    z, x = _turned(12, 4, 30, 2, 4)
    assert _plane_points("G18\nG68 R30 Z2 X4\nG01 Z12 X4 F100\n") == [("feed", x, 0, z)]


def test_g68_in_g19_turns_from_y_toward_z_and_keeps_an_arc_s_centre_and_direction() -> None:
    # R90 about (Y0, Z0): (Y10, Z0) -> (Y0, Z10); G02 to (Y0, Z10) about (0, 0) -> G02 to (Y-10, Z0) about (0, 0)
    events = _events(HEAD + "G19\nG68 R90 Y0 Z0\nG01 Y10 Z0 F100\nG02 Y0 Z10 J-10 K0\nG69\nM30\n")
    assert [(e["move"], e["x"], e["y"], e["z"]) for e in events] == [("feed", 0, 0, 10), ("cw", 0, -10, 0)]
    assert (events[1]["cy"], events[1]["cz"], events[1]["plane"]) == (0, 0, "YZ")


def test_rotation_on_with_its_centre_at_the_origin_is_the_contour_rotation() -> None:
    # [V] TF5200 "#ROTATION ON/OFF": G68's rotation spelled otherwise; ANGLE 90 about the origin: (10, 0) -> (0, 10);
    # OFF: as written; in G18 (Z10, X0) -> (Z0, X10); ANGLE without '=' as the manual's example writes it
    assert _points("#ROTATION ON [ANGLE=90 CENTER1=0 CENTER2=0]\nG01 X10 Y0 F100\n#ROTATION OFF\nG01 X10 Y0\n") == [
        ("feed", 0, 10), ("feed", 10, 0)]
    assert _points("#ROTATION ON [ANGLE=30 CENTER1=0 CENTER2=0]\nG01 X10 Y5 F100\nG69\nG01 X0 Y0\n") == [
        ("feed", *_turned(10, 5, 30, 0, 0)), ("feed", 0, 0)]
    assert _plane_points("G18\n#ROTATION ON [ANGLE -90, CENTER1=0 CENTER2=0]\nG01 Z10 X0 F100\n") == [
        ("feed", -10, 0, 0)]


def test_rotation_on_is_kept_verbatim_where_its_meaning_is_not_settled() -> None:
    text = HEAD + "#ROTATION ON [ANGLE=30 CENTER1=0 CENTER2=0]\nG01 X10 Y0 F100\n#ROTATION OFF\nM30\n"
    assert _translate(text, "isg") == text
    out = _translate(text, "grbl")
    _verify(text, out, "grbl")
    for command in ("#ROTATION ON [ANGLE=30 CENTER1=10 CENTER2=0]", "#ROTATION ON [ANGLE=30]", "#ROTATION ON",
                    "#ROTATION ON [ANGLE=P1 CENTER1=0 CENTER2=0]", "#ROTATION ON [ANGLE=30 CENTER1=0 CENTER2=0 X=1]"):
        kept = HEAD + command + "\nG01 X10 Y0 F100\nM30\n"
        assert _translate(kept, "isg") == kept
        assert f"in.nc:2:1: error: {command.split(' [')[0]} from isg has no equivalent in linuxcnc" in \
            _errors(kept)[0], command


@pytest.mark.parametrize("target", ["fanuc", "siemens", "fagor", "grbl", "grblhal"])
def test_rotation_about_an_unsettled_centre_is_refused_by_name_everywhere_but_isg(target: str) -> None:
    """[?] TF5200 "#ROTATION ON/OFF" says only "offset of the first/second main axis relative to the centre of
    rotation" (its sign is in a figure): a non-zero CENTER1/CENTER2 is neither translated nor simulated."""
    from postproc.plugins import default_registry
    if target not in default_registry().dialects:
        pytest.skip(f"the {target} plugin is not installed")
    command = "#ROTATION ON [ANGLE=30 CENTER1=10 CENTER2=5]"
    kept = HEAD + command + "\nG01 X10 Y0 F100\n#ROTATION OFF\nM30\n"
    assert _errors(kept, target)[0] == f"in.nc:2:1: error: #ROTATION ON from isg has no equivalent in {target}"
    with pytest.raises(ErrorList) as caught:
        _events(kept)
    assert [str(e) for e in caught.value.errors] == ["in.nc:2:1: error: #ROTATION ON cannot be simulated"]


def test_isg_to_isg_keeps_g68_as_written() -> None:
    text = HEAD + "G68 R30 X1 Y2\nG01 X10 Y0 F100\nG69\nM30\n"
    assert _translate(text, "isg") == text


def _verify(a: str, b: str, target: str) -> None:
    report = verify_lines(io.StringIO(a), io.StringIO(b), file_in="a", file_out="b", source="isg", target=target,
                          tolerance=1e-3)
    assert report.ok, report.summary() + "\n--- a\n" + a + "--- b\n" + b


_PLANES = {"G17": ("X", "Y", "Z", "I", "J"), "G18": ("Z", "X", "Y", "K", "I"), "G19": ("Y", "Z", "X", "J", "K")}
"""Plane code -> its first, second and third axis and the centre words of the first two."""


def _program(seed: int) -> str:
    """Rotations, moves and arcs in one plane per program (G17 for seeds 0-9, as before; then G18 and G19
    too): a plane change would end the rotation with a warning."""
    rng = random.Random(seed)
    code = "G17" if seed < 10 else rng.choice(list(_PLANES))
    a1, a2, a3, i1, i2 = _PLANES[code]
    lines = ["%frames", f"N1 G71 G90 G17 G00 X0 Y0 Z5", code]
    spelled = seed >= 10 and rng.random() < 0.5  # #ROTATION ON/OFF, its centre at the origin, in place of G68/G69
    for _ in range(rng.randint(2, 5)):
        if rng.random() < 0.2:
            lines.append("#ROTATION OFF" if spelled else "G69")
        elif spelled:
            lines.append(f"#ROTATION ON [ANGLE={rng.uniform(-180, 180):.3f} CENTER1=0 CENTER2=0]")
        else:
            lines.append(f"G68 R{rng.uniform(-180, 180):.3f} {a1}{rng.randint(-20, 20)} {a2}{rng.randint(-20, 20)}")
        x, y = rng.randint(-20, 20), rng.randint(-20, 20)
        lines.append(f"G01 {a1}{x} {a2}{y} {a3}{rng.randint(-3, 3)} F{rng.randint(50, 500)}")
        kind = rng.choice(["r", "ij", "incremental"])
        if kind == "r":
            ex, ey, radius = radius_arc(rng, x, y)
            lines.append(f"G0{rng.choice('23')} {a1}{ex} {a2}{ey} R{radius:.4f}")
        elif kind == "ij":
            fx, fy, i, j = centre_arc(rng, x, y)
            lines.append(f"G0{rng.choice('23')} {a1}{fx:.4f} {a2}{fy:.4f} {i1}{i} {i2}{j}")
        else:
            lines.append(f"G91 G01 {a1}{rng.randint(-5, 5)} {a2}{rng.randint(-5, 5)}\nG90")
    lines += ["G69", "G00 Z50", "M30"]
    return "\n".join(lines) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(30))
def test_a_random_rotated_program_moves_in_rs274_as_its_isg_toolpath(seed: int) -> None:
    text = _program(seed)
    out = _translate(text, "linuxcnc")
    theirs = [e for e in canonical_moves(run_rs274(out), start=(0.0, 0.0, 0.0)) if "move" in e]
    assert_same_moves(_events(text), theirs, text, out)
    _verify(text, _translate(text, "grbl"), "grbl")
