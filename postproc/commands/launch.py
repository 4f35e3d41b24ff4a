"""The ``postproc`` command's process: ``postproc.commands.cli.main`` with the cyclic garbage collector kept off
what the imports made.

Measured on a one-line translation (57 ms in all), the collector cost 7-9 ms (paired runs): its
collections while the modules load (they only allocate), and above all the last one of the interpreter's
exit, which walks every tracked object (22,000: classes, functions, dictionaries, code tables) and what
they refer to, to free memory the system takes back anyway. So the imports run with it off, and what they made, and at the end what
the run left, is frozen (``gc.freeze``: moved where no collection looks). In between it runs as
usual, each collection then walking only what the run itself allocates. Only the command's process
does this: a program that calls ``main`` (the tests, a caller's worker) keeps its collector as it is.

The same process has the code ``dataclasses`` and ``namedtuple`` generate and the patterns ``re`` compiles while
the modules load compiled once per installation, not at every start (``postproc.commands.generated_code``), unless
``POSTPROC_NO_CODE_CACHE=1`` (a read-only home, or to rule the cache out while chasing a fault).
"""

from __future__ import annotations

import gc
import os
import sys

from .generated_code import CodeCache, cache_path


def run() -> None:
    """The console script and ``python -m postproc``: run the command line, exit with its status."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        cache = _generated_code()
        from .cli import main
        from . import command_line
        command_line.FREEZE_IMPORTS = True  # and what the command's own modules make (``command_line.handler``)
    finally:
        gc.freeze()
        if was_enabled:
            gc.enable()
    try:
        code = main()
    finally:
        if cache is not None:
            cache.save()  # (also after argparse's own exit: --help, a usage error)
    gc.freeze()
    sys.exit(code)


def _generated_code() -> CodeCache | None:
    """The code ``dataclasses`` and ``collections.namedtuple`` generate and the patterns ``re`` compiles, compiled once
    per installation (``postproc.commands.generated_code``), given to them before the first dataclass, named tuple or
    pattern is made; None when ``POSTPROC_NO_CODE_CACHE=1``."""
    if os.environ.get("POSTPROC_NO_CODE_CACHE") == "1":
        return None
    import collections  # (already imported by the interpreter's start)
    from ..entry_points import cache_folder
    cache = CodeCache(cache_path(cache_folder()))
    cache.install(collections)  # first: importing dataclasses makes named tuples (dis)
    cache.install_patterns()
    _inspect_when_read()
    import dataclasses
    cache.install(dataclasses)
    return cache


def _inspect_when_read() -> None:
    """``inspect`` imported where the process first reads one of its names, not with ``dataclasses``, whose only
    use of it is the signature it writes into the docstring of a dataclass that has none (every record of ours has
    one: ``postproc.records``). With ``ast``, ``dis``, ``tokenize`` and ``linecache``, which it imports, it cost
    every start ~5 ms (``-X importtime``), once pluggy (which imports it too) was no longer loaded
    (``postproc.fast.plugin_hooks``). Until then ``sys.modules`` holds a module of that name whose every name
    is the real module's, imported at the first (``importlib.util.LazyLoader`` does not do here: an ``import``
    statement reads a module's ``__spec__``, which loads it). A process that imported it before keeps it.

    One name is there from the start: ``getfullargspec``, a function that calls the real one (importing the module
    then). ``lxml.etree`` binds it as it loads (``from inspect import getfullargspec``, its parser-target code,
    ``parsertarget.pxi`` in lxml 6.1), which read through the stand-in imported ``inspect`` with every set-up file
    (``--machine``): ~18M instructions of a one-line ``translate --machine`` (callgrind). lxml calls it only for a
    parser target with a ``start`` method (postproc has none), and then with the real function's result or
    exception (``tests/test_launch.py``)."""
    if "inspect" in sys.modules:
        return
    import types
    stand_in = types.ModuleType("inspect", "``inspect``, imported when a name of it is first read.")

    def real(name: str) -> object:
        if sys.modules.get("inspect") is stand_in:
            del sys.modules["inspect"]
        import inspect
        stand_in.__dict__.update(vars(inspect))
        return getattr(inspect, name)

    def getfullargspec(func: object) -> object:
        return real("getfullargspec")(func)  # type: ignore[operator]

    stand_in.__getattr__ = real  # type: ignore[method-assign]
    stand_in.__dict__["getfullargspec"] = getfullargspec
    sys.modules["inspect"] = stand_in
