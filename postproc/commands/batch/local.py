"""Running the chunks on this machine: in this process (one job) or in a pool of worker processes.

Workers are forked from this process when it has a single thread (the command line): they start at
once, with postproc imported and the dialects loaded. A process with other threads (an application
embedding postproc, a test run beside a Dask cluster) is not forked, since a fork copies locks that
other threads may hold: its workers come from a fork server that imports postproc once. Workers ignore
Ctrl-C: the terminal sends it to every process of the group, and only this one decides (it cancels
what has not started and ends the workers; the temporary files they leave are swept by the batch).

A worker process that dies (a crash, the out-of-memory killer, ``kill -9``) breaks the pool, and the
pool fails every task not finished. The files being translated at that moment are the ones with a
temporary output of this run (``work``: the name carries the file's number): each of them is then
translated alone, in a pool of its own, so a death there is that file's alone (``internal``); the
other unfinished files go to a fresh pool, as before. Python errors never break a pool: they are the
file's result (``work``).
"""

from __future__ import annotations

import glob
import multiprocessing
import os
import signal
import threading
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from typing import Any, Generator, Sequence

from .plan import Job
from .work import EXIT_ERRORS, TEMP_PREFIX, FileResult, Options, run_chunk

MAX_BLIND_RESTARTS = 3
"""Pools that may break with no file in progress (a worker killed between two files) before the files
left are reported as not translated: the batch always ends."""


def default_jobs() -> int:
    """All the cores this process may run on."""
    try:
        return max(len(os.sched_getaffinity(0)), 1)
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def run_local(chunks: Sequence[Sequence[Job]], options: Options, run_id: str,
              jobs: int) -> Generator[list[FileResult], None, None]:
    """Each chunk's results, as chunks finish. Close the iterator to stop early (workers end)."""
    if jobs <= 1 or len(chunks) <= 1:
        for chunk in chunks:
            yield run_chunk(chunk, options, run_id)
        return
    pending = list(chunks)
    per_chunk = max(len(chunk) for chunk in chunks)
    blind = 0
    while pending:
        unfinished = yield from _pool(pending, options, run_id, jobs)
        suspects = _in_progress(unfinished, run_id)
        for job in suspects:
            yield [_alone(job, options, run_id)]
        blind = blind + 1 if unfinished and not suspects else 0
        rest = [job for job in unfinished if job not in suspects]
        if blind >= MAX_BLIND_RESTARTS:
            yield [lost(job, "worker processes kept dying") for job in rest]
            return
        pending = [rest[i:i + per_chunk] for i in range(0, len(rest), per_chunk)]


def _pool(chunks: Sequence[Sequence[Job]], options: Options, run_id: str,
          jobs: int) -> Generator[list[FileResult], None, list[Job]]:
    """Run ``chunks`` in a pool of ``jobs`` workers; returns the jobs not finished when the pool broke."""
    pool = ProcessPoolExecutor(max_workers=min(jobs, len(chunks)), mp_context=_start_method(),
                               initializer=_worker_signals)
    processes: list[Any] = []
    finished = False
    unfinished: list[Job] = []
    try:
        futures: dict[Future[list[FileResult]], Sequence[Job]] = {
            pool.submit(run_chunk, chunk, options, run_id): chunk for chunk in chunks}
        processes = list((getattr(pool, "_processes", None) or {}).values())
        for future in as_completed(futures):
            try:
                results = future.result()
            except Exception:  # the pool broke: a worker process died
                unfinished.extend(futures[future])
                continue
            yield results
        finished = True
    finally:
        pool.shutdown(wait=finished, cancel_futures=True)
        if not finished:
            _end_workers(processes)
    return sorted(unfinished, key=lambda job: job.number)


def _in_progress(jobs: list[Job], run_id: str) -> list[Job]:
    """The jobs that have a temporary output of this run: those a worker was translating when the pool
    broke (their temporary files are removed: the next break must not find them)."""
    by_number = {job.number: job for job in jobs}
    found: dict[int, Job] = {}
    for folder in {os.path.dirname(job.output) for job in jobs}:
        for path in glob.glob(os.path.join(glob.escape(folder), f"{TEMP_PREFIX}{run_id}-*")):
            number = os.path.basename(path)[len(TEMP_PREFIX) + len(run_id) + 1:].partition("-")[0]
            if number.isdigit() and int(number) in by_number:
                found[int(number)] = by_number[int(number)]
            try:
                os.unlink(path)
            except OSError:
                pass
    return [found[number] for number in sorted(found)]


def _alone(job: Job, options: Options, run_id: str) -> FileResult:
    """Translate one file in a pool of its own: if its worker dies, it was this file."""
    pool = ProcessPoolExecutor(max_workers=1, mp_context=_start_method(), initializer=_worker_signals)
    try:
        return pool.submit(run_chunk, [job], options, run_id).result()[0]
    except Exception as exc:  # the pool broke
        return lost(job, f"its worker process died translating it alone ({type(exc).__name__}: a crash, "
                         "or killed, e.g. out of memory)")
    finally:
        pool.shutdown(wait=True, cancel_futures=True)


def lost(job: Job, why: str) -> FileResult:
    """The result of a file whose worker never answered."""
    return FileResult(job.name, job.output_name, "internal", EXIT_ERRORS,
                      errors=[f"postproc: {job.name}: not translated: {why}"])


def _start_method() -> Any:
    if threading.active_count() == 1 and "fork" in multiprocessing.get_all_start_methods():
        return multiprocessing.get_context("fork")
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(["postproc.commands.batch.work"])
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
