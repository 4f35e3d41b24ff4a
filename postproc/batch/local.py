"""Running the chunks on this machine: in this process (one job) or in a pool of worker processes.

Workers are forked from this process when it has a single thread (the command line): they start at
once, with postproc imported and the dialects loaded. A process with other threads (an application
embedding postproc, a test run beside a Dask cluster) is not forked, since a fork copies locks that
other threads may hold: its workers come from a fork server that imports postproc once. Workers ignore Ctrl-C: the terminal sends it to
every process of the group, and only this one decides (it cancels what has not started and ends the
workers; the temporary files they leave are swept by the batch, see ``command``).

A worker process that dies (killed from outside, out of memory) breaks the pool: the files not
finished then are reported as not translated (``internal``), and the batch ends with exit 1. Python
errors never do that: they are the file's result (``work``). A batch that must survive losing workers
runs on Dask (``--scheduler``), whose own retries handle it.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
import threading
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from typing import Any, Generator, Sequence

from .plan import Job
from .work import EXIT_ERRORS, FileResult, Options, run_chunk


def default_jobs() -> int:
    """All the cores this process may run on."""
    try:
        return max(len(os.sched_getaffinity(0)), 1)
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def run_local(chunks: Sequence[Sequence[Job]], options: Options, run_id: str, jobs: int) -> Generator[list[FileResult], None, None]:
    """Each chunk's results, as chunks finish. Close the iterator to stop early (workers end)."""
    if jobs <= 1 or len(chunks) <= 1:
        for chunk in chunks:
            yield run_chunk(chunk, options, run_id)
        return
    context = _start_method()
    pool = ProcessPoolExecutor(max_workers=min(jobs, len(chunks)), mp_context=context, initializer=_worker_signals)
    finished = False
    try:
        futures: dict[Future[list[FileResult]], Sequence[Job]] = {
            pool.submit(run_chunk, chunk, options, run_id): chunk for chunk in chunks}
        for future in as_completed(futures):
            try:
                results = future.result()
            except Exception as exc:  # the pool broke: a worker process died
                results = [lost(job, f"a worker process died ({type(exc).__name__}: {exc})") for job in futures[future]]
            yield results
        finished = True
    finally:
        processes = list((getattr(pool, "_processes", None) or {}).values())
        pool.shutdown(wait=finished, cancel_futures=True)
        if not finished:
            _end_workers(processes)


def lost(job: Job, why: str) -> FileResult:
    """The result of a file whose worker never answered."""
    return FileResult(job.name, job.output_name, "internal", EXIT_ERRORS,
                      errors=[f"postproc: {job.name}: not translated: {why}"])


def _start_method() -> Any:
    if threading.active_count() == 1 and "fork" in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("fork")
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(["postproc.batch.work"])
    return context


def _worker_signals() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _end_workers(processes: list[Any]) -> None:
    """Stop the workers now (an interrupted batch). ``ProcessPoolExecutor`` has no public way before
    Python 3.14 (``terminate_workers``), hence its ``_processes``, read before ``shutdown`` drops them."""
    for process in processes:
        process.terminate()
    for process in processes:
        process.join(timeout=10)
