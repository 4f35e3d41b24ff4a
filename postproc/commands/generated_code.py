"""What the standard library compiles from text while modules load, compiled once rather than at every start.

``dataclasses`` writes each dataclass's methods (``__init__``, ``__repr__``, ``__eq__``; a frozen one's
``__setattr__``, ``__delattr__`` and ``__hash__``) as source text and compiles it with ``exec``;
``collections.namedtuple`` its ``__new__`` with ``eval``; ``re`` parses every pattern and compiles it to the
matcher's code in Python. A one-line translation meets seven such dataclasses (four of them compiled modules'
classes, whose methods mypyc leaves to ``dataclasses``), eleven named tuples and 24 patterns of the modules it
imports (argparse's, gettext's, the lexers'...): compiling those texts cost it ~33M of its ~362M instructions
(callgrind, compiled build), more than any module it loads.

The command's own process (``postproc.commands.launch``, as it pauses the collector) hands ``dataclasses`` and
``collections`` a ``CodeCache``'s ``exec`` and ``eval``, and ``re`` its pattern compiler: what each text compiled
to before (a code object; a pattern's arguments to the matcher's constructor, ``_sre.compile``), read from a file
in the user's cache folder (beside the entry points', ``postproc.entry_points``) when the process starts and
written again when it ends if a text was new. A text gets what exactly that text compiles to, with what the
built-in would compile it with (the name ``<string>``, no ``__future__`` feature: ``dataclasses`` and
``collections`` have none; for ``eval``, its leading blanks skipped; a pattern, its type and flags): the same code
and the same patterns (equal, as ``re`` compares them: flags and matcher code). A file of another byte-code or
matcher version (its name holds both, with the interpreter's version and optimisation level), or one that does not
read as texts with code objects and pattern arguments, is ignored; one that cannot be written only costs the next
start its compiling. A program that calls ``main`` keeps the standard ``exec``, ``eval`` and ``re``.
"""

from __future__ import annotations

import marshal
import os
import re
import sys
from importlib.util import MAGIC_NUMBER
from types import CodeType, ModuleType
from typing import Any, Callable

from re import _compiler, _constants  # type: ignore[attr-defined]

PatternArguments = tuple[Any, int, list[int], int, dict[str, int], tuple[Any, ...]]
"""What ``re`` hands the matcher's constructor for a pattern: the pattern, its flags, the matcher's code, the number of
groups, the groups by name and the names by group."""

MAX_TEXTS = 600
"""More texts than this in the file (many commands, dialects, set-ups or versions of the installation met) and only
those this run used are written back."""


class CodeCache:
    """Code objects and patterns' arguments by the text (and mode, or type and flags) they were compiled from, read
    from and written to ``path``. The file holds each one marshalled apart, turned back into an object only when a
    run meets its text: a start reads the file's texts, not the objects other commands compiled (a file of every
    dataclass and pattern a test suite met, 390 KB, cost a one-line translation 11M instructions read whole)."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.stored = _read(path)
        """Each text's object as the file holds it (marshalled)."""
        self.codes: dict[str, CodeType] = {}
        self.patterns: dict[str, PatternArguments] = {}
        self.used: set[str] = set()
        self.new: dict[str, Any] = {}
        """What was compiled here (the file is then written again by ``save``)."""

    @property
    def added(self) -> bool:
        """Whether a text was compiled here."""
        return bool(self.new)

    def compiled(self, text: str, mode: str) -> CodeType:
        """The code ``exec`` (mode ``exec``) or ``eval`` (mode ``eval``) would compile ``text`` to."""
        key = mode + "\0" + text
        self.used.add(key)
        code = self.codes.get(key)
        if code is None:
            stored = self._stored(key)
            if isinstance(stored, CodeType):
                code = stored
            else:
                code = self.new[key] = compile(text, "<string>", mode, dont_inherit=True)
            self.codes[key] = code
        return code

    def _stored(self, key: str) -> object:
        """The object the file holds for ``key`` (None if none, or if it does not read)."""
        raw = self.stored.get(key)
        if raw is None:
            return None
        try:
            return marshal.loads(raw)
        except (EOFError, ValueError, TypeError):
            return None

    def save(self) -> None:
        """Write the file again if a text was compiled, whole or not at all (a parallel start reads either)."""
        if not self.new:
            return
        entries = dict(self.stored)
        entries.update((key, marshal.dumps(value)) for key, value in self.new.items())
        if len(entries) > MAX_TEXTS:
            entries = {key: value for key, value in entries.items() if key in self.used}
        tmp = f"{self.path}.{os.getpid()}"
        try:
            os.makedirs(os.path.dirname(self.path), exist_ok=True)
            with open(tmp, "wb") as f:
                f.write(marshal.dumps(entries))
            os.replace(tmp, self.path)
        except (OSError, ValueError):
            try:
                os.unlink(tmp)
            except OSError:
                pass
        self.stored = entries
        self.new = {}

    def install(self, *modules: ModuleType) -> None:
        """Give ``modules`` (``dataclasses``, ``collections``) this cache's ``exec`` and ``eval``: a module-level
        name is found before the built-in of that name."""
        for module in modules:
            module.exec = self.exec  # type: ignore[attr-defined]
            module.eval = self.eval  # type: ignore[attr-defined]

    def install_patterns(self) -> None:
        """Give ``re`` this cache's pattern compiler (``re.compile`` and the module functions call it for a pattern not
        in their own cache of this process)."""
        _compiler.compile = self.pattern_compiler(_compiler.compile)

    def pattern_compiler(self, compile_pattern: Callable[..., re.Pattern[Any]]) -> Callable[..., re.Pattern[Any]]:
        """``re``'s ``compile_pattern``, its answer for a text met before made from the arguments it made then."""
        matcher = _compiler._sre

        def compile(p: Any, flags: int = 0) -> re.Pattern[Any]:
            kind = "s" if isinstance(p, str) else "b" if isinstance(p, bytes) else None
            if kind is None or flags & _constants.SRE_FLAG_DEBUG:  # a parsed pattern, or one to print
                return compile_pattern(p, flags)
            key = f"re\0{kind}{int(flags)}\0{p if kind == 's' else p.decode('latin-1')}"
            self.used.add(key)
            known = self.patterns.get(key)
            if known is None:
                stored = self._stored(key)
                if _pattern_arguments(stored):
                    known = self.patterns[key] = stored  # type: ignore[assignment]
            if known is not None:
                return matcher.compile(*known)  # type: ignore[no-any-return]
            made: list[PatternArguments] = []
            _compiler._sre = _Recording(matcher, made)
            try:
                pattern = compile_pattern(p, flags)
            finally:
                _compiler._sre = matcher
            if len(made) == 1 and made[0][0] is p:  # (another thread compiling meanwhile: not kept)
                self.patterns[key] = self.new[key] = made[0]
            return pattern

        return compile

    def exec(self, source: Any, globals: Any = None, locals: Any = None, /) -> None:
        """The built-in ``exec``, a text compiled from this cache."""
        if globals is None:  # the caller's, as the built-in takes them
            caller = sys._getframe(1)
            globals, locals = caller.f_globals, caller.f_locals if locals is None else locals
        exec(self.compiled(source, "exec") if isinstance(source, str) else source, globals, locals)

    def eval(self, source: Any, globals: Any = None, locals: Any = None, /) -> Any:
        """The built-in ``eval``, a text (past its leading blanks, as the built-in skips them) compiled from this
        cache."""
        if globals is None:
            caller = sys._getframe(1)
            globals, locals = caller.f_globals, caller.f_locals if locals is None else locals
        if isinstance(source, str):
            source = self.compiled(source.lstrip(" \t"), "eval")
        return eval(source, globals, locals)


class _Recording:
    """The matcher's module as ``re``'s compiler sees it while a new pattern compiles: its constructor's arguments are
    kept in ``made``."""

    def __init__(self, matcher: Any, made: list[PatternArguments]) -> None:
        self._matcher = matcher
        self._made = made

    def __getattr__(self, name: str) -> Any:
        return getattr(self._matcher, name)

    def compile(self, pattern: Any, flags: int, code: list[int], groups: int, groupindex: dict[str, int],
                indexgroup: tuple[Any, ...]) -> Any:
        # (plain ints: re hands the flags as an enum and the code with its named opcodes, which marshal does not
        # write; the matcher reads their values)
        self._made.append((pattern, int(flags), [int(c) for c in code], groups, groupindex, indexgroup))
        return self._matcher.compile(pattern, flags, code, groups, groupindex, indexgroup)


def cache_path(folder: str) -> str:
    """The cache file in ``folder`` for this interpreter (its version: a release may compile a text otherwise), its
    byte code's and ``re``'s matcher's versions, and its optimisation level (``-O`` compiles asserts away)."""
    version = f"{sys.implementation.cache_tag}-{sys.version.split()[0]}-o{sys.flags.optimize}"
    formats = f"{MAGIC_NUMBER.hex()}-{marshal.version}-{_constants.MAGIC}"
    return os.path.join(folder, f"generated-code-{version}-{formats}.bin")


def _read(path: str) -> dict[str, bytes]:
    """Each text's marshalled object as the file at ``path`` holds it (none if it holds anything else)."""
    try:
        with open(path, "rb") as f:
            table = marshal.loads(f.read())
    except (OSError, EOFError, ValueError, TypeError):
        return {}
    if not isinstance(table, dict) or not all(isinstance(key, str) and key.startswith(("exec\0", "eval\0", "re\0"))
                                              and isinstance(value, bytes) for key, value in table.items()):
        return {}
    return table


def _pattern_arguments(value: object) -> bool:
    return (isinstance(value, tuple) and len(value) == 6 and isinstance(value[0], (str, bytes))
            and isinstance(value[1], int) and isinstance(value[2], list) and all(isinstance(c, int) for c in value[2])
            and isinstance(value[3], int) and isinstance(value[4], dict) and isinstance(value[5], tuple))
