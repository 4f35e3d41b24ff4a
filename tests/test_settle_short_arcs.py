"""``settle_arc_ends`` leaves an R arc clearly short of half a turn as it is after one bound
(``_Rewriter._short_of_half_turn``), before building the arc and its centre three times (``r_centre_error``): the
bound must never leave an arc the general test would rewrite. Held to the general test on random R arcs (any
sweep, both directions, either sign of R, mm and inch, radii from 0.01 to 100,000 program units), and shown
not to be vacuous (a quarter circle is judged by the bound alone, a semicircle never is).
"""

from __future__ import annotations

import math

from hypothesis import given, settings, strategies as st

from postproc.context import Context
from postproc.errors import Diagnostics, ErrorLevel
from postproc.ir import Motion
from postproc.ir.state import MM_PER_INCH
from postproc.lowering.arc_geometry import r_centre_error
from postproc.lowering.arcs import R_FORM_TOLERANCE_MM, SETTLE, WRITE_SLACK_MM, ArcOption, _Rewriter
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup


def _rewriter(target: str, inch: bool, start: tuple[float, float]) -> _Rewriter:
    ctx = Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE), "fanuc")
    rewriter = _Rewriter(ctx, ArcOption(SETTLE), default_registry().dialect(target))
    if inch:
        rewriter.state.units = "inch"
    rewriter.state.position.update({"X": start[0], "Y": start[1], "Z": 0.0})
    return rewriter


def _general_keeps_r(rewriter: _Rewriter, motion: Motion, share: float) -> bool:
    """The general test of ``_settle_radius``: the arc keeps its R (its centre moves within the tolerance)."""
    mm = MM_PER_INCH if rewriter.state.units == "inch" else 1.0
    arc = rewriter.words(motion, False, ("X", "Y")).arc()
    slack = WRITE_SLACK_MM / mm + abs(float(motion.radius)) * share  # type: ignore[arg-type]
    return r_centre_error(arc, slack) * mm <= R_FORM_TOLERANCE_MM


def _arc(radius: float, sweep_deg: float, angle_deg: float, clockwise: bool, places: int,
         origin: tuple[float, float]) -> tuple[tuple[float, float], Motion]:
    """An R arc of ``sweep_deg`` (negative R over 180) on a chord at ``angle_deg``, its ends rounded to ``places``."""
    half = radius * math.sin(math.radians(min(sweep_deg, 360.0 - sweep_deg)) / 2.0)
    a = math.radians(angle_deg)
    sx, sy = round(origin[0] - half * math.cos(a), places), round(origin[1] - half * math.sin(a), places)
    ex, ey = round(origin[0] + half * math.cos(a), places), round(origin[1] + half * math.sin(a), places)
    r = round(radius, places)
    return (sx, sy), Motion("cw" if clockwise else "ccw", {"X": ex, "Y": ey}, None, -r if sweep_deg > 180 else r)


@settings(max_examples=400, deadline=None)
@given(radius=st.floats(min_value=0.01, max_value=1e5), sweep=st.floats(min_value=0.001, max_value=359.999),
       angle=st.floats(min_value=0.0, max_value=360.0), clockwise=st.booleans(), inch=st.booleans(),
       near_half=st.booleans(), target=st.sampled_from(["grbl", "grblhal"]),
       origin=st.tuples(st.floats(min_value=-1e4, max_value=1e4), st.floats(min_value=-1e4, max_value=1e4)))
def test_an_arc_the_bound_keeps_is_one_the_general_test_keeps(radius: float, sweep: float, angle: float,
                                                              clockwise: bool, inch: bool, near_half: bool,
                                                              target: str, origin: tuple[float, float]) -> None:
    if near_half:
        sweep = 180.0 + (sweep - 180.0) / 1000.0  # within a fifth of a degree of half a turn
    places = 4 if inch else 3
    start, motion = _arc(radius, sweep, angle, clockwise, places, origin)
    rewriter = _rewriter(target, inch, start)
    share = rewriter.target.R_ARC_FLOAT_SLACK
    assert share > 0.0
    if rewriter._short_of_half_turn(motion, False, share):
        assert _general_keeps_r(rewriter, motion, share)


def test_a_quarter_circle_is_judged_by_the_bound_and_a_semicircle_is_not() -> None:
    for inch in (False, True):
        start, quarter = _arc(10.0, 90.0, 30.0, True, 4, (1.0, 2.0))
        rewriter = _rewriter("grbl", inch, start)
        share = rewriter.target.R_ARC_FLOAT_SLACK
        assert rewriter._short_of_half_turn(quarter, False, share)
        assert _general_keeps_r(rewriter, quarter, share)
        start, half = _arc(10.0, 180.0, 30.0, True, 4, (1.0, 2.0))
        rewriter = _rewriter("grbl", inch, start)
        assert not rewriter._short_of_half_turn(half, False, share)
        assert not _general_keeps_r(rewriter, half, share)  # the general test rewrites it (I/J)


def test_the_bound_asks_nothing_it_cannot_see() -> None:
    """Incremental words, an unknown start: the general test decides."""
    start, quarter = _arc(10.0, 90.0, 0.0, True, 3, (0.0, 0.0))
    rewriter = _rewriter("grbl", False, start)
    share = rewriter.target.R_ARC_FLOAT_SLACK
    assert not rewriter._short_of_half_turn(quarter, True, share)
    rewriter.state.position["X"] = None
    assert not rewriter._short_of_half_turn(quarter, False, share)
