"""A pytest plugin that writes each test's CPU time as it ends, to find where the suite's time goes on a shared
machine: wall-clock durations (``--durations``) grow with the load (a test of 8 s of CPU took 100 s at load 15),
CPU seconds hardly do, and a line per test is written at once, so a run stopped early still says what it ran.

    POSTPROC_CPU_TIMES=/tmp/times python -m pytest -n 2 -p tests.support.cpu_times [tests...]

Each process (xdist worker) appends ``nodeid<TAB>own CPU s<TAB>child processes' CPU s<TAB>wall s`` lines to
``$POSTPROC_CPU_TIMES/cpu-<worker>.tsv`` (child processes: rs274, ``postproc`` commands, Dask workers, counted
once they have been waited for). Without the variable the plugin writes nothing.
"""

from __future__ import annotations

import os
import resource
import time
from pathlib import Path
from typing import Generator, TextIO

import pytest

_out: list[TextIO] = []


def _file() -> TextIO | None:
    folder = os.environ.get("POSTPROC_CPU_TIMES")
    if not folder:
        return None
    if not _out:
        Path(folder).mkdir(parents=True, exist_ok=True)
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        _out.append(open(Path(folder) / f"cpu-{worker}.tsv", "a", buffering=1, encoding="utf-8"))
    return _out[0]


def _children() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None) -> Generator[None, None, None]:
    cpu, children, wall = time.process_time(), _children(), time.perf_counter()
    yield
    out = _file()
    if out is not None:
        out.write(f"{item.nodeid}\t{time.process_time() - cpu:.4f}\t{_children() - children:.4f}\t"
                  f"{time.perf_counter() - wall:.4f}\n")
