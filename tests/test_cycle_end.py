"""The end of a cycle block found without expanding it (``CycleExpansion.end``) is where the full
expansion leaves the tool, for every kind, semantics, return level, plane and hole row: the resolver
uses it so that a target keeping the cycle native never pays for the expansion."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.cycles.resolve import EXPANSIONS
from postproc.cycles.section import CannedCycle
from postproc.ir.state import PLANE_AXES

KINDS = sorted({(kind, cls) for cls in EXPANSIONS for kind in cls.KINDS}, key=lambda pair: pair[0])
coordinate = st.floats(-50.0, 50.0, allow_nan=False).map(lambda v: round(v, 3))


@st.composite
def cycles(draw: st.DrawFn) -> tuple[type, CannedCycle]:
    kind, cls = draw(st.sampled_from(KINDS))
    plane = draw(st.sampled_from(["XY", "ZX", "YZ"]))
    first, second, normal = PLANE_AXES[plane]
    bottom = draw(st.floats(-30.0, -1.0).map(lambda v: round(v, 3)))
    r = draw(st.floats(0.0, 10.0).map(lambda v: round(v, 3)))
    initial = draw(st.floats(-5.0, 40.0).map(lambda v: round(v, 3)))
    start = {first: draw(coordinate), second: draw(coordinate), normal: initial}
    step = draw(st.sampled_from([{}, {first: draw(coordinate), second: draw(coordinate)}]))
    return cls, CannedCycle(
        kind, semantics=draw(st.sampled_from(["fanuc", "rs274"])),
        return_level=draw(st.sampled_from(["initial", "r"])), plane=plane, initial=initial, r=r,
        bottom=bottom, top=r - 0.5, q=draw(st.floats(0.5, 8.0)), clearance=0.5,
        dwell=draw(st.sampled_from([None, 0.5])), orient=0.0, feed=100.0, repeat=draw(st.integers(0, 5)),
        spindle="cw", motion="linear", start=start,
        position={first: draw(coordinate), second: draw(coordinate)}, step=step,
        shift={first: 0.5, second: 0.0})


@settings(max_examples=300, deadline=None)
@given(cycles())
def test_the_end_without_expanding_is_where_the_expansion_ends(case: tuple[type, CannedCycle]) -> None:
    cls, cycle = case
    expansion = cls()
    assert expansion.end(cycle) == expansion.expand(cycle)[1]
