"""G71/G72 stock removal: a toolpath derived by hand, LinuxCNC's G72 case, and the refusals."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from postproc.cycles.turning import Seg, TurnMove, rough_facing, rough_turning
from postproc.errors import ProgramError

CONFORMANCE = Path(__file__).resolve().parents[2] / "shared" / "conformance" / "linuxcnc"


def rapid(x: float, z: float, note: str) -> TurnMove:
    return TurnMove("rapid", x, z, note=note)


def feed(x: float, z: float, note: str, f: float = 0.25) -> TurnMove:
    return TurnMove("feed", x, z, feed=f, note=note)


def close(got: list[TurnMove], want: list[TurnMove]) -> None:
    assert len(got) == len(want), "\n".join(map(str, got))
    for g, w in zip(got, want):
        assert (g.kind, g.feed, g.note) == (w.kind, w.feed, w.note), (g, w)
        assert abs(g.x - w.x) < 1e-9 and abs(g.z - w.z) < 1e-9, (g, w)


def shaft(line: int = 10) -> list[Seg]:
    """A = (12, 2): G0 X4; G1 Z-4; G1 X8 Z-8; G1 Z-12; G1 X12 (radius values)."""
    return [
        Seg("line", 12.0, 2.0, 4.0, 2.0, rapid=True, line=line),
        Seg("line", 4.0, 2.0, 4.0, -4.0, line=line + 1),
        Seg("line", 4.0, -4.0, 8.0, -8.0, line=line + 2),
        Seg("line", 8.0, -8.0, 8.0, -12.0, line=line + 3),
        Seg("line", 8.0, -12.0, 12.0, -12.0, line=line + 4),
    ]


def test_g71_type_i_by_hand() -> None:
    # Δd 2, e 0.5, Δu 1 (0.5 radius), Δw 0.2, F0.25. A' = (12.5, 2.2); the offset contour is
    # B'(4.5, 2.2) -> (4.5, -3.8) -> (8.5, -7.8) -> (8.5, -11.8) -> (12.5, -11.8); lowest x 4.5.
    # Levels 12.5 - 2k above 4.5: 10.5, 8.5, 6.5. Where each meets the offset contour:
    #   10.5: the last block (X up at Z-11.8) -> -11.8;
    #    8.5: runs along the Z-parallel block at exactly 8.5 and stops at its end -> -11.8;
    #    6.5: the taper x = 4.5 + t*4 = 6.5 at t = 0.5, z = -3.8 - 0.5*4 = -5.8.
    # Retract 0.5 at 45 degrees: (level + 0.5, end + 0.5); infeed as ns (G0): rapid.
    got = rough_turning((12.0, 2.0), shaft(), 2.0, 0.5, u_diameter=1.0, w=0.2, feed=0.25)
    close(got, [
        rapid(12.5, 2.2, "approach"),
        rapid(10.5, 2.2, "infeed"), feed(10.5, -11.8, "rough"), rapid(11.0, -11.3, "retract"),
        rapid(11.0, 2.2, "return"),
        rapid(8.5, 2.2, "infeed"), feed(8.5, -11.8, "rough"), rapid(9.0, -11.3, "retract"),
        rapid(9.0, 2.2, "return"),
        rapid(6.5, 2.2, "infeed"), feed(6.5, -5.8, "rough"), rapid(7.0, -5.3, "retract"),
        rapid(7.0, 2.2, "return"),
        rapid(4.5, 2.2, "infeed"),
        feed(4.5, -3.8, "contour"), feed(8.5, -7.8, "contour"), feed(8.5, -11.8, "contour"),
        feed(12.5, -11.8, "contour"),
        # Return: the clear X is max(A 12, A' 12.5, profile 12.5) = 12.5 (already there), then Z, then X.
        rapid(12.5, 2.0, "return"), rapid(12.0, 2.0, "return"),
    ])


def test_g71_id_is_the_od_mirrored_by_hand() -> None:
    # A bore: A = (2, 2); G1 X10 (feed infeed, +X); G1 Z-6; G1 X2. Δd 3, e 1, Δu -1 (-0.5 radius), no Δw.
    # A' = (1.5, 2); offset contour B'(9.5, 2) -> (9.5, -6) -> (1.5, -6): infeed +X, levels 1.5 + 3k below
    # 9.5: 4.5, 7.5; both meet the X block at Z-6. Retract: (level - 1, -6 + 1). Clear X toward the axis:
    # the smallest of A 2, A' 1.5 and the profile 1.5 -> 1.5.
    profile = [Seg("line", 2.0, 2.0, 10.0, 2.0, line=1), Seg("line", 10.0, 2.0, 10.0, -6.0, line=2),
               Seg("line", 10.0, -6.0, 2.0, -6.0, line=3)]
    got = rough_turning((2.0, 2.0), profile, 3.0, 1.0, u_diameter=-1.0, feed=0.25)
    close(got, [
        rapid(1.5, 2.0, "approach"),
        feed(4.5, 2.0, "infeed"), feed(4.5, -6.0, "rough"), rapid(3.5, -5.0, "retract"),
        rapid(3.5, 2.0, "return"),
        feed(7.5, 2.0, "infeed"), feed(7.5, -6.0, "rough"), rapid(6.5, -5.0, "retract"),
        rapid(6.5, 2.0, "return"),
        feed(9.5, 2.0, "infeed"), feed(9.5, -6.0, "contour"), feed(1.5, -6.0, "contour"),
        rapid(1.5, 2.0, "return"), rapid(2.0, 2.0, "return"),
    ])


def test_g72_by_hand() -> None:
    # Facing from A = (20, 1): G0 Z-4 (infeed -Z); G1 X6 (cut toward -X); G1 Z1. Δd (Z) 1.5, e 0.3, no allowance. Levels 1 - 1.5k above the lowest
    # z -4: -0.5, -2, -3.5. Each meets the profile at its Z-parallel block X6 -> ends at x = 6.
    profile = [Seg("line", 20.0, 1.0, 20.0, -4.0, rapid=True, line=1),
               Seg("line", 20.0, -4.0, 6.0, -4.0, line=2), Seg("line", 6.0, -4.0, 6.0, 1.0, line=3)]
    got = rough_facing((20.0, 1.0), profile, 1.5, 0.3, feed=0.25)
    close(got, [
        rapid(20.0, -0.5, "infeed"), feed(6.0, -0.5, "rough"), rapid(6.3, -0.2, "retract"),
        rapid(20.0, -0.2, "return"),
        rapid(20.0, -2.0, "infeed"), feed(6.0, -2.0, "rough"), rapid(6.3, -1.7, "retract"),
        rapid(20.0, -1.7, "return"),
        rapid(20.0, -3.5, "infeed"), feed(6.0, -3.5, "rough"), rapid(6.3, -3.2, "retract"),
        rapid(20.0, -3.2, "return"),
        rapid(20.0, -4.0, "infeed"), feed(6.0, -4.0, "contour"), feed(6.0, 1.0, "contour"),
        rapid(20.0, 1.0, "return"),
    ])


def linuxcnc_moves(case: str) -> list[tuple[str, float, float]]:
    rows = []
    for line in (CONFORMANCE / case / "moves.tsv").read_text().splitlines():
        cols = line.split("\t")
        if cols[0] in ("rapid", "feed"):
            rows.append((cols[0], float(cols[1]), float(cols[3])))
    return rows


@pytest.mark.skipif(not (CONFORMANCE / "g72-facing").is_dir(), reason="no LinuxCNC conformance cases")
def test_g72_cuts_and_retracts_like_linuxcnc() -> None:
    # LinuxCNC's g72-facing: profile G1 X50 Z-40; X100 Z-39.999 from (50, 0), I3 (Δd) R0.1 (e), no
    # allowance (D0), so its level passes are comparable: it also cuts a level at the start Z (0), which
    # Fanuc's first infeed skips. Compare each level's cut (start, end) and retract point.
    theirs = linuxcnc_moves("g72-facing")
    passes = [(a[1:], b[1:], c[1:]) for a, b, c in zip(theirs, theirs[1:], theirs[2:])
              if b[0] == "feed" and a[0] == "rapid" and c[0] == "rapid" and b[1] == 100.0 and b[2] < 0]
    assert len(passes) == 13
    profile = [Seg("line", 50.0, 0.0, 50.0, -40.0, line=1), Seg("line", 50.0, -40.0, 100.0, -39.999, line=2)]
    ours = rough_facing((50.0, 0.0), profile, 3.0, 0.1, feed=400.0)
    mine = [(p.x, p.z) for p in ours if p.note in ("rough", "retract")]
    expect = [pt for start, end, retract in passes for pt in (end, retract)]
    assert len(mine) == len(expect)
    for (x, z), (ex, ez) in zip(mine, expect):
        assert math.isclose(x, ex, abs_tol=1.5e-4) and math.isclose(z, ez, abs_tol=1.5e-4)
    # The contour: LinuxCNC feeds (50, -40) -> (100, -39.999); so do we (ns is G1: a fed infeed).
    contour = [(m.kind, m.x, m.z) for m in ours if m.note in ("contour",)]
    assert contour == [("feed", 100.0, -39.999)]
    assert ("feed", 50.0, -40.0) in [(m.kind, m.x, m.z) for m in ours]


@pytest.mark.parametrize("profile, message", [
    # An undercut: X goes back toward the axis at line 12.
    ([Seg("line", 12, 2, 4, 2, line=10), Seg("line", 4, 2, 4, -4, line=11), Seg("line", 4, -4, 3, -6, line=12)],
     "not monotonic in X at line 12"),
    # Z reverses at line 12.
    ([Seg("line", 12, 2, 4, 2, line=10), Seg("line", 4, 2, 4, -4, line=11), Seg("line", 4, -4, 6, -3, line=12)],
     "not monotonic in Z at line 12"),
    # An arc passing its top (x extreme) inside: (4, -4) counter-clockwise about (4, -6) through
    # angle 90 degrees (x = 6) to (4, -8).
    ([Seg("line", 12, 2, 4, 2, line=10), Seg("line", 4, 2, 4, -4, line=11),
      Seg("ccw", 4, -4, 4, -8, cx=4.0, cz=-6.0, line=13)], "not monotonic in X at line 13"),
    ([Seg("cw", 12, 2, 4, 2, cx=8.0, cz=2.0, line=10), Seg("line", 4, 2, 4, -4, line=11)], "straight move"),
    ([Seg("line", 12, 2, 12, -2, line=10)], "first profile block .line 10. must move in X"),
])
def test_g71_refuses(profile: list[Seg], message: str) -> None:
    with pytest.raises(ProgramError, match=message):
        rough_turning((12.0, 2.0), profile, 1.0, 0.5)


def test_g71_type_ii_allows_a_pocket_that_type_i_refuses() -> None:
    pocket = [Seg("line", 12, 2, 4, 2, line=10), Seg("line", 4, 2, 4, -4, line=11),
              Seg("line", 4, -4, 2, -6, line=12), Seg("line", 2, -6, 6, -9, line=13),
              Seg("line", 6, -9, 12, -9, line=14)]
    with pytest.raises(ProgramError, match="monotonic in X at line 12"):
        rough_turning((12.0, 2.0), pocket, 1.0, 0.5)
    assert rough_turning((12.0, 2.0), pocket, 1.0, 0.5, type_ii=True)[-1] == TurnMove("rapid", 12.0, 2.0,
                                                                                      note="return")
    # A type I declaration with a Z move in ns is a contradiction.
    with pytest.raises(ProgramError, match="type II"):
        rough_turning((12.0, 2.0), [Seg("line", 12, 2, 4, 1, line=10), Seg("line", 4, 1, 4, -4, line=11)],
                      1.0, 0.5, type_ii=False)


def test_g71_refuses_bad_words() -> None:
    with pytest.raises(ProgramError, match="depth of cut must be positive"):
        rough_turning((12.0, 2.0), shaft(), 0.0, 0.5)
    with pytest.raises(ProgramError, match="retract"):
        rough_turning((12.0, 2.0), shaft(), 1.0, -0.5)
    with pytest.raises(ProgramError, match="finite"):
        rough_turning((12.0, 2.0), shaft(), math.inf, 0.5)
    with pytest.raises(ProgramError, match="levels .* exceed the limit of 1000"):
        rough_turning((12.0, 2.0), shaft(), 1e-5, 0.5, limit=1000)
