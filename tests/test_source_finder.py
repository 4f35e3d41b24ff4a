"""``postproc.source_finder``: the finder of postproc's pure modules answers as Python's path finder does, for
every module of the installation, and leaves to it what it cannot tell for certain."""

from __future__ import annotations

import importlib
import importlib.machinery
import os
import sys
import time
from pathlib import Path

import pytest

from postproc import native
from postproc.source_finder import SourceFinder

ROOT = Path(__file__).resolve().parents[1]
SUFFIX = importlib.machinery.EXTENSION_SUFFIXES[0]


def _modules(package: str) -> list[str]:
    """Every module and package below ``package`` in the checkout, by its dotted name."""
    base = ROOT / package
    names = []
    for path in sorted(base.rglob("*.py")):
        if "_compiled" in path.parts or "__pycache__" in path.parts:
            continue
        parts = path.relative_to(ROOT).with_suffix("").parts
        names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return [name for name in names if "." in name]


def _spec_facts(spec: importlib.machinery.ModuleSpec | None) -> tuple[object, ...] | None:
    if spec is None:
        return None
    return (spec.name, spec.origin, spec.cached, spec.has_location, type(spec.loader),
            None if spec.submodule_search_locations is None else list(spec.submodule_search_locations))


@pytest.mark.parametrize("package", ["postproc", "dialects"])
def test_every_module_is_found_where_python_finds_it(package: str) -> None:
    finder = SourceFinder(str(ROOT))
    names = _modules(package)
    assert len(names) > 20  # the walk saw the tree
    for name in names:
        parent = importlib.import_module(name.rpartition(".")[0])
        path = list(parent.__path__)
        assert _spec_facts(finder.find_spec(name, path)) == _spec_facts(
            importlib.machinery.PathFinder.find_spec(name, path)), name


def test_a_start_finds_the_pure_modules_with_it() -> None:
    """The entry points install it after the compiled build's finder (which must answer first: a compiled module
    has its source beside the others)."""
    native.install()
    finders = [type(f).__name__ for f in sys.meta_path]
    assert "SourceFinder" in finders
    if native.compiled_modules():
        assert finders.index("CompiledFinder") < finders.index("SourceFinder")


def _tree(tmp_path: Path) -> Path:
    pkg = tmp_path / "postproc"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "plain.py").write_text("X = 1\n")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "built.py").write_text("X = 1\n")
    (pkg / ("built" + SUFFIX)).write_bytes(b"")  # an extension module beside its source
    (pkg / "portion").mkdir()  # no __init__.py: a namespace portion
    (pkg / "legacy.pyc").write_bytes(b"")  # byte code only
    return tmp_path


def test_what_it_cannot_tell_for_certain_is_left_to_python(tmp_path: Path) -> None:
    root = _tree(tmp_path)
    finder = SourceFinder(str(root))
    path = [str(root / "postproc")]
    plain = finder.find_spec("postproc.plain", path)
    assert plain is not None and plain.origin == str(root / "postproc" / "plain.py")
    sub = finder.find_spec("postproc.sub", path)
    assert sub is not None and sub.submodule_search_locations == [str(root / "postproc" / "sub")]
    for name in ("postproc.built", "postproc.portion", "postproc.legacy", "postproc.missing"):
        assert finder.find_spec(name, path) is None, name
    assert finder.find_spec("postproc", None) is None  # a top-level module
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (elsewhere / "plain.py").write_text("")
    assert finder.find_spec("postproc.plain", [str(elsewhere)]) is None  # not the installation's folder
    # a namespace package: the first folder that has it, and nothing past a path entry it does not serve
    assert finder.find_spec("postproc.plain", [str(root / "postproc" / "sub"), str(root / "postproc")]) is not None
    assert finder.find_spec("postproc.plain", [str(root / "postproc" / "sub"), "hook", str(root / "postproc")]) is None


def test_a_module_made_later_is_found(tmp_path: Path) -> None:
    """The folder is listed again when its modification time changes, and after ``importlib.invalidate_caches``."""
    root = _tree(tmp_path)
    finder = SourceFinder(str(root))
    path = [str(root / "postproc")]
    assert finder.find_spec("postproc.later", path) is None
    (root / "postproc" / "later.py").write_text("")
    stamp = time.time_ns() + 5_000_000_000
    os.utime(root / "postproc", ns=(stamp, stamp))
    assert finder.find_spec("postproc.later", path) is not None
    (root / "postproc" / "again.py").write_text("")
    os.utime(root / "postproc", ns=(stamp, stamp))  # the same time: only invalidating the caches shows it
    assert finder.find_spec("postproc.again", path) is None
    finder.invalidate_caches()
    assert finder.find_spec("postproc.again", path) is not None
