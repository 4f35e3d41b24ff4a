"""docs/plugins.md names only what exists: every dotted ``postproc.`` name it cites imports, every file path
it cites is in the repository, every capability flag, writer and block syntax attribute it cites is on its
base class, and its tables of hooks, conformance tests and settings are the code's own, whole."""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import pytest

from postproc import hookspecs
from postproc.dialect import Dialect
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax
from postproc.rs274.writer import WordWriter
from postproc.testing import INI, ConformanceTests

ROOT = Path(__file__).resolve().parents[1]
GUIDE = (ROOT / "docs" / "plugins.md").read_text(encoding="utf-8")
CODE = re.findall(r"`([^`]+)`", re.sub(r"^[ \t]*```.*?^[ \t]*```", "", GUIDE, flags=re.MULTILINE | re.DOTALL))
"""Every inline code span of the guide (outside the fenced blocks; a span may go on to the next line)."""


def _section(title: str) -> str:
    start = GUIDE.index(f"\n## {title}\n")
    end = GUIDE.find("\n## ", start + 1)
    return GUIDE[start:end if end >= 0 else len(GUIDE)]


def _first_column(title: str) -> list[str]:
    """The code spans in the first column of the section's table (several in a cell count each)."""
    names: list[str] = []
    for line in _section(title).splitlines():
        if line.startswith("| `"):
            names += re.findall(r"`([^`]+)`", line.split("|")[1])
    return names


def _resolve(dotted: str) -> object:
    """The object a dotted name names: the longest importable module, then attributes."""
    parts = dotted.split(".")
    for cut in range(len(parts), 0, -1):
        try:
            found: object = importlib.import_module(".".join(parts[:cut]))
        except ImportError:
            continue
        for attr in parts[cut:]:
            found = getattr(found, attr)
        return found
    raise ImportError(dotted)


DOTTED = sorted({m.group(0) for span in CODE for m in re.finditer(r"\bpostproc(?:\.[A-Za-z_]\w*)+", span)})
PATHS = sorted({span.rstrip("/") for span in CODE
                if re.fullmatch(r"(postproc|plugins|dialects|tests|docs)/[\w./-]+", span)})


def test_the_guide_cites_names_and_paths():
    assert len(DOTTED) > 20 and len(PATHS) > 10  # the patterns find what the guide cites


@pytest.mark.parametrize("dotted", DOTTED)
def test_every_cited_public_name_imports(dotted):
    assert not any(part.startswith("_") for part in dotted.split(".")), f"{dotted} is not public"
    _resolve(dotted)


@pytest.mark.parametrize("path", PATHS)
def test_every_cited_path_exists(path):
    assert (ROOT / path).exists(), path


def test_every_capability_flag_in_the_table_is_a_dialect_attribute():
    flags = _first_column("Capability flags")
    assert "NATIVE_CYCLES" in flags and "LINE_RULE" in flags
    assert [f for f in flags if not hasattr(Dialect, f)] == []


def test_the_writer_and_block_syntax_names_are_on_their_bases():
    writer = _section("The writer")
    cited = {name for name in re.findall(r"`([A-Za-z_]+)`", writer)
             if name.isupper() or name.endswith(("_block", "_words")) or name in ("check_reference_return",
                                                                               "feed_beside_units")}
    assert {"DRIVEN_AXES", "STRUCTURE", "structure_block", "motion_words"} <= cited
    assert sorted(n for n in cited if not hasattr(WordWriter, n)) == []
    base = (ROOT / "postproc" / "output" / "writer_base.py").read_text(encoding="utf-8")
    for attr in ("set_aside", "opening"):  # instance attributes, set by the base's constructor
        assert f"`{attr}`" in writer and f"self.{attr}:" in base, attr
    syntax = _section("Code table, reader, block syntax, pipeline")
    for name in ("CODES", "M_GROUPS", "CYCLE_CANCEL_WITH_MOTION", "SPECIAL_G", "OWN_CODES", "OWN_STATE",
                 "OWN_MOTION", "special_g_code", "before_sections", "after_sections"):
        assert f"`{name}`" in syntax and hasattr(NgcWordBlockSyntax, name), name
    for name in ("python_pipeline", "pipeline_file", "PIPELINE_FILE", "PROGRAMS", "LOWERING", "READER"):
        assert re.search(rf"\b{name}\b", GUIDE) and hasattr(Dialect, name), name


def test_the_hook_table_is_the_hook_specification():
    hooks = {name.split("(")[0] for name in _first_column("Entry point and hooks")}
    specs = {name for name in vars(hookspecs) if name.startswith("postproc_")}
    assert hooks == specs


def test_the_conformance_table_lists_every_test_of_the_suite():
    listed = _first_column("The conformance suite")
    tests = sorted(name for name in dir(ConformanceTests) if name.startswith("test_"))
    assert sorted(listed) == tests
    assert f"({len(tests)} tests)" in GUIDE


def test_the_settings_shown_are_the_suites_settings():
    shown = re.findall(r"^(postproc_\w+) = ", _section("The conformance suite"), re.MULTILINE)
    assert sorted(shown) == sorted(INI)
