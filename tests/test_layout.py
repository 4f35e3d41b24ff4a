"""The layout holds: the neutral core spells no dialect's codes and imports no dialect, a plugin imports
only public names of ``postproc``, and the core's modules import each other without a circle."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CORE = sorted((ROOT / "postproc").rglob("*.py"))
PLUGINS = sorted(p for p in (ROOT / "plugins").glob("*/postproc_*/**/*.py"))
DIALECTS = sorted((ROOT / "dialects").rglob("*.py"))
CODE = re.compile(r"[GM]\d+(\.\d+)?")


def imports(path: Path) -> list[tuple[str, list[str], int]]:
    """(absolute module, imported names, line) of every import in the file, functions included."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = ".".join(path.relative_to(_root_of(path)).with_suffix("").parts[:-1])
    if path.name == "__init__.py":
        package = ".".join(path.relative_to(_root_of(path)).parts[:-1])
    out: list[tuple[str, list[str], int]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out.extend((a.name, [], node.lineno) for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            module = node.module or ""
            if node.level:
                base = package.split(".")
                base = base[:len(base) - node.level + 1]
                module = ".".join(base + ([module] if module else []))
            out.append((module, [a.name for a in node.names], node.lineno))
    return out


def _root_of(path: Path) -> Path:
    """The folder a module's dotted name is relative to."""
    for parent in path.parents:
        if not (parent / "__init__.py").exists():
            return parent
    raise AssertionError(path)


@pytest.mark.parametrize("path", PLUGINS, ids=lambda p: str(p.relative_to(ROOT)))
def test_a_plugin_imports_only_public_postproc_names_and_itself(path: Path) -> None:
    own = path.relative_to(_root_of(path)).parts[0]
    for module, names, line in imports(path):
        top = module.split(".")[0]
        if top == own or top in ("__future__", "typing", "re", "copy", "dataclasses", "unicodedata", "math"):
            continue
        assert top == "postproc", f"{path.name}:{line} imports {module}"
        private = [n for n in names if n.startswith("_")] + [p for p in module.split(".") if p.startswith("_")]
        assert not private, f"{path.name}:{line} imports the private name(s) {private} from {module}"


@pytest.mark.parametrize("path", CORE + DIALECTS, ids=lambda p: str(p.relative_to(ROOT)))
def test_the_core_and_built_in_dialects_import_no_plugin(path: Path) -> None:
    in_core = path.is_relative_to(ROOT / "postproc")
    for module, _, line in imports(path):
        top = module.split(".")[0]
        assert not top.startswith("postproc_"), f"{path.name}:{line} imports the plugin {module}"
        assert not (in_core and top == "dialects"), f"{path.name}:{line} imports the dialect {module}"


def _strings(tree: ast.AST) -> list[tuple[str, int]]:
    """String constants outside docstrings (with their lines)."""
    docstrings = set()
    for node in ast.walk(tree):
        body = getattr(node, "body", None)
        if isinstance(body, list):
            for stmt in body:
                if isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant):
                    docstrings.add(id(stmt.value))
    return [(n.value, n.lineno) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings]


@pytest.mark.parametrize("path", CORE, ids=lambda p: str(p.relative_to(ROOT)))
def test_the_core_spells_no_g_or_m_code(path: Path) -> None:
    """No code table, default spelling or message code in postproc/: spellings live in the dialects."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found = [(text, line) for text, line in _strings(tree) if CODE.search(text) and not text.startswith("(")]
    assert not found, f"{path.relative_to(ROOT)} spells codes: {found}"


def test_the_core_imports_without_a_circle() -> None:
    graph: dict[str, set[str]] = {}
    for path in CORE:
        name = ".".join(path.relative_to(ROOT).with_suffix("").parts)
        name = name.removesuffix(".__init__")
        graph[name] = {m for m, _, _ in imports(path) if m.startswith("postproc")}
    for name, deps in graph.items():
        graph[name] = {d if d in graph else d.rpartition(".")[0] for d in deps} - {name}
    state: dict[str, int] = {}

    def visit(node: str, trail: list[str]) -> None:
        if state.get(node) == 2:
            return
        assert state.get(node) != 1, "import circle: " + " -> ".join(trail[trail.index(node):] + [node])
        state[node] = 1
        for dep in sorted(graph.get(node, ())):
            if dep in graph:
                visit(dep, trail + [node])
        state[node] = 2

    for node in sorted(graph):
        visit(node, [])
