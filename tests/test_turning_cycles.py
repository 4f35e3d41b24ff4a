"""G73, G74, G75 and G76: toolpaths derived by hand, LinuxCNC's G76 passes, and threading properties."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from postproc.cycles.turning import (Seg, TurnMove, groove, pattern_repeat, peck_face, thread_depths,
                                     threading)
from postproc.errors import ProgramError

CONFORMANCE = Path(__file__).resolve().parents[2] / "shared" / "conformance" / "linuxcnc"


def R(x: float, z: float, note: str) -> TurnMove:
    return TurnMove("rapid", x, z, note=note)


def F(x: float, z: float, note: str, f: float | None = 0.2) -> TurnMove:
    return TurnMove("feed", x, z, feed=f, note=note)


def close(got: list[TurnMove], want: list[TurnMove], tol: float = 1e-9) -> None:
    assert len(got) == len(want), "\n".join(map(str, got))
    for g, w in zip(got, want):
        assert (g.kind, g.feed, g.note) == (w.kind, w.feed, w.note), (g, w)
        assert abs(g.x - w.x) < tol and abs(g.z - w.z) < tol, (g, w)


def test_g73_by_hand() -> None:
    # A = (10, 2): G0 X4; G1 Z-5; G1 X10. Δi 3, Δk 1, d 3, Δu 0.4 (0.2 radius), Δw 0.1, F0.2.
    # Shifts (0.2 + 3 * (3 - n) / 2, 0.1 + 1 * (3 - n) / 2): (3.2, 1.1), (1.7, 0.6), (0.2, 0.1).
    # Clear X (the ns block comes from +X): the largest of A 10 and every pass: 10 + 3.2 = 13.2.
    profile = [Seg("line", 10, 2, 4, 2, rapid=True, line=1), Seg("line", 4, 2, 4, -5, line=2),
               Seg("line", 4, -5, 10, -5, line=3)]
    got = pattern_repeat((10.0, 2.0), profile, 3.0, 1.0, 3, u_diameter=0.4, w=0.1, feed=0.2)
    close(got, [
        R(13.2, 3.1, "approach"), R(7.2, 3.1, "pass"), F(7.2, -3.9, "pass"), F(13.2, -3.9, "pass"),
        R(13.2, 2.6, "return"), R(11.7, 2.6, "return"),
        R(5.7, 2.6, "pass"), F(5.7, -4.4, "pass"), F(11.7, -4.4, "pass"),
        R(13.2, -4.4, "return"), R(13.2, 2.1, "return"), R(10.2, 2.1, "return"),
        R(4.2, 2.1, "pass"), F(4.2, -4.9, "pass"), F(10.2, -4.9, "pass"),
        R(13.2, -4.9, "return"), R(13.2, 2.0, "return"), R(10.0, 2.0, "return"),
    ])


def test_g73_one_pass_is_the_allowance_only() -> None:
    profile = [Seg("line", 10, 2, 4, 2, line=1), Seg("line", 4, 2, 4, -5, line=2)]
    got = pattern_repeat((10.0, 2.0), profile, 3.0, 1.0, 1, u_diameter=1.0, feed=0.2)
    assert [(m.x, m.z) for m in got if m.note == "pass"] == [(4.5, 2.0), (4.5, -5.0)]
    with pytest.raises(ProgramError, match="at least 1"):
        pattern_repeat((10.0, 2.0), profile, 3.0, 1.0, 0)


def test_g74_peck_drill_on_the_axis_by_hand() -> None:
    # A = (0, 1): G74 R0.5; G74 Z-5 Q2 F0.2 (Q already 2 mm). Pecks to 1-2 = -1, -3, then the bottom -5,
    # each but the last followed by a rapid back of 0.5; no relief; rapid out to Z1.
    close(peck_face((0.0, 1.0), 0.0, -5.0, 2.0, 0.5, feed=0.2), [
        F(0.0, -1.0, "peck"), R(0.0, -0.5, "retract"), F(0.0, -3.0, "peck"), R(0.0, -2.5, "retract"),
        F(0.0, -5.0, "peck"), R(0.0, 1.0, "return"),
    ])


def test_g74_face_groove_by_hand() -> None:
    # A = (20, 1): G74 R0.3; G74 X28 (radius 14) Z-2 P2.5 Q1.5 R0.2. Columns 20, 17.5, 15 and the last
    # at 14 (the step toward 14 is -X, so the relief is +X 0.2); pecks to -0.5 then -2 (rapid back 0.3).
    want: list[TurnMove] = []
    for i, xc in enumerate((20.0, 17.5, 15.0, 14.0)):
        if i:
            want.append(R(xc, 1.0, "position"))
        want += [F(xc, -0.5, "peck"), R(xc, -0.2, "retract"), F(xc, -2.0, "peck"),
                 F(xc + 0.2, -2.0, "relief"), R(xc + 0.2, 1.0, "return")]
    want.append(R(20.0, 1.0, "return"))
    close(peck_face((20.0, 1.0), 14.0, -2.0, 1.5, 0.3, step=2.5, relief=0.2, feed=0.2), want)


def test_g75_groove_by_hand() -> None:
    # A = (15, -10): G75 R0.5; G75 X20 (radius 10) Z-14 P2 Q3 F0.2. Passes at Z-10, -13, -14; pecks
    # to X 13, 11, then 10, each but the last followed by a rapid back of 0.5 (+X); rapid out to X15.
    want: list[TurnMove] = []
    for i, zc in enumerate((-10.0, -13.0, -14.0)):
        if i:
            want.append(R(15.0, zc, "position"))
        want += [F(13.0, zc, "peck"), R(13.5, zc, "retract"), F(11.0, zc, "peck"), R(11.5, zc, "retract"),
                 F(10.0, zc, "peck"), R(15.0, zc, "return")]
    want.append(R(15.0, -10.0, "return"))
    close(groove((15.0, -10.0), 10.0, -14.0, 2.0, 0.5, step=3.0, feed=0.2), want)


@pytest.mark.parametrize("kwargs, message", [
    ({"peck": 0.0}, "peck depth must be positive"),
    ({"step": 0.0}, "step between passes must be positive"),
    ({"retract": -1.0}, "retract"),
    ({"limit": 10}, "exceed the limit of 10 moves"),
])
def test_g75_refuses(kwargs: dict[str, float], message: str) -> None:
    args: dict[str, float] = {"peck": 2.0, "retract": 0.5, "step": 3.0, **kwargs}
    with pytest.raises(ProgramError, match=message):
        groove((15.0, -10.0), 10.0, -14.0, **args)  # type: ignore[arg-type]


def test_g76_by_hand() -> None:
    # A = (12, 5): G76 P026000 Q150 R100; G76 X18 (root radius 9) Z-20 P1200 Q500 F2 (all in um):
    # m 2, r 0, a 60; Δdmin 0.15, d 0.1, k 1.2, Δd 0.5. Depths to k - d = 1.1:
    #   0.5*sqrt(1) = 0.5; 0.5*sqrt(2) = 0.70711 (>= 0.5 + 0.15); 0.5*sqrt(3) = 0.86603 (>= 0.85711);
    #   0.5*sqrt(4) = 1.0 < 0.86603 + 0.15 = 1.01603 -> 1.01603; 0.5*sqrt(5) = 1.11803 < 1.16603, capped at 1.1;
    #   then m = 2 passes at 1.2.
    depths = [0.5, 0.5 * math.sqrt(2), 0.5 * math.sqrt(3), 0.5 * math.sqrt(3) + 0.15, 1.1, 1.2, 1.2]
    assert thread_depths(1.2, 0.5, 0.15, 0.1, 2) == pytest.approx(depths, abs=1e-12)
    # Pass at depth D: X = 9 + (1.2 - D); flank infeed at 30 degrees: Z shifted back (+) by
    # (1.2 - D) * tan(30) = (1.2 - D) * 0.5773503.
    want: list[TurnMove] = []
    for d in depths:
        above, back = 1.2 - d, (1.2 - d) * 0.5773502691896258
        want += [R(12.0, 5.0 + back, "shift"), R(9.0 + above, 5.0 + back, "infeed"),
                 F(9.0 + above, -20.0 + back, "thread", 2.0), R(12.0, -20.0 + back, "pull out")]
    want.append(R(12.0, 5.0, "return"))
    close(threading((12.0, 5.0), 9.0, -20.0, 2.0, 1.2, 0.5, finish_passes=2, min_depth=0.15,
                    allowance=0.1), want, tol=1e-7)


def test_g76_chamfer_and_refusals() -> None:
    # r 10 = 1.0 lead = 2: each pass pulls out over the last 2 of Z at 45 degrees. Δd = k: one pass at
    # full depth, then m = 1 finishing pass; a = 0 (no flank shift).
    got = threading((12.0, 5.0), 9.0, -20.0, 2.0, 1.2, 1.2, finish_passes=1, angle=0.0, chamfer=10)
    assert [(m.note, round(m.x, 9), round(m.z, 9)) for m in got] == [
        ("infeed", 9.0, 5.0), ("thread", 9.0, -18.0), ("thread chamfer", 11.0, -20.0), ("pull out", 12.0, -20.0),
        ("shift", 12.0, 5.0), ("infeed", 9.0, 5.0), ("thread", 9.0, -18.0), ("thread chamfer", 11.0, -20.0), ("pull out", 12.0, -20.0),
        ("return", 12.0, 5.0)]
    with pytest.raises(ProgramError, match="within the thread height"):
        threading((10.0, 5.0), 9.0, -20.0, 2.0, 1.2, 0.5)
    with pytest.raises(ProgramError, match="more than 1000 passes"):
        threading((12.0, 5.0), 9.0, -20.0, 2.0, 1.2, 1e-5, limit=1000)
    with pytest.raises(ProgramError, match="finishing passes must be 1 to 99"):
        threading((12.0, 5.0), 9.0, -20.0, 2.0, 1.2, 0.5, finish_passes=0)


@pytest.mark.skipif(not (CONFORMANCE / "g76").is_dir(), reason="no LinuxCNC conformance cases")
def test_g76_passes_match_linuxcnc() -> None:
    # LinuxCNC's g76 case: drive line X.2 Z.2, I-.075 (crest at .125), J.008 (first depth), K.045,
    # R2.0 (depth j * n^(1/2): the sqrt(n) rule), Q29.5 (infeed along a 29.5-degree flank), H3 spring
    # passes. Its passes start Z .2 - D*tan(29.5); ours start A's Z + (k - D)*tan(a/2), so A's Z is
    # .2 - k*tan(29.5) and a = 59. The root is .125 - .045 = .08. Every pass's start point must agree.
    rows = [line.split("\t") for line in (CONFORMANCE / "g76" / "moves.tsv").read_text().splitlines()]
    theirs = [(float(a[1]), float(a[3])) for a, b in zip(rows, rows[1:]) if a[0] == "rapid" and b[0] == "sync"]
    t = math.tan(math.radians(29.5))
    ours = [(m.x, m.z) for m in threading((0.237, 0.2 - 0.045 * t), 0.08, -0.5, 0.05, 0.045, 0.008,
                                          finish_passes=3, angle=59.0) if m.note == "infeed"]
    assert len(ours) == len(theirs) == 35
    for (x, z), (tx, tz) in zip(ours, theirs):
        assert abs(x - tx) < 1.5e-4 and abs(z - tz) < 1.5e-4


@settings(max_examples=300, deadline=None)
@given(st.floats(0.05, 5.0), st.floats(0.05, 2.0), st.floats(0.0, 0.3), st.floats(0.0, 1.0), st.integers(1, 5))
def test_thread_depths_sum_to_the_height(height: float, first: float, dmin: float, part: float, m: int) -> None:
    allowance = part * height * 0.5
    depths = thread_depths(height, first, dmin, allowance, m)
    steps = [b - a for a, b in zip([0.0] + depths, depths)]
    assert math.isclose(sum(steps), height, abs_tol=1e-12)  # the passes add up to the thread height
    assert depths[-m:] == [height] * m and depths[-m - 1] <= height - allowance + 1e-12
    rough = depths[:-m]
    if height - allowance > 0:
        assert rough and rough[-1] == pytest.approx(height - allowance, abs=1e-12)
    for n, (d, step) in enumerate(zip(rough, steps), start=1):
        assert d >= min(first * math.sqrt(n), height - allowance) - 1e-12  # never shallower than Δd*sqrt(n)
        if n > 1 and d < height - allowance - 1e-12:
            assert step >= dmin - 1e-12  # no infeed below Δdmin except the cap at k - d
        assert step > 0


@settings(max_examples=150, deadline=None)
@given(st.lists(st.tuples(st.floats(-4.0, 4.0), st.floats(-4.0, -0.1)), min_size=1, max_size=5),
       st.floats(-3.0, 3.0), st.floats(-2.0, 2.0), st.integers(1, 6), st.floats(-1.0, 1.0), st.floats(-0.5, 0.5),
       st.booleans())
def test_g73_passes_step_evenly_from_the_relief_to_the_allowance(
        steps: list[tuple[float, float]], di: float, dk: float, d: int, du: float, dw: float, od: bool) -> None:
    a = (20.0, 2.0) if od else (1.0, 2.0)
    x, z = (5.0, 2.0) if od else (10.0, 2.0)
    profile = [Seg("line", a[0], a[1], x, z, rapid=True, line=1)]
    for i, (dx, dz) in enumerate(steps):
        profile.append(Seg("line", x, z, x + dx, z + dz, line=2 + i))
        x, z = x + dx, z + dz
    got = pattern_repeat(a, profile, di, dk, d, u_diameter=du, w=dw, feed=0.3)
    passes = [m for m in got if m.note == "pass"]
    assert len(passes) == d * len(profile)
    for n in range(1, d + 1):
        share = (d - n) / (d - 1) if d > 1 else 0.0
        sx, sz = du / 2 + di * share, dw + dk * share  # pass 1 escapes by Δi + Δu/2, pass d by Δu/2
        for mv, seg in zip(passes[(n - 1) * len(profile):n * len(profile)], profile):
            assert abs(mv.x - (seg.x1 + sx)) < 1e-9 and abs(mv.z - (seg.z1 + sz)) < 1e-9
            assert mv.kind == ("rapid" if seg.rapid else "feed")
    assert (got[-1].x, got[-1].z) == a and got[-1].kind == "rapid"
    # The returns between passes run outside everything cut (beyond A and every pass in the ns block's
    # outward direction), so no rapid crosses the part.
    out = 1.0 if od else -1.0
    clear = max(out * p.x for p in passes + [TurnMove("rapid", a[0], a[1])])
    for p, q in zip(got, got[1:]):
        if q.note == "return" and p.z != q.z:
            assert out * p.x >= clear - 1e-9 and out * q.x >= clear - 1e-9


@settings(max_examples=200, deadline=None)
@given(st.floats(-20.0, 20.0), st.floats(0.05, 12.0), st.floats(0.3, 3.0), st.floats(0.0, 1.0), st.floats(0.5, 4.0),
       st.floats(0.0, 0.5), st.booleans(), st.booleans())
def test_g74_g75_pecks_reach_the_bottom_of_every_pass(x_span: float, depth: float, peck: float, e: float,
                                                      step: float, relief: float, facing: bool, down: bool) -> None:
    a = (10.0, 2.0)
    if facing:  # G74: pecks along Z, passes along X
        x, z = a[0] + x_span, a[1] + (-depth if down else depth)
        got = peck_face(a, x, z, peck, e, step=step, relief=relief, feed=0.1)
        along, across = (lambda m: m.z), (lambda m: m.x)  # noqa: E731
        start_along, end_along, start_across, end_across = a[1], z, a[0], x
    else:  # G75: pecks along X, passes along Z
        x, z = a[0] + (-depth if down else depth), a[1] + x_span
        got = groove(a, x, z, peck, e, step=step, relief=relief, feed=0.1)
        along, across = (lambda m: m.x), (lambda m: m.z)  # noqa: E731
        start_along, end_along, start_across, end_across = a[0], x, a[1], z
    assert (got[-1].x, got[-1].z) == a
    pecks = [m for m in got if m.note == "peck"]
    columns = sorted({across(m) for m in pecks}, key=lambda v: abs(v - start_across))
    # Passes from A's position to the last, never more than Δ apart, the last exactly at the end.
    if depth > 0:
        assert columns[0] == start_across and columns[-1] == end_across
        assert all(abs(b - a_) <= step + 1e-9 for a_, b in zip(columns, columns[1:]))
    position = a
    for m in got:
        if m.note == "peck":  # each peck goes at most Δk beyond the deepest point reached so far
            assert abs(along(m) - start_along) <= abs(end_along - start_along) + 1e-9
        position = (m.x, m.z)
    for c in columns:  # every pass reaches the bottom
        assert any(across(m) == c and along(m) == end_along for m in pecks)
    deepest: dict[float, float] = {}
    for m in pecks:
        c = across(m)
        reached = deepest.get(c, 0.0)
        travel = abs(along(m) - start_along)
        assert travel - reached <= peck + 1e-9
        deepest[c] = max(reached, travel)
    assert position == a
