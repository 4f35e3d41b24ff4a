"""The set-up loader's paths as text: what ``pathlib.PurePath``'s ``parent``, ``/`` and ``name`` and ``Path.is_file`` give,
computed on the path's text (``postproc.xmlio.path_text`` spells a path as ``str(PurePath(path))`` does).

Every ``--machine`` run loads a set-up file, and ``pathlib`` (with ``urllib.parse``, ``ipaddress`` and ``fnmatch``,
which it imports) was the only reason it imported them: ~8M instructions of a one-line ``translate --machine``
(callgrind). The loader's messages and locations name the files exactly as before. Where paths are not POSIX ones
(drives, two separators) each function is ``pathlib``'s own. ``tests/test_setup_paths.py`` holds them to
``pathlib`` on random paths.
"""

from __future__ import annotations

import errno
import os
import stat

from ..xmlio import path_text

POSIX = os.name == "posix"
_MISSING = frozenset((errno.ENOENT, errno.ENOTDIR, errno.EBADF, errno.ELOOP))
"""What ``Path.is_file`` reads as "no file" (``pathlib._IGNORED_ERRNOS``); any other error of ``os.stat`` it raises."""


def parent_text(path: str) -> str:
    """``str(PurePath(path).parent)``: ``.`` for a bare name, the root for a file at the root."""
    if not POSIX:
        from pathlib import PurePath
        return str(PurePath(path).parent)
    text = path_text(path)
    head, slash, name = text.rpartition("/")
    if not slash:
        return "."
    if not name:  # the root itself ("/" or "//")
        return text
    return head if head.strip("/") else head + "/"


def join_text(folder: str, name: str) -> str:
    """``str(PurePath(folder) / name)``: ``name`` itself where it is absolute."""
    if not POSIX:
        from pathlib import PurePath
        return str(PurePath(folder) / name)
    return path_text(os.path.join(folder, name))


def name_text(path: str) -> str:
    """``PurePath(path).name``: the last part, none of the root."""
    if not POSIX:
        from pathlib import PurePath
        return PurePath(path).name
    text = path_text(path)
    return "" if text == "." else text.rpartition("/")[2]


def is_file(path: str) -> bool:
    """``Path(path).is_file()``: a regular file (symbolic links followed); False where there is none, and the error
    raised where ``os.stat`` fails otherwise (a folder that may not be searched: ``PermissionError``), as
    ``pathlib`` does."""
    if not POSIX:
        from pathlib import Path
        return Path(path).is_file()
    try:
        return stat.S_ISREG(os.stat(path_text(path)).st_mode)
    except OSError as exc:
        if exc.errno not in _MISSING:
            raise
        return False
    except ValueError:
        return False
