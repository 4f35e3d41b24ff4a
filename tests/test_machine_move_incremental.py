"""A ``G53`` move under ``G91``: what each reader makes of it (issue 26, cadekiely_o78239_3x3_face_smile.nc).

The family disagrees where it is documented (tests/heldout/corpus.toml has the sources) and no Fanuc or Haas text
was found, so a Fanuc-family reader keeps the block verbatim and refuses it elsewhere by name, and its writer
writes none [?]; LinuxCNC refuses it ("Cannot use g53 incremental": the rs274 here is the oracle); grbl takes its
words as machine positions (gcode.c skips the G91 sum under G53 [V]). Expected points by hand: no work offset, so
machine = work.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable

import pytest

from tests.support.rs274 import RS274Error, available, run_rs274

PROGRAM = "G21 G90 G17\nG0 X1. Z-2.\nG91\nG53 G0 Z-5.\nG90 G0 X2.\nM30\n"


def write(tmp_path: Path, text: str = PROGRAM) -> Path:
    path = tmp_path / "prog.nc"
    path.write_text(text, encoding="utf-8")
    return path


def moves(result: Any) -> list[tuple[float, float]]:
    events = [json.loads(line) for line in result.out.decode().splitlines()[1:]]
    return [(e["x"], e["z"]) for e in events if "move" in e]


def test_a_fanuc_copy_keeps_the_block_verbatim(cli: Callable[..., Any], tmp_path: Path) -> None:
    result = cli("translate", "--from", "fanuc", "--to", "fanuc", write(tmp_path))
    assert result.status == 0, result.err
    assert b"G53 G0 Z-5.\n" in result.out


@pytest.mark.parametrize("target", ["linuxcnc", "isg", "fagor", "grbl", "siemens"])
def test_towards_another_dialect_it_is_refused_by_name_where_it_stands(cli: Callable[..., Any], tmp_path: Path,
                                                                      target: str) -> None:
    result = cli("translate", "--from", "fanuc", "--to", target, write(tmp_path))
    assert result.status != 0
    first = result.err_lines[0]
    assert first.startswith(f"{tmp_path / 'prog.nc'}:4:1: error: G53 in incremental distance mode"), result.err


def test_the_fanuc_simulation_stops_there_naming_it(cli: Callable[..., Any], tmp_path: Path) -> None:
    result = cli("toolpath", "--dialect", "fanuc", write(tmp_path))
    assert result.status != 0
    assert ":4:1: error: G53 in incremental distance mode" in result.err


def test_with_g90_in_the_block_it_is_a_machine_move(cli: Callable[..., Any], tmp_path: Path) -> None:
    result = cli("toolpath", "--dialect", "fanuc", write(tmp_path, PROGRAM.replace("G53 G0", "G90 G53 G0")))
    assert result.status == 0, result.err
    assert moves(result) == [(1, -2), (1, -5), (2, -5)]


def test_grbl_reads_its_words_as_machine_positions(cli: Callable[..., Any], tmp_path: Path) -> None:
    result = cli("toolpath", "--dialect", "grbl", write(tmp_path))
    assert result.status == 0, result.err
    assert moves(result) == [(1, -2), (1, -5), (2, -5)]  # Z-5 in machine coordinates, not -2 - 5


@pytest.mark.parametrize("target", ["fanuc", "mach3"])
def test_a_writer_whose_reader_keeps_it_verbatim_refuses_to_write_one(cli: Callable[..., Any], tmp_path: Path,
                                                                      target: str) -> None:
    result = cli("translate", "--from", "grbl", "--to", target, write(tmp_path))
    assert result.status != 0
    assert (f":4:1: error: the {target} dialect cannot express a move in machine coordinates in incremental "
            "distance mode") in result.err


def test_linuxcnc_refuses_it_as_rs274_does(cli: Callable[..., Any], tmp_path: Path) -> None:
    result = cli("toolpath", "--dialect", "linuxcnc", write(tmp_path))
    assert result.status != 0
    assert ":4:1: error: G53 in incremental distance mode: the controller refuses it" in result.err
    if not available():
        pytest.skip("rs274 not installed")
    with pytest.raises(RS274Error, match="(?i)g53 incremental"):
        run_rs274(PROGRAM)
