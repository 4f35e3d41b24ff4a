"""SINUMERIK ``TURN=`` (``dialects/siemens/helix.py``): a helix's additional full circles.

Expected points are worked out by hand from the manual's motion sequence (ONE NC programming 12/2019, 2.9.7: the
full circles first, then the arc to the end point, Z in proportion to the angle turned); the comments give the
arithmetic. ``examples/siemens/helix.mpf`` runs in LinuxCNC's interpreter (``test_siemens_oracle``).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

ZERO_TOOLS = Path(__file__).resolve().parent / "support" / "zero_tools.xml"
START = "G17 G710 G90 G0 X0 Y50 Z50\nG1 F300\n"


def _translate(text: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.mpf", source="siemens", target=target,
              setup=load_setup(str(ZERO_TOOLS)), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _ends(text: str) -> list[tuple[str, float, float, float]]:
    events = toolpath_events(io.StringIO(text), file="in.mpf", dialect="siemens", setup=load_setup(str(ZERO_TOOLS)))
    return [(e["move"], round(float(e["x"]), 6), round(float(e["y"]), 6), round(float(e["z"]), 6))
            for e in events if "move" in e]


def test_the_manuals_helix_makes_its_full_circles_then_the_arc_to_the_end() -> None:
    """From (0, 50, 50) about (0, 25) counter-clockwise to (0, 0, 33): the arc is 180 degrees, with TURN=3 the
    helix turns 3 * 360 + 180 = 1260 degrees; Z falls 17 in proportion, 17 * 360 / 1260 = 4.857143 a circle."""
    ends = _ends(START + "G3 X0 Y0 Z33 I0 J-25 TURN=3\nM30\n")
    arcs = [e for e in ends if e[0] == "arc"] or ends[1:]
    points = [(x, y, z) for _, x, y, z in arcs]
    assert points[-4:] == [(0, 50, 45.142857), (0, 50, 40.285714), (0, 50, 35.428571), (0, 0, 33)], ends


def test_a_clockwise_helix_with_one_turn() -> None:
    """From (10, 0, 33) about (20, 0) clockwise to (20, 10): 90 degrees, 450 with TURN=1; Z falls 3, 2.4 of it
    in the full circle."""
    ends = _ends("G17 G710 G90 G0 X10 Y0 Z33\nG2 X20 Y10 Z30 I10 J0 TURN=1 F100\nM30\n")
    assert [(x, y, z) for _, x, y, z in ends[-2:]] == [(10, 0, 30.6), (20, 10, 30)], ends


def test_turn_0_is_the_plain_arc() -> None:
    assert _ends(START + "G3 X0 Y0 Z33 I0 J-25 TURN=0\nM30\n") == _ends(START + "G3 X0 Y0 Z33 I0 J-25\nM30\n")


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl", "siemens"])
def test_a_helix_translates_exactly(target: str) -> None:
    text = START + "G3 X0 Y0 Z33 I0 J-25 TURN=3\nG1 X10\nG2 X20 Y10 Z30 I10 J0 TURN=1\nX30 Y0 I0 J-10\nM30\n"
    out = _translate(text, target)
    if target == "siemens":
        assert out == text
        return
    assert out.count("J-25.") == 4, out  # three full circles and the last arc
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source="siemens",
                          target=target, setup=load_setup(str(ZERO_TOOLS)), tolerance=0.0)
    assert report.ok and report.max_deviation == 0, report.summary() + "\n" + out


@pytest.mark.parametrize("line, name", [
    ("G3 X0 Y0 Z33 CR=25 TURN=2", "TURN= with CR="),
    ("G18 G3 X0 Z33 I0 K-25 TURN=2", "TURN= in another plane than G17"),
    ("G91 G3 X0 Y-50 Z-17 I0 J-25 TURN=2", "TURN= in G91"),
    ("G3 X0 Y0 Z33 I0 J-25 TURN=R1", "TURN= with a computed value"),
])
def test_a_helix_not_read_is_kept_verbatim_and_refused_elsewhere_by_name(line: str, name: str) -> None:
    text = START + "R1=2\n" + line + "\nM30\n"
    assert _translate(text, "siemens") == text
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc")
    assert name in str(caught.value.errors[0]), [str(e) for e in caught.value.errors]


@pytest.mark.parametrize("line, message", [
    ("G3 X0 Y0 Z33 I0 J-25 TURN=1.5", "in.mpf:3:22: error: TURN=1.5: a whole number of full circles from 0 to 999"),
    ("G3 X0 Y0 Z33 I0 J-25 TURN=1000", "in.mpf:3:22: error: TURN=1000: a whole number"),
    ("G3 X0 Y0 Z33 I0 J-25 TURN=1 TURN=2", "in.mpf:3:29: error: TURN appears twice in one block"),
    ("G1 X0 Y0 Z33 TURN=1", "in.mpf:3:14: error: TURN= counts the full circles of a helix: G2 or G3"),
])
def test_a_bad_turn_is_a_located_error(line: str, message: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(START + line + "\nM30\n", "fanuc")
    assert str(caught.value.errors[0]).startswith(message), [str(e) for e in caught.value.errors]
