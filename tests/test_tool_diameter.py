"""Haas's cutter compensation columns by diameter in the set-up's ``<Tool>`` (issue 26, deliver 1):
``diameter``/``diameterWear`` where the Haas offsets page shows DIA GEOMETRY / DIA WEAR (its setting 40,
Tool Offset Measure, set to Diameter) [K: Haas mill operator's manual, setting 40 and the tool offsets
page]. ``D n`` offsets the path by half of geometry + wear; a set-up giving one register both a radius and
a diameter is a config error; a program write of such a register's radius (``G10 L12``) is refused, since
whether its R is then a diameter is not confirmed [?].

Expected values are hand-derived: diameter 10 with wear -0.2 is a radius of (10 - 0.2) / 2 = 4.9."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.compensation.tool_table import ToolTable
from postproc.errors import ConfigError, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events

SETUP = """<?xml version='1.0' encoding='UTF-8'?>
<MachineSetup name="haas diameters">
  <Tools>
    <Tool number="1" length="120.0" lengthWear="0.1" diameter="10.0" diameterWear="-0.2"/>
    <Tool number="2" length="80.0" diameter="6.0"/>
  </Tools>
</MachineSetup>
"""


def _setup(tmp_path: Path, text: str = SETUP) -> Any:
    path = tmp_path / "haas.xml"
    path.write_text(text)
    return load_setup(path)


@pytest.mark.parametrize("register, radius", [(1, 4.9), (2, 3.0)])
def test_d_reads_half_the_diameter_and_its_wear(tmp_path: Path, register: int, radius: float) -> None:
    assert ToolTable(_setup(tmp_path)).radius(register) == pytest.approx(radius)


def test_the_path_is_offset_by_half_the_diameter(tmp_path: Path) -> None:
    """LinuxCNC's G41 (simulated by its rules) on the same table: D1 puts the second side 4.9 left of Y0."""
    text = "G21 G90 G17 G40 G49\nG00 X0 Y0 Z5\nG41 D1 G01 X100 Y0 F100\nG01 X200 Y0\nG40 G01 X300 Y-50\nM2\n"
    moves = [e.get("controlled", e) for e in toolpath_events(io.StringIO(text), file="t.ngc", dialect="linuxcnc",
                                                            setup=_setup(tmp_path)) if "move" in e]
    assert (moves[2]["x"], moves[2]["y"]) == pytest.approx((200.0, 4.9))


@pytest.mark.parametrize("attributes", ['radius="5.0" diameter="10.0"', 'diameter="10.0" radiusWear="0.1"',
                                        'offset="100.0" diameter="10.0"'])
def test_a_diameter_beside_a_radius_or_a_shared_value_is_a_config_error(tmp_path: Path, attributes: str) -> None:
    with pytest.raises(ConfigError) as info:
        _setup(tmp_path, SETUP.replace('<Tool number="2" length="80.0" diameter="6.0"/>',
                                       f'<Tool number="2" {attributes}/>'))
    assert "tool 2" in str(info.value), str(info.value)


def test_a_program_write_of_a_diameter_register_is_a_located_error(tmp_path: Path) -> None:
    text = "G21 G90 G17 G40 G49\nG10 L12 P1 R5.\nM30\n"
    with pytest.raises(ErrorList) as info:
        list(toolpath_events(io.StringIO(text), file="t.nc", dialect="fanuc", setup=_setup(tmp_path)))
    message = str(info.value.errors[0])
    assert message.startswith("t.nc:2:") and "diameter" in message, message


def test_the_diameter_columns_round_trip_through_config_dump(cli: Any, tmp_path: Path) -> None:
    path = tmp_path / "haas.xml"
    path.write_text(SETUP)
    result = cli("config", "dump", path)
    assert result.status == 0 and result.out.decode() == SETUP
