"""Throughput and peak memory of ``postproc translate`` against peers and a plain loop.

Usage: python benchmarks/run.py [--sizes 100000 1000000] [--cache DIR] [--pygcode-max N] [--batch full|quick|skip]

Every measured program runs in its own process; its wall time and peak RSS come from
os.wait4 in a minimal launcher.  Figures are printed, never asserted.
"""
from __future__ import annotations

import argparse
import hashlib
import os
import platform
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import generate  # noqa: E402
from peers import NOT_INSTALLED, PARTIAL, TOOLS, fanuc_decimals_copy  # noqa: E402

OURS = "postproc"
PLAIN = "plain loop"
TARGET_PEER, TARGET_PLAIN, TARGET_RSS_MB, TARGET_RSS_BLOCKS = 1.5, 0.8, 64.0, 1_000_000


@dataclass
class Row:
    """One measured (or extrapolated, or failed) tool at one program size."""

    tool: str
    blocks: int
    seconds: float | None = None
    cpu: float | None = None
    rss_mb: float | None = None
    notes: list[str] = field(default_factory=list)

    @property
    def rate(self) -> float | None:
        return self.blocks / self.seconds if self.seconds else None


# Peak RSS must come from a process that is not run.py's own child: a child's ru_maxrss
# starts at its parent's high-water mark (the kernel keeps it across fork/vfork + exec).
# So a bare interpreter (-S, about 8 MB) spawns the tool and reports wait4's figures.
SPAWN = """import os, sys, time
start = time.perf_counter()
pid = os.posix_spawnp(sys.argv[2], sys.argv[2:], os.environ)
_, status, usage = os.wait4(pid, 0)
seconds = time.perf_counter() - start
with open(sys.argv[1], "w") as out:
    cpu = usage.ru_utime + usage.ru_stime
    out.write(f"{os.waitstatus_to_exitcode(status)} {seconds} {cpu} {usage.ru_maxrss}")
"""


def run_once(cmd: list[str]) -> tuple[int, float, float, float, str]:
    """Run cmd in its own process: (exit code, wall s, CPU s, peak RSS MB, stderr tail)."""
    with tempfile.TemporaryDirectory() as tmp:
        result, err = Path(tmp, "result"), Path(tmp, "stderr")
        with open(err, "wb") as err_file:
            subprocess.run([sys.executable, "-S", "-c", SPAWN, str(result), *cmd], cwd=ROOT,
                           stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                           stderr=err_file, check=True)
        code, seconds, cpu, rss_kb = result.read_text().split()
        lines = err.read_text(errors="replace").strip().splitlines()
    tail = lines[-1].removeprefix(f"{cmd[0]}: ") if lines else ""
    return int(code), float(seconds), float(cpu), int(rss_kb) / 1024, tail


def measure(tool: str, cmd: list[str], blocks: int, repeats: int) -> Row:
    """The run with the best wall time of `repeats` runs; peak RSS is the largest seen."""
    row = Row(tool, blocks)
    for _ in range(repeats):
        code, seconds, cpu, rss_mb, err = run_once(cmd)
        if (code == NOT_INSTALLED and tool in TOOLS) or err.endswith(f"No module named {OURS}"):
            return Row(tool, blocks, notes=["not installed"])
        if code != 0:
            return Row(tool, blocks, notes=[f"failed (exit {code}): {err[:90]}"])
        if row.seconds is None or seconds < row.seconds:
            row.seconds, row.cpu = seconds, cpu
        row.rss_mb = max(row.rss_mb or 0.0, rss_mb)
    if repeats > 1:
        row.notes.append(f"best of {repeats}")
    return row


def program(blocks: int, cache: Path) -> Path:
    """The cached generated program of `blocks` blocks (regenerated when generate.py changes)."""
    digest = hashlib.sha1(Path(generate.__file__).read_bytes()).hexdigest()[:10]
    path = cache / f"fanuc-{blocks}-{digest}.nc"
    if not path.exists():
        for stale in cache.glob(f"fanuc-{blocks}-*.nc"):  # from an older generate.py
            stale.unlink()
        tmp = path.with_suffix(".tmp")
        with open(tmp, "w", encoding="ascii", newline="\n") as out:
            generate.write(blocks, out)
        tmp.replace(path)
    return path


def gcodeparser_copy(src: Path) -> Path:
    """The cached ``Z0.`` -> ``Z0.0`` copy gcodeparser needs (made before any timing)."""
    path = src.with_name(src.stem + "-gcodeparser.nc")
    if not path.exists():
        fanuc_decimals_copy(str(src), str(path))
    return path


def bench_size(blocks: int, cache: Path, work: Path, pygcode_max: int,
               pygcode_rows: dict[int, Row]) -> list[Row]:
    """All rows for one program size."""
    src = program(blocks, cache)
    repeats = 2 if blocks < 1_000_000 else 1
    py = sys.executable
    rows = []
    for tool in TOOLS:
        if tool == "pygcode" and blocks > pygcode_max:
            rows.append(extrapolate(pygcode_rows, blocks))
            continue
        path = gcodeparser_copy(src) if tool == "gcodeparser" else src
        row = measure(tool, [py, str(HERE / "peers.py"), tool, str(path)], blocks, repeats)
        if tool == "gcodeparser" and row.seconds:
            row.notes.append("Z0.->Z0.0 copy, drops modal blocks")
        if tool == "pygcode":
            pygcode_rows[blocks] = row
        rows.append(row)
    out = work / "out.nc"
    rows.append(measure(PLAIN, [py, str(HERE / "plainloop.py"), str(src), str(out)],
                        blocks, repeats))
    rows.append(measure(OURS, [py, "-m", "postproc", "translate", str(src), "-o", str(out),
                               "--from", "fanuc", "--to", "fanuc", "--normalize"],
                        blocks, repeats))
    out.unlink(missing_ok=True)
    return rows


def extrapolate(measured: dict[int, Row], blocks: int) -> Row:
    """pygcode at `blocks`, scaled by blocks/s from its largest measured size."""
    usable = [row for row in measured.values() if row.rate]
    if not usable:
        notes = next(iter(measured.values())).notes if measured else ["not measured"]
        return Row("pygcode", blocks, notes=notes)
    base = max(usable, key=lambda row: row.blocks)
    scale = blocks / base.blocks
    return Row("pygcode", blocks, base.seconds * scale, base.cpu * scale, base.rss_mb,
               [f"extrapolated from {base.blocks} blocks (blocks/s and RSS)"])


def fmt(value: float | None, spec: str) -> str:
    return "-" if value is None else format(value, spec)


def print_table(rows: list[Row]) -> None:
    """Print one size's rows with ratios against the fastest peer and the plain loop."""
    peers = [row for row in rows if row.tool in TOOLS and row.rate]
    fastest = max(peers, key=lambda row: row.rate) if peers else None
    plain = next((row for row in rows if row.tool == PLAIN and row.rate), None)
    print(f"{'tool':<12} {'blocks':>9} {'seconds':>8} {'cpu s':>6} {'blocks/s':>10} "
          f"{'x fastest peer':>14} {'x plain loop':>12} {'peak RSS MB':>11}  note")
    for row in rows:
        vs_peer = row.rate / fastest.rate if row.rate and fastest else None
        vs_plain = row.rate / plain.rate if row.rate and plain else None
        print(f"{row.tool:<12} {row.blocks:>9} {fmt(row.seconds, '.2f'):>8} "
              f"{fmt(row.cpu, '.2f'):>6} {fmt(row.rate, ',.0f'):>10} {fmt(vs_peer, '.2f'):>14} "
              f"{fmt(vs_plain, '.2f'):>12} {fmt(row.rss_mb, '.1f'):>11}  {'; '.join(row.notes)}")
    full = [row for row in peers if row.tool not in PARTIAL]
    fastest_full = max(full, key=lambda row: row.rate) if full else None
    ours = next(row for row in rows if row.tool == OURS)
    print_targets(ours, fastest, fastest_full, plain)


def verdict(value: float | None, ok: bool) -> str:
    return "n/a" if value is None else ("PASS" if ok else "MISS")


def print_targets(ours: Row, fastest: Row | None, fastest_full: Row | None,
                  plain: Row | None) -> None:
    """The issue's targets for translate, as PASS/MISS (never asserted)."""
    vs_peer = ours.rate / fastest.rate if ours.rate and fastest else None
    vs_plain = ours.rate / plain.rate if ours.rate and plain else None
    name = fastest.tool if fastest else "none"
    print(f"targets for {OURS} at {ours.blocks} blocks:")
    print(f"  translate >= {TARGET_PEER}x fastest peer parse ({name}): "
          f"{fmt(vs_peer, '.2f')}x  {verdict(vs_peer, (vs_peer or 0) >= TARGET_PEER)}")
    if fastest_full is not None and fastest_full is not fastest and ours.rate:
        print(f"    (info: {ours.rate / fastest_full.rate:.2f}x the fastest peer that parses "
              f"every block, {fastest_full.tool})")
    print(f"  translate >= {TARGET_PLAIN}x plain loop: "
          f"{fmt(vs_plain, '.2f')}x  {verdict(vs_plain, (vs_plain or 0) >= TARGET_PLAIN)}")
    if ours.blocks >= TARGET_RSS_BLOCKS:
        rss = ours.rss_mb
        print(f"  peak RSS < {TARGET_RSS_MB:.0f} MB at {TARGET_RSS_BLOCKS} blocks: "
              f"{fmt(rss, '.1f')} MB  {verdict(rss, (rss or 1e9) < TARGET_RSS_MB)}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100_000, 1_000_000])
    parser.add_argument("--cache", type=Path,
                        default=Path(tempfile.gettempdir()) / "postproc-bench",
                        help="where generated programs are kept between runs")
    parser.add_argument("--pygcode-max", type=int, default=100_000,
                        help="larger sizes extrapolate pygcode from its largest measured size")
    parser.add_argument("--batch", choices=("full", "quick", "skip"), default="full",
                        help="batch files/s and blocks/s (benchmarks/batch.py): full size, --quick size, or none")
    args = parser.parse_args()
    args.cache.mkdir(parents=True, exist_ok=True)
    print(f"python {platform.python_version()} on {platform.machine()}, {os.cpu_count()} CPUs; "
          "seconds = wall time of one process per tool (start-up, imports and I/O included), "
          "blocks/s from it; cpu s = user+sys of that process")
    pygcode_rows: dict[int, Row] = {}
    with tempfile.TemporaryDirectory() as work:
        for blocks in sorted(args.sizes):
            print()
            print_table(bench_size(blocks, args.cache, Path(work), args.pygcode_max, pygcode_rows))
    if args.batch != "skip":
        import batch
        print()
        batch.run(args.batch == "quick", args.cache)


if __name__ == "__main__":
    main()
