"""Rigid tapping towards ISG (issue 26): ISG taps by two strokes, ``G331 Z.. K.. S..`` in and ``G332 Z.. K..``
out with the spindle reversed by the control, K signed by the thread's hand ([V] Beckhoff TF5200
programming manual, "Tapping (G331/G332)").

* LinuxCNC ``G33.1`` (seeded, as ``test_rigid_tapping`` writes them: absolute or incremental, either
  spindle direction) and Fanuc ``M29`` + ``G84``/``G74`` (seeded) translate to ISG: the strokes are there,
  never a feed move in their place, the moves are the source's, the ISG text's own simulation agrees with
  rs274 on the LinuxCNC source, and ``verify`` passes.
* Hand-derived text for one tap; ISG programs with G331/G332 read into taps at the pitch (the hand from the
  sign of K), G332's K optional, and located errors for what is not modelled; a lone stroke towards
  LinuxCNC is refused by name in either ``--on-unsupported`` mode (from ISG and from SINUMERIK, which
  writes the same strokes: helpers shared in ``tests/support/tap_strokes.py``).
"""

from __future__ import annotations

import random

import pytest

from postproc.errors import ErrorList
from tests.support.tap_strokes import moves, to, verified
from tests.test_rigid_tapping import _fanuc_rigid_program, _linuxcnc_taps, needs_rs274, oracle, same_moves

PROGRAMS = 12


def test_g33_1_becomes_the_two_strokes_hand_derived() -> None:
    text = "G21 G90 G17\nS500 M4\nG0 X1 Y2 Z5 F200\nG91 G33.1 Z-8 K1\nM2\n"
    # M4: a left-hand thread, K-1; in to 8 below the start Z5 (G90 for the strokes), out to Z5; then G01 with
    # the spindle direction and feed said again, and G91 back
    assert to("linuxcnc", "isg", text) == ("G17 G71 G90\nS500 M04\nG00 X1. Y2. Z5. F200.\n"
                                           "G90 G331 Z-3. K-1. S500\nG332 Z5. K-1.\nG91 G01 F200. M04\nM02\n")
    verified("linuxcnc", text, to("linuxcnc", "isg", text), "isg")


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_g33_1_reaches_isg_as_strokes_and_moves_as_rs274(seed: int) -> None:
    text = _linuxcnc_taps(random.Random(2000 + seed))
    isg = to("linuxcnc", "isg", text)
    assert isg.count("G331") == isg.count("G332") == text.count("G33.1"), isg
    same_moves(moves(isg, "isg"), oracle(text))
    verified("linuxcnc", text, isg, "isg")


@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_a_fanuc_rigid_tap_reaches_isg_as_strokes(seed: int) -> None:
    text = _fanuc_rigid_program(random.Random(1000 + seed))
    isg = to("fanuc", "isg", text)
    taps = sum(1 for line in text.splitlines() if line.startswith(("G98", "G99", "X")))
    assert isg.count("G331") == isg.count("G332") == taps and "M29" not in isg.replace("(M29", ""), isg
    assert [m["move"] for m in moves(isg, "isg")] == [m["move"] for m in moves(text, "fanuc")]
    verified("fanuc", text, isg, "isg")


def test_an_isg_program_taps_at_its_pitch_each_stroke_one_move() -> None:
    text = "%t\nG71 G90\nS400 M03\nG00 X10 Y10 Z5\nG331 Z-10 K1.5 S400\nG332 Z5\nG331 Z-4 K0.5\nG332 Z5 K0.5\nM30\n"
    taps = [(m["z"], m["f"]) for m in moves(text, "isg") if m["move"] == "tap"]
    assert taps == [(-10, 1.5), (5, 1.5), (-4, 0.5), (5, 0.5)]  # a G332 without K taps at its G331's pitch
    assert to("isg", "isg", text) == text


@pytest.mark.parametrize("text, where", [
    ("%t\nG71\nS400 M03\nG00 Z5\nG331 Z-10 K-1.5\nM30\n", (5, "K")),      # a left-hand stroke, spindle M03
    ("%t\nG71\nS400 M03\nG00 Z5\nG331 Z-10\nM30\n", (5, "G")),            # no pitch
    ("%t\nG71\nS400 M03\nG00 Z5\nG331 Z-10 K1\nG332 Z5 K2\nM30\n", (6, "K")),  # G332's pitch not G331's
])
def test_what_the_strokes_do_not_model_is_a_located_error(text: str, where: tuple[int, str]) -> None:
    with pytest.raises(ErrorList) as info:
        moves(text, "isg")
    line, letter = where
    error = info.value.errors[0]
    assert error.location is not None and error.location.line == line
    assert text.splitlines()[line - 1][error.location.col - 1] == letter


LONE_STROKES = {"isg": "%t\nG71 G90\nS400 M03\nG00 X10 Y10 Z5\nG331 Z-10 K1.5 S400\nG332 Z5\nM30\n",
                "siemens": "G710 G90\nS400 M3\nG0 X10 Y10 Z5\nSPOS=0\nG331 Z-10 K1.5 S400\nG332 Z5\nM30\n"}
"""A tap as its two strokes (lines 5 and 6), in each dialect that writes them."""


@pytest.mark.parametrize("source", sorted(LONE_STROKES))
@pytest.mark.parametrize("mode", ["error", "warn"])
def test_a_lone_stroke_towards_linuxcnc_is_refused(source: str, mode: str) -> None:
    with pytest.raises(ErrorList) as info:
        to(source, "linuxcnc", LONE_STROKES[source], mode)
    assert [e.location.line for e in info.value.errors if e.location][:2] == [5, 6]
    assert all("stroke" in str(e) for e in info.value.errors)
