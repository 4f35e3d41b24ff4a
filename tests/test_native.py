"""The compiled hot path and its pure-Python fallback: which one runs, that a stale or partial build is
never used, and that both translate byte for byte alike (``make test`` also runs the whole suite under
each; see docs/compiled.md)."""

from __future__ import annotations

import ast
import copy
import hashlib
import importlib
import importlib.machinery
import importlib.util
import os
import pickle
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from postproc import native
from postproc.interp.control import While
from postproc.ir.expr import Num
from postproc.ir import Motion
from postproc.ir.source_map import ExecutedBlock

ROOT = Path(__file__).resolve().parents[1]
HOT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["tool"]["postproc"]["compiled"]
MANIFEST = ROOT / "postproc" / "_compiled" / native.MANIFEST
PURE = os.environ.get("POSTPROC_PURE", "") not in ("", "0")
SUFFIX = importlib.machinery.EXTENSION_SUFFIXES[0]


def _module(source: str) -> str:
    return source.removesuffix(".py").replace("/", ".")


def test_the_hot_modules_run_as_the_build_says() -> None:
    """Compiled when a fresh build is there and POSTPROC_PURE is not set, else every one pure."""
    compiled = set(native.compiled_modules())
    for source in HOT:
        module = importlib.import_module(_module(source))
        file = str(module.__file__)
        if compiled:
            assert file.endswith(SUFFIX), f"{source} runs as {file}, not compiled ({native.describe()})"
        else:
            assert file.endswith(".py"), f"{source} runs as {file}"
    if PURE:
        assert not compiled and native.describe() == "pure Python (POSTPROC_PURE=1)"


@pytest.mark.skipif(PURE or not MANIFEST.is_file(), reason="no compiled build to check")
def test_a_compiled_build_is_complete_and_fresh() -> None:
    """An edited hot module must be compiled again (``make install``) before the suite runs compiled."""
    assert sorted(native.compiled_modules()) == sorted(_module(s) for s in HOT), native.describe()


def _tree(tmp_path: Path, source_text: str, recorded: str, with_file: bool = True) -> Path:
    """A fake installation: one hot source and a manifest that records ``recorded`` as its text."""
    (tmp_path / "postproc" / "_compiled" / "postproc").mkdir(parents=True)
    (tmp_path / "postproc" / "hot.py").write_text(source_text, encoding="utf-8")
    file = "postproc/hot" + SUFFIX
    if with_file:
        (tmp_path / "postproc" / "_compiled" / file).write_bytes(b"")
    _write_manifest(tmp_path, file, hashlib.sha256(recorded.encode()).hexdigest(), -1, -1)
    return tmp_path


def _write_manifest(root: Path, file: str, sha256: str, size: int, mtime_ns: int) -> None:
    """A manifest as ``setup.py`` writes it, of one module compiled from a source."""
    lines = [native.MANIFEST_HEADER, f"suffix\t{SUFFIX}", f"postproc.hot\t{file}\tpostproc/hot.py\t{sha256}\t{size}\t{mtime_ns}"]
    (root / "postproc" / "_compiled" / native.MANIFEST).write_text("\n".join(lines) + "\n", encoding="utf-8")


def test_the_manifest_is_read_as_setup_writes_it() -> None:
    text = (f"{native.MANIFEST_HEADER}\nsuffix\t.so\ngroup__mypyc\tgroup__mypyc.so\n"
            "pkg.hot\tpkg/hot.so\tpkg/hot.py\tabc123\t42\t1700000000123456789\n")
    assert native.read_manifest(text) == (".so", {
        "group__mypyc": native.Compiled("group__mypyc.so"),
        "pkg.hot": native.Compiled("pkg/hot.so", "pkg/hot.py", "abc123", 42, 1700000000123456789)})


@pytest.mark.parametrize("text", [
    "", "{}\n", "suffix\t.so\n", f"{native.MANIFEST_HEADER}\n", f"{native.MANIFEST_HEADER}\nsuffix\t.so\nhalf\n",
    f"{native.MANIFEST_HEADER}\nsuffix\t.so\npkg.hot\tpkg/hot.so\tpkg/hot.py\tabc\tbig\t1\n",
])
def test_a_broken_manifest_is_no_build(tmp_path: Path, text: str) -> None:
    with pytest.raises(ValueError):
        native.read_manifest(text)
    root = _tree(tmp_path, "x = 1\n", "x = 1\n")
    (root / "postproc" / "_compiled" / native.MANIFEST).write_text(text, encoding="utf-8")
    assert native.plan(root, {}) == ("not compiled at install time", {})


@pytest.mark.skipif(PURE or not MANIFEST.is_file(), reason="no compiled build to check")
def test_the_build_lists_every_hot_source_with_its_hash() -> None:
    _, modules = native.read_manifest(MANIFEST.read_text(encoding="utf-8"))
    sources = {entry.source: entry for entry in modules.values() if entry.source is not None}
    assert sorted(sources) == sorted(HOT)
    for source, entry in sources.items():
        assert entry.sha256 == hashlib.sha256((ROOT / source).read_bytes()).hexdigest(), source


def test_a_fresh_build_is_planned(tmp_path: Path) -> None:
    reason, files = native.plan(_tree(tmp_path, "x = 1\n", "x = 1\n"), {})
    assert reason == "" and list(files) == ["postproc.hot"]


def test_an_edited_source_runs_pure(tmp_path: Path) -> None:
    reason, files = native.plan(_tree(tmp_path, "x = 2\n", "x = 1\n"), {})
    assert files == {} and reason == "postproc/hot.py changed since it was compiled (run make install)"


def _record_stat(root: Path, size: int, mtime_ns: int) -> None:
    """Record a size and modification time for the fake source, as ``setup.py`` does for a real one."""
    _, modules = native.read_manifest((root / "postproc" / "_compiled" / native.MANIFEST).read_text(encoding="utf-8"))
    entry = modules["postproc.hot"]
    _write_manifest(root, entry.file, entry.sha256, size, mtime_ns)


def test_a_source_with_its_recorded_size_and_time_is_not_hashed(tmp_path: Path) -> None:
    """The manifest's hash is wrong on purpose: the size and time, which match, decide."""
    root = _tree(tmp_path, "x = 1\n", "something else\n")
    st = (root / "postproc" / "hot.py").stat()
    _record_stat(root, st.st_size, st.st_mtime_ns)
    assert native.plan(root, {}) == ("", {"postproc.hot": root / "postproc" / "_compiled" / ("postproc/hot" + SUFFIX)})


def test_a_touched_source_is_hashed(tmp_path: Path) -> None:
    """A size or time that differs from the record is no verdict: the hash is (the same text passes, an
    edit of the same size does not)."""
    root = _tree(tmp_path, "x = 1\n", "x = 1\n")
    st = (root / "postproc" / "hot.py").stat()
    _record_stat(root, st.st_size, st.st_mtime_ns - 1)
    assert native.plan(root, {})[0] == ""
    (root / "postproc" / "hot.py").write_text("x = 2\n", encoding="utf-8")
    assert native.plan(root, {})[0] == "postproc/hot.py changed since it was compiled (run make install)"


def test_a_missing_extension_runs_pure(tmp_path: Path) -> None:
    reason, files = native.plan(_tree(tmp_path, "x = 1\n", "x = 1\n", with_file=False), {})
    assert files == {} and "incomplete" in reason


def test_pure_is_forced_and_no_build_is_pure(tmp_path: Path) -> None:
    assert native.plan(_tree(tmp_path, "x = 1\n", "x = 1\n"), {"POSTPROC_PURE": "1"}) == ("POSTPROC_PURE=1", {})
    assert native.plan(tmp_path / "elsewhere", {}) == ("not compiled at install time", {})


def test_copy_and_pickle_keep_every_attribute() -> None:
    """mypyc's own pickling of a compiled class drops an interpreted subclass's slots (``While.cond``
    came back missing in a batch): ``slot_state`` keeps them, compiled or not."""
    loop = While("1", Num(3.0))
    motion = Motion("feed", {"X": 1.0})
    block = ExecutedBlock(7, "G1 X1", "\n", [("G", "1"), ("X", "1")], None)
    for obj in (loop, motion, block):
        for twin in (copy.copy(obj), copy.deepcopy(obj), pickle.loads(pickle.dumps(obj))):
            assert type(twin) is type(obj)
            for name in ("label", "cond", "mode", "axes", "line", "text", "words", "origin"):
                if hasattr(obj, name):
                    assert getattr(twin, name) == getattr(obj, name), name


@pytest.mark.skipif(PURE or not MANIFEST.is_file(), reason="no compiled build to compare with")
@pytest.mark.parametrize("args", [
    ["--from", "fanuc", "--to", "fanuc"],
    ["--from", "fanuc", "--to", "fanuc", "--normalize"],
    ["--from", "fanuc", "--to", "linuxcnc"],
    ["--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn"],
])
def test_compiled_and_pure_translate_alike(args: list[str], tmp_path: Path) -> None:
    """A differential check within one run: every bundled Fanuc example, translated by a compiled and a
    pure process, gives the same bytes, warnings and status."""
    programs = sorted((ROOT / "examples" / "fanuc").glob("*.nc"))
    assert programs
    runs = []
    for pure in ("0", "1"):
        out = tmp_path / pure
        out.mkdir()
        env = {**os.environ, "POSTPROC_PURE": pure}
        results = []
        for program in programs:
            done = subprocess.run([sys.executable, "-m", "postproc", "translate", str(program), *args,
                                   "-o", str(out / program.name)], env=env, capture_output=True)
            text = (out / program.name).read_bytes() if (out / program.name).exists() else b""
            results.append((program.name, done.returncode, done.stderr, text))
        runs.append(results)
    assert runs[0] == runs[1]


@pytest.mark.parametrize("source", HOT)
def test_a_compiled_module_follows_the_rules_mypyc_needs(source: str) -> None:
    """docs/compiled.md: every class allows interpreted subclasses (plugins subclass them; copy and
    pickle create instances without ``__init__`` only then), and no class body chains an assignment."""
    tree = ast.parse((ROOT / source).read_text(encoding="utf-8"))
    for node in ast.walk(tree):
        if not isinstance(node, ast.ClassDef):
            continue
        marks = [ast.unparse(d) for d in node.decorator_list]
        assert "mypyc_attr(allow_interpreted_subclasses=True)" in marks, f"{source}: class {node.name}"
        for stmt in node.body:
            assert not (isinstance(stmt, ast.Assign) and len(stmt.targets) > 1), \
                f"{source}:{stmt.lineno}: split the chained assignment (mypyc refuses it in a class body)"


def _setup_module(monkeypatch: pytest.MonkeyPatch, root: Path) -> object:
    """``setup.py`` as a module, its ``setup()`` call a no-op (pure, so mypyc does not run), its checkout ``root``."""
    import setuptools
    monkeypatch.setenv("POSTPROC_PURE", "1")
    monkeypatch.setattr(setuptools, "setup", lambda **kwargs: None)
    spec = importlib.util.spec_from_file_location("postproc_setup_under_test", ROOT / "setup.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    monkeypatch.setattr(module, "HERE", root)
    monkeypatch.setattr(module, "hot_sources", lambda: ["postproc/hot.py"])
    return module


def test_a_source_edited_during_the_build_runs_pure(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The manifest records each source as it was when the build started: a hot module edited while mypyc and
    the C compiler ran (minutes) is a changed source at the next start, not taken as the one compiled (the
    manifest was hashed when the build ended, so the edit read as compiled: a stale compiled module)."""
    from types import SimpleNamespace
    root = _tree(tmp_path, "x = 1\n", "x = 1\n")
    setup = _setup_module(monkeypatch, root)
    setup.record_sources(["postproc/hot.py"])  # type: ignore[attr-defined]
    (root / "postproc" / "hot.py").write_text("x = 22\n", encoding="utf-8")  # the edit, mid-build
    build = SimpleNamespace(extensions=[SimpleNamespace(name=setup.PREFIX + "postproc.hot")])  # type: ignore[attr-defined]
    setup.BuildCompiled._write_manifest(build, root)  # type: ignore[attr-defined]
    assert native.plan(root, {}) == ("postproc/hot.py changed since it was compiled (run make install)", {})
    (root / "postproc" / "hot.py").write_text("x = 1\n", encoding="utf-8")  # the text compiled: fresh again
    assert native.plan(root, {})[0] == ""


@pytest.mark.parametrize("argv,only", [
    (["dist_info", "--output-dir", "/tmp/meta", "--keep-egg-info"], True),  # pip's metadata step (setuptools)
    (["egg_info"], True),  # the build requirements
    (["editable_wheel", "--dist-dir", "/tmp/w"], False),  # pip's build step: compiles
    (["bdist_wheel"], False),
    (["build_ext", "--inplace"], False),
    (["egg_info", "build_ext"], False),  # a build named after the metadata still compiles
    ([], False),
])
def test_only_a_build_runs_mypyc(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, argv: list[str], only: bool) -> None:
    """pip asks setup.py for the metadata in one process and builds in another: the first must not type-check
    and translate the hot modules (it doubled mypyc's minutes in a fresh ``make run``), the second must. The
    argument lists are setuptools' own (``setuptools.build_meta``)."""
    setup = _setup_module(monkeypatch, tmp_path)
    assert setup.metadata_only(argv) is only  # type: ignore[attr-defined]


@pytest.mark.parametrize("value,flags", [
    ("", None),  # a plain build: no profile flag
    ("generate", "-fprofile-generate"),
    ("use", "-fprofile-use"),
])
def test_a_profile_phase_adds_its_flags(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, value: str,
                                        flags: str | None) -> None:
    """``make compile``'s profile-guided build (``POSTPROC_PGO``): each phase compiles and links every extension
    with its gcc flags, into the one objects folder both phases share (pip's editable build would use a new
    temporary folder each time, and the second phase would not find the first's counts); a plain build adds none.
    A phase never leaves an older training's counts to mix with a new one."""
    from types import SimpleNamespace
    setup = _setup_module(monkeypatch, tmp_path)
    objects = tmp_path / "build" / "objects"
    monkeypatch.setattr(setup, "OBJECTS", objects)
    stale = objects / "x" / "old.gcda"
    stale.parent.mkdir(parents=True)
    stale.write_bytes(b"")
    monkeypatch.setenv("POSTPROC_PGO", value)
    monkeypatch.setattr(setup, "is_gcc", lambda command: True)
    monkeypatch.setattr(setup.build_ext, "build_extensions", lambda self: None)  # type: ignore[attr-defined]
    ext = SimpleNamespace(extra_compile_args=["-O3"], extra_link_args=[])
    build = setup.BuildCompiled.__new__(setup.BuildCompiled)  # type: ignore[attr-defined]
    build.compiler, build.extensions, build.build_temp = None, [ext], "/tmp/elsewhere"
    build.build_extensions()
    assert build.build_temp == str(objects)
    if flags is None:
        assert ext.extra_compile_args == ["-O3"] and ext.extra_link_args == []
    else:
        assert flags in ext.extra_compile_args and flags in ext.extra_link_args
        assert ext.extra_compile_args[0] == "-O3"  # (after mypyc's own: the profile's flags come last)
    assert stale.exists() is (value != "generate")


def test_an_unknown_profile_phase_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A misspelt ``POSTPROC_PGO`` stops the build with the values it takes, not a silently plain build."""
    setup = _setup_module(monkeypatch, tmp_path)
    monkeypatch.setenv("POSTPROC_PGO", "generat")
    with pytest.raises(SystemExit, match="generate"):
        setup.pgo_phase()  # type: ignore[attr-defined]


def test_the_profile_phases_need_gcc(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """clang takes other profile flags and files, so its build is plain: ``is_gcc`` asks the compiler itself
    (a compiler that cannot be run is not gcc)."""
    setup = _setup_module(monkeypatch, tmp_path)
    fake = tmp_path / "cc"
    fake.write_text("#!/bin/sh\necho 'Debian clang version 14.0.6'\n", encoding="utf-8")
    fake.chmod(0o755)
    assert setup.is_gcc([str(fake)]) is False  # type: ignore[attr-defined]
    fake.write_text("#!/bin/sh\necho 'gcc (Debian 12.2.0-14) 12.2.0'\necho 'This is free software; "
                    "Copyright (C) 2022 Free Software Foundation, Inc.'\n", encoding="utf-8")
    assert setup.is_gcc([str(fake)]) is True  # type: ignore[attr-defined]
    assert setup.is_gcc([str(tmp_path / "missing")]) is False  # type: ignore[attr-defined]
