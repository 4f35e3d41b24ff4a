"""grbl's dynamic tool length offset (``G43.1 Z<length>``, [V] grbl wiki "Grbl v1.1 Commands"): read and
simulated, and written for a Fanuc ``G43 H``/``G44 H`` from the set-up's tool table
(``postproc.grbl_family.lengths``). Expected points and lengths are worked out by hand in the comments."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine_setup import MachineSetup, MachineSettings
from postproc.setup.machine import ToolData
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines


def _setup(lengths: dict[int, float], units: str = "mm", touched_off: bool = False) -> MachineSetup:
    setup = MachineSetup()
    setup.machine = MachineSettings(units=units, tool_lengths="touched_off" if touched_off else "table")
    setup.tools = {str(n): ToolData(number=n, length=v, radius=0.0) for n, v in lengths.items()}
    return setup


def _moves(text: str, dialect: str, setup: MachineSetup) -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(text).readlines(), file="t", dialect=dialect, setup=setup)
    return [e for e in events if "move" in e]


def _to_grbl(text: str, setup: MachineSetup) -> tuple[str, str]:
    out, warned = io.StringIO(), io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.nc", source="fanuc", target="grbl", setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=warned))
    return out.getvalue(), warned.getvalue()


def test_grbl_g43_1_moves_the_controlled_point_by_its_z() -> None:
    moves = _moves("G21 G90\nG43.1 Z25.\nG0 Z10.\nG49\nG0 Z10. X1.\n", "grbl", MachineSetup())
    # 10 programmed + 25 offset; after G49 the controlled point is the programmed one again
    assert [(m["z"], m.get("controlled", {}).get("z")) for m in moves] == [(10, 35), (10, None)]


def test_grbl_g43_1_in_inch_is_scaled_to_mm() -> None:
    moves = _moves("G20 G90\nG43.1 Z1.\nG0 Z2.\n", "grbl", MachineSetup())
    assert moves[0]["z"] == 50.8 and moves[0]["controlled"]["z"] == 76.2  # (2 + 1) in = 76.2 mm


def test_grbl_g43_1_needs_its_z() -> None:
    with pytest.raises(ErrorList) as info:
        _moves("G43.1\n", "grbl", MachineSetup())
    assert str(info.value.errors[0]) == "t:1:1: error: G43.1 needs the tool length as its Z word"


@pytest.mark.parametrize("source, written", [
    # G43 adds register 3 (42.5 mm); G44 subtracts it, so grbl's G43.1 takes the negated length
    ("G21 G90\nG43 H3 Z50.\nG0 X1.\nG49\n", ["G43.1 Z42.5", "G0 Z50."]),
    ("G21 G90\nG44 H3 Z50.\nG0 X1.\nG49\n", ["G43.1 Z-42.5", "G0 Z50."]),
    # an inch program gets the length in inches: 42.5 / 25.4 = 1.6732283464..., never rounded silently
    ("G20 G90\nG43 H3 Z2.\nG0 X1.\nG49\n", ["G43.1 Z1.67322835", "G0 Z2."]),
    # a register the program writes (G10 L10 P3 R10.) replaces the set-up's
    ("G21 G90\nG10 L10 P3 R10.\nG43 H3 Z50.\n", ["G43.1 Z10.", "G0 Z50."]),
])
def test_fanuc_length_offset_becomes_g43_1_before_its_motion(source: str, written: list[str]) -> None:
    setup = _setup({3: 42.5})
    out, warned = _to_grbl(source, setup)  # grbl has no G10 L10: the register's write is read into G43.1
    lines = out.splitlines()
    at = next(n for n, line in enumerate(lines) if line.startswith("G43.1"))
    assert lines[at:at + 2] == written and warned == ""
    assert ("G49" in lines) == ("G49" in source)
    assert not any(line.startswith("G10") for line in lines)
    report = verify_lines(io.StringIO(source).readlines(), io.StringIO(out).readlines(), file_in="t.nc",
                          file_out="t.gcode", source="fanuc", target="grbl", setup=setup)
    assert report.ok and report.max_deviation == 0, report.summary()


@pytest.mark.parametrize("source, written", [
    # the register written in inches (G10 L10 P3 R1. under G20: 25.4 mm), read under G21: 25.4 mm
    ("G20 G90\nG10 L10 P3 R1.\nG21\nG43 H3 Z50.\n", "G43.1 Z25.4"),
    # ... and read back in inches, after a block of millimetres between: 1 in
    ("G20 G90\nG10 L10 P3 R1.\nG21\nG0 X1.\nG20\nG43 H3 Z2.\n", "G43.1 Z1."),
    # inches, then millimetres before the offset: the set-up's 42.5 mm as it stands
    ("G20 G90\nG0 X1.\nG21\nG43 H3 Z50.\n", "G43.1 Z42.5"),
])
def test_the_units_in_force_where_the_step_reads_a_register_or_writes_a_length(source: str, written: str) -> None:
    """The step follows the units of every block before the one it changes (``UnitsAndDistance``)."""
    setup = _setup({3: 42.5})
    out, warned = _to_grbl(source, setup)
    assert written in out.splitlines() and warned == ""
    report = verify_lines(io.StringIO(source).readlines(), io.StringIO(out).readlines(), file_in="t.nc",
                          file_out="t.gcode", source="fanuc", target="grbl", setup=setup)
    assert report.ok and report.max_deviation == 0, report.summary()


def test_the_power_on_units_count_for_the_length() -> None:
    """A machine that powers on in inches (``<Controller startUnits="inch">``): the program's first block gets
    them (``postproc.syntaxes.power_on_units``), so 42.5 mm is written 42.5 / 25.4 = 1.67322835 in."""
    setup = _setup({3: 42.5})
    setup.controller.start_units = "inch"
    out, _ = _to_grbl("G90\nG43 H3 Z2.\n", setup)
    assert "G43.1 Z1.67322835" in out.splitlines()


def test_a_set_up_in_inches_gives_lengths_in_inches() -> None:
    out, _ = _to_grbl("G21 G90\nG43 H1 Z50.\n", _setup({1: 2.0}, units="inch"))
    assert "G43.1 Z50.8" in out.splitlines()  # 2 in of the set-up, written in the program's mm


def test_a_missing_length_names_the_element_to_add() -> None:
    with pytest.raises(ErrorList) as info:
        _to_grbl("G21 G90\nN10 G43 H07 Z50.\n", _setup({1: 10.0}))
    assert [str(e) for e in info.value.errors] == [
        't.nc:2:9: error: the set-up gives tool length register 7 no value: add <Tool number="7" length=".."/> '
        "to its <Tools>, or write the register in the program"]


def test_touched_off_tools_drop_the_offset_with_a_note() -> None:
    source = "G21 G90\nN10 G43 H07 Z50. M8\nG0 X5.\nG49\n"
    setup = _setup({}, touched_off=True)
    out, warned = _to_grbl(source, setup)
    assert out.splitlines()[1] == "N10 G0 Z50. M8 (TOOL LENGTH H7 DROPPED: TOOLS ARE TOUCHED OFF AT THE CHANGE)"
    assert warned == ""
    report = verify_lines(io.StringIO(source).readlines(), io.StringIO(out).readlines(), file_in="t.nc",
                          file_out="t.gcode", source="fanuc", target="grbl", setup=setup)
    assert report.ok and report.max_deviation == 0
    assert any("touched off" in note for note in report.ignored)
    # the source itself simulates with zero lengths there: the controlled point is the programmed one
    assert all("controlled" not in m for m in _moves(source, "fanuc", setup))


def test_touched_off_round_trips_through_config_dump(cli: Any, tmp_path: Any) -> None:
    path = tmp_path / "router.xml"
    path.write_text('<?xml version=\'1.0\' encoding=\'UTF-8\'?>\n<MachineSetup name="router">\n'
                    '  <Machine toolLengths="touched_off"/>\n</MachineSetup>\n')
    result = cli("config", "dump", path)
    assert result.status == 0 and result.out.decode() == path.read_text()
    path.write_text('<MachineSetup name="router">\n  <Machine toolLengths="zeroed"/>\n</MachineSetup>\n')
    result = cli("config", "check", path)
    assert result.status == 1 and "toolLengths" in result.err


def test_a_g43_1_written_ahead_of_the_blocks_own_g20_is_in_the_units_before_it() -> None:
    """``G43 H1 G20`` (LinuxCNC's cds.ngc, ``n0090 G43 H1 g20``): the G43.1 goes in a block of its own
    ahead of the G20, so grbl reads its Z in mm (the power-on units): 101 mm, not 101 / 25.4 read as mm."""
    setup = _setup({1: 101.0})
    text = "G90\nG43 H1 G20\nG0 X0 Y0 Z3\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.ngc", source="linuxcnc", target="grbl", setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert out.getvalue().splitlines()[1:3] == ["G43.1 Z101.", "G20"]
    moves = _moves(out.getvalue(), "grbl", setup)
    assert moves[0]["controlled"]["z"] == pytest.approx(3 * 25.4 + 101.0)  # Z3 inch + 101 mm
    report = verify_lines(io.StringIO(text).readlines(), io.StringIO(out.getvalue()).readlines(), file_in="t.ngc",
                          file_out="t.gcode", source="linuxcnc", target="grbl", setup=setup)
    assert report.ok and report.max_deviation == 0, report.summary()
