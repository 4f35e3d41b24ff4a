"""Fagor ``G81``/``G89`` with no dwell ``K`` (issue 26, defects).

The Fagor manual says what a cycle block without ``K`` does: "[K5] Dwell ... If not programmed, the CNC will take
the value of K0" [V: Fagor 8055-M programming manual p.162, G81; K for the 8070 and for G89, whose words are the
same]. So a ``G81`` without ``K`` (or with ``K0``) drills with no dwell: Fanuc's and LinuxCNC's ``G81``, and a
``G89`` without one bores with the feed out and no dwell: their ``G85``. Before, the reader took every Fagor
``G81`` as the dwelling cycle, and a Fanuc target got ``G82`` with no ``P`` (a dwell its manual does not define
without ``P``), LinuxCNC a ``G82`` that rs274 refuses ("G82 needs a dwell time P").
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support import rs274
from tests.support.pair_checks import PairChecks

CHECK = PairChecks(MachineSetup())
HEAD = "%DRILL\nG71 G90 G17\nG00 X0 Y0 Z50\nS1000 M03\n"


def _program(cycle: str) -> str:
    return HEAD + cycle + "\nX10\nG80\nM30\n"


def _cycle_line(out: str) -> str:
    return next(line for line in out.splitlines() if " G8" in line or line.startswith("G8"))


@pytest.mark.parametrize(("cycle", "fanuc"), [
    ("G81 G99 Z5 I-10 F100", "G81"), ("G81 G99 Z5 I-10 K0 F100", "G81"), ("G89 G99 Z5 I-10 F100", "G85"),
    ("G81 G99 Z5 I-10 K0.5 F100", "G82"), ("G89 G99 Z5 I-10 K0.5 F100", "G89"),
])
def test_a_cycle_without_a_dwell_is_written_without_one(cycle: str, fanuc: str) -> None:
    program = _program(cycle)
    out = CHECK.translate(program, "fagor", "fanuc")
    line = _cycle_line(out)
    assert f"{fanuc} " in line, out
    assert ("P500" in line) == ("K0.5" in cycle), out
    CHECK.verify(program, out, "fagor", "fanuc")


@pytest.mark.parametrize("cycle", ["G81 G99 Z5 I-10 F100", "G81 G99 Z5 I-10 K0 F100"])
def test_the_simulation_dwells_nowhere_without_k(cycle: str) -> None:
    events = list(toolpath_events(io.StringIO(_program(cycle)), file="in.nc", dialect="fagor"))
    assert [e for e in events if e.get("event") == "dwell"] == []
    # hand-derived: to R (Z5) at each hole, feed to I-10, rapid back to R (G99)
    assert [(e["move"], e["x"], e["z"]) for e in events if "move" in e and e["line"] >= 5] == [
        ("rapid", 0, 5), ("feed", 0, -10), ("rapid", 0, 5), ("rapid", 10, 5), ("feed", 10, -10), ("rapid", 10, 5)]


def test_towards_linuxcnc_the_drill_runs_in_rs274() -> None:
    program = _program("G81 G99 Z5 I-10 F100")
    out = CHECK.translate(program, "fagor", "linuxcnc")
    assert "G81 " in _cycle_line(out), out
    CHECK.verify(program, out, "fagor", "linuxcnc")
    if not rs274.available():
        pytest.skip("rs274 is not installed")
    theirs = rs274.motions(rs274.canonical_moves(rs274.run_rs274(out, tool_table="T1 P1 Z0 D0\n")))
    ours = rs274.motions(e for e in toolpath_events(io.StringIO(program), file="in.nc", dialect="fagor")
                         if "move" in e)
    rs274.assert_same_moves(ours, theirs, out)


def test_a_fagor_copy_keeps_g81_without_k() -> None:
    program = _program("G81 G99 Z5 I-10 F100")
    assert CHECK.translate(program, "fagor", "fagor") == program


@pytest.mark.parametrize(("cycle", "code"), [("G81 G99 Z5 I-10 F100", "G81"), ("G89 G99 Z5 I-10 F100", "G89")])
def test_a_rewritten_fagor_cycle_without_a_dwell_is_its_own_code_again(cycle: str, code: str) -> None:
    """A Fagor copy that rewrites its blocks (``--units inch``) writes the plain drill/bore from Fagor's code
    table (``G81``/``G89`` without ``K``: the manual's K0), and reading the result back gives the same holes: the
    toolpath (millimetres, as the simulation reports it), hand-derived, feeds to the bottom, rapids back to R
    (G89: feeds back), and dwells nowhere. (Before, the table had no row for the neutral drill/bore: "cannot express the drill
    cycle".)"""
    program = _program(cycle)
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="fagor", target="fagor", units="inch")
    line = _cycle_line(out.getvalue())
    assert code in line.split() and "K" not in line, out.getvalue()
    events = list(toolpath_events(io.StringIO(out.getvalue()), file="out.nc", dialect="fagor"))
    assert [e for e in events if e.get("event") == "dwell"] == []
    moves = [(e["move"], round(e["x"], 5), round(e["z"], 5)) for e in events if "move" in e and e["line"] >= 5]
    r, bottom, x = 5, -10, 10
    back = "rapid" if code == "G81" else "feed"  # G89 (Fanuc's G85 without K) feeds out
    assert moves == [("rapid", 0, r), ("feed", 0, bottom), (back, 0, r),
                     ("rapid", x, r), ("feed", x, bottom), (back, x, r)], out.getvalue()
