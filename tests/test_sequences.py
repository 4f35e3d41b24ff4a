"""Sequence templates: tool change, operation start, program end, the tool list, ``--define`` and the
date, each placed where the translation calls it, read back by the target and verified against the source."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import ConfigError
from postproc.setup.machine_setup import load_setup
from postproc.ir.source_map import OutputMap
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parents[1]
O1001 = ROOT / "examples/fanuc/o1001_plate_drill_tap.nc"
DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"

TOOL_CHANGE = ("(TOOL CHANGE {{ operation }}: T{{ tool }}{% if previous_tool %} AFTER T{{ previous_tool }}"
               "{% endif %})\nT{{ tool }} M06")


def _setup(tmp_path: Path, templates: str, dialect: str = "fanuc") -> Path:
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + f'<MachineSetup name="vmc" dialect="{dialect}">\n  <Templates>\n'
                    f"{templates}  </Templates>\n</MachineSetup>\n")
    return path


def _translate(setup: Path, target: str = "fanuc", source: Path = O1001, **kw: object) -> str:
    out = io.StringIO()
    translate(io.StringIO(source.read_text()), out, file=str(source), source="fanuc", target=target,
              setup=load_setup(setup), **kw)  # type: ignore[arg-type]
    return out.getvalue()


def test_the_tool_change_template_replaces_each_tool_change_block(tmp_path):
    setup = _setup(tmp_path, f"    <ToolChange>{TOOL_CHANGE}</ToolChange>\n")
    lines = _translate(setup).splitlines()
    # o1001 loads T1 (line 12), T2 (line 26), T3 (line 41): each N.. T M06 block becomes the template's two lines
    assert [line for line in lines if "M06" in line] == ["T1 M06", "T2 M06", "T3 M06"]
    assert "(TOOL CHANGE 1: T1)" in lines and "(TOOL CHANGE 2: T2 AFTER T1)" in lines
    assert lines[lines.index("(TOOL CHANGE 3: T3 AFTER T2)") - 1] == "(TAP M10 X 1.5 - F = 1.5 X S400 = 600)"
    assert not any(line.startswith(("N40 ", "N170 ", "N310 ")) for line in lines)


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
def test_a_translation_with_the_tool_change_template_verifies_at_zero_deviation(tmp_path, target):
    ext = target
    setup = _setup(tmp_path, "    <ToolChange>(LOAD T{{ tool }})\nT{{ tool }} M6</ToolChange>\n", ext)
    text = _translate(setup, target)
    assert text.count("(LOAD T") == 3
    report = verify_lines(io.StringIO(O1001.read_text()), io.StringIO(text), file_in=str(O1001), file_out="out",
                          source="fanuc", target=target, setup=with_tools(load_setup(setup)), target_setup=None,
                          tolerance=0.0, allow_ignored=True, overlay=None)
    assert report.ok, report.summary()


def test_operation_start_is_written_before_each_tool_change_with_the_comment_that_names_it(tmp_path):
    setup = _setup(tmp_path, "    <OperationStart>(OPERATION {{ operation }}: {{ name }}, LINE {{ line }}"
                             "{% if first_use %}, NEW TOOL{% endif %})</OperationStart>\n")
    lines = _translate(setup).splitlines()
    at = lines.index("(OPERATION 1: SPOT DRILL, LINE 12, NEW TOOL)")
    assert (lines[at - 1], lines[at + 1]) == ("(SPOT DRILL)", "N40 T1 M06")
    at = lines.index("(OPERATION 2: DRILL 8.5 THRU, LINE 26, NEW TOOL)")
    assert lines[at + 1] == "N170 T2 M06"
    assert "(OPERATION 3: TAP M10 X 1.5 - F = 1.5 X S400 = 600, LINE 41, NEW TOOL)" in lines


def test_the_header_lists_the_tools_with_their_first_use(tmp_path):
    setup = _setup(tmp_path, "    <Header>{% for t in tools %}(T{{ t.number }} FIRST AT LINE {{ t.line }})\n"
                             "{% endfor %}</Header>\n")
    lines = _translate(setup).splitlines()
    assert lines[:4] == ["%", "(T1 FIRST AT LINE 12)", "(T2 FIRST AT LINE 26)", "(T3 FIRST AT LINE 41)"]


def test_program_end_replaces_the_end_block(tmp_path):
    setup = _setup(tmp_path, "    <ProgramEnd>(END OF {{ program }} FROM LINE {{ line }})\nM30</ProgramEnd>\n")
    lines = _translate(setup).splitlines()
    assert lines[-3:] == ["(END OF o1001_plate_drill_tap FROM LINE 54)", "M30", "%"]
    assert "N440 M30" not in lines


def test_defines_and_a_reproducible_date(tmp_path, monkeypatch):
    setup = _setup(tmp_path, "    <Header>(BY {{ operator }} ON {{ date }} FROM {{ source_file }})</Header>\n")
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "86400")
    lines = _translate(setup, defines={"operator": "ANNA"}).splitlines()
    assert lines[1] == f"(BY ANNA ON 1970-01-02 FROM {O1001})"
    lines = _translate(setup, defines={"operator": "ANNA", "date": "2024-05-01"}).splitlines()
    assert lines[1] == f"(BY ANNA ON 2024-05-01 FROM {O1001})"


def test_the_setup_values_are_in_the_context_by_their_xml_names(tmp_path):
    setup = _setup(tmp_path, "    <Header>(G73 RETRACT {{ setup.Cycles.peckRetract }} ON {{ setup.name }})</Header>\n")
    assert _translate(setup).splitlines()[1] == "(G73 RETRACT 0.5 ON vmc)"


@pytest.mark.parametrize("define, message", [
    ("NAME", "--define takes NAME=VALUE, got 'NAME'"),
    ("1X=2", "--define '1X': a name is a letter"),
    ("for=2", "--define 'for': a name is a letter"),
    ("tool=2", "--define tool: the translation sets tool itself"),
])
def test_bad_defines_are_usage_errors(cli, tmp_path, define, message):
    result = cli("translate", O1001, "--from", "fanuc", "--to", "fanuc", "--define", define)
    assert result.status == 2
    assert result.err.startswith(f"postproc: {message}")


def test_a_define_reaches_the_template_through_the_cli(cli, tmp_path):
    setup = _setup(tmp_path, "    <Header>(JOB {{ job }})</Header>\n")
    result = cli("translate", O1001, "--from", "fanuc", "--to", "fanuc", "--machine", setup, "--define", "job=4711")
    assert result.status == 0, result.err
    assert result.out.decode().splitlines()[1] == "(JOB 4711)"
    assert cli("config", "check", setup).status == 1  # 'job' is undefined without --define
    assert cli("config", "check", setup, "--define", "job=1").status == 0


def test_output_the_target_cannot_read_is_an_error_at_the_template(cli, tmp_path):
    setup = _setup(tmp_path, "    <Header>(OK)</Header>\n    <ToolChange>(T{{ tool }})\nT{{ tool }} M06 G999</ToolChange>\n")
    result = cli("translate", O1001, "--from", "fanuc", "--to", "fanuc", "--machine", setup, "-o", tmp_path / "o.nc")
    assert result.status == 1
    assert result.err.startswith(f"{setup}:5:1: error: template tool_change: the fanuc reader refuses its output, "
                                 "line 2 'T1 M06 G999': unknown G code G999")
    assert not (tmp_path / "o.nc").exists()
    check = cli("config", "check", setup)  # config check finds it too, with its sample values
    assert check.status == 1 and check.err.startswith(f"{setup}:5:1: error: template tool_change: the fanuc")


def test_a_template_that_leaves_a_modal_setting_changed_is_refused(tmp_path):
    setup = _setup(tmp_path, "    <ToolChange>G91 G28 Z0.\nT{{ tool }} M06</ToolChange>\n")
    with pytest.raises(ConfigError, match=r"template tool_change leaves distance changed \(from absolute to "
                                          r"incremental\)"):
        _translate(setup)
    restored = _setup(tmp_path, "    <ToolChange>G91 G28 Z0.\nG90\nT{{ tool }} M06</ToolChange>\n")
    assert "G91 G28 Z0." in _translate(restored)


def test_a_tool_change_block_with_other_words_cannot_be_replaced(tmp_path):
    program = tmp_path / "p.nc"
    program.write_text("G21 G90\nT1 M06 G43 H01 G0 Z50.\nM30\n")
    setup = _setup(tmp_path, "    <ToolChange>T{{ tool }} M06</ToolChange>\n")
    with pytest.raises(ConfigError) as info:
        _translate(setup, source=program)
    assert info.value.message == ("the tool_change template replaces this whole block, which also programs "
                                  "ToolLengthOffset, Motion: put the tool change in a block of its own")
    assert info.value.location.line == 2


def test_grbl_gets_the_setups_tool_change_instead_of_its_pause(tmp_path):
    program = tmp_path / "p.nc"
    program.write_text("G21 G90\nG0 X0. Y0. Z10.\nT2 M06\nG1 Z-1. F100.\nM30\n")
    setup = _setup(tmp_path, "    <ToolChange>M5\n(CHANGE TO T{{ tool }} AND PRESS START)\nM0</ToolChange>\n", "grbl")
    lines = _translate(setup, "grbl", source=program).splitlines()
    at = lines.index("(CHANGE TO T2 AND PRESS START)")
    assert lines[at - 1:at + 2] == ["M5", "(CHANGE TO T2 AND PRESS START)", "M0"]


def test_the_output_map_marks_template_lines_as_generated(tmp_path):
    setup = _setup(tmp_path, "    <Header>(H1)\n(H2)</Header>\n    <ToolChange>T{{ tool }} M06</ToolChange>\n")
    out_map = OutputMap()
    text = _translate(setup, output_map=out_map)
    lines = text.splitlines()
    assert len(out_map.lines) == len(lines)
    assert out_map.lines[1:3] == [(None, "header"), (None, "header")]
    assert out_map.lines[lines.index("T1 M06")] == (None, "tool_change")
    assert out_map.lines[lines.index("N10 G21 G17 G90")] == (8, None)
    assert out_map.generated() == [2, 3] + [i + 1 for i, line in enumerate(lines) if line.endswith(" M06")]


def test_without_block_templates_or_tools_the_program_streams(tmp_path):
    from postproc.errors import Diagnostics
    from postproc.plugins import default_registry
    from postproc.lowering.sequences import Sequences
    fanuc = default_registry().dialect("fanuc")
    setup = load_setup(_setup(tmp_path, "    <Header>(H {{ program }})</Header>\n"))
    blocks = iter([])
    sequences = Sequences(fanuc.context("p.nc", setup, Diagnostics()), "fanuc", fanuc)
    assert sequences.before_lowering(blocks) is blocks and not sequences.needs_tools
    listing = load_setup(_setup(tmp_path, "    <Footer>{{ tools | length }}</Footer>\n"))
    assert Sequences(fanuc.context("p.nc", listing, Diagnostics()), "fanuc", fanuc).needs_tools


def test_templates_round_trip_through_config_dump(cli, tmp_path):
    setup = tmp_path / "m.xml"
    setup.write_text(DECLARATION + '<MachineSetup name="m" dialect="fanuc">\n  <Templates>\n'
                     "    <Header>(H)</Header>\n    <Footer>(F)</Footer>\n    <ToolChange>T{{ tool }} M06</ToolChange>\n"
                     "    <OperationStart>(OP {{ operation }})</OperationStart>\n"
                     "    <ProgramEnd>M30</ProgramEnd>\n  </Templates>\n</MachineSetup>\n")
    result = cli("config", "dump", setup)
    assert result.status == 0, result.err
    assert result.out == setup.read_bytes()
