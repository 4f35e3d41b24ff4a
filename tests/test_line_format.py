"""``<Output>`` line formatting: block numbers, case, line ending, line length, on every writer that
takes them, each output read back by the target's own reader."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from postproc.api import read_program, translate
from postproc.errors import ConfigError, ErrorList
from postproc.setup.machine_setup import MachineSetup, OutputSettings

PROGRAM = "%\nO0010 (TEST)\n(FIRST OP)\nN5 G21 G90 G17\nT1 M06\nG0 X1. Y2.\nN99 G1 Z-1. F100.\n/G0 Z5.\nM30\n%\n"


def _write(target: str, text: str = PROGRAM, **output: object) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="p.nc", source="fanuc", target=target,
              setup=MachineSetup(output=OutputSettings(**output)))  # type: ignore[arg-type]
    result = out.getvalue()
    read_program(io.StringIO(result), file="out", dialect=target)  # the target reads what was written
    return result


def test_every_line_with_words_is_numbered_from_start_by_step():
    lines = _write("fanuc", block_numbers="all", renumber_start=100, renumber_step=5).splitlines()
    assert lines == ["%", "O0010 (TEST)", "(FIRST OP)", "N100 G21 G90 G17", "N105 T1 M06", "N110 G0 X1. Y2.",
                     "N115 G1 Z-1. F100.", "/ N120 G0 Z5.", "N125 M30", "%"]


def test_only_tool_changes_are_numbered():
    lines = _write("fanuc", block_numbers="tool-changes", renumber_start=1, renumber_step=1).splitlines()
    assert lines[3:9] == ["G21 G90 G17", "N1 T1 M06", "G0 X1. Y2.", "G1 Z-1. F100.", "/ G0 Z5.", "M30"]


def test_numbers_can_be_removed():
    text = _write("fanuc", block_numbers="none")
    assert "N5" not in text and "N99" not in text and "G21 G90 G17\n" in text


def test_numbers_wrap_past_the_maximum():
    lines = _write("fanuc", block_numbers="all", renumber_start=10, renumber_step=10, number_max=30).splitlines()
    assert lines[3:9] == ["N10 G21 G90 G17", "N20 T1 M06", "N30 G0 X1. Y2.", "N10 G1 Z-1. F100.", "/ N20 G0 Z5.",
                          "N30 M30"]


def test_numbering_works_across_dialects():
    """The writer's own renumbering only ran for a same-dialect translation; line numbering runs for all."""
    lines = _write("linuxcnc", block_numbers="all", renumber_start=10, renumber_step=10).splitlines()
    import re
    numbers = [int(m.group(1)) for line in lines if (m := re.match(r"(?:/ )?N(\d+) ", line))]
    assert numbers == list(range(10, 10 * len(numbers) + 1, 10)) and len(numbers) >= 6
    assert not any(re.search(r"\bN(5|99)\b", line) for line in lines)  # the source's numbers are gone


def test_a_program_that_jumps_to_block_numbers_is_not_renumbered():
    text = "G21 G90\n#1=0\nN10 #1=#1+1\nIF [#1 LT 3] GOTO 10\nM30\n"
    with pytest.raises(ErrorList, match="jumps to block numbers"):
        _write("fanuc", text, block_numbers="none")


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_lower_case_where_the_reader_takes_it(target):
    text = _write(target, "G21 G90\nG0 X1. Y2. (KEEP THIS)\nM30\n", case="lower")
    assert "g0 x1. y2. (KEEP THIS)" in text


def test_lower_case_is_refused_for_fanuc():
    with pytest.raises(ConfigError, match='<Output case="lower">: the fanuc reader takes upper-case addresses only'):
        _write("fanuc", case="lower")


def test_crlf_line_endings():
    text = _write("fanuc", line_ending="crlf")
    assert text.count("\r\n") == text.count("\n") == PROGRAM.count("\n")
    assert _write("fanuc", PROGRAM.replace("\n", "\r\n"), line_ending="lf") == PROGRAM


def test_a_line_too_long_is_a_located_error():
    with pytest.raises(ErrorList) as info:
        _write("fanuc", max_line_length=12)
    first = info.value.errors[0]
    assert first.location.line == 4  # "O0010 (TEST)" is 12 characters, "N5 G21 G90 G17" (line 4) 14
    assert "more than <Output maxLineLength=\"12\">" in first.message


def test_defaults_change_nothing_and_stay_off_the_hot_path():
    from postproc.output.line_format import LineFormat
    from postproc.errors import Diagnostics
    from postproc.plugins import default_registry
    fanuc = default_registry().dialect("fanuc")
    assert LineFormat.for_run(fanuc.context("p.nc", MachineSetup(), Diagnostics()), "fanuc", False) is None
    assert _write("fanuc") == PROGRAM


LIMIT = 10_000_000
"""grbl 1.1 and grblHAL ``gcode.c``: ``MAX_LINE_NUMBER``, a larger N is error 27 and the line is not run [V]."""


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
@pytest.mark.parametrize("mode", ["all", "tool-changes"])
def test_numbering_grbl_cannot_take_refuses_the_set_up(target, mode):
    """``numberMax`` above grbl's limit: the set-up is refused before anything is written (the numbering it states
    cannot run there), not wrapped elsewhere nor passed for a program too short to reach it."""
    with pytest.raises(ConfigError, match=f'<Output numberMax="{LIMIT + 1}">: the {target} controller refuses a '
                                          f'block number above {LIMIT}'):
        _write(target, block_numbers=mode, renumber_start=10, renumber_step=10, number_max=LIMIT + 1)
    with pytest.raises(ConfigError, match=f'<Output renumberStart="{LIMIT + 5}">: the {target} controller'):
        _write(target, block_numbers=mode, renumber_start=LIMIT + 5, number_max=LIMIT)


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
def test_numbering_up_to_grbls_limit_wraps_and_runs(target):
    from tests.support.grbl_rules import grbl_problems
    from tests.support.grblhal_rules import grblhal_problems
    text = _write(target, PROGRAM.replace("/G0", "G0"), block_numbers="all", renumber_start=LIMIT - 20,
                  renumber_step=10, number_max=LIMIT)  # (grbl has no block delete)
    numbers = [int(m.group(1)) for line in text.splitlines() if (m := re.match(r"(?:/ )?N(\d+) ", line))]
    assert numbers[:5] == [LIMIT - 20, LIMIT - 10, LIMIT, LIMIT - 20, LIMIT - 10]
    assert (grbl_problems if target == "grbl" else grblhal_problems)(text) == []


def test_other_targets_keep_a_large_number_max():
    lines = _write("linuxcnc", block_numbers="all", renumber_start=LIMIT, number_max=LIMIT + 100).splitlines()
    assert any(line.startswith(f"N{LIMIT + 10} ") for line in lines)


def test_the_refusal_is_located_at_the_setting(tmp_path: Path):
    from postproc.setup.machine_setup import load_setup
    path = tmp_path / "m.xml"
    path.write_text('<?xml version="1.0" encoding="UTF-8"?>\n<MachineSetup name="t">\n  <Input/>\n'
                    '  <Output blockNumbers="all" numberMax="99999999"/>\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as info:
        translate(io.StringIO(PROGRAM), io.StringIO(), file="p.nc", source="fanuc", target="grbl",
                  setup=load_setup(path))
    assert str(info.value).startswith(f"{path}:4:1: error: <Output numberMax=\"99999999\">: the grbl controller")
