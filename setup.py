"""Build hook: compile the hot modules with mypyc when it can, and install pure Python when it cannot.

The modules are listed in ``pyproject.toml`` (``[tool.postproc] compiled``). Their extensions go into
``postproc/_compiled/`` (named as the modules they replace), never next to the ``.py`` files, so one
installation holds both and ``postproc.native`` chooses at start-up (``POSTPROC_PURE=1`` forces pure
Python). ``manifest.txt`` there records what was compiled from which source (by SHA-256, size and time,
taken before mypyc reads the sources: an edit made while the build runs then reads as a changed source,
never as the one compiled); it is written only when every extension was built, so a failed compile (no C
compiler) leaves pure Python.
Nothing is compiled when ``POSTPROC_PURE=1`` at install time or when mypyc cannot type-check.

mypyc writes one C file a module (``multi_file``), and the build compiles them on every core
(``POSTPROC_BUILD_JOBS``, default the CPU count): one C file for the whole group was one compiler process of
minutes on one core, the longest step of a fresh ``make run``.

``make compile`` builds it guided by a profile (gcc's ``-fprofile-generate``/``-fprofile-use``,
``POSTPROC_PGO``): built once instrumented, trained on the bench's workloads, built again. Measured, it takes
~8% of the CPU time off every bench row (docs/compiled.md): our code retires fewer instructions a cycle than
its peers, and the profile lays each compiled function's hot path out straight with its cold code apart.
"""

from __future__ import annotations

import hashlib
import importlib.machinery
import os
import shutil
import subprocess
import sys
import time
import tomllib
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

from setuptools import setup
from setuptools.command.build_ext import build_ext

HERE = Path(__file__).resolve().parent
PREFIX = "postproc._compiled."
"""Extension names: the compiled tree inside the package, mirroring the modules' dotted names."""

PGO_PHASES: dict[str, list[str]] = {
    "generate": ["-fprofile-generate", "-fprofile-update=single"],
    "use": ["-fprofile-use", "-fprofile-partial-training", "-Wno-missing-profile"],
}
"""``POSTPROC_PGO`` -> gcc's flags: ``generate`` builds the hot path instrumented (each run of it adds its
counts to the ``.gcda`` files beside the objects); ``use`` builds it optimised by those counts, a function no
training run reached optimised as without them (``-fprofile-partial-training``). Unset: a plain build."""

OBJECTS = HERE / "build" / "objects"
"""The C objects (and the profile's counts beside them): one place for both builds of a profile-guided
compile, where pip's editable build would use a new temporary folder each time."""

GROUP = "postproc_hot"
"""The mypyc group: its shared library is ``postproc_hot__mypyc``, imported by every module's shim."""


def hot_sources() -> list[str]:
    with open(HERE / "pyproject.toml", "rb") as f:
        return list(tomllib.load(f)["tool"]["postproc"]["compiled"])


SourceRecord = tuple[str, int, int]
"""A source's SHA-256, size in bytes and modification time in ns, as the manifest records them."""

SOURCES_AT_START: dict[str, SourceRecord] = {}
"""Each hot source as it was before mypyc read it (``record_sources``): what the manifest says was compiled.
Hashed when the build ended instead, a source edited during the minutes of a build was recorded as
compiled while its extension held the text before the edit (a stale compiled module)."""


def record_source(path: Path) -> SourceRecord:
    """``path``'s record: its size and time before its text, so a size and time a start trusts without
    hashing (``postproc.native``) were the file's before mypyc read it."""
    st = path.stat()
    return hashlib.sha256(path.read_bytes()).hexdigest(), st.st_size, st.st_mtime_ns


def record_sources(sources: list[str]) -> None:
    """Records every hot source, before the build reads any."""
    SOURCES_AT_START.clear()
    SOURCES_AT_START.update((source, record_source(HERE / source)) for source in sources)


def _note(message: str) -> None:
    print(f"postproc build: {message}", file=sys.stderr)


METADATA_COMMANDS = frozenset({"egg_info", "dist_info"})
"""setuptools' commands that only describe the distribution (name, version, entry points)."""
BUILD_COMMANDS = frozenset({"build", "build_ext", "build_py", "bdist_wheel", "bdist_egg", "editable_wheel",
                            "develop", "install"})


def metadata_only(argv: list[str]) -> bool:
    """This run of setup.py only writes the metadata: pip asks for it first, in a process of its own
    (setuptools' ``dist_info``; ``egg_info`` for the build requirements), and then builds in another. The
    metadata does not depend on the extensions, and mypyc run for it type-checked and translated every hot
    module once more for nothing (measured in docs/compiled.md)."""
    words = [a for a in argv if not a.startswith("-")]
    return bool(words) and words[0] in METADATA_COMMANDS and not BUILD_COMMANDS.intersection(words)


def compiled_extensions() -> list[Any]:
    """mypyc's extensions for the hot modules, renamed into the compiled tree; [] for pure Python (or for a
    run that only writes the metadata)."""
    if os.environ.get("POSTPROC_PURE", "") not in ("", "0"):
        _note("POSTPROC_PURE is set: installing pure Python")
        return []
    if metadata_only(sys.argv[1:]):
        return []
    try:
        from mypyc.build import mypycify
    except ImportError:
        _note("mypyc is not available: installing pure Python")
        return []
    sources = hot_sources()
    options = ["--config-file", str(HERE / "pyproject.toml"), "--explicit-package-bases"]
    try:
        record_sources(sources)
        _note(f"type-checking and translating {len(sources)} hot modules to C with mypyc (about a minute)")
        started = time.monotonic()
        extensions = mypycify(options + sources, opt_level="3", group_name=GROUP, multi_file=True,
                              target_dir=str(HERE / "build" / "mypyc"))
        _note(f"mypyc done in {time.monotonic() - started:.0f} s")
    except SystemExit:  # mypy reported type errors (printed above)
        _note("mypyc could not compile the hot modules: installing pure Python")
        return []
    for ext in extensions:
        ext.name = PREFIX + ext.name
        ext.optional = True  # a compile failure (no C compiler) leaves pure Python, not a failed install
    return extensions


def pgo_phase() -> str:
    """``POSTPROC_PGO``'s phase (``generate``, ``use``) or "" for a plain build; an unknown value is an error."""
    phase = os.environ.get("POSTPROC_PGO", "")
    if phase and phase not in PGO_PHASES:
        raise SystemExit(f"POSTPROC_PGO={phase!r}: expected one of {', '.join(PGO_PHASES)} or nothing")
    return phase


def is_gcc(command: list[str]) -> bool:
    """Whether the C compiler is gcc (whose profile flags and ``.gcda`` files the phases use; clang's differ)."""
    try:
        out = subprocess.run([command[0], "--version"], capture_output=True, text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError):
        return False
    return "Free Software Foundation" in out and "clang" not in out


def build_jobs() -> int:
    """How many C files compile at once: ``POSTPROC_BUILD_JOBS``, else one per CPU."""
    try:
        return max(1, int(os.environ.get("POSTPROC_BUILD_JOBS", "") or os.cpu_count() or 1))
    except ValueError:
        return os.cpu_count() or 1


def compile_in_parallel(compiler: Any, jobs: int) -> None:
    """Make ``compiler.compile`` (distutils' ``CCompiler``) compile an extension's sources ``jobs`` at a
    time: setuptools compiles one extension's sources one after another, and mypyc's group is one
    extension of many C files. The steps are ``CCompiler.compile``'s own (set-up, then ``_compile`` per
    object); each C file is still compiled by one compiler process, as before."""
    def compile(sources: list[str], output_dir: str | None = None, macros: Any = None,
                include_dirs: Any = None, debug: bool = False, extra_preargs: Any = None,
                extra_postargs: Any = None, depends: Any = None) -> list[str]:
        macros, objects, extra_postargs, pp_opts, build = compiler._setup_compile(
            output_dir, macros, include_dirs, sources, depends, extra_postargs)
        cc_args = compiler._get_cc_args(pp_opts, debug, extra_preargs)

        def one(obj: str) -> None:
            src, ext = build[obj]
            compiler._compile(obj, src, ext, cc_args, extra_postargs, pp_opts)

        if len(objects) > 1:
            _note(f"compiling {len(objects)} C files, {jobs} at a time")
        started = time.monotonic()
        with ThreadPoolExecutor(jobs) as pool:
            list(pool.map(one, objects))  # list: a failed compile raises here
        if len(objects) > 1:
            _note(f"compiled them in {time.monotonic() - started:.0f} s")
        return list(objects)

    compiler.compile = compile


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

    def finalize_options(self) -> None:
        super().finalize_options()
        if not self.parallel:
            self.parallel = build_jobs()  # the small per-module extensions too, several at a time

    def build_extensions(self) -> None:
        if self.compiler is not None:
            compile_in_parallel(self.compiler, build_jobs())
        self.build_temp = str(OBJECTS)
        phase = pgo_phase()
        if phase and self.compiler is not None and not is_gcc(self.compiler.compiler_so):
            _note(f"POSTPROC_PGO={phase}: the C compiler is not gcc, building without a profile")
            phase = ""
        if phase == "generate":  # counts from an earlier training (or an older source) must not mix in
            for counts in OBJECTS.rglob("*.gcda"):
                counts.unlink()
        if phase:
            _note(f"POSTPROC_PGO={phase}: {' '.join(PGO_PHASES[phase])}")
            for ext in self.extensions:
                ext.extra_compile_args = [*ext.extra_compile_args, *PGO_PHASES[phase]]
                ext.extra_link_args = [*ext.extra_link_args, *PGO_PHASES[phase]]
        super().build_extensions()

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
                sha256, size, mtime_ns = SOURCES_AT_START[source]  # a start compares size and time first
                fields += [source, sha256, str(size), str(mtime_ns)]
            lines.append("\t".join(fields))
        (tree / "manifest.txt").write_text("\n".join(lines) + "\n", encoding="utf-8")
        _note(f"compiled {len(by_module)} hot modules into {tree}")


setup(ext_modules=compiled_extensions(), cmdclass={"build_ext": BuildCompiled})
