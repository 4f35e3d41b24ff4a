"""``postproc translate`` over many files: the batch mode of the command (docs/cli.md, "Batch").

A batch is several inputs, a folder among them, or any batch option. The single-file
command is untouched: one file (or ``-``) with none of these is translated as before.
"""

from __future__ import annotations

import argparse
import contextlib
import glob
import os
import sys
import uuid
from typing import Generator

from ...errors import UsageError
from ...lowering.arcs import ArcOption
from ...plugins import default_registry
from ...setup.machine_setup import check_named_file, load_setup
from .cluster import run_cluster
from .local import default_jobs, run_local
from .plan import CHUNK_BYTES, CHUNK_FILES, Job, chunks, plan_jobs
from .progress import progress_for
from .report import Report, Tally, messages
from .work import TEMP_PREFIX, FileResult, Options

def run_batch(args: argparse.Namespace, renumber: tuple[int, int | None] | None) -> int:
    """Translate every file; the exit status is the worst file's."""
    outdir = _outdir(args)
    options = _options(args, renumber)
    jobs = plan_jobs(args.input, outdir, ext=args.ext, include=args.include or ())
    report = Report(args.report) if args.report else None
    try:
        os.makedirs(outdir, exist_ok=True)
    except OSError as exc:
        if report is not None:
            report.close()
        raise UsageError(f"cannot write {outdir}: {exc.strerror}") from None
    workers = args.jobs or default_jobs()
    groups = chunks(jobs, CHUNK_BYTES, args.files_per_task or CHUNK_FILES)
    run_id = uuid.uuid4().hex[:12]
    tally = Tally(len(jobs))
    progress = progress_for(len(jobs), sum(job.size for job in jobs), sys.stderr)
    sizes = {job.name: job.size for job in jobs}
    where, runner = _runner(args.scheduler, groups, options, run_id, workers)
    try:
        with contextlib.closing(runner):
            for results in runner:
                for result in results:
                    tally.add(result)
                    if report is not None:
                        report.add(result)
                    for line in messages(result):
                        progress.message(line)
                progress.advance(len(results), sum(r.blocks for r in results), sum(sizes[r.file] for r in results))
    finally:
        progress.clear()
        _sweep({os.path.dirname(job.output) for job in jobs}, run_id)
        if report is not None:
            report.close()
        summary = tally.summary(source=options.source, target=options.target, where=where, report=args.report)
        sys.stdout.flush()
        sys.stdout.buffer.write((summary + "\n").encode("utf-8", "surrogateescape"))  # file names as they are
        sys.stdout.buffer.flush()
    return tally.exit


def _runner(scheduler: str | None, groups: list[list[Job]], options: Options, run_id: str,
            workers: int) -> tuple[str, Generator[list[FileResult], None, None]]:
    """Where the batch runs (for the summary) and the results as they come from there."""
    if scheduler == "local":
        return f"a Dask LocalCluster of {_workers(workers)}", run_cluster(groups, options, run_id, scheduler, workers)
    if scheduler:
        return f"Dask scheduler {scheduler}", run_cluster(groups, options, run_id, scheduler, workers)
    where = "1 job, in this process" if workers == 1 or len(groups) == 1 else _workers(min(workers, len(groups)))
    return where, run_local(groups, options, run_id, workers)


def _workers(count: int) -> str:
    return f"{count} worker process{'es' if count != 1 else ''}"


def _outdir(args: argparse.Namespace) -> str:
    if args.in_place:
        raise UsageError("--in-place replaces one file; a batch writes into the folder -o OUTDIR names")
    if args.output in (None, "-"):
        raise UsageError("a batch (several inputs, a folder, or a batch option) needs -o OUTDIR, a folder")
    outdir: str = args.output
    if os.path.exists(outdir) and not os.path.isdir(outdir):
        raise UsageError(f"-o {outdir}: a batch writes into a folder, and this is a file")
    return outdir


def _options(args: argparse.Namespace, renumber: tuple[int, int | None] | None) -> Options:
    """Check what can be checked once (dialects, set-up, --lib, --define) before any file is read."""
    from ...lowering.sequences import parse_defines
    registry = default_registry()
    registry.dialect(args.source)
    if registry.dialect(args.target).WRITER is None:
        raise UsageError(f"the {args.target} dialect cannot be written (it is read-only)")
    machine = os.path.abspath(args.machine) if args.machine else None
    if machine is not None:
        check_named_file(args.machine)  # as the command line spelt it
        from ...fast.setup_values import plain_record
        load_setup(machine, groups=registry.setup_groups, lane=plain_record)  # a set-up error is the whole batch's (exit 1), found before any file
    for folder in args.lib:
        if not os.path.isdir(folder):
            raise UsageError(f"--lib {folder}: no such directory")
    if args.scheduler and args.scheduler != "local" and "://" not in args.scheduler:
        raise UsageError(f"--scheduler takes 'local' or an address such as tcp://host:8786, got {args.scheduler!r}")
    return Options(source=args.source, target=args.target, machine=machine,
                   lib=tuple(os.path.abspath(folder) for folder in args.lib), on_unsupported=args.on_unsupported,
                   normalize=args.normalize, renumber=renumber, verify=args.verify, tolerance=args.tolerance,
                   allow_ignored=args.allow_ignored, defines=tuple(parse_defines(args.define).items()),
                   units=args.units, transform=args.transform.text if args.transform is not None else None,
                   arcs=_arc_text(args.arcs))


def _arc_text(arcs: ArcOption | None) -> str | None:
    """``--arcs`` back as text (what a worker parses again)."""
    if arcs is None:
        return None
    return f"{arcs.form}:{arcs.tolerance!r}" if arcs.form == "lines" else arcs.form


def _sweep(folders: set[str], run_id: str) -> None:
    """Remove the temporary files of this run that a killed or interrupted worker left behind."""
    for folder in folders:
        for path in glob.glob(os.path.join(glob.escape(folder), f"{TEMP_PREFIX}{run_id}-*")):
            with contextlib.suppress(OSError):
                os.unlink(path)
