"""Cutter compensation of a Haas mill (``rs274.cutter_rules.HAAS_A``/``HAAS_B``): Fanuc's straight-corner rules,
with what the Haas manual leaves out refused by name, resolved into moves for grbl and grblHAL.

The program is the first lap of a held-out Haas hand program (``tests/heldout/haas/enier_mill_hp_4.nc``, lines
18-29 and its 1st lap: G41 D01 on a 3 x 2 in rectangle cut clockwise, tool on the left, so outside it). Every
expected point is derived by hand from the rules the Haas manual gives (setting 43 A: the start-up move ends
square to the next move at its start; setting 58 FANUC: an outside corner of at most 270 degrees is a sharp
corner where the offset paths meet; the G40 block starts offset, square to the last move at its end, and ends
at the programmed point), with the 1/4 in end mill's radius r = 0.125 in.
"""

from __future__ import annotations

import io
import pytest

from dialects.fanuc import Fanuc
from postproc.api import translate
from postproc.rs274.cutter_rules import HAAS_A, HAAS_B, HAAS_T, HAAS_T_B
from postproc.errors import Diagnostics, ErrorList
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

R = 0.125
"""in: a 1/4 in end mill (D01)."""


def _haas(startup: str = "A") -> MachineSetup:
    setup = with_tools(radii={1: R * 25.4}, lengths={1: 100.0})
    setup.controller.variant = "haas"
    setup.controller.cutter_startup = startup  # type: ignore[assignment]
    return setup


LAP = ("G17 G20 G40 G49 G80\nT01 M06\nG00 G90 G17 G40 G49 G54\nG00 G54 X-1.0 Y-1.0\nS10000 M03\n"
       "G43 H01 Z0.1\nG01 Z-0.325 F108.0\nG41 D01 X0.25\nY2.25\nX3.25\nY0.25\nX0.25\nG40 X-1.0\nG00 Z0.1\nM30\n")
HAND = [(0.25 - R, -1.0),  # start-up along +X, ends square to the next move (+Y): r to its left, -X
        (0.25 - R, 2.25 + R),  # outside corners of 270 degrees: the offset paths meet
        (3.25 + R, 2.25 + R),
        (3.25 + R, 0.25 - R),
        (0.25, 0.25 - R),  # the last compensated move (-X) ends square to itself at its end: r to its left, -Y
        (-1.0, 0.25)]  # the G40 block ends at its programmed point


def _plane_moves(text: str, dialect: str, setup: MachineSetup) -> list[tuple[float, float]]:
    """The controlled points of the feed moves in the plane after the plunge, in inches."""
    events = toolpath_events(io.StringIO(text), file="t.nc", dialect=dialect, setup=setup)
    moves = [{**e, **e.get("controlled", {})} for e in events if "move" in e]
    feeds = [m for m in moves if m["move"] == "feed"]
    return [(round(m["x"] / 25.4, 6), round(m["y"] / 25.4, 6)) for m in feeds[1:]]


def _close(got: list[tuple[float, float]], expected: list[tuple[float, float]], tolerance: float) -> None:
    assert len(got) == len(expected), got
    for (x, y), (ex, ey) in zip(got, expected):
        assert abs(x - ex) <= tolerance and abs(y - ey) <= tolerance, (got, expected)


def test_the_set_up_chooses_the_haas_rules_by_setting_43() -> None:
    assert Fanuc.cutter_rules(_haas()) is HAAS_A
    assert Fanuc.cutter_rules(_haas("B")) is HAAS_B
    lathe = _haas()
    lathe.input.machine_type = "lathe"
    assert Fanuc.cutter_rules(lathe) is HAAS_T  # a Haas lathe: Fanuc T's rules (tests/test_haas_nose.py)
    lathe.controller.cutter_startup = "B"
    assert Fanuc.cutter_rules(lathe) is HAAS_T_B


def test_the_haas_lap_is_simulated_by_hand() -> None:
    _close(_plane_moves(LAP, "fanuc", _haas()), HAND, 1e-9)


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
def test_the_haas_lap_is_written_as_its_compensated_moves(target: str) -> None:
    if target not in default_registry().dialects:
        pytest.skip(f"the {target} plugin is not installed")
    setup = _haas()
    out = io.StringIO()
    translate(io.StringIO(LAP), out, file="t.nc", source="fanuc", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    text = out.getvalue()
    assert "G41" not in text and "G42" not in text, text
    _close(_plane_moves(text, target, setup), HAND, 1e-4)  # written to 4 places of an inch
    report = verify_lines(io.StringIO(LAP), io.StringIO(text), file_in="t.nc", file_out="out", source="fanuc",
                          target=target, setup=setup)
    assert report.ok, report.summary()


def _refusal(text: str, setup: MachineSetup | None = None) -> str:
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(text), file="t.nc", dialect="fanuc", setup=setup or _haas()))
    return str(caught.value.errors[0])


HEAD = "G20 G90 G17 G0 X0 Y0 Z0\n"


def test_what_the_haas_manual_leaves_out_is_refused_by_name() -> None:
    """An arc as the start-up move, an arc as the cancel (exit) move, and an acute outside corner (over 270 degrees
    outside: the manual's "extra linear motion", whose ends it does not give) are refused as not simulated,
    where Fanuc's own rules run or alarm."""
    name = HAAS_A.name
    assert _refusal(HEAD + "G41 D01 G3 X2. Y0 R1. F10.\nG1 Y2.\nG40 X0 Y0\nM30\n") == (
        "t.nc:2:1: error: an arc as the start-up move of cutter compensation cannot be simulated under the rules of "
        f"{name} (how its control runs one is not in our sources: start it with a straight move)")
    assert _refusal(HEAD + "G41 D01 G1 X1. F10.\nY1.\nG40 G2 X2. Y0 R1.\nM30\n") == (
        f"t.nc:4:1: error: an arc right after cutter compensation is cancelled cannot be simulated under the rules "
        f"of {name} (how its control runs one is not in our sources)")
    # the tool on the left of +X then back down-left at 30 degrees off -X: a corner of 330 degrees outside
    assert _refusal(HEAD + "G41 D01 G1 X1. F10.\nY1.\nX3.\nX0 Y0.\nG40 X-1.\nM30\n").startswith(
        "t.nc:5:1: error: an acute outer corner (over 270 degrees outside) cannot be simulated under the rules of "
        f"{name}")
    fanuc = with_tools(radii={1: R * 25.4})  # the same corner under Fanuc's rules: extended by the radius
    assert len(list(toolpath_events(io.StringIO(HEAD + "G41 D01 G1 X1. F10.\nY1.\nX3.\nX0 Y0.\nG40 X-1.\nM30\n"),
                                    file="t.nc", dialect="fanuc", setup=fanuc))) > 0


def test_a_haas_without_the_radius_names_the_tool_to_add() -> None:
    setup = MachineSetup()
    setup.controller.variant = "haas"
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(LAP.replace("G43 H01 Z0.1", "Z0.1")), io.StringIO(), file="t.nc", source="fanuc",
                  target="grbl", setup=setup, diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert [str(e) for e in caught.value.errors] == [
        't.nc:8:1: error: the set-up gives tool radius register 1 no value: add <Tool number="1" radius=".."/> to '
        "its <Tools>, or write the register in the program"]


def test_where_the_rules_are_not_modelled_the_refusal_names_what_is_unknown() -> None:
    """An ISG program's cutter compensation towards grbl: not "grbl cannot express it" (a compensated path is
    what grbl gets where the source's rules are known) but which rules are not known."""
    with pytest.raises(ErrorList) as isg:
        translate(io.StringIO("G17 G90 G0 X0 Y0\nG41 D1 G1 X10 F100\nG40 X0\nM30\n"), io.StringIO(), file="t.nc",
                  source="isg", target="grbl", setup=with_tools(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert [str(e) for e in isg.value.errors] == [
        "t.nc:2:1: error: cutter radius compensation (left) cannot be resolved into moves for grbl, which has none: "
        "the cutter compensation rules of the isg control are not modelled"]
