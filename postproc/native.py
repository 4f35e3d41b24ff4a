"""The compiled hot path (mypyc), used only when it was built from exactly the sources on disk.

``setup.py`` compiles the hot modules (``[tool.postproc] compiled`` in ``pyproject.toml``) into
``postproc/_compiled/``, a tree that mirrors their dotted names, and writes ``manifest.txt`` there with
the SHA-256 of every source it compiled (``MANIFEST``). The ``.py`` files stay where they are, so one installation
holds both: a meta-path finder placed before Python's own serves the compiled modules, unless
``POSTPROC_PURE=1``, the tree is missing (no C compiler at install time) or incomplete, or a source
differs from the one compiled (an edited checkout runs pure Python until ``make install`` rebuilds it).

The compiled modules are one group that calls itself natively, so it is used whole or not at all: a
pure module in their midst would not be the class they check against.

A start compares each source's size and modification time with those the manifest recorded, and hashes
only a source whose differ (a copied installation, a touched file): hashing every hot source (and
importing ``hashlib``, which loads OpenSSL) cost a one-line translation ~5 ms of its start-up. The check
works on path strings (``os.path``, one ``os.stat`` a file): with ``pathlib`` objects (two made and parsed a
module, ``is_file``) it cost every start ~8M instructions of its ~11M (callgrind, compiled build).
"""

from __future__ import annotations

import importlib.machinery
import os
import stat
import sys
from importlib.machinery import ModuleSpec
from types import ModuleType
from typing import TYPE_CHECKING, Mapping, Sequence

from .source_finder import SourceFinder

if TYPE_CHECKING:
    from pathlib import Path  # (made where asked for: a start makes no path object, and pathlib imports urllib.parse)

_ROOT = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
"""The folder that holds ``postproc/`` and ``dialects/`` (site-packages, or the checkout when editable); as a
``pathlib.Path``, ``ROOT``."""

PURE_VARIABLE = "POSTPROC_PURE"

MANIFEST = "manifest.txt"
"""The compiled tree's manifest, as ``setup.py`` writes it: UTF-8 text, fields separated by tabs. Its
first line is ``MANIFEST_HEADER``, its second ``suffix`` and the extension suffix it was built for; then
one line per compiled module: its dotted name and its file (relative to the tree), and for a module
compiled from a source (every one but the group's shared library) that source (relative to the root),
its SHA-256, size in bytes and modification time in ns. Plain lines, not JSON: importing ``json`` cost
every start ~1 ms."""
MANIFEST_HEADER = "postproc compiled manifest 1"


class Compiled:
    """One line of the manifest: a compiled module's file, and the source it was compiled from. (A plain class:
    as a ``typing.NamedTuple`` its creation compiled each field's annotation and generated the tuple's code, ~1.5M
    instructions of every start.)"""

    __slots__ = ("file", "source", "sha256", "size", "mtime_ns")

    def __init__(self, file: str, source: str | None = None, sha256: str = "", size: int = -1,
                 mtime_ns: int = -1) -> None:
        self.file = file
        """Relative to the compiled tree."""
        self.source = source
        """Relative to the root; None for the group's shared library."""
        self.sha256 = sha256
        self.size = size
        self.mtime_ns = mtime_ns

    def _key(self) -> tuple[str, str | None, str, int, int]:
        return self.file, self.source, self.sha256, self.size, self.mtime_ns

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Compiled) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __repr__(self) -> str:
        return f"Compiled{self._key()!r}"


class CompiledFinder:
    """Finds the compiled modules (and their shared library) in ``postproc/_compiled/``."""

    def __init__(self, files: Mapping[str, str | Path]) -> None:
        self.files = files

    def find_spec(self, fullname: str, path: Sequence[str] | None,
                  target: ModuleType | None = None) -> ModuleSpec | None:
        file = self.files.get(fullname)
        if file is None:
            return None
        loader = importlib.machinery.ExtensionFileLoader(fullname, str(file))
        return importlib.machinery.ModuleSpec(fullname, loader, origin=str(file))


def _digest(path: str) -> str:
    import hashlib
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def _fresh(path: str, entry: Compiled) -> bool:
    """Whether the source at ``path`` is the one the manifest ``entry`` was compiled from."""
    try:
        st = os.stat(path)
        if st.st_size == entry.size and st.st_mtime_ns == entry.mtime_ns:
            return True
        return _digest(path) == entry.sha256
    except OSError:
        return False


def plan(root: Path, environ: Mapping[str, str]) -> tuple[str, dict[str, Path]]:
    """Why pure Python runs (or ``""``), and the compiled files by module name, for the installation
    in ``root`` (the folder holding ``postproc/``)."""
    from pathlib import Path
    reason, files = _plan(str(root), environ)
    return reason, {name: Path(file) for name, file in files.items()}


def _plan(root: str, environ: Mapping[str, str]) -> tuple[str, dict[str, str]]:
    """``plan`` on path strings (what a start runs)."""
    if environ.get(PURE_VARIABLE, "") not in ("", "0"):
        return f"{PURE_VARIABLE}={environ[PURE_VARIABLE]}", {}
    compiled = os.path.join(root, "postproc", "_compiled")
    try:
        with open(os.path.join(compiled, MANIFEST), encoding="utf-8") as f:
            built_for, modules = read_manifest(f.read())
    except (OSError, ValueError):
        return "not compiled at install time", {}
    suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
    if built_for != suffix:
        return f"compiled for {built_for}, not {suffix}", {}
    files: dict[str, str] = {}
    tree, top = compiled + os.sep, root + os.sep  # (paths by concatenation: os.path.join is Python code)
    for name, entry in modules.items():
        file = tree + entry.file
        try:
            is_file = stat.S_ISREG(os.stat(file).st_mode)
        except (OSError, ValueError):
            is_file = False
        if not is_file:
            return f"the compiled build is incomplete ({entry.file} is missing)", {}
        source = entry.source
        if source is not None:
            if not _fresh(top + source, entry):
                return f"{source} changed since it was compiled (run make install)", {}
        files[name] = file
    return "", files


def read_manifest(text: str) -> tuple[str, dict[str, Compiled]]:
    """The extension suffix and the compiled modules by name of a manifest's text (``MANIFEST``);
    ValueError if it is not one."""
    lines = text.splitlines()
    if len(lines) < 2 or lines[0] != MANIFEST_HEADER or not lines[1].startswith("suffix\t"):
        raise ValueError("not a postproc manifest")
    modules: dict[str, Compiled] = {}
    for line in lines[2:]:
        fields = line.split("\t")
        if len(fields) == 2:
            modules[fields[0]] = Compiled(fields[1])
        elif len(fields) == 6:
            name, file, source, sha256, size, mtime_ns = fields
            modules[name] = Compiled(file, source, sha256, int(size), int(mtime_ns))
        else:
            raise ValueError(f"a manifest line with {len(fields)} fields")
    return lines[1].partition("\t")[2], modules


_REASON, _FILES = _plan(_ROOT, os.environ)


def install() -> None:
    """Put the compiled modules first on the import path, and the finder of the pure modules
    (``postproc.source_finder``) right after them. Called by postproc's entry points (``api``, ``cli``,
    ``plugins``, ``batch``, ``testing``) before they import anything else; a process that imported a hot
    module by itself first keeps pure Python (the group is used whole or not at all)."""
    global _REASON, _FILES
    if any(isinstance(f, SourceFinder) for f in sys.meta_path):
        return
    early = sorted(name for name in _FILES if name in sys.modules)
    if early:
        _REASON, _FILES = f"{early[0]} was imported before postproc's entry points", {}
    sys.meta_path.insert(0, SourceFinder(_ROOT))
    if _FILES:
        sys.meta_path.insert(0, CompiledFinder(_FILES))


def compiled_modules() -> list[str]:
    """The hot modules this process runs compiled (sources listed in the manifest)."""
    return sorted(name for name in _FILES if not name.endswith("__mypyc"))


def describe() -> str:
    """One line for ``postproc --version``: which build of the hot path runs, and why."""
    if _FILES:
        return f"compiled (mypyc): {len(compiled_modules())} hot modules"
    return f"pure Python ({_REASON})"


def __getattr__(name: str) -> Path:
    """``ROOT``: the folder that holds ``postproc/`` and ``dialects/``, a ``pathlib.Path`` made when first read."""
    if name == "ROOT":
        from pathlib import Path
        return Path(_ROOT)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
