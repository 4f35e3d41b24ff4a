"""Build hook: compile the hot modules with mypyc when it can, and install pure Python when it cannot.

The modules are listed in ``pyproject.toml`` (``[tool.postproc] compiled``). Their extensions go into
``postproc/_compiled/`` (named as the modules they replace), never next to the ``.py`` files, so one
installation holds both and ``postproc.native`` chooses at start-up (``POSTPROC_PURE=1`` forces pure
Python). ``manifest.txt`` there records what was compiled from which source (by SHA-256); it is
written only when every extension was built, so a failed compile (no C compiler) leaves pure Python.
Nothing is compiled when ``POSTPROC_PURE=1`` at install time or when mypyc cannot type-check.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import os
import shutil
import sys
import tomllib
from pathlib import Path
from typing import Any

from setuptools import setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
PREFIX = "postproc._compiled."
"""Extension names: the compiled tree inside the package, mirroring the modules' dotted names."""

GROUP = "postproc_hot"
"""The mypyc group: its shared library is ``postproc_hot__mypyc``, imported by every module's shim."""


def hot_sources() -> list[str]:
    with open(HERE / "pyproject.toml", "rb") as f:
        return list(tomllib.load(f)["tool"]["postproc"]["compiled"])


def _note(message: str) -> None:
    print(f"postproc build: {message}", file=sys.stderr)


def compiled_extensions() -> list[Any]:
    """mypyc's extensions for the hot modules, renamed into the compiled tree; [] for pure Python."""
    if os.environ.get("POSTPROC_PURE", "") not in ("", "0"):
        _note("POSTPROC_PURE is set: installing pure Python")
        return []
    try:
        from mypyc.build import mypycify
    except ImportError:
        _note("mypyc is not available: installing pure Python")
        return []
    sources = hot_sources()
    options = ["--config-file", str(HERE / "pyproject.toml"), "--explicit-package-bases"]
    try:
        extensions = mypycify(options + sources, opt_level="3", group_name=GROUP,
                              target_dir=str(HERE / "build" / "mypyc"))
    except SystemExit:  # mypy reported type errors (printed above)
        _note("mypyc could not compile the hot modules: installing pure Python")
        return []
    for ext in extensions:
        ext.name = PREFIX + ext.name
        ext.optional = True  # a compile failure (no C compiler) leaves pure Python, not a failed install
    return extensions


class BuildCompiled(build_ext):
    """Builds the compiled tree, then writes its manifest only if every extension is there."""

    def run(self) -> None:
        roots = self._roots()
        for root in roots:
            shutil.rmtree(root / "postproc" / "_compiled", ignore_errors=True)
        super().run()
        if self.extensions:
            for root in roots:
                self._write_manifest(root)

    def _roots(self) -> list[Path]:
        """Where the compiled tree goes: the build folder, and the checkout too when built in place."""
        roots = [Path(self.build_lib)]
        if self.inplace or getattr(self, "editable_mode", False):
            roots.append(HERE)
        return roots

    def copy_extensions_to_source(self) -> None:
        for ext in self.extensions:  # the compiled tree's folders do not exist in a fresh checkout
            fullname = self.get_ext_fullname(ext.name)
            Path(HERE, *fullname.split(".")[:-1]).mkdir(parents=True, exist_ok=True)
        super().copy_extensions_to_source()

    def _write_manifest(self, root: Path) -> None:
        tree = root / "postproc" / "_compiled"
        suffix = importlib.machinery.EXTENSION_SUFFIXES[0]
        by_module = {Path(s).with_suffix("").as_posix().replace("/", "."): s for s in hot_sources()}
        # postproc.native.MANIFEST describes these lines (tab-separated text: reading JSON costs a start ~1 ms)
        lines = ["postproc compiled manifest 1", f"suffix\t{suffix}"]
        for ext in self.extensions:
            name = ext.name.removeprefix(PREFIX)
            file = Path(*name.split(".")).as_posix() + suffix
            if not (tree / file).is_file():
                _note(f"{name} was not compiled: installing pure Python")
                return
            fields = [name, file]
            if name in by_module:
                source = by_module[name]
                st = (HERE / source).stat()  # a start compares these first (postproc.native)
                fields += [source, hashlib.sha256((HERE / source).read_bytes()).hexdigest(), str(st.st_size),
                           str(st.st_mtime_ns)]
            lines.append("\t".join(fields))
        (tree / "manifest.txt").write_text("\n".join(lines) + "\n", encoding="utf-8")
        _note(f"compiled {len(by_module)} hot modules into {tree}")


setup(ext_modules=compiled_extensions(), cmdclass={"build_ext": BuildCompiled})
