"""Fanuc's tool compensation memories in the set-up's ``<Tool>`` (issue 26, deliver 1): memory A one value
per offset number for H and D (``offset``), B that value plus a shared wear (``offsetWear``), C separate
geometry and wear for H and D (``length``/``lengthWear``, ``radius``/``radiusWear``) [K: Fanuc Series 0i
Model B connection manual (function) B-63833EN-1/02, 10.2 "Tool compensation memory"].

Expected points are hand-derived from the values below: the controlled Z of ``G43 H n Z50.`` is 50 plus
register n's length (geometry + wear), the compensated side of an X move under ``G41 D n`` is the radius
(geometry + wear) to the left."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.api import read_program
from postproc.compensation.tool_table import ToolTable
from postproc.errors import ConfigError
from postproc.ir import DataSetting
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events

SETUP = """<?xml version='1.0' encoding='UTF-8'?>
<MachineSetup name="memories">
  <Tools>
    <Tool number="1" offset="100.0"/>
    <Tool number="2" offset="80.0" offsetWear="-0.25"/>
    <Tool number="3" length="90.0" radius="4.0" lengthWear="0.5" radiusWear="-0.1"/>
    <Tool number="21" offset="5.0"/>
  </Tools>
</MachineSetup>
"""


def _setup(tmp_path: Path, text: str = SETUP) -> Any:
    path = tmp_path / "memories.xml"
    path.write_text(text)
    return load_setup(path)


def _settings(text: str) -> list[DataSetting]:
    return [s for b in read_program(io.StringIO(text), file="t.nc", dialect="fanuc")
            if isinstance(s := b.sections.get("DataSetting"), DataSetting)]


def _controlled(text: str, setup: Any, dialect: str = "fanuc") -> list[tuple[float, float, float]]:
    out = []
    for e in toolpath_events(io.StringIO(text), file="t.nc", dialect=dialect, setup=setup):
        if "move" in e:
            point = e.get("controlled", e)
            out.append((point["x"], point["y"], point["z"]))
    return out


@pytest.mark.parametrize("register, length", [(1, 100.0), (2, 79.75), (3, 90.5)])
def test_the_length_of_each_memory_type(tmp_path: Path, register: int, length: float) -> None:
    """A: the one value; B: value + shared wear (80 - 0.25); C: the H geometry + its wear (90 + 0.5)."""
    moves = _controlled(f"G21 G90 G17 G40 G49\nG43 H{register} G00 Z50.\nM30\n", _setup(tmp_path))
    assert moves[-1][2] == pytest.approx(50.0 + length)


@pytest.mark.parametrize("register, radius", [(21, 5.0), (2, 79.75), (3, 3.9)])
def test_the_radius_of_each_memory_type(tmp_path: Path, register: int, radius: float) -> None:
    """D n reads memory A/B's one value (and wear) as a radius, memory C's D columns (4 - 0.1)."""
    assert ToolTable(_setup(tmp_path)).radius(register) == pytest.approx(radius)


def test_a_radius_offsets_the_path_by_the_memory_value(tmp_path: Path) -> None:
    """LinuxCNC's G41 (simulated by its rules) reads the same table: D21's memory A value 5 puts the second
    side of the path 5 to the left of Y0."""
    text = "G21 G90 G17 G40 G49\nG00 X0 Y0 Z5\nG41 D21 G01 X100 Y0 F100\nG01 X200 Y0\nG40 G01 X300 Y-50\nM2\n"
    assert _controlled(text, _setup(tmp_path), "linuxcnc")[2][:2] == pytest.approx((200.0, 5.0))


def test_a_program_write_of_a_memory_a_register_is_its_length_and_its_radius(tmp_path: Path) -> None:
    """Memory A: ``G10 L11 P21 R6.`` writes offset 21's one value (no wear there), so H21 is 6 long and
    D21 offsets by 6; on memory B's register 2 the same write is its wear (80 + 6)."""
    text = "G21 G90 G17 G40 G49\nG10 L11 P21 R6.\nG10 L11 P2 R6.\nG43 H21 G00 Z50.\nG43 H2 G00 Z50.\nM30\n"
    moves = _controlled(text, _setup(tmp_path))
    assert [m[2] for m in moves] == pytest.approx([56.0, 136.0])
    table = ToolTable(_setup(tmp_path))
    for setting in _settings(text):
        table.write(setting, 1.0)
    assert table.radius(21) == pytest.approx(6.0) and table.radius(2) == pytest.approx(86.0)


def test_a_shared_value_beside_separate_columns_is_a_config_error(tmp_path: Path) -> None:
    with pytest.raises(ConfigError) as info:
        _setup(tmp_path, SETUP.replace('<Tool number="1" offset="100.0"/>',
                                       '<Tool number="1" offset="100.0" radius="3.0"/>'))
    assert "offset/offsetWear" in str(info.value) and "memory C" in str(info.value)


def test_the_memory_types_round_trip_through_config_dump(cli: Any, tmp_path: Path) -> None:
    path = tmp_path / "memories.xml"
    path.write_text(SETUP)
    result = cli("config", "dump", path)
    assert result.status == 0 and result.out.decode() == SETUP
