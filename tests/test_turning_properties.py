"""Properties of G71/G72 roughing over generated profiles, judged by an independent model
(``tests/support/turning_model.py``): cases are generated in the canonical frame (infeed toward -x,
cut toward -z), mirrored into OD/ID, toward/away from the chuck, turning/facing, and mirrored back.

For every case: no move enters the finishing allowance (the profile offset by Δu/2, Δw); no rapid
enters material not yet cut; no feed cuts deeper than Δd; the levels are Δd apart from A'; what the
levels leave is at most Δd above the offset profile (the scallop); the contour pass is the offset
profile within 1 um; nothing is left above it; the cycle ends at A.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from hypothesis import HealthCheck, assume, given, settings, strategies as st

from postproc.cycles.turning import Seg, TurnMove, rough_facing, rough_turning
from tests.support.turning_model import Air, Mirror, Outline, arc_between, chord_angle, replay, samples, shift

TOL = 1e-6


@dataclass(frozen=True)
class Case:
    a: tuple[float, float]
    profile: list[Seg]
    depth: float
    retract: float
    u: float
    w: float
    type_ii: bool
    mirror: Mirror


@st.composite
def cases(draw: st.DrawFn, type_ii: bool) -> Case:
    fl = lambda lo, hi: draw(st.floats(lo, hi, allow_nan=False))  # noqa: E731
    # Snapped cases put X values on a 0.5 grid with Δd 0.5 or 1 and no allowance: levels then land
    # exactly on vertices and Z-parallel blocks, the edge cases of where a level meets the profile.
    snap = draw(st.booleans())
    q = (lambda v: round(v * 2.0) / 2.0) if snap else (lambda v: v)  # noqa: E731
    xa, za = q(fl(6.0, 16.0)), fl(-3.0, 3.0)
    xb = q(fl(0.5, xa - 0.5))
    zb = za + (fl(-1.0, 0.0) if type_ii and draw(st.booleans()) else 0.0)
    profile = [Seg("line", xa, za, xb, zb, rapid=draw(st.booleans()), line=1)]
    x, z = xb, zb
    last = "ns"
    for i in range(draw(st.integers(1, 6))):
        # Never two X walls in a row: down and back up at one Z is a slot of no width, which no level
        # can enter (the contour pass alone cuts it, to its full depth).
        kinds = ["h", "taper", "arc"] if last in ("ns", "v") else ["h", "v", "taper", "arc"]
        kind = last = draw(st.sampled_from(kinds))
        dz = 0.0 if kind == "v" else -fl(0.2, 6.0)
        if type_ii:
            dx = 0.0 if kind == "h" else fl(-4.0, 4.0)
        else:
            dx = 0.0 if kind == "h" else fl(0.2, 4.0)
        dx = q(max(0.5 - x, min(xa + 3.0 - x, dx)))
        if kind == "v" and abs(dx) < 0.1:
            continue
        x1, z1 = x + dx, z + dz
        if kind == "arc" and abs(dx) > 0.05:
            beta = chord_angle(dx, dz)
            room = min(beta - math.pi / 2, math.pi - beta) if not type_ii else min(beta - math.pi / 2,
                                                                                    3 * math.pi / 2 - beta)
            sweep = 2 * room * fl(0.05, 0.95)
            if sweep > 1e-3:
                profile.append(arc_between(x, z, x1, z1, sweep, draw(st.booleans()), 2 + i))
                x, z = x1, z1
                continue
        profile.append(Seg("line", x, z, x1, z1, line=2 + i))
        x, z = x1, z1
    if draw(st.booleans()):  # the nf block often leaves the part outward
        profile.append(Seg("line", x, z, x + q(fl(0.5, 3.0)), z, line=20))
    mirror = Mirror(draw(st.booleans()), draw(st.sampled_from([1.0, -1.0])), draw(st.sampled_from([1.0, -1.0])))
    if snap:
        return Case((xa, za), profile, draw(st.sampled_from([0.5, 1.0])), fl(0.0, 1.5), 0.0, 0.0, type_ii, mirror)
    return Case((xa, za), profile, fl(0.4, 3.0), fl(0.0, 1.5), fl(0.0, 0.5), fl(0.0, 0.3), type_ii, mirror)


def run(case: Case) -> list[TurnMove]:
    """Call the cycle on the mirrored case and bring its moves back to the canonical frame."""
    m = case.mirror
    start = m.pt(*case.a)
    profile = [m.seg(s) for s in case.profile]
    ux, uz = m.pt(case.u, case.w)
    cycle = rough_facing if m.swap else rough_turning
    moves = cycle(start, profile, case.depth, case.retract, u_diameter=2 * ux, w=uz, feed=0.2,
                  type_ii=case.type_ii)
    return [m.unmove(mv) for mv in moves]


def check(case: Case, moves: list[TurnMove]) -> None:
    (xa, za), u, w, depth = case.a, case.u, case.w, case.depth
    offset = [shift(s, u, w) for s in case.profile]
    outline = Outline(offset[1:])
    z_end, z_b = offset[-1].z1, offset[0].z1
    # The start point must be clear of the allowance, or the moves from and to it cannot be.
    assume(all(outline.at(za + (z_b - za) * i / 20) <= xa - TOL for i in range(21)))
    air = Air(xa)  # the start point is clear of the stock: nothing above its X is material
    assert math.isclose(moves[-1].x, xa, abs_tol=1e-9) and math.isclose(moves[-1].z, za, abs_tol=1e-9)
    inside = lambda z: z_end + 1e-7 < z < z_b - 1e-7  # noqa: E731
    contour_seen = False
    for x0, z0, mv in replay(case.a, moves):
        if mv.note == "contour" and not contour_seen:
            contour_seen = True
            for i in range(1, 200):  # the scallop: the levels left at most Δd above the offset profile
                z = z_end + (z_b - z_end) * i / 200
                assert air.at(z) - outline.at(z) <= depth + TOL, (z, air.at(z), outline.at(z))
        for sx, sz, vertical in samples(x0, z0, mv):
            if not inside(sz):
                continue
            part = min(outline.at(sz - 1e-6), outline.at(sz + 1e-6)) if vertical else outline.at(sz)
            # (The contour pass is the offset profile itself, walls included: compared exactly below.)
            assert mv.note == "contour" or sx >= part - TOL, ("into the allowance", mv, sx, sz, part)
            clear = air.at(sz)
            if mv.kind == "rapid":
                assert sx >= clear - TOL, ("rapid into material", mv, sx, sz, clear)
            else:
                assert clear - sx <= depth + TOL, ("deeper than the depth of cut", mv, sx, sz, clear)
        if mv.kind != "rapid":
            air.cut(x0, z0, mv)
    assert contour_seen
    for i in range(1, 200):  # nothing is left above the offset profile
        z = z_end + (z_b - z_end) * i / 200
        assert air.at(z) <= outline.at(z) + TOL, (z, air.at(z), outline.at(z))
    # The contour pass is the offset profile B'..C'.
    contour = [mv for mv in moves if mv.note == "contour"]
    assert len(contour) == len(offset) - 1
    for mv, seg in zip(contour, offset[1:]):
        assert mv.kind == ("feed" if seg.kind == "line" else seg.kind)
        assert abs(mv.x - seg.x1) < 1e-6 and abs(mv.z - seg.z1) < 1e-6
        if seg.cx is not None:
            assert mv.cx is not None and mv.cz is not None and seg.cz is not None
            assert abs(mv.cx - seg.cx) < 1e-6 and abs(mv.cz - seg.cz) < 1e-6
    # The levels are Δd apart, the first Δd below A'.
    levels = sorted({round(mv.x, 9) for mv in moves if mv.note == "rough"}, reverse=True)
    for k, level in enumerate(levels, start=1):
        assert abs(level - (xa + u - k * depth)) < 1e-6, (levels, xa + u, depth)


SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(cases(type_ii=False))
def test_type_i_roughing(case: Case) -> None:
    check(case, run(case))


@SETTINGS
@given(cases(type_ii=True))
def test_type_ii_roughing(case: Case) -> None:
    check(case, run(case))
