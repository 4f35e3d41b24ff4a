"""SINUMERIK ``AR=`` (a circle by its opening angle, with its centre or its end point): hand-derived arcs,
translations verified, LinuxCNC's interpreter (``examples/siemens/opening_angle.mpf`` in
``test_siemens_oracle``)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

ARCS = ("G710 G17 G90 G0 X10 Y0 Z0\nG3 I-10 J0 AR=90 F100\nG2 X10 Y0 AR=90\nG91 G3 X-10 Y10 AR=270\n"
        "G90 G2 I0 J-5 AR=180\nG3 X20 Y0 AR=90 Z-2\nM30\n")


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def test_an_arc_by_opening_angle_moves_as_derived_by_hand() -> None:
    arcs = [(e["move"], e["x"], e["y"], e["z"], e["cx"], e["cy"])
            for e in toolpath_events(io.StringIO(ARCS), file="in.mpf", dialect="siemens") if "cx" in e]
    assert arcs == [
        # from (10, 0) round the centre (10-10, 0) = (0, 0), 90 degrees counter-clockwise: (0, 10)
        ("ccw", 0, 10, 0, 0, 0),
        # (0, 10) to (10, 0) clockwise over 90 degrees: the chord is 10*sqrt2, the radius 10, the centre (0, 0)
        ("cw", 10, 0, 0, 0, 0),
        # G91: (10, 0) to (0, 10) counter-clockwise over 270 degrees: the centre right of the chord, (10, 10)
        ("ccw", 0, 10, 0, 10, 10),
        # round (0, 10-5) = (0, 5), 180 degrees clockwise: (0, 0)
        ("cw", 0, 0, 0, 0, 5),
        # (0, 0) to (20, 0) counter-clockwise over 90 degrees with Z: radius 10*sqrt2, the centre left of the way
        # (+X, so +Y): (10, 10); a helix
        ("ccw", 20, 0, -2, 10, 10)]


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "siemens"])
def test_an_arc_by_opening_angle_translates_exactly(target: str) -> None:
    out = _translate(ARCS, target)
    if target == "siemens":
        assert out == ARCS
        return
    report = verify_lines(io.StringIO(ARCS), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target=target, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out


@pytest.mark.parametrize("line, message", [
    ("G3 I-10 J0 AR=0", "2:12: error: AR=0: the opening angle is more than 0 and less than 360 degrees"),
    ("G3 I-10 J0 AR=360", "AR=360: the opening angle is more than 0 and less than 360"),
    ("G3 X0 Y10 I-10 AR=90", "AR= takes either the centre (I, J) or the end point (X, Y), not both"),
    ("G3 AR=90", "AR= takes either the centre (I, J) or the end point (X, Y), not both or neither"),
    ("G1 X0 Y10 AR=90", "AR= is the opening angle of a circle: G2 or G3 is in force with it"),
    ("G3 X0 Y10 CR=10 AR=90", "AR= with CR= or K"),
    ("G3 X10 Y0 AR=90", "AR= with the end point at the start point makes no circle"),
    ("G18 G3 I-10 K0 AR=90", "AR= is read in G17 (the XY plane) only"),
    ("G3 I-10 J0 AR=90 AR=45", "AR appears twice in one block"),
])
def test_a_bad_opening_angle_is_a_located_error(line: str, message: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(f"G710 G17 G90 G0 X10 Y0 Z0 F100\n{line}\nM30\n", "linuxcnc")
    assert any(message in str(e) for e in caught.value.errors), caught.value.errors


@pytest.mark.parametrize("line, name", [("G3 I-10 J0 AR=R1", "AR= with a computed angle"),
                                        ("G3 X=R1 Y0 AR=90", "AR= with computed coordinates")])
def test_a_computed_opening_angle_is_kept_verbatim(line: str, name: str) -> None:
    text = f"G710 G17 G90 G0 X10 Y0 Z0 F100\nR1=90\n{line}\nM30\n"
    assert _translate(text, "siemens") == text
    with pytest.raises(ErrorList) as caught:
        _translate(text, "linuxcnc")
    assert name in str(caught.value.errors[0])


# -- CIP: a circle through an intermediate point -------------------------------------------------------------

CIP = ("G710 G17 G90 G0 X10 Y0 Z0\nG1 F100\nCIP X-10 Y0 I1=0 J1=10\nCIP X10 Y0 I1=0 J1=-10\n"
       "CIP X0 Y10 I1=7 J1=7 Z0\nG1 X30\nM30\n")


def test_a_circle_through_an_intermediate_point_moves_as_derived_by_hand() -> None:
    moves = [(e["move"], e["x"], e["y"], e.get("cx"), e.get("cy"))
             for e in toolpath_events(io.StringIO(CIP), file="in.mpf", dialect="siemens") if "move" in e]
    assert moves == [
        ("rapid", 10, 0, None, None),
        # (10, 0) through (0, 10) to (-10, 0): the circle round (0, 0), turning left (counter-clockwise)
        ("ccw", -10, 0, 0, 0),
        # (-10, 0) through (0, -10) to (10, 0): round (0, 0), turning left again
        ("ccw", 10, 0, 0, 0),
        # (10, 0) through (7, 7) to (0, 10): |(7, 7) - (0, 0)| is not 10, so the centre is not (0, 0): the
        # perpendicular bisector of (10,0)-(0,10) is y = x; the centre (c, c) is as far from (10, 0) as from
        # (7, 7): (c-10)^2 + c^2 = 2 (c-7)^2, so -20c + 100 = -28c + 98, c = -0.25
        ("ccw", 0, 10, -0.25, -0.25),
        # G1 ends CIP: a straight feed from (0, 10)
        ("feed", 30, 10, None, None)]


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "siemens"])
def test_a_circle_through_an_intermediate_point_translates_exactly(target: str) -> None:
    out = _translate(CIP, target)
    if target == "siemens":
        assert out == CIP
        return
    report = verify_lines(io.StringIO(CIP), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target=target, tolerance=0.0)
    assert report.ok, report.summary() + "\n" + out


@pytest.mark.parametrize("lines, name", [
    ("CIP X-10 Y0 I1=0 J1=10\nX20", "a move under CIP without its own intermediate point"),
    ("CIP X-10 Y0 Z5 I1=0 J1=10 K1=2", "CIP off the XY plane, in G91 or without its intermediate point"),
    ("G91\nCIP X-20 Y0 I1=-10 J1=10", "CIP off the XY plane, in G91"),
    ("G3 CIP X-10 Y0 I1=0 J1=10", "CIP (a circle through an intermediate point)"),
    ("CIP X-10 Y0 I1=0", "without its intermediate point I1, J1"),
    ("CIP X-10 Y0 I1=R1 J1=10", "I1= with a computed value"),
])
def test_a_circle_through_a_point_that_is_not_read_is_kept_verbatim(lines: str, name: str) -> None:
    text = f"G710 G17 G90 G0 X10 Y0 Z0\nG1 F100\nR1=0\n{lines}\nG1 X0\nM30\n"
    assert _translate(text, "siemens") == text
    with pytest.raises(ErrorList) as caught:
        _translate(text, "linuxcnc")
    assert any(name in str(e) for e in caught.value.errors), caught.value.errors


@pytest.mark.parametrize("line, message", [
    ("CIP X30 Y0 I1=20 J1=0", "3:1: error: CIP: the start, the intermediate point and the end point lie on one line"),
    ("CIP X-10 Y0 I1=0 J1=10 I1=1", "I1 appears twice in one block"),
])
def test_a_bad_circle_through_a_point_is_a_located_error(line: str, message: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(f"G710 G17 G90 G0 X10 Y0 Z0\nG1 F100\n{line}\nM30\n", "linuxcnc")
    assert any(message in str(e) for e in caught.value.errors), caught.value.errors
