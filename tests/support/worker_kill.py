"""A Dask worker plugin that kills its worker once, for the test that a batch survives losing a worker.

The first worker to finish a postproc task (its result in the worker's memory, not yet reported to the
scheduler) claims a marker file and kills its own process with SIGKILL: no clean-up, as a machine that
loses power. Claiming the marker with ``O_EXCL`` makes it happen exactly once in the whole cluster,
whichever worker gets there first and however many times workers restart.
"""

from __future__ import annotations

import os
import signal
from typing import Any

from distributed.diagnostics.plugin import WorkerPlugin


class KillOnce(WorkerPlugin):
    """Registered with ``client.register_plugin``; distributed calls ``transition`` on every worker."""

    name = "postproc-kill-once"

    def __init__(self, marker: str) -> None:
        self.marker = marker

    def transition(self, key: Any, start: str, finish: str, **kwargs: Any) -> None:
        if finish != "memory" or not str(key).startswith("postproc-"):
            return
        try:
            fd = os.open(self.marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            return
        os.write(fd, f"{os.getpid()} {key}\n".encode())
        os.close(fd)
        os.kill(os.getpid(), signal.SIGKILL)
