"""A Fanuc tool length change written alone, translated for a Fagor (``Fagor.LENGTH_AT_AXIS_MOVE``,
``postproc.lowering.length_timing``).

The facts: Fanuc applies a ``G43 H``/``G49`` given without Z at the next move of any axis (the simulation's
model, ``postproc.compensation.tool_length``); a Fagor "starts applying it when the longitudinal
(perpendicular) axis starts moving" [V: Fagor CNC 8055/8055i programming manual 8.2]. So the move that applies
it on the Fanuc gets the Z the program stands at: the Fagor's Z then moves, to the same programmed Z, with the
new length, as the Fanuc's does. Expected texts are derived by hand from those rules and the Fagor spellings
(``G43 D<n>`` on, ``G44`` off, ``G71`` metric [V: 8070 programming manual]); expected points from the lengths
below (tool 1: 100 mm, tool 2: 20 mm); ``verify`` must pass at zero deviation.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine import AxisTravel, ToolData
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

HAAS_MILL = Path(__file__).resolve().parent / "heldout" / "setups" / "haas_mill.xml"


def _setup() -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {"1": ToolData(number=1, length=100.0, radius=3.0), "2": ToolData(number=2, length=20.0, radius=1.0)}
    return setup


def _translate(text: str, setup: MachineSetup) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target="fagor", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _verified(text: str, setup: MachineSetup | None = None) -> list[str]:
    setup = setup or _setup()
    out = _translate(text, setup)
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="in.nc",
                          file_out="out", source="fanuc", target="fagor", setup=setup)
    assert report.ok and report.max_deviation == 0.0, (out, report.summary())
    return out.splitlines()


def _errors(text: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, setup or _setup())
    return [str(e) for e in caught.value.errors]


ALONE = "G21 G90 G0 X0 Y0 Z50.\nT1 M06\nG43 H01\nG00 X10.\nG01 Z5. F100.\nG49\nG00 X20.\nG00 Z50.\nM30\n"
"""Fanuc: the X10 traverse takes the controlled Z to program Z 50 with length 100 (machine 150); after G49 the X20
traverse to program Z 5 without it (machine 5)."""


def test_a_length_change_alone_goes_beside_the_next_move_with_the_z_it_stands_at() -> None:
    assert _verified(ALONE) == [
        "G71 G90 G00 X0. Y0. Z50.", "T1 M06", "G43 D01 G00 X10. Z50.", "G01 Z5. F100.", "G44 G00 X20. Z5.",
        "G00 Z50.", "M30"]


def test_the_fagor_output_moves_as_the_hand_derived_points() -> None:
    """The output read back as Fagor: programmed (controlled) Z 50 at X10, Z 5 at X20 (hand-derived above)."""
    out = _translate(ALONE, _setup())
    moves = [e for e in toolpath_events(io.StringIO(out), file="out", dialect="fagor", setup=_setup()) if "move" in e]
    ends = [(m["x"], m["z"]) for m in moves]
    assert ends == [(0, 50), (10, 50), (10, 5), (20, 5), (20, 50)]


def test_an_incremental_z_move_applies_it_on_both() -> None:
    """The next move is ``G91 G00 Z-5.``: Fanuc applies the change in it, so does the Fagor (its Z moves): the
    change goes beside it as it is, with no Z added."""
    text = "G21 G90 G0 X0 Y0 Z50.\nG43 H01\nG91 G00 Z-5.\nG90 G01 X10. F100.\nM30\n"
    assert _verified(text)[1:3] == ["G91 G43 D01 G00 Z-5.", "G90 G01 X10. F100."]


def test_where_z_is_not_known_the_change_is_a_located_error() -> None:
    assert _errors("G21 G90\nG43 H01\nG00 X10.\nG01 Z5. F100.\nM30\n") == [
        "in.nc:2:5: error: this tool length change applies at the next move on the source's controller and only "
        "when Z next moves on the target's, and the programmed Z is not known where it applies: program Z beside "
        "the length change"]


def test_an_incremental_move_without_z_is_a_located_error() -> None:
    """``G91 G00 X10.`` after the change: no absolute Z to write beside it (whether a ``Z0`` increment moves the
    Fagor's axis is not in the manual): refused, located at the change."""
    assert _errors("G21 G90 G0 X0 Y0 Z50.\nG43 H01\nG91 G00 X10.\nG90 G01 Z5. F100.\nM30\n") == [
        "in.nc:2:5: error: this tool length change applies at the next move on the source's controller and only "
        "when Z next moves on the target's, and the programmed Z is not known where it applies: program Z beside "
        "the length change"]


def test_a_reference_return_after_the_change_is_a_located_error() -> None:
    """A Fagor return is a move in machine coordinates (``G53``), which takes no length: refused by name."""
    setup = _setup()
    setup.travel = {a: AxisTravel(name=a, home=0.0) for a in "XYZ"}  # type: ignore[arg-type]
    assert _errors("G21 G90 G0 X0 Y0 Z50.\nG43 H01\nG28 Z60.\nM30\n", setup) == [
        "in.nc:2:5: error: this tool length change applies at the next move on the source's controller and only "
        "when Z next moves on the target's, and the next move is a reference return, which the target makes in "
        "machine coordinates: program Z beside the length change"]


def test_a_change_beside_a_move_stays_where_it_is() -> None:
    """``G43 H01 Z50.`` applies on both in its own block: unchanged, as before."""
    assert _verified("G21 G90 G0 X0 Y0 Z80.\nG43 H01 Z50.\nG00 X10.\nM30\n")[1] == "G43 D01 G00 Z50."


HAAS = ("%\nO1\nN5 G00 G17 G40 G49 G55 G80 G90 G98\nN10 G53 Z0.\nN15 T1 M06\nN20 S3500 M03\nN25 G43 H01\n"
        "N30 G00 X-.750 Y0.\nN35 Z1. M08\nN40 G01 Z0. F10.\nN45 G53 G49 Z0.\nN50 M30\n%\n")
"""The course's Haas start (tests/heldout/haas/cadekiely_*): G55 (z -375 mm in ``haas_mill.xml``), the machine's
Z home (``G53 Z0.``: program Z 0 + 375 mm = 14.7638 in), then ``G43 H01`` alone and an XY move. Inch at power-on."""


def test_the_haas_course_start_translates_and_verifies_with_the_z_after_g53() -> None:
    setup = load_setup(HAAS_MILL)
    setup.tools = {"1": ToolData(number=1, length=100.0, radius=3.0)}
    lines = _verified(HAAS, setup)
    assert "N30 G43 D01 G00 X-0.75 Y0. Z14.76377953" in lines, lines  # 375 / 25.4 in, to the writer's 8 places
