"""Writing a command's output: complete or not at all, and never at the cost of what ``-o`` names.

The output is written to a temporary file first (no partial outputs; ``temporary_file``) and then:
- a regular file (or a new name) is replaced atomically by renaming the temporary file over it,
  keeping the old file's permission bits (a new file gets the umask's, as any program's output);
- a symlink is followed: its target is what gets written (replaced, if it is a regular file);
- a device, FIFO or socket (``-o /dev/null``, ``-o /dev/stdout``) is written in place, never replaced
  (as root, renaming over ``/dev/null`` deleted the device);
- no ``-o``: standard output.
Writing over the input is refused unless the caller allows it (``--in-place``): the comparison is by
device and inode, so a symlink, a hard link or another spelling of the path is the same file.
"""

from __future__ import annotations

import os
import stat
import sys
from typing import BinaryIO, Callable, TextIO

from ..errors import UsageError

ENCODING = {"encoding": "utf-8", "errors": "surrogateescape", "newline": ""}
"""Programs are read and written byte-faithfully: undecodable bytes survive as surrogates."""
BUFFER = 1 << 20


def write_output(path: str | None, write: Callable[[TextIO], object], *, binary: bool = False,
                 input_path: str | None = None, in_place: bool | None = None) -> None:
    """Run ``write`` on a temporary file and put the result where ``path`` says (stdout if None).
    ``in_place``: True allows ``path`` to be the input, False refuses it and names ``--in-place``,
    None refuses it (the command has no such option)."""
    target, regular = (None, True) if path is None else _target(path, input_path, in_place)
    folder = os.path.dirname(target) if target is not None and regular else None
    try:
        fd, tmp = temporary_file(folder)
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror}") from None
    try:
        mode, kwargs = ("wb", {}) if binary else ("w", ENCODING)
        with os.fdopen(fd, mode, buffering=BUFFER, **kwargs) as out:  # type: ignore[call-overload]
            write(out)
        if target is None:
            _copy(tmp, sys.stdout.buffer)
        elif regular:
            _replace(tmp, target, str(path))
        else:
            _into_device(tmp, target, str(path))
    finally:
        if os.path.lexists(tmp):
            os.unlink(tmp)


TEMPORARY_PREFIX = ".postproc-"
TEMPORARY_NAMES = 100
"""Random names tried in a folder before giving up (``tempfile``'s ``TMP_MAX`` is 10000; a name has
64 random bits here, so a second draw is already a surprise)."""


def temporary_file(folder: str | None) -> tuple[int, str]:
    """A new file of this run's own, open for writing: ``(descriptor, absolute path)``, created in
    ``folder`` (beside the target, so that renaming it over the target is atomic), or where None in the
    first usable temporary folder (``tempfile.gettempdir``'s choice: ``$TMPDIR``, ``$TEMP``, ``$TMP``,
    then the system's).

    What ``tempfile.mkstemp`` does, with ``os`` alone: created exclusively (``O_EXCL``: never an
    existing file, nor a symlink planted under the name), mode 0600, not inherited by child processes,
    a random name drawn again when taken. ``tempfile`` imports shutil, random, bz2 and lzma: a few ms of
    every command that writes a file, a tenth of a one-line translation's start-up."""
    flags = (os.O_RDWR | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_BINARY", 0))
    failed: OSError = FileNotFoundError("no folder for the temporary output")
    for place in [folder] if folder is not None else _temporary_folders():
        for _ in range(TEMPORARY_NAMES):
            name = os.path.abspath(os.path.join(place, TEMPORARY_PREFIX + os.urandom(8).hex()))
            try:
                return os.open(name, flags, 0o600), name  # os.open's descriptors are not inheritable
            except FileExistsError as exc:
                failed = exc  # another file has this name: draw another
            except OSError as exc:
                failed = exc  # not usable: the next folder, if any
                break
    raise failed


def _temporary_folders() -> list[str]:
    """Where ``tempfile.gettempdir`` looks, in its order (it takes the first it can write in)."""
    found = [folder for folder in (os.environ.get(name) for name in ("TMPDIR", "TEMP", "TMP")) if folder]
    if os.name == "nt":
        found += [os.path.expanduser(r"~\AppData\Local\Temp"), os.path.expandvars(r"%SYSTEMROOT%\Temp"),
                  r"c:\temp", r"c:\tmp", r"\temp", r"\tmp"]
    else:
        found += ["/tmp", "/var/tmp", "/usr/tmp"]
    try:
        found.append(os.getcwd())
    except OSError:
        found.append(os.curdir)
    return found


def _target(path: str, input_path: str | None, in_place: bool | None) -> tuple[str, bool]:
    """Where to write and whether it is (or will be) a regular file, after the usage checks.

    A regular or new file is named by its real path (symlinks followed), so the rename replaces the
    target and not the link; anything else is opened through ``path`` itself."""
    try:
        st = os.stat(path)
    except FileNotFoundError:
        st = None  # a new file, or a symlink to one
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror}") from None
    if st is not None and stat.S_ISDIR(st.st_mode):
        raise UsageError(f"cannot write {path}: it is a directory")
    if st is not None and not stat.S_ISREG(st.st_mode):
        return path, False
    target = os.path.realpath(path)
    folder = os.path.dirname(target)
    if not os.path.isdir(folder):
        raise UsageError(f"cannot write {path}: no such directory {folder}")
    if input_path is not None and not in_place and _same_file(input_path, target):
        hint = " (give --in-place to do that)" if in_place is False else ""
        raise UsageError(f"-o {path} would overwrite the input {input_path}{hint}")
    return target, True


def _same_file(a: str, b: str) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:  # one of them does not exist: not the same file
        return False


def _replace(tmp: str, target: str, path: str) -> None:
    """Rename the finished temporary file over ``target``, with the old file's mode or the umask's."""
    try:
        old = os.stat(target).st_mode if os.path.exists(target) else None
        os.chmod(tmp, stat.S_IMODE(old) if old is not None else 0o666 & ~_umask())
        os.replace(tmp, target)
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror}") from None


def _into_device(tmp: str, target: str, path: str) -> None:
    """Copy the finished output into a device, FIFO or socket, which stays what it is."""
    try:
        with open(target, "wb") as out:
            _copy(tmp, out)
    except BrokenPipeError:
        raise UsageError(f"cannot write {path}: the reading end of the pipe is closed") from None
    except OSError as exc:
        raise UsageError(f"cannot write {path}: {exc.strerror}") from None


def _copy(tmp: str, out: BinaryIO) -> None:
    with open(tmp, "rb") as src:
        while chunk := src.read(BUFFER):
            out.write(chunk)
    out.flush()


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
