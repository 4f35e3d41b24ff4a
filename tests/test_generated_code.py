"""``postproc.commands.generated_code``: the code ``dataclasses`` and ``collections.namedtuple`` generate is the code
the built-ins compile, whether it was compiled in this process or read from the cache file; the command's process
writes the file once and reads it after; a file that is not one is ignored."""

from __future__ import annotations

import collections
import dataclasses
import marshal
import os
import re
import subprocess
import sys
from pathlib import Path
from types import CodeType, FunctionType
from typing import Any, Iterator

import pytest
from hypothesis import given, settings, strategies as st

from postproc.commands.generated_code import CodeCache, cache_path


@pytest.fixture
def installed(tmp_path: Path) -> Iterator[CodeCache]:
    """A cache given to both modules for one test, the built-ins back after it."""
    cache = CodeCache(cache_path(str(tmp_path)))
    cache.install(dataclasses, collections)
    try:
        yield cache
    finally:
        for module in (dataclasses, collections):
            del module.exec  # type: ignore[attr-defined]
            del module.eval  # type: ignore[attr-defined]


def _code_facts(code: CodeType) -> tuple[Any, ...]:
    consts = tuple(_code_facts(c) if isinstance(c, CodeType) else c for c in code.co_consts)
    return (code.co_code, consts, code.co_names, code.co_varnames, code.co_freevars, code.co_cellvars,
            code.co_argcount, code.co_kwonlyargcount, code.co_flags, code.co_name, code.co_filename)


def _methods(cls: type) -> dict[str, tuple[Any, ...]]:
    """The generated methods' code (``__repr__`` is wrapped by dataclasses' recursion guard)."""
    found = {name: getattr(value, "__wrapped__", value) for name, value in vars(cls).items()}
    return {name: _code_facts(value.__code__) for name, value in found.items()
            if isinstance(value, FunctionType) and value.__code__.co_filename == "<string>"}


FIELDS = st.lists(st.tuples(st.sampled_from(["int", "str", "float", "tuple[int, ...]", "'list[str] | None'"]),
                            st.sampled_from(["none", "value", "factory"])), min_size=0, max_size=6)


def _define(shape: list[tuple[str, str]], frozen: bool, slots: bool, order: bool) -> type:
    lines = ["import dataclasses", f"@dataclasses.dataclass(frozen={frozen}, slots={slots}, order={order})",
             "class Made:"]
    defaults = {"none": "", "value": " = 0", "factory": " = dataclasses.field(default_factory=list)"}
    lines += [f"    f{i}: {kind}" + defaults[default]
              for i, (kind, default) in enumerate(sorted(shape, key=lambda s: s[1] != "none"))]
    lines += ["    pass"]
    space: dict[str, Any] = {"__name__": __name__}  # (a module dataclasses finds in sys.modules)
    exec(compile("\n".join(lines), "made", "exec"), space)
    made: type = space["Made"]
    return made


@settings(max_examples=30, deadline=None)
@given(shape=FIELDS, frozen=st.booleans(), slots=st.booleans(), order=st.booleans())
def test_a_dataclass_gets_the_methods_the_builtin_compiles(tmp_path_factory: pytest.TempPathFactory,
                                                            shape: list[tuple[str, str]], frozen: bool,
                                                            slots: bool, order: bool) -> None:
    plain = _methods(_define(shape, frozen, slots, order))
    cache = CodeCache(cache_path(str(tmp_path_factory.mktemp("cache"))))
    cache.install(dataclasses)
    try:
        first = _methods(_define(shape, frozen, slots, order))  # compiled here
        cache.save()
        again = CodeCache(cache.path)  # read back from the file
        again.install(dataclasses)
        second = _methods(_define(shape, frozen, slots, order))
        assert not again.added  # every text came from the file
    finally:
        del dataclasses.exec  # type: ignore[attr-defined]
    assert plain == first == second and set(plain) >= {"__init__", "__repr__", "__eq__"}


def test_a_named_tuple_gets_the_new_the_builtin_compiles(tmp_path: Path) -> None:
    plain = collections.namedtuple("Made", "a b c", defaults=(3,))
    cache = CodeCache(cache_path(str(tmp_path)))
    cache.install(collections)
    try:
        made = collections.namedtuple("Made", "a b c", defaults=(3,))
    finally:
        del collections.eval  # type: ignore[attr-defined]
    assert made(1, 2) == (1, 2, 3) and made._make([4, 5, 6]).c == 6
    assert "eval\0" + "lambda _cls, a, b, c: _tuple_new(_cls, (a, b, c))" in cache.codes
    assert _code_facts(made.__new__.__code__) == _code_facts(plain.__new__.__code__)


def test_exec_and_eval_keep_the_builtins_meaning(installed: CodeCache) -> None:
    """A caller's own globals and locals when none are given, leading blanks skipped by ``eval``, and code objects
    passed through."""
    answer = 41
    assert dataclasses.eval("  answer + 1") == 42  # type: ignore[attr-defined]
    space: dict[str, Any] = {}
    dataclasses.exec("x = 1", space)  # type: ignore[attr-defined]
    assert space["x"] == 1
    assert collections.eval(compile("2 * 3", "<string>", "eval")) == 6  # type: ignore[attr-defined]
    with pytest.raises(SyntaxError):
        dataclasses.exec("def")  # type: ignore[attr-defined]


@pytest.mark.parametrize("content", [b"", b"garbage", marshal.dumps([1, 2]), marshal.dumps({"exec\0x": 1}),
                                     marshal.dumps({1: compile("1", "<string>", "eval")}),
                                     marshal.dumps({"re\0s0\0a": ("a", 0, [1, "x"], 0, {}, ())})])
def test_a_file_that_is_not_a_cache_is_ignored(tmp_path: Path, content: bytes) -> None:
    path = cache_path(str(tmp_path))
    Path(path).write_bytes(content)
    cache = CodeCache(path)
    assert cache.stored == {}
    cache.compiled("1 + 1", "eval")
    cache.save()
    assert CodeCache(path).stored.keys() == {"eval\0" + "1 + 1"}


def test_an_entry_that_does_not_read_is_compiled_again(tmp_path: Path) -> None:
    path = cache_path(str(tmp_path))
    Path(path).write_bytes(marshal.dumps({"eval\0" + "1 + 1": b"garbage", "re\0s0\0a+": marshal.dumps((1, 2))}))
    cache = CodeCache(path)
    assert eval(cache.compiled("1 + 1", "eval")) == 2
    import re._compiler as compiler
    assert cache.pattern_compiler(compiler.compile)("a+", 0) == compiler.compile("a+", 0)
    cache.save()
    again = CodeCache(path)
    assert eval(again.compiled("1 + 1", "eval")) == 2 and not again.added
    assert again.pattern_compiler(compiler.compile)("a+", 0).match("aa") and not again.added


def test_a_start_turns_back_only_what_it_meets(tmp_path: Path) -> None:
    """The file's other texts stay marshalled: reading it makes no code object."""
    cache = CodeCache(cache_path(str(tmp_path)))
    for n in range(50):
        cache.compiled(f"{n} + 1", "eval")
    cache.save()
    again = CodeCache(cache.path)
    assert len(again.stored) == 50 and again.codes == {}
    again.compiled("7 + 1", "eval")
    assert list(again.codes) == ["eval\0" + "7 + 1"]


def test_an_unwritable_folder_only_costs_the_compiling(tmp_path: Path) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    cache = CodeCache(cache_path(str(blocker / "below")))
    cache.compiled("1", "eval")
    cache.save()  # no error
    assert not (blocker / "below").exists()


def test_the_command_writes_the_file_once_and_reads_it_after(tmp_path: Path) -> None:
    program = tmp_path / "one.nc"
    program.write_text("G0 X1. Y2.\n")
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path / "cache"))
    args = [sys.executable, "-m", "postproc", "translate", str(program), "--from", "fanuc", "--to", "grbl",
            "-o", str(tmp_path / "one.gcode")]
    done = subprocess.run(args, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    (path,) = (tmp_path / "cache" / "postproc").glob("generated-code-*")
    texts = CodeCache(str(path)).stored
    assert any("__init__" in key for key in texts) and any(key.startswith("eval\0lambda _cls") for key in texts)
    assert len([key for key in texts if key.startswith("re\0")]) > 10  # argparse's, gettext's, the lexers'...
    written = path.stat().st_mtime_ns
    done = subprocess.run(args, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert path.stat().st_mtime_ns == written  # nothing new to compile: not written again
    assert (tmp_path / "one.gcode").read_text()


def test_the_command_writes_no_file_when_the_cache_is_turned_off(tmp_path: Path) -> None:
    program = tmp_path / "one.nc"
    program.write_text("G0 X1. Y2.\n")
    env = dict(os.environ, XDG_CACHE_HOME=str(tmp_path / "cache"), POSTPROC_NO_CODE_CACHE="1")
    args = [sys.executable, "-m", "postproc", "translate", str(program), "--from", "fanuc", "--to", "grbl",
            "-o", str(tmp_path / "one.gcode")]
    done = subprocess.run(args, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert not list((tmp_path / "cache").glob("postproc/generated-code-*"))
    assert (tmp_path / "one.gcode").read_text()


ATOMS = st.sampled_from(["a", "b", r"\d", r"\w", r"\s", ".", "[a-c]", "[^x]", r"\(", "X", "é", "^", "$", r"\b"])


def _regex(children: st.SearchStrategy[str]) -> st.SearchStrategy[str]:
    return st.one_of(
        st.tuples(children, children).map("".join),
        st.tuples(children, children).map("|".join),
        children.map(lambda r: f"(?:{r})"), children.map(lambda r: f"({r})"),
        st.tuples(st.sampled_from(["x", "y", "name"]), children).map(lambda t: f"(?P<{t[0]}>{t[1]})"),
        st.tuples(children, st.sampled_from(["*", "+", "?", "{2}", "{1,3}", "*?", "++", "*+"])).map(
            lambda t: f"(?:{t[0]}){t[1]}"),
        children.map(lambda r: f"(?={r})"), children.map(lambda r: f"(?i:{r})"))


REGEXES = st.recursive(ATOMS, _regex, max_leaves=8)
FLAGS = st.sampled_from([0, re.IGNORECASE, re.MULTILINE | re.DOTALL, re.VERBOSE, re.ASCII, re.IGNORECASE | re.ASCII])


@settings(max_examples=60, deadline=None)
@given(text=REGEXES, flags=FLAGS, as_bytes=st.booleans())
def test_a_pattern_is_the_one_re_compiles(tmp_path_factory: pytest.TempPathFactory, text: str, flags: int,
                                          as_bytes: bool) -> None:
    """Equal as ``re`` compares patterns (flags and the matcher's code), compiled here or read from the file."""
    import re._compiler as compiler
    if as_bytes:
        if flags & re.ASCII or not text.isascii():
            return
        source: str | bytes = text.encode()
    else:
        source = text
    try:
        plain = compiler.compile(source, flags)
    except re.error:
        return
    cache = CodeCache(cache_path(str(tmp_path_factory.mktemp("cache"))))
    first = cache.pattern_compiler(compiler.compile)(source, flags)
    cache.save()
    again = CodeCache(cache.path)
    second = again.pattern_compiler(compiler.compile)(source, flags)
    assert not again.added and len(again.patterns) == 1  # read from the file
    assert plain == first == second
    assert (plain.pattern, plain.flags, plain.groups, plain.groupindex) == \
        (second.pattern, second.flags, second.groups, second.groupindex)
