"""LinuxCNC tool tables (issue 26, deliver 1): ``<Tool pocket>``, a set-up's ``<Tools table="tool.tbl">`` read into
its tools (``postproc.setup.tool_table_file``), ``config check`` of the file and its pockets, ``config dump`` with
and without ``--flatten``, and the table written back, which rs274 reads (``-t``): its own report of each tool's
number, length, diameter and pocket (``#5400``, ``#5403``, ``#5410``, ``#<_current_pocket>``) is the oracle."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, strategies as st

from postproc.errors import ConfigError, ErrorList
from postproc.setup.tool_table_file import parse_tool_table, tool_table_text
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import load_setup
from tests.support.rs274 import available, run_rs274

TABLE = """T1 P1 Z0.511 D0.125 ;1/8 end mill
T2 P2 Z0.1 D0.0625 ;1/16 end mill
t3 p3 d0.201 z+1.273 ;#7 tap drill

T18 P7 Z2.5 D0.5
; a remark alone
"""
"""A table as people write them (the first lines are from a LinuxCNC user's ``tool.tbl``; lower case and a sign
are read by LinuxCNC too [V: ``tool_parse.cc``]); in inches, the machine's units below."""

CANONICAL = """T1 P1 Z0.511 D0.125 ;1/8 end mill
T2 P2 Z0.1 D0.0625 ;1/16 end mill
T3 P3 Z1.273 D0.201 ;#7 tap drill
T18 P7 Z2.5 D0.5
"""
"""``TABLE`` as the table writer writes it (by hand: letters upper case, one order, no blank or remark lines)."""


def write_setup(folder: Path, table: str = TABLE, tools: str = "") -> Path:
    (folder / "tool.tbl").write_text(table, encoding="utf-8")
    path = folder / "m.xml"
    path.write_text(f'<MachineSetup name="m" dialect="linuxcnc"><Machine units="inch"/><Tools table="tool.tbl">{tools}'
                    "</Tools></MachineSetup>", encoding="utf-8")
    return path


def test_a_table_becomes_the_setups_tools(tmp_path: Path) -> None:
    setup = load_setup(write_setup(tmp_path))
    assert setup.tools == {
        "1": ToolData(number=1, pocket=1, comment="1/8 end mill", length=0.511, radius=0.0625),
        "2": ToolData(number=2, pocket=2, comment="1/16 end mill", length=0.1, radius=0.03125),
        "3": ToolData(number=3, pocket=3, comment="#7 tap drill", length=1.273, radius=0.1005),
        "18": ToolData(number=18, pocket=7, length=2.5, radius=0.25),
    }
    assert setup.tool_table == "tool.tbl"


def test_a_tool_element_overrides_the_table(tmp_path: Path) -> None:
    setup = load_setup(write_setup(tmp_path, tools='<Tool number="2" length="0.2"/><Tool number="5" length="1.0"/>'))
    assert setup.tools["2"] == ToolData(number=2, pocket=2, comment="1/16 end mill", length=0.2, radius=0.03125)
    assert setup.tools["5"] == ToolData(number=5, length=1.0)


def test_import_dump_reimport_is_identical(cli: Any, tmp_path: Path) -> None:
    path = write_setup(tmp_path, tools='<Tool number="2" length="0.2"/>')
    dumped = cli("config", "dump", path)
    assert dumped.status == 0
    assert dumped.out.decode() == ("<?xml version='1.0' encoding='UTF-8'?>\n<MachineSetup name=\"m\" dialect=\"linuxcnc\">\n"
                                   "  <Machine units=\"inch\"/>\n  <Tools table=\"tool.tbl\">\n"
                                   "    <Tool number=\"2\" length=\"0.2\"/>\n  </Tools>\n</MachineSetup>\n")
    flat = cli("config", "dump", "--flatten", path)
    again = tmp_path / "flat.xml"
    again.write_bytes(flat.out)
    assert 'table=' not in flat.out.decode() and 'pocket="7"' in flat.out.decode()
    assert load_setup(again).tools == load_setup(path).tools
    assert cli("config", "dump", "--flatten", again).out == flat.out


def test_the_table_written_back_is_the_table_read() -> None:
    tools = [tool for _, tool in parse_tool_table(TABLE, "tool.tbl")]
    assert tool_table_text(tools) == CANONICAL
    assert [tool for _, tool in parse_tool_table(CANONICAL, "t")] == tools


finite = st.floats(min_value=-1000, max_value=1000, allow_nan=False, allow_infinity=False)


@given(st.lists(st.tuples(st.integers(0, 9999), st.integers(0, 1000), st.none() | finite, st.none() | finite,
                          st.none() | st.text(st.characters(min_codepoint=32, max_codepoint=0x2FF), min_size=1,
                                              max_size=30).filter(lambda s: s.rstrip() == s)),
                unique_by=(lambda t: t[0], lambda t: t[1]), max_size=8))
def test_any_table_round_trips(rows: list[tuple[int, int, float | None, float | None, str | None]]) -> None:
    tools = [ToolData(number=n, pocket=p, length=z, radius=r, comment=c) for n, p, z, r, c in rows]
    text = tool_table_text(tools)
    assert [tool for _, tool in parse_tool_table(text, "t")] == tools
    assert tool_table_text([tool for _, tool in parse_tool_table(text, "t")]) == text


@pytest.mark.parametrize(("line", "message"), [
    ("T1 P1 Z0.5\nT2 P1 Z0.5\n", "t.tbl:2:1: pocket P1 holds tool T1 too (line 1; a pocket holds one tool)"),
    ("T3 Z1\n", "t.tbl:1:1: a tool table line needs P (LinuxCNC files a line without P in the pocket of the line before)"),
    ("T4 P4 X0.5 Z1\n", "t.tbl:1:7: X, a lathe tool's X offset, is not read from a tool table yet: give the lathe "
                        "offsets as <Tool x z>"),
    ("T4 P4 I95 Z1\n", "t.tbl:1:7: I, the front angle, is not read from a tool table yet (a set-up has no such tool data)"),
    ("T5 P5 K3\n", "t.tbl:1:7: 'K3' is no word of a LinuxCNC tool table (T P X Y Z A B C U V W D I J Q, a remark after ';')"),
    ("T1 P1\nT1 P6\n", "t.tbl:2:1: tool T1 appears twice (line 1 and here)"),
    ("1 1 0.5 0.1\n", "t.tbl:1:1: an old-style tool table line (numbers without letters) is not read: write it as T.. P.. "
                      "Z.. D.."),
    ("T7 P7 Zabc\n", "t.tbl:1:7: Z needs a number, got 'abc'"),
    ("T7 P7 Znan\n", "t.tbl:1:7: Z needs a number, got 'nan'"),
    ("T7 P1.5\n", "t.tbl:1:4: P needs a whole number, got '1.5'"),
    ("T7 P7 Z1 Z2\n", "t.tbl:1:10: Z appears twice on the line"),
])
def test_a_line_linuxcnc_would_skip_or_misfile_is_a_located_error(line: str, message: str) -> None:
    with pytest.raises(ConfigError) as err:
        parse_tool_table(line, "t.tbl")
    assert f"{err.value.location}: {err.value.message}" == message


def test_zeros_in_the_columns_not_read_change_nothing() -> None:
    # tooledit-style lines with every column: zero offsets and angles are no data lost
    (_, tool), = parse_tool_table("T1 P1 X+0.000 Y+0.000 Z+1.000 A0 B0 C0 U0 V0 W0 D+0.500 I+0.0 J0 Q0 ;x\n", "t")
    assert tool == ToolData(number=1, pocket=1, comment="x", length=1.0, radius=0.25)


def test_every_problem_at_once(tmp_path: Path, cli: Any) -> None:
    path = write_setup(tmp_path, table="T1 P1\nT2 Q3\nT3 P3 Zx\n")
    run = cli("config", "check", path)
    assert run.status == 1
    table = tmp_path / "tool.tbl"
    assert run.err.splitlines() == [
        f"{table}:2:4: error: Q, a lathe tool's orientation, is not read from a tool table yet: give it as <Tool tip>, "
        "in Fanuc's numbering",
        f"{table}:3:7: error: Z needs a number, got 'x'"]


def test_pockets_are_checked_in_the_setup(tmp_path: Path) -> None:
    path = write_setup(tmp_path, tools='<Tool number="9" pocket="7" length="1"/>')
    with pytest.raises((ConfigError, ErrorList)) as err:
        load_setup(path)
    assert 'pocket 7 holds tool 18 too' in str(getattr(err.value, "message", err.value))


def test_a_missing_table_is_an_error_of_the_setup(tmp_path: Path, cli: Any) -> None:
    path = tmp_path / "m.xml"
    path.write_text('<MachineSetup name="m"><Tools table="none.tbl"/></MachineSetup>', encoding="utf-8")
    run = cli("config", "check", path)
    assert run.status == 1 and "<Tools table>: cannot read the tool table" in run.err


def test_what_a_linuxcnc_table_cannot_hold_is_refused() -> None:
    with pytest.raises(ConfigError, match="Fanuc memory A/B"):
        tool_table_text([ToolData(number=1, offset=3.0)])
    with pytest.raises(ConfigError, match="lathe offset"):
        tool_table_text([ToolData(number=1, x=1.0, z=2.0)])
    with pytest.raises(ConfigError, match="pocket 4 holds tool 1 too"):
        tool_table_text([ToolData(number=1, pocket=4), ToolData(number=4)])


def test_wear_is_added_into_the_one_column() -> None:
    text = tool_table_text([ToolData(number=2, length=10.0, length_wear=-0.25, radius=3.0, radius_wear=-0.5)])
    assert text == "T2 P2 Z9.75 D5\n"


# -- rs274 reads the table written -------------------------------------------------------------------------

_REPORT = re.compile(r'MESSAGE\("\s*T(\S+) Z(\S+) D(\S+) P(\S+)"\)')


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_reads_the_table_written(tmp_path: Path) -> None:
    setup = load_setup(write_setup(tmp_path))
    text = tool_table_text(setup.tools.values())
    program = ["G20"]
    for tool in setup.tools.values():
        program += [f"T{tool.number} M6", "(debug, T#5400 Z#5403 D#5410 P#<_current_pocket>)"]
    calls = run_rs274("\n".join(program + ["M2"]), tool_table=text)
    found = [tuple(float(v) for v in m.groups()) for m in map(_REPORT.search, calls) if m]
    assert found == [(t.number, t.length, 2 * (t.radius or 0.0), t.pocket) for t in setup.tools.values()]
