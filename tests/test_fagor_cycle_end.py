"""A Fagor fixed cycle ends with ``G80`` before any move outside it (``dialects/fagor/cycle_end.py``).

Whether a motion code ends an 8070 fixed cycle is not confirmed [?]; a Fagor cycle is modal, so if it does
not, the old output (``G81 ..`` then ``G00 X20. Y20.``) drilled at X20 Y20. Expected lines are derived by hand
from Fanuc's rule (a group-01 code or a ``G53 G00`` ends the cycle, a reference return leaves it: DIALECTS.md
2.1); the property's oracle is the simulation of the Fanuc source, and the Fagor output is read back by
the Fagor reader, which refuses a motion code while a cycle is active.
"""

from __future__ import annotations

import io

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from postproc.errors import Diagnostics
from postproc.ir import Block, CycleCall, Motion
from postproc.cycles.section import CannedCycle
from postproc.setup.machine import AxisTravel
from postproc.setup.machine_setup import MachineSetup
from tests.support.pair_checks import PairChecks

from dialects.fagor import Fagor
from dialects.fagor.cycle_end import end_cycles_before_moves

HOME = {"X": -400.0, "Y": -250.0, "Z": -12.5}
SETUP = MachineSetup()
SETUP.travel = {a: AxisTravel(name=a, home=h) for a, h in HOME.items()}  # type: ignore[arg-type]
START = "G21 G90 G94 G17\nG00 X0. Y0. Z10.\nG98 G81 X5. Y5. Z-3. R2. F100.\n"
"""A Fanuc drilling cycle; Fagor writes it ``G98 G81 X5. Y5. Z2. I-3. F100.``."""
WRITTEN = ["G17 G71 G90 G94", "G00 X0. Y0. Z10.", "G98 G81 X5. Y5. Z2. I-3. F100."]


CHECK = PairChecks(SETUP)
_translate, _errors, _verify = CHECK.translate, CHECK.errors, CHECK.verify


@pytest.mark.parametrize(("source", "written"), [
    ("X10.\nG00 X20. Y20.\n", ["X10.", "G80", "G00 X20. Y20."]),
    ("G01 X30. F50.\n", ["G80", "G01 X30. F50."]),
    ("G02 X10. Y10. R5.\n", ["G80", "G02 X10. Y10. R5."]),
    ("G00\nX20.\n", ["G80", "G00", "G00 X20."]),
    ("G53 G00 Z0.\n", ["G80", "G53 G00 Z0."]),
    ("G28 Z20.\n", ["G80", "G00 Z20.", "G53 G00 Z-12.5"]),
])
def test_a_move_after_a_cycle_is_written_after_g80(source: str, written: list[str]) -> None:
    out = _translate(START + source + "M30\n", "fanuc", "fagor")
    assert out.splitlines() == WRITTEN + written + ["M30"]
    _verify(START + source + "M30\n", out, "fanuc", "fagor")


def test_an_expanded_cycle_after_a_native_one_starts_after_g80() -> None:
    """A Fanuc G83 reaches Fagor expanded (its rapids and feeds), so G81 must end before its first rapid."""
    source = START + "G83 X10. Z-8. R2. Q4.\nG80\nM30\n"
    out = _translate(source, "fanuc", "fagor").splitlines()
    assert out[3:6] == ["G80", ";peck_deep from line 4: G83 X10. Z-8. R2. Q4.", "G00 X10. Y5. Z10."]
    assert out.count("G80") == 2  # and the source's own after it
    _verify(source, "\n".join(out) + "\n", "fanuc", "fagor")


@pytest.mark.parametrize("source", ["G80\nG00 X20.\n", "G80 G00 X20.\n", "G00 G80 X20.\n"])
def test_a_source_that_cancels_gets_no_second_g80(source: str) -> None:
    out = _translate(START + source + "M30\n", "fanuc", "fagor").splitlines()
    assert out.count("G80") + sum(line.startswith("G80 ") for line in out) == 1, out


def test_holes_and_dwells_of_the_cycle_need_no_g80() -> None:
    """Its holes repeat the cycle, a dwell and a reference return of no axis move nowhere else."""
    out = _translate(START + "X10.\nY10.\nG04 P500\nG28\nX12.\nG80\nM30\n", "fanuc", "fagor").splitlines()
    assert out.count("G80") == 1 and out[-2:] == ["G80", "M30"]


@pytest.mark.parametrize(("text", "column", "code"), [
    ("G00 X20\n", 1, "G00"), ("N20 G01 X20\n", 5, "G01"), ("G53 G00 Z0\n", 5, "G00"), ("G03 X1 Y1 R1\n", 1, "G03"),
])
def test_reading_fagor_a_motion_code_in_a_cycle_is_refused(text: str, column: int, code: str) -> None:
    program = "G71 G90\nG00 X0 Y0 Z10\nG81 X5 Y5 Z2 I-3 F100\n" + text + "M30\n"
    assert _errors(program, "fagor", "fanuc") == [
        f"in.nc:4:{column}: error: {code} while a fixed cycle is active: whether a motion code ends the cycle on "
        "the 8070 is not confirmed (write G80 before it)"]


@pytest.mark.parametrize("text", ["G80\nG00 X20\n", "G80 G00 X20\n", "X7\nG80\nG01 X20 F50\n"])
def test_reading_fagor_a_move_after_g80_is_a_plain_move(text: str) -> None:
    program = "G71 G90\nG00 X0 Y0 Z10\nG81 X5 Y5 Z2 I-3 F100\n" + text + "M30\n"
    out = _translate(program, "fagor", "fanuc")
    lines = out.splitlines()
    assert any(line.startswith("G80") for line in lines)
    assert lines[-2] in ("G00 X20.", "G80 G00 X20.", "G01 X20. F50.")


def test_a_hole_after_a_reference_return_that_keeps_the_source_cycle_is_refused() -> None:
    """Fanuc's G28 leaves the cycle in force; Fagor's G80 before the return does not, so a later hole without
    the cycle code would be a plain move there (the step alone: Fanuc's reader loses the position at G28)."""
    ctx = Fagor.context("in.nc", SETUP, Diagnostics(warn_stream=io.StringIO()))
    blocks = [Block(1, "G81", "\n"), Block(2, "G28 Z20.", "\n"), Block(3, "X3.", "\n"), Block(4, "G81 X4.", "\n")]
    blocks[0].add(CycleCall("drill"))
    blocks[0].add(CannedCycle("drill", semantics="fanuc", call=True))
    blocks[1].add(Motion("home", {"Z": 20.0}))
    blocks[2].add(CannedCycle("drill", semantics="fanuc"))
    blocks[3].add(CannedCycle("drill", semantics="fanuc", call=True))
    out = list(end_cycles_before_moves(iter(blocks), ctx, Fagor))
    assert [(b.line, list(b.sections)) for b in out] == [
        (1, ["CycleCall", "CannedCycle"]), (2, ["CycleCancel"]), (2, ["Motion"]), (3, ["CannedCycle"]),
        (4, ["CannedCycle"])]
    assert [str(e) for e in ctx.diagnostics.errors] == [
        "in.nc:3:1: error: a hole of a fixed cycle after a reference return: Fagor ends the cycle with G80 before "
        "the return (whether a motion ends it on the 8070 is not confirmed), so the hole needs the cycle called "
        "again"]


VALUE = st.integers(-40, 40).map(lambda v: f"{v / 4:g}" if v % 4 else f"{v // 4}.")


@st.composite
def programs(draw: st.DrawFn) -> str:
    """A Fanuc program of native (G81, G82, G85, G89) and expanded (G83, G73) cycles, their holes, moves of
    every motion code, G53 moves and cancels, in any order."""
    lines = ["G21 G90 G94 G17", "G00 X0. Y0. Z10.", "F200.", "S1000 M03"]
    for _ in range(draw(st.integers(1, 10))):
        kind = draw(st.sampled_from(["native", "expanded", "hole", "move", "machine", "cancel"]))
        if kind == "native":
            code = draw(st.sampled_from(["G81", "G82", "G85", "G89"]))
            dwell = " P500" if code in ("G82", "G89") else ""
            level = draw(st.sampled_from(["G98", "G99"]))
            lines.append(f"{level} {code} X{draw(VALUE)} Y{draw(VALUE)} Z-12. R2.{dwell}")
        elif kind == "expanded":
            lines.append(f"G98 {draw(st.sampled_from(['G83', 'G73']))} X{draw(VALUE)} Z-8. R2. Q3.")
        elif kind == "hole":
            lines.append(f"X{draw(VALUE)} Y{draw(VALUE)}")  # a hole while a cycle is active, else a move
        elif kind == "move":
            lines.append(f"{draw(st.sampled_from(['G00', 'G01']))} X{draw(VALUE)} Z{draw(st.integers(3, 20))}.")
        elif kind == "machine":
            lines += ["G53 G00 Z0.", "G00 Z10."]  # (a work position again: a cycle needs its initial level)
        else:
            lines.append("G80")
    return "\n".join(lines + ["G80", "M30"]) + "\n"


@settings(max_examples=40, deadline=None)
@given(programs())
def test_cycles_and_moves_reach_fagor_along_the_same_toolpath_and_read_back(program: str) -> None:
    """Verify reads the Fagor output with the Fagor reader, which refuses a motion code in a cycle: so no
    written move relies on a motion code ending a cycle, and the toolpath is the source's."""
    out = _translate(program, "fanuc", "fagor")
    _verify(program, out, "fanuc", "fagor")
    back = _translate(out, "fagor", "fanuc")
    _verify(program, back, "fanuc", "fanuc")
