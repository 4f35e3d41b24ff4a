"""Rigid tapping towards SINUMERIK (issue 26, task 2): SINUMERIK taps by the strokes ``G331 Z.. K.. S..`` in and
``G332 Z.. K..`` out, the spindle reversed by the control, K signed by the direction, after ``SPOS=`` has put
the spindle under position control ([K] SINUMERIK 840D sl Fundamentals, "Tapping without compensating chuck
(G331, G332)", as quoted at https://en.cncforum.net/t/siemens-cnc-milling-g331-g332-codes-thread-interpolation/197:
``SPOS=0`` / ``G331 Z-25 K0.8 S600`` / ``G332 Z5 K0.8``).

* LinuxCNC ``G33.1`` (seeded: absolute or incremental, either spindle direction) and Fanuc ``M29`` +
  ``G84``/``G74`` (seeded) translate to SINUMERIK: a ``G33.1`` as ``CYCLE84`` called once where the tool
  stands (``tests/test_siemens_tap_cycle.py`` derives its parameters), a Fanuc tap cycle as ``MCALL CYCLE84``
  where it moves alike, else as ``SPOS`` and the two strokes; never a feed move in their place, the SINUMERIK
  text's own simulation moves as rs274 runs the LinuxCNC source, and ``verify`` passes.
* ``SPOS=<angle>`` reads back as an oriented spindle stop: an event of its own, except right before a tap,
  where it is the tap's preparation (as Fanuc's ``M29``); SINUMERIK programs with SPOS, G331 and G332 round
  trip byte for byte; what is not modelled is kept verbatim by name.
"""

from __future__ import annotations

import random
from typing import Any

import pytest

from postproc.errors import ErrorList
from postproc.simulate.stream import prepared_taps
from tests.support.tap_strokes import events, moves, to, verified
from tests.test_rigid_tapping import _fanuc_rigid_program, _linuxcnc_taps, needs_rs274, oracle, same_moves

PROGRAMS = 8


def test_g33_1_in_g91_becomes_spos_and_the_two_strokes_hand_derived() -> None:
    text = "G21 G90 G17\nS500 M4\nG0 X1 Y2 Z5 F200\nG91 G33.1 Z-8 K1\nM2\n"
    # in G91 (CYCLE84's levels are absolute): M4, a left-hand thread, K-1; SPOS=0 (the set-up's orientation
    # angle) before G331; in to 8 below the start Z5 (G90 for the strokes), out to Z5; then G1 with the spindle
    # direction (back to speed control) and the feed said again, and G91 back
    assert to("linuxcnc", "siemens", text) == ("G17 G710 G90\nS500 M4\nG0 X1. Y2. Z5. F200.\nSPOS=0\n"
                                               "G90 G331 Z-3. K-1. S500\nG332 Z5. K-1.\nG91 G1 F200. M4\nM2\n")
    verified("linuxcnc", text, to("linuxcnc", "siemens", text), "siemens")


def test_g33_1_in_g90_becomes_cycle84_once_hand_derived() -> None:
    text = "G21 G90 G17\nS500 M4\nG0 X1 Y2 Z5 F200\nG33.1 Z-3 K1\nM2\n"
    # from Z5 (RTP = RFP = 5, SDIS 0) to Z-3 (DP); M4: SDAC 4, a left-hand thread, PIT -1; SST = SST1 = S
    assert to("linuxcnc", "siemens", text) == ("G17 G710 G90\nS500 M4\nG0 X1. Y2. Z5. F200.\n"
                                               "CYCLE84(5., 5., 0, -3., , , 4, , -1., 0, 500, 500)\nM2\n")
    verified("linuxcnc", text, to("linuxcnc", "siemens", text), "siemens")


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_g33_1_reaches_siemens_as_cycle84_and_moves_as_rs274(seed: int) -> None:
    text = _linuxcnc_taps(random.Random(2600 + seed))
    siemens = to("linuxcnc", "siemens", text)
    taps = text.count("G33.1")
    # CYCLE84 once in G90, the strokes in G91 (the cycle's levels are absolute)
    assert siemens.count("CYCLE84(") + siemens.count("G331") == taps, siemens
    assert siemens.count("SPOS=0") == siemens.count("G331") == siemens.count("G332"), siemens
    same_moves(moves(siemens, "siemens"), oracle(text))
    verified("linuxcnc", text, siemens, "siemens")


@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_a_fanuc_rigid_tap_reaches_siemens_as_cycle84_or_strokes(seed: int) -> None:
    text = _fanuc_rigid_program(random.Random(2700 + seed))
    siemens = to("fanuc", "siemens", text)
    assert "CYCLE84(" in siemens or siemens.count("SPOS=0") == siemens.count("G331") == siemens.count("G332") > 0, \
        siemens
    assert [m for m in moves(siemens, "siemens") if m["move"] == "tap"] and "G1 Z" not in siemens
    assert "M29" not in siemens.replace(";M29", "")
    assert [m["move"] for m in moves(siemens, "siemens")] == [m["move"] for m in moves(text, "fanuc")]
    verified("fanuc", text, siemens, "siemens")


SIEMENS_TAPS = ("G710 G90\nS400 M3\nG0 X10 Y10 Z5\nSPOS=0\nG331 Z-10 K1.5 S400\nG332 Z5\nG331 Z-4 K1.5\n"
                "G332 Z5 K1.5\nG1 F100 M3\nSPOS=90\nG0 Z20\nSPOS=R1\nM30\n")


def test_a_siemens_program_taps_at_its_pitch_and_spos_is_an_oriented_stop() -> None:
    text = SIEMENS_TAPS.replace("SPOS=R1\n", "")
    evs = events(text, "siemens")
    taps = [(e["z"], e["f"]) for e in evs if e.get("move") == "tap"]
    assert taps == [(-10, 1.5), (5, 1.5), (-4, 1.5), (5, 1.5)]  # a second G331 under position control: no SPOS
    # SPOS=0 right before G331 is the tap's preparation (no event); SPOS=90 before a rapid is an oriented stop
    assert [e for e in evs if "event" in e and e["event"] != "end"] == [
        {"line": 2, "event": "spindle", "dir": "cw"}, {"line": 10, "event": "orient", "angle": 90}]
    assert [e["line"] for e in evs if e.get("move") == "rapid"] == [3, 11]


def test_siemens_taps_and_spos_round_trip_byte_for_byte() -> None:
    assert to("siemens", "siemens", SIEMENS_TAPS) == SIEMENS_TAPS


def test_an_oriented_stop_reaches_linuxcnc_and_back() -> None:
    text = "G21 G90\nS400 M3\nG0 X1 Y2 Z5\nM19 R90\nG0 Z20\nM2\n"
    siemens = to("linuxcnc", "siemens", text)
    assert "SPOS=90\n" in siemens
    verified("linuxcnc", text, siemens, "siemens")


def test_an_orientation_is_held_back_only_while_a_tap_may_follow() -> None:
    orient = {"line": 4, "event": "orient", "angle": 0}
    tap = {"line": 5, "move": "tap", "z": -1.0}
    rapid = {"line": 5, "move": "rapid", "z": 1.0}
    out: list[dict[str, Any]] = [dict(rapid), dict(orient)]
    held = prepared_taps(out, None)
    assert out == [rapid] and held == orient  # the block ends with it: what follows is not known yet
    out = [dict(tap)]
    assert prepared_taps(out, held) is None and out == [tap]  # a tap follows: its preparation
    out = [dict(rapid)]
    assert prepared_taps(out, orient) is None and out == [orient, rapid]  # a move follows: an event


@pytest.mark.parametrize("word", ["SPOS=DC(10)", "SPOS=ACP(10)", "SPOS[2]=10"])
def test_a_positioning_mode_or_another_spindle_is_kept_verbatim_by_name(word: str) -> None:
    text = f"G710 G90\nS400 M3\n{word}\nM30\n"
    assert to("siemens", "siemens", text) == text
    with pytest.raises(ErrorList) as info:
        events(text, "siemens")
    error = info.value.errors[0]
    assert error.location is not None and error.location.line == 3 and "SPOS" in str(error)


ISG_STROKES = "G71 G90 G17\nM03 S500\nG00 X1 Y2 Z10\nG331 Z-10 K1.5\nG332 Z10 K1.5\nM30\n"


def test_isg_strokes_reach_siemens_as_its_own_after_spos_hand_derived() -> None:
    """ISG and SINUMERIK spell and mean G331/G332 alike (``postproc.isg_family.taps``): the strokes were refused
    towards SINUMERIK (no synchronised tap for it); they are written as read, after SPOS=0 (the set-up's angle)
    that puts SINUMERIK's spindle under position control."""
    assert to("isg", "siemens", ISG_STROKES) == ("G17 G710 G90\nS500 M3\nG0 X1. Y2. Z10.\nSPOS=0\n"
                                                 "G331 Z-10. K1.5 S500\nG332 Z10. K1.5\nM30\n")
    verified("isg", ISG_STROKES, to("isg", "siemens", ISG_STROKES), "siemens")


def test_siemens_strokes_reach_isg_as_its_own() -> None:
    siemens = to("isg", "siemens", ISG_STROKES)
    isg = to("siemens", "isg", siemens)
    assert isg.splitlines()[3:6] == ["M19", "G331 Z-10. K1.5 S500", "G332 Z10. K1.5"]
    verified("siemens", siemens, isg, "isg")
