"""Batch translation: files/s on many small programs and blocks/s on a few large ones, at 1 and 2 jobs,
each as a ratio against the single-file command run once per file (a shell loop), measured in the same run.

Usage: python benchmarks/batch.py [--quick] [--cache DIR] [--to DIALECT]

Full size: 10,000 programs of 100-149 blocks (the shell loop is timed on the first 200 of them: at
~0.3 s a start it would take most of an hour on all) and 20 programs of 50,000-50,019 blocks. ``--quick``:
500 small and 4 large of about 10,000 blocks, for development. Each measurement is one process (start-up
included), timed by wall clock; figures are printed, never asserted.
"""
from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import generate  # noqa: E402

FULL = {"small": 10_000, "small_blocks": 100, "loop_sample": 200, "large": 20, "large_blocks": 50_000}
QUICK = {"small": 500, "small_blocks": 100, "loop_sample": 50, "large": 4, "large_blocks": 10_000}
TINY = {"small": 6, "small_blocks": 100, "loop_sample": 2, "large": 2, "large_blocks": 300}
"""Only for the harness's own test (tests/test_bench_harness.py): figures this small measure start-up."""
SIZES = {"full": FULL, "quick": QUICK, "tiny": TINY}
PER_FOLDER = 1000
"""Small programs are spread over folders of this many (as a program library is)."""


@dataclass
class Result:
    name: str
    files: int
    blocks: int
    seconds: float | None
    note: str = ""

    @property
    def files_per_s(self) -> float | None:
        return self.files / self.seconds if self.seconds else None

    @property
    def blocks_per_s(self) -> float | None:
        return self.blocks / self.seconds if self.seconds else None


def corpus(cache: Path, kind: str, count: int, blocks: int) -> Path:
    """``count`` generated programs of ``blocks`` to ``blocks + 49`` blocks each, cached between runs.

    All are cut from generate.py's one program (its default seed: other seeds can start with a feed move
    that has no feed rate yet, an error), each a different length, so no two files are the same."""
    digest = f"{kind}-{count}x{blocks}-cut-{os.path.getmtime(generate.__file__):.0f}"
    folder = cache / digest
    if folder.is_dir():
        return folder
    for stale in cache.glob(f"{kind}-*"):
        shutil.rmtree(stale)
    tmp = cache / (digest + ".tmp")
    shutil.rmtree(tmp, ignore_errors=True)
    for n in range(count):
        sub = tmp / f"lib{n // PER_FOLDER:02}"
        sub.mkdir(parents=True, exist_ok=True)
        with open(sub / f"O{1000 + n}.nc", "w", encoding="ascii", newline="\n") as out:
            generate.write(blocks + n % 50, out)
    tmp.rename(folder)
    return folder


def files_of(folder: Path) -> list[Path]:
    return sorted(p for p in folder.rglob("*.nc"))


def timed(cmd: list[str]) -> tuple[float | None, str]:
    """Wall seconds of one process (None and the last error line if it fails)."""
    start = time.perf_counter()
    done = subprocess.run(cmd, cwd=ROOT, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                          stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - start
    # exit 1 only for programs with errors, which the generated ones do not have
    if done.returncode != 0:
        return None, (done.stderr.strip().splitlines() or ["?"])[-1][:90]
    return seconds, ""


def single_file_loop(files: list[Path], out: Path, target: str) -> float | None:
    """The baseline: the single-file command once per file, one after another (as a shell loop)."""
    out.mkdir(parents=True, exist_ok=True)
    total = 0.0
    for path in files:
        seconds, err = timed([sys.executable, "-m", "postproc", "translate", str(path), "-o",
                              str(out / path.name), "--from", "fanuc", "--to", target])
        if seconds is None:
            print(f"  single-file command failed on {path}: {err}")
            return None
        total += seconds
    return total


def batch(folder: Path, out: Path, target: str, jobs: int) -> tuple[float | None, str]:
    shutil.rmtree(out, ignore_errors=True)
    return timed([sys.executable, "-m", "postproc", "translate", str(folder), "-o", str(out),
                  "--from", "fanuc", "--to", target, "--jobs", str(jobs)])


def measure(sizes: dict[str, int], cache: Path, target: str) -> list[tuple[str, list[Result]]]:
    small = corpus(cache, "small", sizes["small"], sizes["small_blocks"])
    large = corpus(cache, "large", sizes["large"], sizes["large_blocks"])
    tables = []
    with tempfile.TemporaryDirectory() as work:
        out = Path(work)
        for label, folder, sample in (("small", small, sizes["loop_sample"]), ("large", large, sizes["large"])):
            files = files_of(folder)
            blocks = sum(lines(path) for path in files)
            chosen = files[:sample]
            loop = single_file_loop(chosen, out / "loop", target)
            rows = [Result(f"single-file command x {len(chosen)}", len(chosen), sum(lines(path) for path in chosen),
                           loop, "baseline" + ("" if len(chosen) == len(files) else f" (first {len(chosen)} files)"))]
            for jobs in (1, 2):
                seconds, err = batch(folder, out / "batch", target, jobs)
                rows.append(Result(f"batch --jobs {jobs}", len(files), blocks, seconds, err))
            size = generate_blocks(label, sizes)
            tables.append((f"{len(files):,} programs of {size:,}-{size + 49:,} blocks", rows))
    return tables


def generate_blocks(label: str, sizes: dict[str, int]) -> int:
    return sizes[f"{label}_blocks"]


def lines(path: Path) -> int:
    with open(path, "rb") as f:
        return sum(chunk.count(b"\n") for chunk in iter(lambda: f.read(1 << 20), b""))


def fmt(value: float | None, spec: str) -> str:
    return "-" if value is None else format(value, spec)


def print_tables(tables: list[tuple[str, list[Result]]], target: str) -> None:
    print(f"batch translate fanuc -> {target} on {os.cpu_count()} CPUs (wall time of one process per row, "
          "start-up included; the baseline runs the single-file command once per file)")
    for title, rows in tables:
        base = rows[0]
        print(f"\n{title}")
        print(f"{'run':<32} {'files':>7} {'seconds':>8} {'files/s':>9} {'blocks/s':>10} {'x baseline':>10}  note")
        for row in rows:
            ratio = row.files_per_s / base.files_per_s if row.files_per_s and base.files_per_s else None
            print(f"{row.name:<32} {row.files:>7} {fmt(row.seconds, '.2f'):>8} {fmt(row.files_per_s, ',.1f'):>9} "
                  f"{fmt(row.blocks_per_s, ',.0f'):>10} {fmt(ratio, '.2f'):>10}  {row.note}")
        one, two = rows[1], rows[2]
        if one.seconds and two.seconds:
            print(f"{'--jobs 2 / --jobs 1':<32} {'':>7} {'':>8} {'':>9} {'':>10} {one.seconds / two.seconds:>10.2f}")


def run(size: str, cache: Path, target: str = "linuxcnc") -> list[tuple[str, list[Result]]]:
    """Measure and print the batch tables at `size` (full, quick or tiny); return them."""
    cache.mkdir(parents=True, exist_ok=True)
    tables = measure(SIZES[size], cache, target)
    print_tables(tables, target)
    return tables


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a small corpus, for development")
    parser.add_argument("--cache", type=Path, default=Path(tempfile.gettempdir()) / "postproc-bench",
                        help="where generated programs are kept between runs")
    parser.add_argument("--to", default="linuxcnc", help="target dialect (default linuxcnc)")
    args = parser.parse_args()
    run("quick" if args.quick else "full", args.cache, args.to)


if __name__ == "__main__":
    main()
