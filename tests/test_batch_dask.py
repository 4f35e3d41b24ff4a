"""The batch on Dask: a LocalCluster gives the single-process outputs byte for byte, and a worker killed in
the middle of a batch still leaves every file translated, written whole and reported once.

No timing is assumed anywhere: the kill is triggered by the batch's own progress (the first task to
finish), the commands run to their end, and every wait has a generous timeout for a loaded machine.
"""

from __future__ import annotations

import json
import logging
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

distributed = pytest.importorskip("distributed")
cloudpickle = pytest.importorskip("cloudpickle")

from tests.support import worker_kill  # noqa: E402  (needs distributed)

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples/fanuc").glob("*.nc"))
TIMEOUT = 900
"""Seconds for one batch command (it takes a few; a loaded 2-CPU machine can be many times slower)."""
FILES = 30


@pytest.fixture(scope="module")
def corpus(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """30 programs in three folders (the Fanuc examples under several names)."""
    root = tmp_path_factory.mktemp("corpus") / "progs"
    for n in range(FILES):
        folder = root / f"cell{n % 3}"
        folder.mkdir(parents=True, exist_ok=True)
        shutil.copy(EXAMPLES[n % len(EXAMPLES)], folder / f"o{2000 + n}.nc")
    return root


def translate(*args: object) -> subprocess.CompletedProcess[str]:
    """``postproc translate ARGS`` in its own process (as a user runs it; workers are its children)."""
    command = [sys.executable, "-m", "postproc", "translate", *map(str, args),
               "--from", "fanuc", "--to", "linuxcnc", "--ext", "ngc"]
    return subprocess.run(command, capture_output=True, text=True, timeout=TIMEOUT, cwd=ROOT,
                          env={**os.environ, "HOME": str(Path(str(args[0])).parent)})


def tree(folder: Path) -> dict[str, bytes]:
    """Every file under ``folder`` (temporary ones too: none may be left) by relative path."""
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def single_process(corpus: Path) -> dict[str, bytes]:
    """The outputs of the batch in this machine's single process, the reference."""
    out = corpus.parent / "single"
    result = translate(corpus, "-o", out, "--jobs", "1")
    assert result.returncode == 0, result.stderr
    outputs = tree(out)
    assert len(outputs) == FILES
    return outputs


def report_files(path: Path) -> list[str]:
    lines = [json.loads(line) for line in path.read_text().splitlines()]
    assert {(line["status"], line["exit"]) for line in lines} == {("ok", 0)}, lines
    return sorted(line["file"] for line in lines)


def test_a_local_cluster_writes_what_one_process_writes(corpus, single_process, tmp_path):
    out, report = tmp_path / "out", tmp_path / "report.jsonl"
    result = translate(corpus, "-o", out, "--scheduler", "local", "--jobs", "2", "--files-per-task", "4",
                       "--report", report)
    assert result.returncode == 0, result.stderr
    assert "a Dask LocalCluster of 2 worker processes" in result.stdout
    assert tree(out) == single_process
    assert report_files(report) == sorted(f"{corpus}/cell{n % 3}/o{2000 + n}.nc" for n in range(FILES))


def test_a_worker_killed_mid_batch_loses_no_file_and_repeats_none(corpus, single_process, tmp_path):
    """The first task to finish kills its worker before the scheduler hears of it: distributed runs the
    task again (on the other worker or the restarted one), which writes the same bytes again; the
    report still has each file once and the outputs are exactly the single-process ones."""
    marker = tmp_path / "killed"
    out, report = tmp_path / "out", tmp_path / "report.jsonl"
    cloudpickle.register_pickle_by_value(worker_kill)  # workers need not import the tests
    try:
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                      silence_logs=logging.ERROR) as cluster, \
                distributed.Client(cluster, timeout="120s") as client:
            client.register_plugin(worker_kill.KillOnce(str(marker)))
            result = translate(corpus, "-o", out, "--scheduler", cluster.scheduler_address,
                               "--files-per-task", "1", "--report", report)
            client.wait_for_workers(2, timeout=300)  # the nanny's restart is over before the cluster closes
    finally:
        cloudpickle.unregister_pickle_by_value(worker_kill)
    assert marker.exists(), "no worker was killed: the test did not test anything"
    assert result.returncode == 0, result.stderr
    assert tree(out) == single_process
    assert report_files(report) == sorted(f"{corpus}/cell{n % 3}/o{2000 + n}.nc" for n in range(FILES))
