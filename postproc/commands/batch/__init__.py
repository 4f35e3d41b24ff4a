"""Batch translation: many programs, or whole folders, into an output folder.

``plan`` turns the command line's inputs into jobs (input, output, size) and refuses what cannot work
before any file is touched; ``work`` translates (and verifies) one chunk of jobs in a worker;
``local`` runs the chunks in this process or a process pool; ``cluster`` on a Dask cluster;
``report`` writes the JSON lines report and the summary; ``command`` is the ``translate`` command's
batch mode. One file's failure is that file's result, never the batch's.

Only ``is_batch`` lives here: the single-file command asks it and imports none of the batch machinery.
"""

from __future__ import annotations

import argparse
import os

from ... import native

native.install()  # the compiled hot path, before any of its modules is imported

BATCH_OPTIONS = ("jobs", "report", "verify", "scheduler", "ext", "include", "files_per_task")
"""Options that only a batch has: any of them makes the command a batch."""


def is_batch(args: argparse.Namespace) -> bool:
    """Several inputs, a folder among them, or a batch option. (``-o`` naming a folder is not enough:
    for one file that stays the usage error the single-file contract says it is.)"""
    inputs: list[str] = args.input
    return (len(inputs) > 1 or any(path != "-" and os.path.isdir(path) for path in inputs)
            or any(getattr(args, name) not in (None, False, []) for name in BATCH_OPTIONS))
