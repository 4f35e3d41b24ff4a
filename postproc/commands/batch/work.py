"""What a worker does: translate (and verify) each file of a chunk, and say how it went.

A result is data, never an exception: one file's errors (or a bug of ours it triggers) are that file's
result and the chunk goes on. An output appears only complete: it is written to a temporary file
beside it, named with the run's id (so the batch can sweep away what a killed worker left), and
renamed over the output when the translation (and, with ``--verify``, its verification) succeeded.
Writing is idempotent: a task that runs again (a Dask worker lost after writing) writes the same bytes.
"""

from __future__ import annotations

import functools
import io
import os
import tempfile
import time
from dataclasses import dataclass, field
from typing import Any, Sequence

from ... import api
from ...errors import Diagnostics, ErrorList, PostprocError, UsageError
from ...lowering.arcs import ArcOption, parse_arc_option
from ...output.outfile import BUFFER, ENCODING
from ...plugins import default_registry
from ...setup.machine_setup import MachineSetup, load_setup
from .plan import Job

TEMP_PREFIX = ".postproc-"
"""Temporary outputs are ``.postproc-<run id>-<job number>-<random>`` beside the output."""

EXIT_OK, EXIT_ERRORS, EXIT_USAGE = 0, 1, 2


@dataclass(frozen=True, slots=True)
class Options:
    """Everything a worker needs besides the file (plain data: it travels to other processes and machines)."""

    source: str
    target: str
    machine: str | None = None
    """Absolute path of the set-up, loaded once per worker process."""
    lib: tuple[str, ...] = ()
    on_unsupported: str = "error"
    normalize: bool = False
    renumber: tuple[int, int | None] | None = None
    verify: bool = False
    tolerance: float = 0.001
    allow_ignored: bool = False
    defines: tuple[tuple[str, str], ...] = ()
    """``--define NAME=VALUE`` for the set-up's templates, as (name, value) pairs."""
    units: str | None = None
    """``--units``: every file converted to mm or inch."""
    transform: str | None = None
    """``--transform`` as written (parsed again by each worker: plain text travels)."""
    arcs: str | None = None
    """``--arcs`` as written (``lines:0.01``, ``ijk``, ``r``)."""


@dataclass(slots=True)
class FileResult:
    """How one file went: one line of the report."""

    file: str
    output: str
    status: str
    """``ok``, ``error`` (the program has errors), ``verify`` (the translation failed verification),
    ``usage`` (cannot be read or written), ``internal`` (a bug of ours, or the cluster gave up on it)."""
    exit: int
    warnings: list[str] = field(default_factory=list)
    errors: list[str] = field(default_factory=list)
    max_deviation: float | None = None
    verify: str | None = None
    """The verification's summary (first line and what it did not compare), with ``--verify``."""
    blocks: int = 0
    seconds: float = 0.0

    def as_json(self) -> dict[str, Any]:
        return {"file": self.file, "output": self.output, "status": self.status, "exit": self.exit,
                "warnings": self.warnings, "errors": self.errors, "max_deviation": self.max_deviation,
                "verify": self.verify, "blocks": self.blocks, "seconds": round(self.seconds, 6)}


def run_chunk(jobs: Sequence[Job], options: Options, run_id: str) -> list[FileResult]:
    """Translate each job of a chunk (a worker's task)."""
    return [run_job(job, options, run_id) for job in jobs]


def run_job(job: Job, options: Options, run_id: str) -> FileResult:
    """Translate one file into its output; every failure becomes the result."""
    start = time.perf_counter()
    result = FileResult(job.name, job.output_name, "ok", EXIT_OK)
    try:
        _translate(job, options, run_id, result)
    except ErrorList as errs:
        _failed(result, "error", EXIT_ERRORS, [str(e) for e in errs.errors] + [f"postproc: {n}" for n in errs.notes])
    except UsageError as err:
        _failed(result, "usage", EXIT_USAGE, [f"postproc: {err.message}"])
    except PostprocError as err:
        _failed(result, "error", EXIT_ERRORS, [str(err)])
    except OSError as exc:
        _failed(result, "usage", EXIT_USAGE, [f"postproc: {job.name}: {exc.strerror or exc}"])
    except Exception as exc:  # a bug of ours: this file's result, never the batch's end
        _failed(result, "internal", EXIT_ERRORS, [f"postproc: internal error: {type(exc).__name__}: {exc}"])
    result.blocks = _lines(job.path)
    result.seconds = time.perf_counter() - start
    return result


def _failed(result: FileResult, status: str, code: int, errors: list[str]) -> None:
    result.status, result.exit = status, code
    result.errors.extend(errors)


def _translate(job: Job, options: Options, run_id: str, result: FileResult) -> None:
    setup = _setup(options)
    folder = os.path.dirname(job.output)
    if os.path.isdir(job.output):
        raise UsageError(f"cannot write {job.output_name}: it is a directory")
    try:
        src = open(job.path, "r", buffering=BUFFER, **ENCODING)  # type: ignore[call-overload]
    except OSError as exc:
        raise UsageError(f"cannot read {job.name}: {exc.strerror}") from None
    try:
        os.makedirs(folder, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f"{TEMP_PREFIX}{run_id}-{job.number}-", dir=folder)
    except OSError as exc:
        src.close()
        raise UsageError(f"cannot write {job.output_name}: {exc.strerror}") from None
    try:
        diagnostics = Diagnostics(warn_stream=io.StringIO())
        try:
            with src, os.fdopen(fd, "w", buffering=BUFFER, **ENCODING) as out:  # type: ignore[call-overload]
                api.translate(src, out, file=job.name, source=options.source, target=options.target,
                              setup=setup, on_unsupported=options.on_unsupported, diagnostics=diagnostics,
                              defines=dict(options.defines), units=options.units, transform=options.transform,
                              arcs=_arcs(options))
        finally:
            result.warnings.extend(str(w) for w in diagnostics.warnings)
        if options.verify and not _verified(job, tmp, options, result):
            return
        os.chmod(tmp, 0o666 & ~_UMASK)
        os.replace(tmp, job.output)
    finally:
        if os.path.lexists(tmp):
            os.unlink(tmp)


def _verified(job: Job, tmp: str, options: Options, result: FileResult) -> bool:
    """Verify the finished temporary output against the input; a failure is the file's result."""
    from ...simulate.verify import verify_lines
    from ...transforms.spec import parse_transform
    arcs = _arcs(options)
    with open(job.path, "r", **ENCODING) as a, open(tmp, "r", **ENCODING) as b:  # type: ignore[call-overload]
        report = verify_lines(a, b, file_in=job.name, file_out=job.output_name, source=options.source,
                              target=options.target, setup=_setup(options), tolerance=options.tolerance,
                              allow_ignored=options.allow_ignored,
                              transform=parse_transform(options.transform) if options.transform else None,
                              chord_tolerance=arcs.tolerance if arcs is not None and arcs.form == "lines" else None)
    result.max_deviation = report.max_deviation
    result.verify = report.summary()
    if not report.ok:
        _failed(result, "verify", EXIT_ERRORS,
                [f"postproc: {job.name}: verification failed, not written: {report.summary().splitlines()[0]}"])
    return report.ok


def _arcs(options: Options) -> ArcOption | None:
    return parse_arc_option(options.arcs) if options.arcs else None


@functools.lru_cache(maxsize=4)
def _setup(options: Options) -> MachineSetup:
    """The set-up, loaded once per worker process (the client has already checked it loads)."""
    from ...fast.setup_values import plain_record  # the set-up lane, as the single-file command has it
    setup = load_setup(options.machine, groups=default_registry().setup_groups, lane=plain_record) \
        if options.machine else MachineSetup()
    setup.library.extend(options.lib)
    if options.normalize:  # as the single-file command does (its outputs and ours are the same bytes)
        setup.output.normalize = True
    if options.renumber:
        from ..renumbering import apply_renumber
        apply_renumber(setup.output, options.renumber, options.source, options.target)
    return setup


def _lines(path: str) -> int:
    """How many lines (blocks) the input has, for blocks/s (a fast pass over bytes already cached)."""
    count, last = 0, b"\n"
    try:
        with open(path, "rb") as f:
            while chunk := f.read(BUFFER):
                count += chunk.count(b"\n")
                last = chunk[-1:]
    except OSError:
        return 0
    return count + (last != b"\n")


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


_UMASK = _umask()
"""Read once at import (``os.umask`` sets it while reading: not something to do in a thread per file)."""

