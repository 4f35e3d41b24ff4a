"""The core's packages import one way: down a declared order of layers, with no circle between packages.

A unit is a package directly under ``postproc/`` (``ir``, ``cycles``, its subpackages with it) or a module
directly under it (``api``, ``dialect``). ``LAYERS`` below is the order, bottom first: a unit may import
the units of lower layers and those listed before it in its own layer, nothing else. It was derived from the
import graph (each unit's floor: the longest chain of imports below it) and ordered by meaning where the graph
leaves it free; every import, lazy ones and ``if TYPE_CHECKING:`` ones included, and every deferred import by
name (``register_lazy("postproc.rs274...")``), goes down it (``tests/support/import_graph.py``).

A new arrow up fails here with the file and line that draws it. Mend it by moving the code to where it
belongs, or by passing the value down (a hook the higher package fills, as ``postproc.cycles.hole_ends`` does
for lowering); move a unit in ``LAYERS`` only when its place in the architecture changes, and say why.

Built-in dialects and plugins stand on top of the registry layer: they may import the core up to it
(``postproc.plugins`` included), never the speed lane, the simulator, the API or the command line.
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from tests.support.import_graph import Graph, arrows_not_down, find_circle, imports, unit_graph

pytestmark = pytest.mark.one_build(reason="a scan of the source files (ast): it runs no postproc code")

ROOT = Path(__file__).resolve().parents[1]

LAYERS: tuple[tuple[str, tuple[str, ...], str], ...] = (
    ("ground", ("records", "errors", "xmlio", "numbers", "cycle_words", "source_finder", "native", "version", "entry_points",
                "collector"),
     "records, errors and XML, number text, the hole-cycle word record, build and entry-point facts, the "
     "collector's pause: the standard library only"),
    ("model", ("ir", "setup", "geometry", "interp", "compensation", "context", "block_rules"),
     "the neutral IR, the machine set-up, and the neutral computations over them (geometry, expressions and "
     "variables, tool compensation, one run's context): the ground"),
    ("reading and writing", ("syntaxes", "output", "dialect", "reading"),
     "syntax objects, writers, the Dialect base and reading a program through its pipeline: the model"),
    ("resolution", ("lowering", "frames", "cycles", "patterns", "transforms"),
     "the steps that resolve a machine feature per target (frames, canned cycles, hole patterns, "
     "translation transforms): reading and writing"),
    ("family bases", ("rs274", "isg_family", "grbl_family"),
     "the only place a controller family's words are spelled: the resolution layer"),
    ("registry", ("hookspecs", "core_plugin", "plugin_manager", "plugins"),
     "the plugin hooks, the core's own registrations and the registry of dialects: the family bases"),
    ("fast lane", ("fast",),
     "speed-only shortcuts chosen per run, held to the general path by differential tests: the registry"),
    ("services", ("drawing", "simulate", "api"),
     "backplot drawing, the simulator and verify, the Python API: the fast lane"),
    ("front", ("commands", "testing", "__main__"),
     "the command line and the conformance-suite pytest plugin: everything"),
)
ORDER = [unit for _, units, _ in LAYERS for unit in units]
PLUGIN_CEILING = "plugins"
"""The highest unit a dialect or plugin may import (the registry layer's top)."""


@functools.cache
def core_graph() -> Graph:
    """The graph between the core's units (read once a session, when a test first asks)."""
    return unit_graph(ROOT, "postproc")


def test_the_order_places_every_unit_once() -> None:
    assert len(ORDER) == len(set(ORDER)), "a unit stands twice in LAYERS"
    units = {p.stem if p.is_file() else p.name for p in (ROOT / "postproc").iterdir()
             if (p.is_file() and p.suffix == ".py") or (p / "__init__.py").is_file()}
    assert units == set(ORDER), f"unplaced: {sorted(units - set(ORDER))}; gone: {sorted(set(ORDER) - units)}"


def test_the_core_packages_import_without_a_circle() -> None:
    circle = find_circle(core_graph())
    assert circle is None, "import circle between packages: " + " -> ".join(circle or [])


def test_every_core_import_goes_down_the_layers() -> None:
    wrong = arrows_not_down(core_graph(), ORDER)
    assert not wrong, "\n".join(wrong)


EXTENSIONS = sorted([*(ROOT / "dialects").rglob("*.py"), *(ROOT / "plugins").glob("*/postproc_*/**/*.py")])


@pytest.mark.parametrize("path", EXTENSIONS, ids=lambda p: str(p.relative_to(ROOT)))
def test_a_dialect_or_plugin_imports_the_core_only_up_to_the_registry(path: Path) -> None:
    wrong = above_the_ceiling(imports(path), ORDER, PLUGIN_CEILING)
    assert not wrong, f"{path.relative_to(ROOT)}: " + "; ".join(wrong)


def above_the_ceiling(found: list[tuple[str, list[str], int]], order: list[str], ceiling: str) -> list[str]:
    """The imports of ``postproc`` units placed above ``ceiling`` in ``order`` (``imports``' triples)."""
    top = order.index(ceiling)
    wrong = []
    for module, names, line in found:
        parts = module.split(".")
        if parts[0] != "postproc":
            continue
        units = parts[1:2] or names  # ``from postproc import simulate`` names its unit
        above = [u for u in units if u in order and order.index(u) > top]
        if above:
            wrong.append(f"line {line} imports {module} {names}: above {ceiling}")
    return wrong


# -- the checker itself, on graphs small enough to see by eye ------------------------------------------------

def test_the_checker_finds_a_planted_arrow_up() -> None:
    graph = {"low": {}, "mid": {"low": ["mid.py:1"]}, "top": {"mid": ["top.py:2"]}}
    order = ["low", "mid", "top"]
    assert arrows_not_down(graph, order) == []
    graph["low"]["top"] = ["low.py:7"]
    assert arrows_not_down(graph, order) == ["low -> top runs up the declared order (low.py:7)"]
    assert find_circle(graph) == ["low", "top", "mid", "low"]


def test_the_checker_refuses_a_sideways_arrow_against_the_row_order_and_an_unplaced_unit() -> None:
    graph = {"a": {"b": ["a.py:3"]}, "b": {}, "new": {"a": ["new.py:1"]}}
    assert arrows_not_down(graph, ["a", "b"]) == ["new has no place in the declared order",
                                                  "a -> b runs up the declared order (a.py:3)"]
    assert arrows_not_down({"a": {"x": ["a.py:9"]}}, ["a"]) == [
        "a -> x: x has no place in the declared order (a.py:9)"]
    assert arrows_not_down({"a": {"a": ["a.py:1"]}}, ["a"]) == ["a -> a runs up the declared order (a.py:1)"]


def test_the_reader_counts_lazy_type_checking_relative_and_by_name_imports(tmp_path: Path) -> None:
    pkg = tmp_path / "pkg"
    for folder in (pkg, pkg / "low", pkg / "high", pkg / "high" / "inner"):
        folder.mkdir()
        (folder / "__init__.py").write_text("")
    (pkg / "top.py").write_text("from . import high\n")
    (pkg / "low" / "typed.py").write_text(
        "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from ..high import thing\n")
    (pkg / "low" / "lazy.py").write_text("def f() -> None:\n    from pkg.top import x\n")
    (pkg / "low" / "named.py").write_text('LATER = "pkg.high.inner.deep:Name"\nNOT = "pkg.nowhere:Name"\n')
    (pkg / "high" / "inner" / "deep.py").write_text("from ...low import typed\nfrom .. import inner\n")
    graph = unit_graph(tmp_path, "pkg")
    assert graph == {
        "top": {"high": ["pkg/top.py:1"]},
        "low": {"high": ["pkg/low/named.py:1", "pkg/low/typed.py:3"], "top": ["pkg/low/lazy.py:2"]},
        "high": {"low": ["pkg/high/inner/deep.py:1"]},
    }
    assert find_circle(graph) == ["high", "low", "high"]


def test_the_ceiling_refuses_a_planted_import_above_it() -> None:
    order = ["ir", "plugins", "fast", "api"]
    found = [("postproc.ir.block", ["Block"], 1), ("postproc.plugins", ["default_registry"], 2), ("re", [], 3)]
    assert above_the_ceiling(found, order, "plugins") == []
    found += [("postproc.fast.lane", ["lane"], 4), ("postproc", ["api", "ir"], 5)]
    assert above_the_ceiling(found, order, "plugins") == [
        "line 4 imports postproc.fast.lane ['lane']: above plugins", "line 5 imports postproc ['api', 'ir']: above plugins"]
