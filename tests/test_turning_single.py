"""G90, G92, G94 and G70: toolpaths derived by hand (radius values; the arithmetic in the comments)."""

from __future__ import annotations

import pytest

from postproc.cycles.turning import Seg, TurnMove, finishing, single_facing, single_threading, single_turning
from postproc.errors import ProgramError


def close(got: list[TurnMove], want: list[TurnMove]) -> None:
    assert len(got) == len(want), got
    for g, w in zip(got, want):
        assert (g.kind, g.feed, g.note) == (w.kind, w.feed, w.note), (g, w)
        for a, b in ((g.x, w.x), (g.z, w.z), (g.cx, w.cx), (g.cz, w.cz)):
            assert (a is None) == (b is None) and (a is None or b is None or abs(a - b) < 1e-9), (g, w)


def test_g90_straight() -> None:
    # From X50 Z2 (radius 25): G90 X40 Z-30 F0.2 -> radius 20.
    close(single_turning((25.0, 2.0), 20.0, -30.0, feed=0.2), [
        TurnMove("rapid", 20.0, 2.0, note="approach"),      # side 1: X to the cut
        TurnMove("feed", 20.0, -30.0, feed=0.2, note="cut"),  # side 2: along Z
        TurnMove("feed", 25.0, -30.0, feed=0.2, note="face out"),  # side 3: X back to 25
        TurnMove("rapid", 25.0, 2.0, note="return"),         # side 4
    ])


def test_g90_taper() -> None:
    # the cut starts at radius 20 + (-2.5) = 17.5 at Z2 and ends at (20, -30).
    close(single_turning((25.0, 2.0), 20.0, -30.0, r=-2.5, feed=0.2), [
        TurnMove("rapid", 17.5, 2.0, note="approach"),
        TurnMove("feed", 20.0, -30.0, feed=0.2, note="cut"),
        TurnMove("feed", 25.0, -30.0, feed=0.2, note="face out"),
        TurnMove("rapid", 25.0, 2.0, note="return"),
    ])


def test_g90_taper_against_u_beyond_start_is_refused() -> None:
    # U = 20 - 25 = -5 (radius); R = +6 would start the cut at 26, outside the start point.
    with pytest.raises(ProgramError, match="taper"):
        single_turning((25.0, 2.0), 20.0, -30.0, r=6.0)
    # R = +5 is the limit the Fanuc manual allows (|R| <= |U/2| in diameter terms).
    assert single_turning((25.0, 2.0), 20.0, -30.0, r=5.0)[0] == TurnMove("feed", 20.0, -30.0, feed=None,
                                                                            note="cut")


def test_g94_straight_and_taper() -> None:
    # From radius 30, Z2: G94 X20 Z-2 F0.2 -> radius 10.
    close(single_facing((30.0, 2.0), 10.0, -2.0, feed=0.2), [
        TurnMove("rapid", 30.0, -2.0, note="approach"),
        TurnMove("feed", 10.0, -2.0, feed=0.2, note="cut"),
        TurnMove("feed", 10.0, 2.0, feed=0.2, note="turn out"),
        TurnMove("rapid", 30.0, 2.0, note="return"),
    ])
    # the cut starts at Z = -2 + (-1) = -3 at radius 30.
    assert single_facing((30.0, 2.0), 10.0, -2.0, r=-1.0, feed=0.2)[0] == TurnMove("rapid", 30.0, -3.0,
                                                                                   note="approach")


def test_g92_square_exit() -> None:
    # From radius 15, Z5: G92 X18 Z-20 F1.5 -> radius 9.
    close(single_threading((15.0, 5.0), 9.0, -20.0, 1.5), [
        TurnMove("rapid", 9.0, 5.0, note="approach"),
        TurnMove("feed", 9.0, -20.0, feed=1.5, note="thread"),
        TurnMove("rapid", 15.0, -20.0, note="pull out"),
        TurnMove("rapid", 15.0, 5.0, note="return"),
    ])


def test_g92_chamfer_on_a_taper() -> None:
    # the thread runs from (8, 5) to (9, -20), 25 long. Chamfer 10 tenths of 1.5 = 1.5:
    # it starts 1.5 before Z-20, at t = 1 - 1.5/25 = 0.94: x = 8 + 0.94 * 1 = 8.94, z = 5 - 0.94 * 25 = -18.5,
    # and ends 1.5 further out at 45 degrees: (9 + 1.5, -20) = (10.5, -20).
    close(single_threading((15.0, 5.0), 9.0, -20.0, 1.5, r=-1.0, chamfer=10), [
        TurnMove("rapid", 8.0, 5.0, note="approach"),
        TurnMove("feed", 8.94, -18.5, feed=1.5, note="thread"),
        TurnMove("feed", 10.5, -20.0, feed=1.5, note="thread chamfer"),
        TurnMove("rapid", 15.0, -20.0, note="pull out"),
        TurnMove("rapid", 15.0, 5.0, note="return"),
    ])


@pytest.mark.parametrize("kwargs, message", [
    ({"chamfer": 100}, "0 to 99"),
    ({"chamfer": 99}, "longer than the thread"),     # 9.9 * 3 = 29.7 > 25
    ({"lead": 0.0}, "lead"),
])
def test_g92_refuses(kwargs: dict[str, float], message: str) -> None:
    args = {"lead": 3.0, **kwargs}
    with pytest.raises(ProgramError, match=message):
        single_threading((15.0, 5.0), 9.0, -20.0, **args)  # type: ignore[arg-type]


def test_g92_chamfer_beyond_start_x_is_refused() -> None:
    # Chamfer 1.5 outward from radius 9 would end at 10.5, past the start's radius 10.
    with pytest.raises(ProgramError, match="beyond the start"):
        single_threading((10.0, 5.0), 9.0, -20.0, 1.5, chamfer=10)


def test_g70_runs_the_profile_with_its_own_feeds_and_returns() -> None:
    # A = (30, 2). G0 X10 (rapid); G1 Z-10 F0.1; G2 X15 Z-15 R5 (centre (15, -10): start angle
    # atan2(10-15, -10+10) = -90 deg, end atan2(15-15, -15+10) = 180 deg: a clockwise quarter);
    # G1 X30 without an F of its own in the profile -> the F modal at G70 (0.3).
    profile = [
        Seg("line", 30.0, 2.0, 10.0, 2.0, rapid=True, line=11),
        Seg("line", 10.0, 2.0, 10.0, -10.0, feed=0.1, line=12),
        Seg("cw", 10.0, -10.0, 15.0, -15.0, cx=15.0, cz=-10.0, feed=0.1, line=13),
        Seg("line", 15.0, -15.0, 30.0, -15.0, line=14),
    ]
    close(finishing((30.0, 2.0), profile, feed=0.3), [
        TurnMove("rapid", 10.0, 2.0, note="finish"),
        TurnMove("feed", 10.0, -10.0, feed=0.1, note="finish"),
        TurnMove("cw", 15.0, -15.0, 15.0, -10.0, feed=0.1, note="finish"),
        TurnMove("feed", 30.0, -15.0, feed=0.3, note="finish"),
        TurnMove("rapid", 30.0, 2.0, note="return"),
    ])


def test_g70_profile_must_chain() -> None:
    with pytest.raises(ProgramError, match="line 12"):
        finishing((30.0, 2.0), [Seg("line", 30.0, 2.0, 10.0, 2.0, line=11),
                                Seg("line", 10.0, 2.5, 10.0, -10.0, line=12)])
    with pytest.raises(ProgramError, match="arc at line 13"):
        finishing((10.0, 0.0), [Seg("cw", 10.0, 0.0, 15.0, -15.0, cx=15.0, cz=-10.0, line=13)])
