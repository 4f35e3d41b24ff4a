"""Run one untrusted computation in a child process with bounded memory and time.

Templates come from configuration an integrator may not fully trust, and Python cannot bound the
memory of a computation in-process (``'x'|center(10**9)``, a loop that doubles a string): the child
has an address-space limit (``RLIMIT_AS``) and a CPU limit, and the parent kills it at a deadline.
Only used at start-up (a few milliseconds per ``fork``), never per block. Where ``fork`` does not
exist the computation runs in-process, bounded only by what the caller checks itself.
"""

from __future__ import annotations

import json
import math
import os
import select
import signal
import time
from dataclasses import dataclass
from typing import Any, Callable

try:
    import resource
except ImportError:  # pragma: no cover - not POSIX
    resource = None  # type: ignore[assignment]

MEMORY_LIMIT = 256 << 20
"""Bytes of address space the child may add to what the parent had mapped when it forked."""
MAX_REPORT = 16 << 20
"""Largest report (JSON bytes) the parent reads back."""


@dataclass(frozen=True, slots=True)
class Bounded:
    """What came back: the function's JSON value, or why there is none."""

    value: Any = None
    failure: str | None = None
    """'time' (deadline or CPU limit), 'memory' (killed, or ``MemoryError``), or 'crash'."""
    peak_rss: int = 0
    """The child's peak resident set in bytes (from ``wait4``), inherited pages included."""


def run_bounded(fn: Callable[[], Any], seconds: float, memory: int = MEMORY_LIMIT) -> Bounded:
    """``fn()`` in a forked child: its JSON-serialisable value, or the limit it hit.

    A ``MemoryError`` inside ``fn`` is reported as 'memory'; every other exception is ``fn``'s own
    business (it should return a description instead of raising).
    """
    if not hasattr(os, "fork") or resource is None:
        return _here(fn)
    base = _mapped_bytes()
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: never returns
        os.close(read_end)
        _child(fn, write_end, base + memory if base else 0, seconds)
    os.close(write_end)
    try:
        data, timed_out = _read_until(read_end, time.monotonic() + seconds)
    except BaseException:  # interrupted (Ctrl-C): leave no child behind
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
        raise
    finally:
        os.close(read_end)
    if timed_out:
        os.kill(pid, signal.SIGKILL)
    _, status, usage = os.wait4(pid, 0)
    peak = usage.ru_maxrss * 1024
    if timed_out:
        return Bounded(failure="time", peak_rss=peak)
    if os.WIFSIGNALED(status):
        sig = os.WTERMSIG(status)
        return Bounded(failure="time" if sig == signal.SIGXCPU else "memory" if sig == signal.SIGKILL else "crash",
                       peak_rss=peak)
    try:
        report = json.loads(data)
    except ValueError:
        return Bounded(failure="memory" if os.WEXITSTATUS(status) == 3 else "crash", peak_rss=peak)
    if report.get("memory"):
        return Bounded(failure="memory", peak_rss=peak)
    return Bounded(value=report.get("value"), peak_rss=peak)


def _here(fn: Callable[[], Any]) -> Bounded:
    try:
        return Bounded(value=fn())
    except MemoryError:
        return Bounded(failure="memory")


def _child(fn: Callable[[], Any], out: int, address_space: int, seconds: float) -> None:
    """Set the limits, run, write the JSON report, exit without running any parent clean-up."""
    code = 0
    try:
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        if address_space:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
        cpu = math.ceil(seconds) + 1
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
        try:
            report: dict[str, Any] = {"value": fn()}
        except MemoryError:
            report = {"memory": True}
        data = json.dumps(report).encode("utf-8")
        if len(data) > MAX_REPORT:
            data = b'{"memory": true}'
        view = memoryview(data)
        while view:
            view = view[os.write(out, view):]
    except MemoryError:
        code = 3
    except BaseException:
        code = 4
    finally:
        os._exit(code)


def _read_until(fd: int, deadline: float) -> tuple[bytes, bool]:
    """Everything the child writes until it closes the pipe; True when the deadline passed first."""
    chunks: list[bytes] = []
    size = 0
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            return b"", True
        ready, _, _ = select.select([fd], [], [], left)
        if not ready:
            return b"", True
        chunk = os.read(fd, 1 << 16)
        if not chunk:
            return b"".join(chunks), False
        size += len(chunk)
        if size > MAX_REPORT:
            return b"", False
        chunks.append(chunk)


def _mapped_bytes() -> int:
    """This process's address space in bytes (Linux ``/proc``), or 0 when unknown (no limit set)."""
    try:
        with open("/proc/self/statm", "rb") as f:
            pages = int(f.read().split()[0])
    except (OSError, ValueError, IndexError):
        return 0
    return pages * os.sysconf("SC_PAGE_SIZE")
