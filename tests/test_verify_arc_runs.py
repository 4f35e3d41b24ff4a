"""verify's arc runs (``postproc.simulate.runs.merge_arc``): consecutive arcs are one run when they cut one
circle, judged by the path, not by the centres alone. Found by the held-out set (issue 26): CamBam's helical bores
(``tests/heldout/mach3/ugs_cambam_ordbot_handle.nc``) begin each turn with an arc of 0.0123 mm whose end radius is
0.00003 mm off its start radius; ISG and Fagor move that arc's centre onto its chord's bisector, 0.00087 mm away
(``postproc.geometry.arc_end``), and cut the same circle within a micron. By centres alone the source's helix was one run
and the translation's was split at every such arc: verify said the structure differs, where the paths are the
same."""

from __future__ import annotations

import io
import math

import pytest

from postproc.api import translate
from postproc.simulate.normal_move import Move
from postproc.simulate.runs import merge_arc
from postproc.simulate.verify import verify_lines

EPS = 0.0005
"""Half verify's default tolerance: the merge distance ``compare`` gives ``normalise``."""

BORE = """G21 G90 G64 G40
G0 Z3.0
G17
M3 S1000
G0 X6.3248 Y185.0123
G1 F15.0 Z0.0
G2 F450.0 X6.325 Y185.0 Z-0.0018 I-0.3248 J-0.0123
G2 X5.8375 Y184.7185 Z-0.1018 I-0.325 J0.0
G2 Y185.2815 Z-0.2018 I0.1625 J0.2815
G2 X6.3248 Y185.0123 Z-0.3 I0.1625 J-0.2815
G2 X6.325 Y185.0 Z-0.3018 I-0.3248 J-0.0123
G2 X5.8375 Y184.7185 Z-0.4018 I-0.325 J0.0
G2 Y185.2815 Z-0.5018 I0.1625 J0.2815
G2 X6.3248 Y185.0123 Z-0.6 I0.1625 J-0.2815
G2 X6.325 Y185.0 I-0.3248 J-0.0123
G2 X5.8375 Y184.7185 I-0.325 J0.0
G2 Y185.2815 I0.1625 J0.2815
G2 X6.3248 Y185.0123 I0.1625 J-0.2815
G0 Z3.0
M5
M30
"""
"""Two helical turns of 0.3 mm and a flat turn at the bottom, as the CamBam file has each hole (its lines 634-643
and 680-688, the depths shortened)."""


@pytest.mark.parametrize("target", ["isg", "fagor"])
def test_a_cambam_helical_bore_verifies_towards_a_centre_moving_target(target: str) -> None:
    out = io.StringIO()
    translate(io.StringIO(BORE), out, file="bore.nc", source="mach3", target=target)
    report = verify_lines(io.StringIO(BORE), io.StringIO(out.getvalue()), file_in="bore.nc", file_out="o.nc",
                          source="mach3", target=target)
    assert report.ok, report.summary()
    # the paths differ by the centre move's effect on a 2-degree arc: well under a micron
    assert report.max_deviation < 0.0005


def _arc(kind: str, start: tuple[float, float], end: tuple[float, float], centre: tuple[float, float],
         sweep: float, line: int, z: tuple[float, float] = (0.0, 0.0)) -> Move:
    m = Move(kind, {"x": start[0], "y": start[1], "z": z[0]}, {"x": end[0], "y": end[1], "z": z[1]}, 100.0,
             line, line)
    m.plane, m.centre = "XY", centre
    m.radius = math.hypot(start[0] - centre[0], start[1] - centre[1])
    m.sweep = sweep
    return m


def _on(c: tuple[float, float], r: float, degrees: float) -> tuple[float, float]:
    a = math.radians(degrees)
    return (c[0] + r * math.cos(a), c[1] + r * math.sin(a))


def test_a_short_arc_about_a_moved_centre_continues_the_circle_it_lies_on() -> None:
    """A ccw quarter circle of radius 1 about the origin (0 to 90 degrees), then 90 to 91 degrees on the same
    circle, written about a centre 0.003 mm along the short arc's bisector (the line from the origin at 90.5
    degrees): the short arc stays within 0.003 * (1 - cos 0.5 deg) ~ 1e-7 mm of the circle, so it continues the
    run (hand-derived), which then sweeps 91 degrees about the origin; the centres alone (0.003 mm apart, over
    ``EPS``) would not have merged them."""
    o = (0.0, 0.0)
    run = _arc("ccw", _on(o, 1, 0), _on(o, 1, 90), o, math.pi / 2, 1)
    moved = (0.003 * math.cos(math.radians(90.5)), 0.003 * math.sin(math.radians(90.5)))
    s, e = _on(o, 1, 90), _on(o, 1, 91)
    short = _arc("ccw", s, e, moved, math.radians(1.0), 2)
    assert math.hypot(*moved) > EPS
    assert merge_arc(run, short, EPS)
    assert run.centre == o and run.last_line == 2
    assert run.sweep == pytest.approx(math.radians(91.0), abs=1e-5)


def test_a_run_that_sweeps_less_takes_the_centre_of_the_arc_that_continues_it() -> None:
    """The other order: the 1-degree arc about the moved centre first (0 to 1 degree on the unit circle), then the
    quarter circle about the origin (1 to 91 degrees): the run is re-centred on the origin and sweeps 91 degrees,
    its start radius measured about the origin (1, hand-derived)."""
    o = (0.0, 0.0)
    moved = (0.003 * math.cos(math.radians(0.5)), 0.003 * math.sin(math.radians(0.5)))
    run = _arc("ccw", _on(o, 1, 0), _on(o, 1, 1), moved, math.radians(1.0), 1)
    quarter = _arc("ccw", _on(o, 1, 1), _on(o, 1, 91), o, math.pi / 2, 2)
    assert merge_arc(run, quarter, EPS)
    assert run.centre == o
    assert run.radius == pytest.approx(1.0, abs=1e-12)
    assert run.sweep == pytest.approx(math.radians(91.0), abs=1e-9)


@pytest.mark.parametrize("off", [0.002, 0.01])
def test_an_arc_on_another_circle_is_not_merged(off: float) -> None:
    """A quarter circle about a centre ``off`` mm from the run's (over ``EPS``), sweeping as far as the run: its
    middle lies about ``off`` from the run's circle, so it stays a move of its own, whichever sweeps less."""
    o = (0.0, 0.0)
    c = (off * math.cos(math.radians(135)), off * math.sin(math.radians(135)))
    r = math.hypot(_on(o, 1, 90)[0] - c[0], _on(o, 1, 90)[1] - c[1])
    for first_sweep in (math.pi / 2, math.pi / 4):
        run = _arc("ccw", _on(o, 1, 90 - math.degrees(first_sweep)), _on(o, 1, 90), o, first_sweep, 1)
        other = _arc("ccw", _on(o, 1, 90), _on(c, r, 180), c, math.pi / 2, 2)
        assert not merge_arc(run, other, EPS)


def test_a_helix_piece_at_another_rate_is_not_merged() -> None:
    """On the same circle but descending 0.1 mm over a quarter where the run descended 0.1 mm over a half: not one
    helix (``_one_helix``), whatever the circle test says."""
    o = (0.0, 0.0)
    run = _arc("ccw", _on(o, 1, 0), _on(o, 1, 180), o, math.pi, 1, z=(0.0, -0.1))
    more = _arc("ccw", _on(o, 1, 180), _on(o, 1, 270), (0.0, 0.0009), math.pi / 2, 2, z=(-0.1, -0.2))
    assert not merge_arc(run, more, EPS)
