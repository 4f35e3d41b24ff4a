"""The conformance suite fails usefully: run it (pytest, in a subprocess, as a plugin author would) on
deliberately broken copies of the Mach3 example plugin and read the report.

Each copy is the example package copied and renamed, with one defect put in by a text edit, and made
installed by a ``.dist-info`` folder with its entry point on ``PYTHONPATH`` (what pip would write):
a writer that drops the Y word, a capability flag that lies (an oriented spindle stop with no M19 row),
a reader whose error has no location, a pipeline file that says other than ``python_pipeline``, and
native cycles without the rules they follow (``CYCLE_SEMANTICS``).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PLUGIN = ROOT / "plugins" / "example_dialect"

DEFECTS: dict[str, list[tuple[str, str, str]]] = {
    # name: (file, text, replacement), each text must occur in the copy
    "dropy": [("writer.py", "for axis, value in s.axes.items())", "for axis, value in s.axes.items() if axis != \"Y\")")],
    "lies": [("__init__.py", "SPINDLE_ORIENTATION = False", "SPINDLE_ORIENTATION = True")],
    "notap": [("__init__.py", 'NATIVE_CYCLES = frozenset({"drill", "peck_chip", "peck_deep"})',
               'NATIVE_CYCLES = frozenset({"drill", "peck_chip", "peck_deep", "tap"})')],
    "unlocated": [("reader.py", "    DIALECT = \"mach3\"\n",
                   "    DIALECT = \"mach3\"\n\n"
                   "    def read(self, lines):  # type: ignore[no-untyped-def]\n"
                   "        from postproc.errors import ParseError\n"
                   "        for block in super().read(lines):\n"
                   "            if \"#\" in (block.text or \"\"):\n"
                   "                raise ParseError(\"parameters are not supported\")\n"
                   "            yield block\n")],
    "drift": [("mach3.xml", '<CannedCycleResolveSyntax semantics="rs274"/>',
               '<CannedCycleResolveSyntax semantics="fanuc"/>')],
    "norules": [("__init__.py", '    CYCLE_SEMANTICS = "rs274"\n', "")],
}

TEST_MODULE = '''
import pytest
from pathlib import Path
from postproc.testing import ConformanceTests, DialectUnderTest

HERE = Path(__file__).parent

@pytest.fixture(params=["dropy", "lies", "notap", "unlocated", "drift", "norules"])
def postproc_conformance(request):
    name = request.param
    others = frozenset({"mach3", "dropy", "lies", "notap", "unlocated", "drift", "norules"}) - {name}
    return DialectUnderTest(name, HERE / "examples", HERE / ("invalid_" + name), HERE / "zero_tools.xml",
                            skip_targets=others)

class TestBroken(ConformanceTests):
    pass
'''


def _broken_copy(site: Path, name: str) -> None:
    package = site / f"postproc_broken_{name}"
    shutil.copytree(PLUGIN / "postproc_mach3", package)
    for file, old, new in DEFECTS.get(name, []):
        path = package / file
        text = path.read_text()
        assert old in text, f"the example plugin changed: {old!r} is not in {file}"
        path.write_text(text.replace(old, new))
    for path in package.iterdir():
        if path.suffix in (".py", ".xml"):
            text = path.read_text()
            text = text.replace("Mach3BlockSyntax", f"Broken{name.title()}BlockSyntax")
            text = text.replace('NAME = "mach3"', f'NAME = "{name}"').replace('DIALECT = "mach3"', f'DIALECT = "{name}"')
            text = text.replace('dialect="mach3"', f'dialect="{name}"').replace('DIALECT: ClassVar[str] = "mach3"',
                                                                               f'DIALECT: ClassVar[str] = "{name}"')
            path.write_text(text)
    info = site / f"postproc_broken_{name}-0.1.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: postproc-broken-{name}\nVersion: 0.1\n")
    (info / "entry_points.txt").write_text(f"[postproc]\n{name} = postproc_broken_{name}\n")


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> str:
    work = tmp_path_factory.mktemp("broken")
    site = work / "site"
    site.mkdir()
    for name in DEFECTS:
        _broken_copy(site, name)
    suite = work / "suite"
    shutil.copytree(PLUGIN / "examples", suite / "examples", ignore=shutil.ignore_patterns("invalid"))
    for name in DEFECTS:
        shutil.copytree(PLUGIN / "examples" / "invalid", suite / f"invalid_{name}")
    (suite / "invalid_unlocated" / "parameter.nc").write_text("G21 G90\n#1=2\nG0 X#1\nM30\n")
    (suite / "test_broken.py").write_text(TEST_MODULE)
    shutil.copy(Path(__file__).resolve().parent / "support" / "zero_tools.xml", suite)  # the examples' G43 registers
    env = {**os.environ, "PYTHONPATH": str(site), "HYPOTHESIS_PROFILE": ""}
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "--rootdir", str(suite),
                          "-o", "postproc_max_examples=10", str(suite)],
                         cwd=suite, env=env, capture_output=True, text=True, timeout=600)
    assert run.returncode == 1, run.stdout + run.stderr
    return run.stdout


def _section(report: str, test: str, case: str) -> str:
    """The failure text pytest printed for ``test[case]``."""
    head = f"TestBroken.{test}[{case}]"
    assert head in report, f"{head} did not fail:\n{report}"
    start = report.index(head)
    end = report.find("\n____", start)
    return report[start:end if end >= 0 else len(report)]


def test_a_writer_that_drops_a_word_is_caught_with_the_line_it_moves_wrongly(report: str) -> None:
    text = _section(report, "test_generated_programs_round_trip", "dropy")
    assert "the dropy text does not move the tool as the IR it was written from" in text
    assert "--- written:" in text  # the program as the broken writer wrote it


def test_a_lying_capability_flag_is_named_with_what_the_writer_did(report: str) -> None:
    text = _section(report, "test_capability_flags_match_the_writer", "lies")
    assert "lies: SPINDLE_ORIENTATION = True, but the writer refuses an oriented spindle stop" in text
    assert "probe.nc:3:1: error: the lies dialect cannot express an oriented spindle stop" in text


def test_a_native_cycle_the_code_table_cannot_spell_is_named(report: str) -> None:
    """The example has no G84 row: claiming the tap cycle native fails in the writer, which the suite
    finds without an example that taps."""
    text = _section(report, "test_capability_flags_match_the_writer", "notap")
    assert "but the writer refuses the tap cycle: probe.nc:3:1: error: the notap dialect cannot express the tap cycle" in text


def test_an_unlocated_error_is_reported_as_such(report: str) -> None:
    text = _section(report, "test_invalid_programs_fail_with_located_errors", "unlocated")
    assert "parameter.nc" in text and "an error without FILE:LINE:COL: 'error: parameters are not supported'" in text


def test_a_pipeline_file_that_drifted_from_python_pipeline_is_shown_beside_it(report: str) -> None:
    """A run reads with ``python_pipeline`` and never sees the file: only this check does."""
    text = _section(report, "test_python_pipeline_is_the_pipeline_file", "drift")
    assert "drift: python_pipeline under a mill set-up is not the pipeline of mach3.xml" in text
    assert '<CannedCycleResolveSyntax semantics="rs274"/>' in text
    assert '<CannedCycleResolveSyntax semantics="fanuc"/>' in text


def test_checks_the_defects_do_not_touch_still_pass(report: str) -> None:
    summary = report.splitlines()
    for case in ("dropy", "lies", "notap", "unlocated", "drift"):
        for test in ("test_examples_read_back_byte_for_byte", "test_ir_survives_xml"):
            assert f"FAILED test_broken.py::TestBroken::{test}[{case}]" not in summary, report
    assert not any(line.startswith("FAILED") and "[lies]" in line and "capability" not in line for line in summary), report


def test_native_cycles_without_their_rules_are_named(report: str) -> None:
    """The core has no family default: a plugin listing native cycles must say whose rules they follow."""
    text = _section(report, "test_capability_flags_match_the_writer", "norules")
    assert "norules: NATIVE_CYCLES without CYCLE_SEMANTICS (fanuc or rs274)" in text
