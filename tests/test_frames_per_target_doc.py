"""docs/dialects.md's table "Each frame command per target" kept true: each row's commands, each alone in a small
G17 mill program of the row's dialect, translated to every target column, land as the cell says: *native* (the
command written as the source wrote it), *evaluated* (it becomes a comment, later points carry it), *refused* (a
located error). The table is read from the document itself, so a change to either shows here."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList

DOC = Path(__file__).resolve().parents[1] / "docs" / "dialects.md"

HEADS = {
    "fanuc": "%\nO1000\nG21 G17 G90\nG00 X0. Y0. Z5.\n{cmd}\nG01 X10. Y5. F100.\nM30\n%\n",
    "linuxcnc": "G21 G17 G90\nG0 X0 Y0 Z5\n{cmd}\nG1 X10 Y5 F100\nM2\n",
    "grbl": "G21 G17 G90\nG0 X0 Y0 Z5\n{cmd}\nG1 X10 Y5 F100\nM2\n",
    "grblhal": "G21 G17 G90\nG0 X0 Y0 Z5\n{cmd}\nG1 X10 Y5 F100\nM2\n",
    "siemens": "G17 G71 G90\nG0 X0 Y0 Z5\n{cmd}\nG1 X10 Y5 F100\nM30\n",
    "isg": "N1 G71 G90 G17 G00 X0 Y0 Z5\n{cmd}\nG01 X10 Y5 F100\nM30\n",
}
"""A program of each source dialect with ``{cmd}`` among its moves."""

ROWS: dict[str, tuple[str, list[str]]] = {
    "Fanuc `G52`": ("fanuc", ["G52 X10.", "G92 X0. Y0.", "G68 X0. Y0. R30.", "G51 X0. Y0. P2000", "G51.1 X5.",
                              "G16"]),
    "LinuxCNC `G52`": ("linuxcnc", ["G52 X10", "G92 X0 Y0", "G92 X1\nG92.1", "G92 X1\nG92.2\nG92.3",
                                    "G10 L2 P1 R30"]),  # (its X Y part: a work offset setting, not a frame)
    "grbl `G92`": ("grbl", ["G92 X0 Y0", "G92 X1\nG92.1"]),
    "grblHAL `G92`, `G92.1`": ("grblhal", ["G92 X0 Y0", "G92 X1\nG92.1", "G92 X1\nG92.2"]),
    "grblHAL `G92.3`": ("grblhal", ["G92.3"]),
    "SINUMERIK `TRANS`": ("siemens", ["TRANS X10", "ATRANS X10", "ROT RPL=30", "AROT RPL=30", "SCALE X2 Y2",
                                      "ASCALE X2 Y2", "MIRROR X0", "AMIRROR X0"]),
    "ISG `G68": ("isg", ["G68 R30 X0 Y0", "G18\nG68 R30 Z0 X0\nG17", "G19\nG68 R30 Y0 Z0\nG17",
                         "#ROTATION ON [ANGLE=30 CENTER1=0 CENTER2=0]"]),
    "ISG `G92` (preset)": ("isg", ["G92 X0 Y0", "#ROTATION ON [ANGLE=30 CENTER1=5 CENTER2=0]"]),
}
"""The start of a row's first cell -> its source dialect and the commands tried (every one the row names, or
one of each pair of a command and its cancel)."""


def _table() -> tuple[list[str], dict[str, list[str]]]:
    text = DOC.read_text(encoding="utf-8")
    start = text.index("| source command |")
    lines = text[start:].split("\n\n", 1)[0].splitlines()
    targets = [c.strip() for c in lines[0].strip("|").split("|")][1:]
    rows = {}
    for line in lines[2:]:
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        rows[cells[0]] = cells[1:]
    return targets, rows


TARGETS, TABLE = _table()
CASES = [(label, target) for label in ROWS for target in TARGETS]


def _row(label: str) -> list[str]:
    found = [cells for first, cells in TABLE.items() if first.startswith(label)]
    assert len(found) == 1, f"no single row of docs/dialects.md starts with {label!r}"
    return found[0]


def _landing(source: str, command: str, target: str) -> str:
    text = HEADS[source].format(cmd=command)
    out = io.StringIO(newline="")
    try:
        translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target,
                  diagnostics=Diagnostics(warn_stream=io.StringIO()))
    except ErrorList as err:
        assert all(re.match(r"t\.nc:\d+:\d+: error: ", str(e)) for e in err.errors), err.errors
        return "refused"
    last = command.splitlines()[-1] if source != "isg" or not command.startswith("G1") else command.splitlines()[1]
    written = [re.sub(r"\(.*?\)|;.*", "", line) for line in out.getvalue().splitlines()]
    key = last.split()[0] if not last.startswith("#") else last
    return "native" if any(key in line for line in written) else "evaluated"


@pytest.mark.parametrize("label, target", CASES)
def test_each_frame_command_lands_on_each_target_as_the_table_says(label: str, target: str) -> None:
    source, commands = ROWS[label]
    cell = _row(label)[TARGETS.index(target)]
    want = cell.split()[0]
    for command in commands:
        assert _landing(source, command, target) == want, (label, command, target, cell)


def test_every_row_that_reads_a_frame_is_checked() -> None:
    checked = {first for first in TABLE for label in ROWS if first.startswith(label)}
    assert checked == {first for first, cells in TABLE.items() if not cells[0].startswith("not read")}
