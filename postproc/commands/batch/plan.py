"""From the command line's inputs to jobs: which files, written where, in which chunks.

Everything that would make the batch write the wrong file is refused here, before any file is read:
an output folder that is an input folder, two inputs that would be written to one output, an output
that is its own input. Files inside the output folder are not inputs (a second run over a folder that
holds its own output folder does not translate its previous output).
"""

from __future__ import annotations

import fnmatch
import os
from dataclasses import dataclass
from typing import Iterator, Sequence

from ...errors import UsageError


@dataclass(frozen=True, slots=True)
class Job:
    """One file to translate."""

    path: str
    """Absolute path of the input (workers on other machines see the same shared path)."""
    name: str
    """The input as messages and the report name it: the user's spelling of the folder, then the
    relative path."""
    output: str
    """Absolute path of the output."""
    output_name: str
    size: int
    """Bytes, for the progress bar's estimate and for balancing chunks."""
    number: int = 0
    """Its place in the batch (0, 1, ...): names its temporary output, so a broken pool can tell which
    files were being translated (``local``)."""


CHUNK_BYTES = 256 << 10
"""A chunk (one task for a worker) holds files up to about this many bytes..."""
CHUNK_FILES = 32
"""...and at most this many: small programs share a task (less per-task overhead), a large one has
its own."""


def plan_jobs(inputs: Sequence[str], outdir: str, *, ext: str | None = None,
              include: Sequence[str] = ()) -> list[Job]:
    """The jobs for ``inputs`` (files and folders) written under ``outdir``, keeping each file's path
    relative to the folder it was found in (a file named directly keeps its name). ``ext`` replaces
    the last suffix of each output's name (or adds one); None keeps the name. ``include``: shell
    patterns a file found in a folder must match (by name); files named directly are always taken."""
    if not inputs:
        raise UsageError("no input given")
    out_real = os.path.realpath(outdir)
    jobs: list[Job] = []
    by_output: dict[str, Job] = {}
    for given in inputs:
        for path, rel in _files(given, out_real, include):
            out_rel = _with_ext(rel, ext)
            output = os.path.join(out_real, out_rel)
            job = Job(path=os.path.abspath(path), name=os.path.join(given, rel) if os.path.isdir(given) else given,
                      output=output, output_name=os.path.join(outdir, out_rel), size=_size(path),
                      number=len(jobs))
            if os.path.realpath(job.path) == output:
                raise UsageError(f"-o {outdir} would overwrite the input {job.name} with its translation")
            other = by_output.get(output)
            if other is not None:
                raise UsageError(f"{other.name} and {job.name} would both be written to {job.output_name}")
            by_output[output] = job
            jobs.append(job)
    if not jobs:
        raise UsageError(f"no files to translate in {', '.join(inputs)}")
    return jobs


def _files(given: str, out_real: str, include: Sequence[str]) -> Iterator[tuple[str, str]]:
    """(path, path relative to ``given``) of every file ``given`` names, in a stable order."""
    if given == "-":
        raise UsageError("'-' (standard input) cannot be one of several inputs; name the files")
    if os.path.isfile(given):
        yield given, os.path.basename(given)
        return
    if not os.path.isdir(given):
        raise UsageError(f"cannot read {given}: no such file or directory")
    if os.path.realpath(given) == out_real:
        raise UsageError(f"-o {given}: the output folder cannot be an input folder")
    for folder, dirs, names in os.walk(given, onerror=_unreadable):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".")
                         and os.path.realpath(os.path.join(folder, d)) != out_real)
        for name in sorted(names):
            path = os.path.join(folder, name)
            if name.startswith(".") or not os.path.isfile(path):
                continue  # hidden files (editors', ours in progress) and what is not a regular file
            if include and not any(fnmatch.fnmatchcase(name, pattern) for pattern in include):
                continue
            yield path, os.path.relpath(path, given)


def _unreadable(err: OSError) -> None:
    raise UsageError(f"cannot read {err.filename}: {err.strerror}")


def _with_ext(rel: str, ext: str | None) -> str:
    if ext is None:
        return rel
    head, name = os.path.split(rel)
    stem, dot, _ = name.rpartition(".")
    base = stem if dot and stem else name  # ".nc" alone is a name, not a suffix
    return os.path.join(head, base + ("." + ext.lstrip(".") if ext.strip(".") else ""))


def _size(path: str) -> int:
    try:
        return os.stat(path).st_size
    except OSError:
        return 0  # reported when the worker cannot read it


def chunks(jobs: Sequence[Job], max_bytes: int = CHUNK_BYTES, max_files: int = CHUNK_FILES) -> list[list[Job]]:
    """Consecutive jobs grouped into tasks, the largest tasks first (they would otherwise finish last
    and leave the other workers idle)."""
    groups: list[list[Job]] = []
    current: list[Job] = []
    size = 0
    for job in jobs:
        if current and (size + job.size > max_bytes or len(current) >= max_files):
            groups.append(current)
            current, size = [], 0
        current.append(job)
        size += job.size
    if current:
        groups.append(current)
    groups.sort(key=lambda group: -sum(job.size for job in group))
    return groups
