"""Running the chunks on a Dask cluster (``--scheduler tcp://host:8786``) or a ``LocalCluster``
(``--scheduler local``).

Scheduling, retries and worker loss are distributed's own: each chunk is one task (``pure=False``, a
key with the run's id), and a task whose worker dies is run again elsewhere, up to distributed's
``allowed-failures``; after that its files are reported as not translated. A task that runs twice
writes the same bytes twice (outputs are renamed into place whole), and its results reach the report
once, since this client reads each future once: every file is translated and reported exactly once.

Inputs and outputs are on a path every worker sees (the jobs carry absolute paths), and every worker
has postproc (with the same dialect plugins) installed.
"""

from __future__ import annotations

import contextlib
import logging
from typing import Any, Generator, Sequence

from ...errors import UsageError
from .local import lost
from .plan import Job
from .work import FileResult, Options, run_chunk

CONNECT_TIMEOUT = "120s"
"""How long to wait for the scheduler (a loaded machine, a cluster still starting)."""


def run_cluster(chunks: Sequence[Sequence[Job]], options: Options, run_id: str, scheduler: str,
                jobs: int) -> Generator[list[FileResult], None, None]:
    """Each chunk's results, as tasks finish on the cluster. Close the iterator to stop early (the
    tasks not finished are cancelled)."""
    distributed = _import_distributed()
    with contextlib.ExitStack() as stack:
        client = _client(distributed, scheduler, jobs, stack)
        futures: dict[Any, Sequence[Job]] = {}
        for number, chunk in enumerate(chunks):
            future = client.submit(run_chunk, chunk, options, run_id, key=f"postproc-{run_id}-{number}", pure=False)
            futures[future] = chunk
        try:
            for future in distributed.as_completed(list(futures)):
                try:
                    results: list[FileResult] = future.result()
                except Exception as exc:  # distributed gave up on the task (its workers kept dying)
                    results = [lost(job, f"the cluster gave up on it ({type(exc).__name__}: {exc})")
                               for job in futures[future]]
                future.release()
                yield results
        finally:
            client.cancel(list(futures))


def _import_distributed() -> Any:
    try:
        import distributed
    except ImportError:
        raise UsageError("--scheduler needs Dask: install postproc with its dask extra "
                         "(pip install 'postproc[dask]')") from None
    return distributed


def _client(distributed: Any, scheduler: str, jobs: int, stack: contextlib.ExitStack) -> Any:
    """A client of the named scheduler, or of a local cluster of ``jobs`` single-threaded worker
    processes that lives as long as the batch."""
    if scheduler == "local":
        cluster = stack.enter_context(distributed.LocalCluster(
            n_workers=jobs, threads_per_worker=1, processes=True, dashboard_address=None,
            silence_logs=logging.ERROR))
        return stack.enter_context(distributed.Client(cluster, timeout=CONNECT_TIMEOUT))
    try:
        return stack.enter_context(distributed.Client(scheduler, timeout=CONNECT_TIMEOUT))
    except (OSError, TimeoutError, ValueError) as exc:
        raise UsageError(f"--scheduler {scheduler}: cannot connect ({exc})") from None
