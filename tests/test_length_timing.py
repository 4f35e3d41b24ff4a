"""A tool length change translated between controllers that apply it at different moments
(``postproc.lowering.length_timing``): LinuxCNC and grbl at the next absolute Z ([V] rs274, grbl
``gcode.c``), Fanuc at the next move (the simulation's model). Expected texts are written out by hand;
``verify`` (both sides simulated by their own rule) must pass at zero deviation. Tool 1: 100 mm."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines


def _setup() -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {"1": ToolData(number=1, length=100.0, radius=3.0), "2": ToolData(number=2, length=20.0, radius=1.0)}
    return setup


def _translate(text: str, source: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target, setup=_setup(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _verified(text: str, source: str, target: str) -> list[str]:
    out = _translate(text, source, target)
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="in.nc",
                          file_out="out", source=source, target=target, setup=_setup())
    assert report.ok and report.max_deviation == 0.0, (out, report)
    return out.splitlines()


FANUC_ALONE = "G21 G90 G0 X0 Y0 Z50.\nT1 M06\nG43 H01\nG00 X10.\nG01 Z5. F100.\nG49\nG00 X20.\nG00 Z50.\nM30\n"
"""Fanuc: the X10 traverse takes the controlled Z to 50 + 100 with it; after G49 the X20 traverse to 5."""
LINUXCNC_ALONE = "G21 G90 G0 X0 Y0 Z50\nT1 M6\nG43 H1\nG0 X10\nG0 Z5\nG49\nG0 X20\nG0 Z50\nM2\n"
"""LinuxCNC: the X10 traverse keeps the machine Z at 50, Z5 goes to 105; the X20 traverse keeps 105."""


def test_fanuc_to_linuxcnc_gives_the_next_move_the_change_and_its_z() -> None:
    assert _verified(FANUC_ALONE, "fanuc", "linuxcnc") == [
        "G21 G90 G0 X0. Y0. Z50.", "T1 M6", "G43 H01 G0 X10. Z50.", "G1 Z5. F100.", "G49 G0 X20. Z5.", "G0 Z50.",
        "M30"]


def test_fanuc_to_grbl_writes_the_length_then_the_move_with_its_z() -> None:
    assert _verified(FANUC_ALONE, "fanuc", "grbl")[2:5] == ["G43.1 Z100.", "G0 X10. Z50.", "G1 Z5. F100."]


def test_fanuc_to_isg_selects_the_data_beside_the_completed_move() -> None:
    assert _verified(FANUC_ALONE, "fanuc", "isg")[2] == "D01 G00 X10. Z50."


def test_linuxcnc_to_fanuc_writes_the_change_at_the_next_absolute_z() -> None:
    assert _verified(LINUXCNC_ALONE, "linuxcnc", "fanuc") == [
        "G21 G90 G00 X0. Y0. Z50.", "T1 M06", "G00 X10.", "G43 H01 G00 Z5.", "G00 X20.", "G49 G00 Z50.", "M02"]


def test_linuxcnc_changes_that_cancel_before_any_z_write_nothing() -> None:
    """G43 H1 then G49 before Z: the machine never took the length; the next absolute Z has none."""
    text = "G21 G90 G0 X0 Y0 Z50\nG43 H1\nG0 X10\nG49\nG0 Z5\nG43 H2\nG43 H1\nG0 Z6\nM2\n"
    assert _verified(text, "linuxcnc", "fanuc")[1:] == ["G00 X10.", "G00 Z5.", "G43 H01 G00 Z6.", "M02"]


def test_fanuc_change_before_an_incremental_move_is_a_located_error() -> None:
    text = "G21 G90 G0 X0 Y0 Z50.\nG43 H01\nG91 G00 X10.\nM30\n"
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc", "linuxcnc")
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:2:5: error: this tool length change applies at the next move on the source's controller and only "
        "at the next absolute Z on the target's, and the programmed Z is not known where it applies: program Z "
        "beside the length change"]


def test_linuxcnc_change_waiting_at_a_tool_table_write_is_a_located_error() -> None:
    """G43 H1 reads the register when it is programmed; written at the later Z it would read the new value."""
    text = "G21 G90 G0 X0 Y0 Z50\nG43 H1\nG10 L1 P1 Z2\nG0 Z5\nM2\n"
    with pytest.raises(ErrorList) as caught:
        _translate(text, "linuxcnc", "fanuc")
    assert [str(e) for e in caught.value.errors][:1] == [
        "in.nc:3:1: error: a data setting while a tool length change waits for the next absolute Z (the source "
        "applies it there, the target at its next move): program Z beside the length change"]


def test_a_change_that_changes_nothing_stays_where_it_is() -> None:
    """The G49 of a start-up line cancels no length in force: written as it stands, both ways; a G49
    left waiting at the program end changed no move and is left out (written alone, a Fanuc G49 could
    move Z there)."""
    start = "G21 G90 G49\nG0 X0 Y0\nG0 Z50\nM2\n"
    assert _verified(start, "linuxcnc", "fanuc")[0] == "G21 G90 G49"
    assert _verified(start.replace("M2", "M30"), "fanuc", "linuxcnc")[0] == "G21 G90 G49"
    trailing = "G21 G90 G0 X0 Y0 Z50\nG43 H1 Z60\nG49\nM2\n"
    assert _verified(trailing, "linuxcnc", "fanuc")[1:] == ["G43 H01 G00 Z60.", "M02"]
    fanuc = trailing.replace("M2", "M30").replace("Z60", "Z60.")
    assert _verified(fanuc, "fanuc", "linuxcnc")[1:] == ["G43 H01 G0 Z60.", "G49", "M30"]


FANUC_END = "G21 G90 G0 X0 Y0 Z50.\nG43 H01 Z50.\nG1 Z10. F100.\nG49\nG91 G28 Z0\nG90\nM30\n"
"""A common program end. Fanuc (the next-move model): G49 applies at the return's intermediate move, incremental Z0
from the programmed Z10: the controlled Z goes from 110 to 10, then to the reference point."""


def test_a_cancel_before_an_incremental_reference_return_writes_its_point_absolutely() -> None:
    """It was refused (the next move is a reference return). LinuxCNC's G91 G28 Z0 would pass through where the
    machine stands (110): its point is written absolutely, Z10, beside the G49, and G91 follows again."""
    assert _verified(FANUC_END, "fanuc", "linuxcnc")[3:6] == ["G90 G49 G28 Z10.", "G91", "G90"]
    assert _verified(FANUC_END, "fanuc", "grbl")[4:7] == ["G49", "G90 G28 Z10.", "G91"]


def test_a_cancel_before_an_absolute_reference_return_goes_beside_it() -> None:
    """G90 G28 Z20: both rules take the point Z20 with the new length (none): the change goes there."""
    text = FANUC_END.replace("G91 G28 Z0", "G28 Z20.")
    assert _verified(text, "fanuc", "linuxcnc")[3] == "G49 G28 Z20."


def test_an_incremental_return_from_an_unknown_z_shifts_its_increment() -> None:
    """It was refused (no absolute Z known). The source takes the intermediate point at the programmed Z plus the
    increment with the new length; the target's increment runs from where the machine stands, so it is the
    source's plus the new length minus the old: G43 H01 (0 -> 100): Z0 becomes Z100; G49 (100 -> 0) with Z2:
    Z-98. X and Y keep theirs. grbl gets G43.1 Z100. in a block of its own (its axis word)."""
    text = "G21 G90 G0 X0 Y0\nG91 G43 H01 G28 Z0\nG90 G1 X5. F100.\nG49\nG91 G28 X0 Y0 Z2.\nG90\nM30\n"
    assert _verified(text, "fanuc", "linuxcnc")[1:4] == [
        "G91 G43 H01 G28 Z100.", "G90 G1 X5. F100.", "G91 G49 G28 X0. Y0. Z-98."]
    assert _verified(text, "fanuc", "grbl")[1:6] == [
        "G43.1 Z100.", "G91 G28 Z100.", "G90 G1 X5. F100.", "G49", "G91 G28 X0. Y0. Z-98."]
    assert _verified("G21 G90 G0 X0 Y0\nG43 H01\nG91 G28 Z0\nG90\nM30\n", "fanuc", "linuxcnc")[1] == (
        "G91 G43 H01 G28 Z100.")


def test_an_incremental_return_without_z_is_still_refused() -> None:
    """``G91 G28 X0 Y0`` after G49: the source takes the new length at that move; the target could only by naming
    Z, which would send Z to the reference point too."""
    text = "G21 G90 G0 X0 Y0 Z50.\nG43 H01 Z50.\nG49\nG91 G28 X0 Y0\nG90\nM30\n"
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc", "linuxcnc")
    assert "in.nc:3:1: error: this tool length change applies at the next move" in str(caught.value.errors[0])
