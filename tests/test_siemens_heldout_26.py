"""SINUMERIK jumps and arc centres (issue 26, tests/heldout/siemens/cead_goto.mpf, cead_arc.mpf): ``GOTOC`` to a missing target goes on
with the next block (alarm 14080 suppressed), and a jump destination may be a bare block number (``GOTOF 90``)
[K: SINUMERIK 840D sl Programming Manual Fundamentals, "Program jumps to jump markers"]. Expected paths are
worked by hand from the programs below."""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.simulate.toolpath import toolpath_events


def _xs(text: str) -> list[float]:
    return [e["x"] for e in toolpath_events(io.StringIO(text), file="t.mpf", dialect="siemens") if "move" in e]


JUMPS = ("N10 G1 X5 Y0 F100\nN20 R1=2\nN30 GOTOC NOWHERE\nN40 X10\nN50 IF R1>1 GOTOC N70\nN60 X20\n"
         "N70 X30\nN80 GOTOF 100\nN90 X40\nN100 X50\nN110 M30\n")


def test_gotoc_to_a_missing_target_goes_on_and_a_bare_number_is_a_block_number() -> None:
    """N30 falls through to N40 (X10); N50 jumps over N60 to N70 (X30); N80 jumps over N90 to N100 (X50)."""
    assert _xs(JUMPS) == [5.0, 10.0, 30.0, 50.0]


@pytest.mark.parametrize("word", ["GOTOF", "GOTO", "GOTOB"])
def test_other_jumps_to_a_missing_target_stay_errors(word: str) -> None:
    with pytest.raises(ErrorList) as info:
        _xs(f"N10 G1 X0 Y0 F100\nN20 {word} NOWHERE\nN30 X10\nM30\n")
    assert [str(e) for e in info.value.errors] == [f"t.mpf:2:{len(word) + 6}: error: {word} nowhere: no such "
                                                   f"target in this file"]


def test_gotob_to_a_bare_number_jumps_back() -> None:
    """R1 counts 2, 1, 0: X takes 10 and 20 (R1 = 2 then 1 at N30), then the loop ends."""
    text = "N10 G1 X5 Y0 F100\nN20 R1=2\nN30 X=30-10*R1\nN40 R1=R1-1\nN50 IF R1>0 GOTOB 30\nN60 M30\n"
    assert _xs(text) == [5.0, 10.0, 20.0]


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "isg"])
def test_a_missing_gotoc_target_is_evaluated_for_another_controller(target: str) -> None:
    """A target's jump to a missing block is an alarm: the program reaches it evaluated (same moves), with
    the reason, never as a jump to nowhere."""
    out, err = io.StringIO(), io.StringIO()
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=err)
    translate(io.StringIO(JUMPS), out, file="t.mpf", source="siemens", target=target, diagnostics=diagnostics)
    assert "a jump to nowhere, which is missing, goes on with the next block" in err.getvalue()
    assert "GOTO" not in re.sub(r"\(.*?\)", "", out.getvalue()).upper()


def test_a_gotoc_whose_target_exists_stays_a_fanuc_jump() -> None:
    out = io.StringIO()
    translate(io.StringIO(JUMPS.replace("GOTOC NOWHERE", "GOTOC N60")), out, file="t.mpf", source="siemens",
              target="fanuc")
    lines = out.getvalue().splitlines()
    assert "N30 GOTO 60" in lines and "N80 GOTO 100" in lines


# -- a centre word along the plane's normal (tests/heldout/siemens/cead_arc.mpf:11) -----------------------
def _arcs(text: str) -> list[tuple[float, ...]]:
    return [(e["x"], e["y"], e["z"], e["cx"], e["cy"]) for e in
            toolpath_events(io.StringIO(text), file="t.mpf", dialect="siemens") if e.get("move") == "cw"]


@pytest.mark.parametrize("extra", ["", " K5", " K=-3"])
def test_a_k_on_a_g17_helix_moves_nothing(extra: str) -> None:
    """From (0, 50, 0) about (0, 25), clockwise half a turn to (0, 0), Z rising to 10: the K component of the
    centre point lies along the helix's axis, so the path is the same with or without it."""
    text = f"G17 G1 X0 Y50 Z0 F1000\nG2 X0 Y0 Z10 I0 J-25{extra}\nM30\n"
    assert _arcs(text) == [(0.0, 0.0, 10.0, 0.0, 25.0)]


def test_the_fanuc_reader_still_refuses_a_centre_off_the_plane() -> None:
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO("G17 G90 G1 X0 Y50 Z0 F1000\nG2 X0 Y0 Z10 I0 J-25 K5\nM30\n"),
                             file="t.nc", dialect="fanuc"))
    assert "arc centre offset along Z is outside the XY plane" in str(info.value.errors[0])
