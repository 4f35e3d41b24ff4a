"""Batch translation: many programs, or whole folders, into an output folder.

``plan`` turns the command line's inputs into jobs (input, output, size) and refuses what cannot work
before any file is touched; ``work`` translates (and verifies) one chunk of jobs in a worker;
``local`` runs the chunks in this process or a process pool; ``cluster`` on a Dask cluster;
``report`` writes the JSON lines report and the summary; ``command`` is the ``translate`` command's
batch mode. One file's failure is that file's result, never the batch's.
"""

from .. import native
native.install()  # the compiled hot path, before any of its modules is imported
