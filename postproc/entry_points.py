"""The installed plugins' entry points, remembered between runs while the installation is unchanged.

Finding them (``importlib.metadata``) costs a one-line translation a seventh of its start-up: importing
it pulls in the email package, then every distribution's metadata folder is listed and read. What that
discovery reads is cheap to observe: the interpreter, ``sys.path``, and in each folder on it the
folder's modification time and the names of its ``*.dist-info``/``*.egg-info`` folders with the time and
size of each one's ``entry_points.txt``. Installing, removing or reinstalling a distribution (pip rewrites its
metadata folder, editable installs too) or editing an ``entry_points.txt`` changes that key; the cached
answer is used only while the key is the same. A key is not trusted (nothing is cached) when a finder
on ``sys.meta_path`` other than a path finder supplies distributions, or while the newest time in it is less than
``SETTLE`` seconds old (a file system with coarse times, an installation still under way).

The cache is one small text file per interpreter and group in the user's cache folder: its version, the
key as Python writes it (``repr``: compared, never evaluated), then one ``name=value`` line per entry
point (entry_points.txt is itself line-based). A cache that cannot be read or written is ignored
(discovery runs as before). ``POSTPROC_NO_ENTRY_POINT_CACHE=1`` turns it off.
"""

from __future__ import annotations

import importlib
import os
import stat
import sys
import time
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from os import PathLike

SETTLE = 2.0
"""Seconds a key's newest time must lie in the past before the answer is cached under it."""
METADATA_SUFFIXES = (".dist-info", ".egg-info")
VERSION = 1
"""Bumped when the file's layout changes (an older file is then ignored)."""

EntryPoints = list[tuple[str, str]]
"""(name, value) of each entry point of a group, in discovery order (``importlib.metadata``'s)."""


def entry_points(group: str, cache_dir: str | PathLike[str] | None = None, settle: float = SETTLE) -> EntryPoints:
    """The group's entry points: from the cache while its key holds, else discovered (and cached once
    every time in the key is ``settle`` seconds old)."""
    if os.environ.get("POSTPROC_NO_ENTRY_POINT_CACHE") == "1" or not _standard_finders():
        return discover(group)
    key, newest = installation_key()
    head = f"postproc entry points {VERSION}\n{key!r}\n"
    path = os.path.join(cache_dir or cache_folder(), f"entry-points-{_interpreter_id()}-{group}.txt")
    cached = _read(path)
    if cached is not None and cached.startswith(head):
        return [(name, value) for name, _, value in (line.partition("=") for line in cached[len(head):].splitlines())]
    found = discover(group)
    if newest < time.time() - settle and all("\n" not in n + v and "=" not in n for n, v in found):
        _write(path, head + "".join(f"{name}={value}\n" for name, value in found))
    return found


def discover(group: str) -> EntryPoints:
    """What ``importlib.metadata`` finds, in its order (pluggy's ``load_setuptools_entrypoints`` order)."""
    import importlib.metadata
    return [(ep.name, ep.value) for dist in importlib.metadata.distributions() for ep in dist.entry_points
            if ep.group == group]


def load(value: str) -> Any:
    """The object an entry point names (``module`` or ``module:attr.attr``), as ``EntryPoint.load`` does."""
    module, _, attrs = value.partition("[")[0].strip().partition(":")
    found: Any = importlib.import_module(module.strip())
    for attr in attrs.strip().split(".") if attrs.strip() else ():
        found = getattr(found, attr)
    return found


def installation_key() -> tuple[list[Any], float]:
    """What discovery reads, as JSON-able data, and the newest modification time in it (seconds). A metadata
    folder stands in it by its ``entry_points.txt`` alone: adding, removing or replacing the folder changes the
    folder that holds it, and its other files hold no entry point. (Stating each metadata folder too, and
    joining paths with ``os.path.join``, cost every start ~1M instructions of the key's ~3M.)"""
    key: list[Any] = [sys.executable, sys.prefix, sys.version, sys.path]
    newest = 0.0
    for entry in sys.path:
        folder = entry or "."
        try:
            st = os.stat(folder)
        except OSError:
            key.append(None)
            continue
        newest = max(newest, st.st_mtime)
        key.append([st.st_mtime_ns, st.st_size])
        if not stat.S_ISDIR(st.st_mode):
            continue  # a zip file: its time and size stand for its contents
        try:
            names = sorted(name for name in os.listdir(folder) if _is_metadata(name.lower()))
        except OSError:
            key.append(None)
            continue
        for name in names:
            try:
                st = os.stat(folder + os.sep + name + os.sep + "entry_points.txt")
            except OSError:
                key.append([name, None])
                continue
            newest = max(newest, st.st_mtime)
            key.append([name, st.st_mtime_ns, st.st_size])
    return key, newest


def _is_metadata(low: str) -> bool:
    """A distribution's metadata folder, by its name in lower case (what ``importlib.metadata`` looks in)."""
    return low.endswith(METADATA_SUFFIXES) or low == "egg-info"


def _standard_finders() -> bool:
    """True when only path finders supply distributions (what the key observes): the standard one, and
    the ``importlib_metadata`` backport's (dask imports it; it takes over the standard one's search of
    ``sys.path``)."""
    from importlib.machinery import PathFinder
    return all(finder is PathFinder or not hasattr(finder, "find_distributions")
               or type(finder).__module__.partition(".")[0] == "importlib_metadata" for finder in sys.meta_path)


def _interpreter_id() -> str:
    """A short name for the interpreter and its ``sys.path`` (two that share it only take turns: the key
    tells them apart). The path is in the name because it differs between ways of starting the same
    interpreter (the ``postproc`` script, ``python -m postproc``, a batch worker, a benchmark's script):
    with one file for all, each would find the other's key and discover again. The name is the text's
    32-bit FNV-1a hash, in Python: importing ``zlib`` for its CRC cost every start ~1.3M instructions."""
    code = 0x811C9DC5
    for byte in f"{sys.executable}\0{sys.prefix}\0{chr(0).join(sys.path)}".encode():
        code = ((code ^ byte) * 0x01000193) & 0xFFFFFFFF
    return format(code, "08x")


def cache_folder() -> str:
    """The user's cache folder for postproc (``$XDG_CACHE_HOME/postproc``, else ``~/.cache/postproc``): this module's
    files, and the generated code's (``postproc.commands.generated_code``)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "postproc")


def _read(path: str) -> str | None:
    """The file's text (paths as strings, ``os.path``: a start makes no ``pathlib`` object, whose module imports
    ``urllib.parse`` and ``ipaddress``)."""
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except (OSError, ValueError):
        return None


def _write(path: str, data: str) -> None:
    """Written whole or not at all (a temporary file renamed), so a parallel run never reads half."""
    folder, name = os.path.split(path)
    tmp = os.path.join(folder, f".{name}.{os.getpid()}")
    try:
        os.makedirs(folder, exist_ok=True)
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError:
        try:
            os.unlink(tmp)
        except OSError:
            pass
