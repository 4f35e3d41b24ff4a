"""rs274 reads at most 252 bytes a line ("Command too long" beyond, found by the "templates" fuzz kind with a
long ``--define`` value in a header comment): a longer line has its comment shortened with a warning, or is
refused with a located error; no written line is longer."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc_linuxcnc.lines import LINE_LENGTH

from tests.support.linuxcnc_rules import available, linuxcnc_problems

DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"


def _translate(program: str, setup: object = None, defines: dict[str, str] | None = None) -> tuple[str, str]:
    out, warnings = io.StringIO(), io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="fanuc", target="linuxcnc", setup=setup,
              defines=defines or {}, diagnostics=Diagnostics(warn_stream=warnings))
    return out.getvalue(), warnings.getvalue()


@pytest.mark.skipif(not available(), reason="LinuxCNC's rs274 is not installed")
def test_a_long_comment_is_shortened_to_what_rs274_reads() -> None:
    text, warnings = _translate("G21 G90\n(" + "A" * 300 + ")\nG0 X1. Y2. (" + "B" * 260 + ")\nM30\n")
    lines = text.splitlines()
    assert lines[1] == "(" + "A" * (LINE_LENGTH - 2) + ")" and len(lines[2]) == LINE_LENGTH
    assert lines[2].startswith("G0 X1. Y2. (BBB") and lines[2].endswith("B)")
    assert "in.nc:2:1: warning: a line longer than the 252 bytes LinuxCNC reads" in warnings
    assert linuxcnc_problems(text) == []


def test_a_long_value_in_a_template_comment_is_shortened(tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + '<MachineSetup name="m">\n  <Templates>\n    <Header>(JOB {{ job }})</Header>\n'
                    "  </Templates>\n</MachineSetup>\n")
    text, _ = _translate("G21 G90\nG0 X1.\nM30\n", load_setup(path), {"job": "x" * 400})
    assert len(text.splitlines()[0]) == LINE_LENGTH


def test_a_line_whose_code_is_too_long_is_refused_at_the_template(tmp_path: Path) -> None:
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + '<MachineSetup name="m">\n  <Templates>\n'
                    f"    <Header>(A)\nG4{' ' * 260}P1</Header>\n  </Templates>\n</MachineSetup>\n")
    with pytest.raises(ErrorList) as info:
        _translate("G21 G90\nG0 X1.\nM30\n", load_setup(path))
    assert str(info.value).startswith(f"{path}:4:1: error: the line is 264 bytes long, more than the 252 "
                                      "LinuxCNC reads")


@pytest.mark.skipif(not available(), reason="LinuxCNC's rs274 is not installed")
def test_the_limit_counts_bytes() -> None:
    """rs274 reads bytes: 200 characters of two bytes each are 400 (found by the fuzz kind)."""
    text, _ = _translate("G21 G90\n(" + "\u00e9" * 200 + ")\nG0 X1.\nM30\n")
    assert text.splitlines()[1] == "(" + "\u00e9" * 125 + ")"  # 252 bytes
    assert linuxcnc_problems(text) == []
