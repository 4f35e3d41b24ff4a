"""Fagor 8070 moves in machine coordinates (``G53``), reference returns written with them, and the cutting
mode ``G05``: what the reader accepts, and a seeded property that Fanuc programs mixing them with G90/G91
translate to Fagor and back along the same toolpath (``verify``, deviation 0).

Expected values are hand-derived (the set-up's home, the tool length); the property's oracle is the
simulation of the Fanuc source, independent of the Fagor writer.
"""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.setup.machine import AxisTravel, ToolData
from postproc.setup.machine_setup import MachineSetup
from tests.support.pair_checks import PairChecks

HOME = {"X": -400.0, "Y": -250.0, "Z": -12.5}


def _make_setup() -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {"2": ToolData(number=2, length=25.5, radius=5.0)}
    setup.travel = {a: AxisTravel(name=a, home=h) for a, h in HOME.items()}  # type: ignore[arg-type]
    return setup


SETUP = _make_setup()


CHECK = PairChecks(SETUP)
_translate, _errors, _verify = CHECK.translate, CHECK.errors, CHECK.verify


def test_a_fagor_g53_is_read_only_as_an_absolute_move() -> None:
    assert _translate("G71 G90\nG53 G00 Z0\nM30\n", "fagor", "fanuc").splitlines()[1] == "G53 G00 Z0."
    assert _translate("G71 G91\nG53 G90 G00 Z0\nM30\n", "fagor", "fanuc").splitlines()[1] == "G53 G90 G00 Z0."
    assert _errors("G71 G90\nG01 X1 F100\nG53 Z0\nM30\n", "fagor", "fanuc") == [
        "in.nc:3:1: error: G53 with a motion other than G00 in force: whether the 8070 then moves at the feed "
        "rate is not confirmed (write G00 in the block)"]
    assert "a linear move in machine coordinates" in _errors("G21 G90\nG53 G1 Z0 F100\nM2\n", "linuxcnc",
                                                             "fagor")[0]
    assert _errors("G71 G90\nG53\nG00 X1\nM30\n", "fagor", "fanuc") == [
        "in.nc:2:1: error: G53 without an axis word: what it does on the 8070 (a zero offset deselection?) is "
        "not confirmed"]
    assert _errors("G71 G91\nG53 G00 Z0\nM30\n", "fagor", "fanuc")[0] == (  # (a Fanuc writes none either)
        "in.nc:2:1: error: G53 under G91: whether the 8070 takes its positions as increments is not confirmed "
        "(write G90 in the block)")


def test_a_reference_return_with_an_intermediate_point_moves_there_first() -> None:
    """G28 X10. Y5. in G90: a rapid to (10, 5), then G53 to the set-up's home of X and Y (-400, -250)."""
    text = "G21 G90\nG00 X1. Y1. Z3.\nG28 X10. Y5.\nM30\n"
    out = _translate(text, "fanuc", "fagor")
    assert out.splitlines()[2:4] == ["G00 X10. Y5.", "G53 G00 X-400. Y-250."]
    _verify(text, out, "fanuc", "fagor")


def test_what_a_reference_return_block_ends_comes_after_the_return() -> None:
    """Fanuc ends the block's M05 after its motion: in the G53 move's block (Fagor, as Fanuc, ends it after the
    motion: ``stops_before_motion``), not before; the return's zero increment leaves only the G53 move, and the
    next block's own G90 owes no G91 (``postproc.isg_family.machine_moves``)."""
    text = "G21 G90\nG00 Z5.\nS100 M03\nG91 G28 Z0. M05\nG90\nM30\n"
    out = _translate(text, "fanuc", "fagor")
    assert out.splitlines()[3:5] == ["G53 G90 G00 Z-12.5 M05", "G90"]
    _verify(text, out, "fanuc", "fagor")


def test_a_reference_return_of_no_axis_moves_nothing() -> None:
    text = "G21 G90\nG00 Z5.\nG28\nM30\n"
    out = _translate(text, "fanuc", "fagor")
    assert out.splitlines()[2] == ";LINE 3: G28"
    _verify(text, out, "fanuc", "fagor")


MOVE = st.sampled_from(["G00", "G01"])
VALUE = st.integers(-40, 40).map(lambda v: f"{v / 4:g}" if v % 4 else f"{v // 4}.")


@st.composite
def programs(draw: st.DrawFn) -> str:
    """A Fanuc program of moves in work and machine coordinates, reference returns of Z and of X Y, G90/G91
    switches and cutting/exact-stop modes, with a tool length in force part of the time."""
    lines = ["G21 G90 G94", "G00 X0. Y0. Z10.", "F200."]
    incremental = False  # a G53 under G91 is not known for a Fanuc [?] (refused by name): G90 goes beside it then
    for _ in range(draw(st.integers(1, 8))):
        kind = draw(st.sampled_from(["work", "machine", "home_z", "home_xy", "distance", "path", "length"]))
        if kind == "work":
            lines.append(f"{draw(MOVE)} X{draw(VALUE)} Z{draw(VALUE)}")
        elif kind == "machine":
            lines.append(("G90 " if incremental else "") + f"G53 {draw(MOVE)} Z{draw(VALUE)}"
                         + (f" X{draw(VALUE)}" if draw(st.booleans()) else ""))
            incremental = False
        elif kind == "home_z":
            relative = draw(st.booleans())
            lines.append("G91 G28 Z0." if relative else f"G28 Z{draw(VALUE)}")
            incremental = incremental or relative
        elif kind == "home_xy":
            lines.append(f"G28 X{draw(VALUE)} Y{draw(VALUE)}")
        elif kind == "distance":
            lines.append(draw(st.sampled_from(["G90", "G91"])))
            incremental = lines[-1] == "G91"
        elif kind == "path":
            lines.append(draw(st.sampled_from(["G64", "G61"])))
        else:
            lines.append(draw(st.sampled_from(["G43 H02 Z20.", "G49 Z30."])))  # (a length change beside Z)
    return "\n".join(lines + ["M30"]) + "\n"


@settings(max_examples=40, deadline=None)
@given(programs())
def test_machine_moves_and_reference_returns_keep_the_toolpath_to_fagor_and_back(program: str) -> None:
    out = _translate(program, "fanuc", "fagor")
    _verify(program, out, "fanuc", "fagor")
    back = _translate(out, "fagor", "fanuc")
    _verify(program, back, "fanuc", "fanuc")
