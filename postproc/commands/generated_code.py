"""The code the standard library generates while modules load, compiled once rather than at every start.

``dataclasses`` writes each dataclass's methods (``__init__``, ``__repr__``, ``__eq__``; a frozen one's
``__setattr__``, ``__delattr__`` and ``__hash__``) as source text and compiles it with ``exec``;
``collections.namedtuple`` its ``__new__`` with ``eval``. A one-line translation meets seven such dataclasses (four
of them compiled modules' classes, whose methods mypyc leaves to ``dataclasses``) and eleven named tuples of the
standard modules it imports: parsing and compiling those texts cost it ~20M of its ~357M instructions (callgrind,
compiled build), more than any module it loads.

The command's own process (``postproc.commands.launch``, as it pauses the collector) hands the two modules' ``exec``
and ``eval`` a ``CodeCache``: the code objects compiled from each text met before, read from a file in the user's
cache folder (beside the entry points', ``postproc.entry_points``) when the process starts and written again when
it ends if it compiled a new text. A text runs the code compiled from exactly that text, with what the built-in
would compile it with (the name ``<string>``, no ``__future__`` feature: ``dataclasses`` and ``collections`` have
none; for ``eval``, its leading blanks skipped): the same code, so the same classes. A file of another byte-code
version (its name holds the magic number), or one that does not read as texts and code objects, is ignored, and
one that cannot be written only costs the next start its compiling. A program that calls ``main`` keeps the
standard ``exec`` and ``eval``.
"""

from __future__ import annotations

import marshal
import os
import sys
from importlib.util import MAGIC_NUMBER
from types import CodeType, ModuleType
from typing import Any

MAX_TEXTS = 4000
"""More texts than this in the file (many versions of the installation met) and only those this run used are
written back."""


class CodeCache:
    """Code objects by the text (and mode) they were compiled from, read from and written to ``path``."""

    def __init__(self, path: str) -> None:
        self.path = path
        self.codes = _read(path)
        self.used: set[str] = set()
        self.added = False
        """Whether a text was compiled here (the file is then written again by ``save``)."""

    def compiled(self, text: str, mode: str) -> CodeType:
        """The code ``exec`` (mode ``exec``) or ``eval`` (mode ``eval``) would compile ``text`` to."""
        key = mode + "\0" + text
        code = self.codes.get(key)
        if code is None:
            code = self.codes[key] = compile(text, "<string>", mode, dont_inherit=True)
            self.added = True
        self.used.add(key)
        return code

    def save(self) -> None:
        """Write the file again if a text was compiled, whole or not at all (a parallel start reads either)."""
        if not self.added:
            return
        codes = self.codes if len(self.codes) <= MAX_TEXTS else {k: self.codes[k] for k in self.used}
        tmp = f"{self.path}.{os.getpid()}"
        try:
            os.makedirs(os.path.dirname(self.path), exist_ok=True)
            with open(tmp, "wb") as f:
                f.write(marshal.dumps(codes))
            os.replace(tmp, self.path)
        except (OSError, ValueError):
            try:
                os.unlink(tmp)
            except OSError:
                pass
        self.added = False

    def install(self, *modules: ModuleType) -> None:
        """Give ``modules`` (``dataclasses``, ``collections``) this cache's ``exec`` and ``eval``: a module-level
        name is found before the built-in of that name."""
        for module in modules:
            module.exec = self.exec  # type: ignore[attr-defined]
            module.eval = self.eval  # type: ignore[attr-defined]

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


def cache_path(folder: str) -> str:
    """The cache file in ``folder`` for this interpreter's byte code."""
    return os.path.join(folder, f"generated-code-{MAGIC_NUMBER.hex()}-{marshal.version}.bin")


def _read(path: str) -> dict[str, CodeType]:
    try:
        with open(path, "rb") as f:
            codes = marshal.loads(f.read())
    except (OSError, EOFError, ValueError, TypeError):
        return {}
    if not isinstance(codes, dict) or not all(isinstance(k, str) and isinstance(v, CodeType)
                                              for k, v in codes.items()):
        return {}
    return codes
