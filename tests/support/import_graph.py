"""The import graph of a source tree, read with ``ast`` (nothing is imported), and the two checks the layout
tests make of it: a circle, and an arrow that does not go down a declared order.

Every import counts wherever it stands: at the top, inside a function (a lazy import is still a dependency,
only a later one) and under ``if TYPE_CHECKING:`` (the type checker and mypyc follow it: a circle there is
a circle in the compiled build's module graph). A string that is a whole dotted module path of the tree
(``"postproc.rs274.lathe_cycles:LatheCycleSyntax"``, what ``register_lazy``, ``Lazy`` and ``LazyStep``
import later by name) counts as an import of that module too: a deferred import is an import.
"""

from __future__ import annotations

import ast
import functools
import re
from pathlib import Path

# A string naming a module to import later: ``pkg.module`` or ``pkg.module:name``.
_MODULE_TEXT = re.compile(r"[A-Za-z_]\w*(?:\.[A-Za-z_]\w*)+(?::[A-Za-z_]\w*)?")


def root_of(path: Path) -> Path:
    """The folder a module's dotted name is relative to (the first parent without ``__init__.py``)."""
    for parent in path.parents:
        if not (parent / "__init__.py").exists():
            return parent
    raise AssertionError(path)


def module_name(path: Path, root: Path) -> str:
    """``postproc/ir/block.py`` -> ``postproc.ir.block``; a package's ``__init__.py`` -> the package."""
    return ".".join(path.relative_to(root).with_suffix("").parts).removesuffix(".__init__")


@functools.lru_cache(maxsize=None)
def _read(path: Path) -> tuple[tuple[tuple[str, tuple[str, ...], int, int], ...], tuple[tuple[str, int], ...]]:
    """One walk of the file's tree: its import statements as (module as written, names, line, level) and its
    strings that name a module (``named_modules``). Kept per file: several tests read the same tree, and a
    parse of the whole core takes seconds on a loaded machine."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    found: list[tuple[str, tuple[str, ...], int, int]] = []
    named: list[tuple[str, int]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found.extend((a.name, (), node.lineno, 0) for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            found.append((node.module or "", tuple(a.name for a in node.names), node.lineno, node.level))
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and _MODULE_TEXT.fullmatch(node.value):
            named.append((node.value.partition(":")[0], node.lineno))
    return tuple(found), tuple(named)


def imports(path: Path, root: Path | None = None) -> list[tuple[str, list[str], int]]:
    """(absolute module, imported names, line) of every import statement in the file, functions and
    ``if TYPE_CHECKING:`` included. ``root``: what dotted names are relative to (default ``root_of``)."""
    root = root_of(path) if root is None else root
    package = module_name(path, root)
    if path.name != "__init__.py":
        package = package.rpartition(".")[0]
    out: list[tuple[str, list[str], int]] = []
    for module, names, line, level in _read(path)[0]:
        if level:
            base = package.split(".")
            base = base[:len(base) - level + 1]
            module = ".".join(base + ([module] if module else []))
        out.append((module, list(names), line))
    return out


def named_modules(path: Path) -> list[tuple[str, int]]:
    """(module, line) of every string constant in the file that is a whole dotted module path, with an
    optional ``:name`` (a deferred import by name); whether the module exists is the caller's to check."""
    return list(_read(path)[1])


Graph = dict[str, dict[str, list[str]]]
"""unit -> unit it imports -> the places (``path:line``) that import it."""


def unit_graph(root: Path, package: str) -> Graph:
    """The graph between the units of ``root/package``: a unit is a direct subpackage (``postproc.ir``,
    its subpackages included) or a module directly in the package (``postproc.api``), named without the
    package (``ir``, ``api``). An import of the package itself by a name (``from postproc import api``)
    is an import of that name's unit. Imports within one unit are not arrows."""
    top = root / package
    modules = {module_name(p, root): p for p in sorted(top.rglob("*.py"))}
    graph: Graph = {}

    def unit(module: str) -> str | None:
        parts = module.split(".")
        if parts[0] != package or len(parts) < 2:
            return None
        return parts[1]

    for name, path in modules.items():
        here = unit(name)
        if here is None:
            continue
        graph.setdefault(here, {})
        where = str(path.relative_to(root))
        found = [(m, line) for m, line in named_modules(path) if m in modules]
        for module, names, line in imports(path, root):
            found += [(f"{package}.{n}", line) for n in names] if module == package else [(module, line)]
        for module, line in found:
            there = unit(module)
            if there is not None and there != here:
                graph[here].setdefault(there, []).append(f"{where}:{line}")
    return graph


def find_circle(graph: dict[str, set[str]] | Graph) -> list[str] | None:
    """One circle of the graph (``[a, b, a]``), or None; only nodes with an entry of their own are followed."""
    state: dict[str, int] = {}  # 1: on the trail, 2: done

    def visit(node: str, trail: list[str]) -> list[str] | None:
        if state.get(node) == 2:
            return None
        if state.get(node) == 1:
            return trail[trail.index(node):] + [node]
        state[node] = 1
        for dep in sorted(graph.get(node, ())):
            if dep in graph:
                found = visit(dep, trail + [node])
                if found:
                    return found
        state[node] = 2
        return None

    for node in sorted(graph):
        found = visit(node, [])
        if found:
            return found
    return None


def arrows_not_down(graph: Graph, order: list[str]) -> list[str]:
    """Every arrow of ``graph`` that does not point to a unit earlier in ``order`` (bottom first), and
    every unit of the graph ``order`` does not place, each as a sentence with the places that import."""
    rank = {unit: i for i, unit in enumerate(order)}
    wrong = [f"{unit} has no place in the declared order" for unit in sorted(graph) if unit not in rank]
    for unit, deps in sorted(graph.items()):
        for dep, places in sorted(deps.items()):
            if unit in rank and dep not in rank:
                wrong.append(f"{unit} -> {dep}: {dep} has no place in the declared order ({', '.join(places)})")
            elif unit in rank and rank[dep] >= rank[unit]:
                wrong.append(f"{unit} -> {dep} runs up the declared order ({', '.join(places)})")
    return wrong
