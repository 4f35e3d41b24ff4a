"""``make bench``: postproc against peers and baselines measured in the same run, as ratios, with the
targets of issue 30 marked PASS/MISS.

Usage: python benchmarks/run.py [--quick] [--rows ROW ...] [--sizes N ...] [--runs R] [--holes H]
                                [--macro-holes H] [--cache DIR] [--pygcode-max N] [--batch full|quick|tiny|skip]

Rows: translate fanuc->fanuc/grbl/grblhal/linuxcnc/isg/fagor (every lowering target, the lossless copy and --normalize) against gcode-lib's parse and a plain streaming
loop, toolpath and verify against gcode-lib's position tracking, peak memory and its growth with program
length (at each of --sizes); canned-cycle holes/s and a parametric loop's interpreted blocks/s against the plain loop over
their output; start-up against a bare interpreter; batch files/s (benchmarks/batch.py). Every measured
command is its own process (wall time, CPU and peak RSS from os.wait4); commands compared with each
other run interleaved in rounds, a figure is the median of --runs rounds. Printed, never asserted.
``--quick``: small sizes and one round, for development; ``--rows``: only some rows, each with the
baselines it is compared with (``ROWS``). What each row means: docs/benchmarks.md.
"""
from __future__ import annotations

import argparse
import compileall
import io
import os
import platform
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import batch  # noqa: E402
import generate  # noqa: E402
import workloads  # noqa: E402
from peers import PARSERS, PARTIAL, fanuc_decimals_copy  # noqa: E402
from summary import (FLAT_TARGET, PLAIN_TARGET, RSS_TARGET_MB, TOOLPATH_TARGET, VERIFY_TARGET, Line,  # noqa: E402
                     Target, at_least_x, print_summary)
from timing import Runs, paired_ratio, rate, rounds  # noqa: E402
from translations import TRANSLATIONS  # noqa: E402
from workloads import PLAIN, PY, at_least_lines, cached, prepare, translate  # noqa: E402

PEERS = [PY, str(HERE / "peers.py")]
MACHINE = HERE / "machine.xml"
"""The tools of the generated programs (their G43 H01-H03): toolpath and verify simulate the lengths."""
ROWS: dict[str, tuple[str, ...]] = {
    **{row: (t.label, "gcode-lib") + (("plain loop",) if row == "normalize" else ()) for row, t in TRANSLATIONS.items()},
    "toolpath": ("toolpath --format jsonl", "gcode-lib-state"),
    "verify": ("verify fanuc / linuxcnc", "gcode-lib-state x 2 files"),
    "peers": ("gcode-lib", "gcodeparser", "pygcode", "plain loop"),
    "cycles": (), "macro": (), "startup": (), "batch": (),
}
"""``--rows`` names -> the commands of a CAM program size each needs (its own and its baselines, run in the
same rounds); the last four are workloads of their own."""
POSTPROC_LABELS = [t.label for t in TRANSLATIONS.values()] + ["toolpath --format jsonl", "verify fanuc / linuxcnc"]
"""The postproc commands of a CAM program size, whose peak RSS is bounded and must stay flat."""


def size_commands(blocks: int, src: Path, work: Path, pygcode_max: int,
                  rows: set[str] | None = None) -> dict[str, list[str]]:
    """Every command measured at one program size (only those ``rows`` need, when given), in the order a
    round runs them."""
    prepared = work / "verify-input.ngc"
    commands: dict[str, list[str]] = {}
    for tool in PARSERS:
        if tool == "pygcode" and blocks > pygcode_max:
            continue
        path = gcodeparser_copy(src) if tool == "gcodeparser" else src
        commands[tool] = [*PEERS, tool, str(path)]
    commands["plain loop"] = [*PLAIN, str(src), str(work / "plain.out")]
    for row, t in TRANSLATIONS.items():
        commands[t.label] = translate(src, work / f"out.{row}", "fanuc", t.target, *t.options(MACHINE))
    commands["gcode-lib-state"] = [*PEERS, "gcode-lib-state", str(src)]
    commands["toolpath --format jsonl"] = [*workloads.postproc(), "toolpath", str(src), "--dialect", "fanuc",
                                           "--machine", str(MACHINE), "--format", "jsonl",
                                           "-o", str(work / "toolpath.jsonl")]
    commands["gcode-lib-state x 2 files"] = [*PEERS, "gcode-lib-state", str(src), str(prepared)]
    commands["verify fanuc / linuxcnc"] = [*workloads.postproc(), "verify", str(src), str(prepared),
                                           "--from", "fanuc", "--to", "linuxcnc", "--machine", str(MACHINE)]
    if rows is None:
        return commands
    needed = {label for row in rows for label in ROWS[row]}
    return {label: cmd for label, cmd in commands.items() if label in needed}


def gcodeparser_copy(src: Path) -> Path:
    """The cached ``Z0.`` -> ``Z0.0`` copy gcodeparser needs (made before any timing)."""
    path = src.with_name(src.stem + "-gcodeparser.nc")
    if not path.exists():
        fanuc_decimals_copy(str(src), str(path))
    return path


def bench_size(blocks: int, cache: Path, work: Path, runs: int, pygcode_max: int,
               rows: set[str] | None = None) -> dict[str, Runs]:
    """Measure every command at one size (those of ``rows``, when given; the input of verify is prepared
    first, untimed)."""
    src = cached(cache, f"fanuc-{blocks}", lambda: generate.blocks(blocks))
    commands = size_commands(blocks, src, work, pygcode_max, rows)
    if "gcode-lib-state x 2 files" in commands:
        note = prepare(translate(src, work / "verify-input.ngc", "fanuc", "linuxcnc"))
        if note:
            print(f"preparing verify's input failed: {note}")
    outputs = {t.label: (work / f"out.{row}", blocks - 2) for row, t in TRANSLATIONS.items()}
    results = rounds(commands, runs, at_least_lines(outputs))
    gcode_lib, plain = results.get("gcode-lib"), results.get("plain loop")
    print(f"\n{blocks:,}-block CAM program (units = its blocks; x gcode-lib and x plain loop: paired ratios)")
    print(f"{'command':<34} {'seconds':>8} {'cpu s':>6} {'blocks/s':>10} {'x gcode-lib':>11} "
          f"{'x plain loop':>12} {'peak RSS MB':>11}  note")
    for label, entry in results.items():
        vs_lib = paired_ratio(entry, gcode_lib) if gcode_lib else None
        note = entry.note or ("drops modal blocks (Z0.->Z0.0 copy)" if label in PARTIAL else "")
        print(f"{label:<34} {fmt(entry.seconds, '.2f'):>8} {fmt(entry.cpu, '.2f'):>6} "
              f"{fmt(rate(entry, blocks), ',.0f'):>10} {fmt(vs_lib, '.2f'):>11} "
              f"{fmt(paired_ratio(entry, plain) if plain else None, '.2f'):>12} {fmt(entry.rss_mb, '.1f'):>11}  "
              f"{note}")
    if blocks > pygcode_max:
        print(f"(pygcode not run above --pygcode-max {pygcode_max:,} blocks: it is the slowest peer)")
    return results


def fmt(value: float | None, spec: str) -> str:
    return "-" if value is None else format(value, spec)


def translate_lines(blocks: int, results: dict[str, Runs]) -> list[Line]:
    """Throughput lines of one size: translate x3 against gcode-lib (and the plain loop), toolpath, verify."""
    size = f"{blocks:,} blocks"
    lib = results.get("gcode-lib") or Runs("gcode-lib", [], note="not run")
    lines = []
    for row, t in TRANSLATIONS.items():
        ours = results.get(t.label)
        if ours is None:
            continue  # not among --rows
        lines.append(Line(t.label, size, rate(ours, blocks), "blocks/s", "gcode-lib parse",
                          paired_ratio(ours, lib), at_least_x(t.times_gcode_lib), ours.note or lib.note))
        plain = results.get("plain loop")
        if row == "normalize" and plain is not None:
            lines.append(Line(t.label, size, rate(ours, blocks), "blocks/s",
                              "plain loop", paired_ratio(ours, plain), at_least_x(PLAIN_TARGET),
                              ours.note or plain.note))
    for label, peer, times in (("toolpath --format jsonl", "gcode-lib-state", TOOLPATH_TARGET),
                               ("verify fanuc / linuxcnc", "gcode-lib-state x 2 files", VERIFY_TARGET)):
        if label not in results:
            continue
        ours = results[label]
        base = results.get(peer) or Runs(peer, [], note="not run")
        lines.append(Line(label, size, rate(ours, blocks), "blocks/s", f"{peer} (position only)",
                          paired_ratio(ours, base), at_least_x(times), ours.note or base.note))
    return lines


def memory_lines(blocks: int, results: dict[str, Runs]) -> list[Line]:
    """Peak RSS of each postproc command at one size, against gcode-lib's parse (x = ours / its)."""
    lib = results.get("gcode-lib")
    lines = []
    for label in POSTPROC_LABELS:
        if label not in results:
            continue
        ours = results[label]
        ratio = ours.rss_mb / lib.rss_mb if ours.rss_mb and lib and lib.rss_mb else None
        target = Target("figure", "<", RSS_TARGET_MB, "< 64 MB")
        lines.append(Line(f"peak RSS {label}", f"{blocks:,} blocks", ours.rss_mb, "MB",
                          "gcode-lib parse's peak RSS", ratio, target, ours.note))
    return lines


def flat_lines(by_size: dict[int, dict[str, Runs]]) -> list[Line]:
    """Growth of peak RSS from the smallest to the largest size (needs two sizes)."""
    small, large = min(by_size), max(by_size)
    if small == large:
        return []
    lines = []
    for label in POSTPROC_LABELS:
        if label not in by_size[small]:
            continue
        low, high = by_size[small][label].rss_mb, by_size[large][label].rss_mb
        growth = high - low if low and high else None
        lines.append(Line(f"RSS growth {label}", f"{small:,}->{large:,}", growth, "MB",
                          f"itself at {small:,} blocks", high / low if low and high else None,
                          Target("ratio", "<=", FLAT_TARGET, f"<= {FLAT_TARGET:g}x (flat)")))
    return lines


def batch_lines(tables: list[tuple[str, list[batch.Result]]]) -> list[Line]:
    """Batch files/s (small programs) and blocks/s (large ones) against one command per file."""
    lines = []
    for (title, rows), (unit, attr) in zip(tables, (("files/s", "files_per_s"), ("blocks/s", "blocks_per_s"))):
        base = rows[0]
        for row in rows[1:]:
            ratio = row.files_per_s / base.files_per_s if row.files_per_s and base.files_per_s else None
            lines.append(Line(row.name, title.split(" of ")[0], getattr(row, attr), unit,
                              "one command per file", ratio, None, row.note or "one run"))
    return lines


def parse_args() -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true",
                        help="small sizes and one round, for development (explicit options still win)")
    parser.add_argument("--rows", nargs="+", choices=list(ROWS), metavar="ROW",
                        help=f"only these rows, with their baselines ({', '.join(ROWS)}; default all)")
    parser.add_argument("--sizes", type=int, nargs="+", help="CAM program sizes (default 100000 1000000)")
    parser.add_argument("--runs", type=int, help="rounds; each figure is their median (default 3)")
    parser.add_argument("--holes", type=int, help="holes of the canned-cycle program (default 100000)")
    parser.add_argument("--macro-holes", type=int, help="holes of the parametric program (default 20000)")
    parser.add_argument("--cache", type=Path, default=Path(tempfile.gettempdir()) / "postproc-bench",
                        help="where generated programs are kept between runs")
    parser.add_argument("--pygcode-max", type=int, default=100_000,
                        help="pygcode (the slowest peer) runs only up to this size")
    parser.add_argument("--batch", choices=("full", "quick", "tiny", "skip"),
                        help="batch files/s and blocks/s (benchmarks/batch.py): full, quick, tiny (the "
                             "harness's test) or none")
    args = parser.parse_args()
    quick = args.quick
    defaults = {"sizes": [2_000] if quick else [100_000, 1_000_000], "runs": 1 if quick else 3,
                "holes": 2_000 if quick else 100_000, "macro_holes": 1_000 if quick else 20_000,
                "batch": "quick" if quick else "full"}
    for name, value in defaults.items():
        if getattr(args, name) is None:
            setattr(args, name, value)
    if min(args.sizes) < generate.MIN_BLOCKS or args.runs < 1 or args.holes < 1 or args.macro_holes < 1:
        parser.error(f"sizes need at least {generate.MIN_BLOCKS} blocks; runs, holes at least 1")
    return args


def current_byte_code() -> None:
    """Byte-compiles the checkout's packages (skipping what is current) before anything is measured, as
    ``make compile`` and ``benchmarks/callgrind.sh`` do. Where ``PYTHONDONTWRITEBYTECODE`` is set no run
    writes a .pyc, so after a merge every start compiled each edited module from source again: measured
    with ``benchmarks/startup.py`` on one compiled install, ``postproc dialects`` took 265 ms of CPU with
    the byte code of the day before and 125 ms with current byte code (the 2026-11-30 start-up "regression"
    of ``run.py --rows startup``: 285 ms against 72 ms; the code itself had grown far less)."""
    root = HERE.parent
    for folder in ("postproc", "dialects", "plugins"):
        if (root / folder).is_dir():
            compileall.compile_dir(root / folder, quiet=1)


def main() -> None:
    args = parse_args()
    current_byte_code()
    if isinstance(sys.stdout, io.TextIOWrapper):
        sys.stdout.reconfigure(line_buffering=True)  # progress shows in a log file too
    args.cache.mkdir(parents=True, exist_ok=True)
    print(f"python {platform.python_version()} on {platform.machine()}, {os.cpu_count()} CPUs; every command "
          f"one process (start-up, imports and I/O included); median of {args.runs} round(s)")
    throughput: list[Line] = []
    memory: list[Line] = []
    by_size: dict[int, dict[str, Runs]] = {}
    rows: set[str] | None = None if args.rows is None else set(args.rows)
    wanted = (lambda row: True) if rows is None else rows.__contains__
    cycles: list[Line] = []
    macro: list[Line] = []
    startup: list[Line] = []
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        if rows is None or rows - {"cycles", "macro", "startup", "batch"}:
            for blocks in sorted(set(args.sizes)):
                by_size[blocks] = bench_size(blocks, args.cache, work, args.runs, args.pygcode_max, rows)
                throughput += translate_lines(blocks, by_size[blocks])
                memory += memory_lines(blocks, by_size[blocks])
            memory += flat_lines(by_size)
        if wanted("cycles"):
            cycles = workloads.cycles(args.holes, args.cache, work, args.runs)
        if wanted("macro"):
            macro = workloads.macro(args.macro_holes, args.cache, work, args.runs)
        if wanted("startup"):
            startup = workloads.startup(work, args.runs)
    batched: list[Line] = []
    if args.batch != "skip" and wanted("batch"):
        print()
        batched = batch_lines(batch.run(args.batch, args.cache))
    print()
    print_summary(throughput + cycles + macro + startup + memory + batched, args.runs)


if __name__ == "__main__":
    main()
