"""Timing whole processes: wall time, CPU time and peak RSS of one command, in rounds.

A figure is the median of its runs.  Commands compared with each other run interleaved, one round
after another (each round runs every command once), so a ratio is taken run by run between
commands that saw the same load on this shared machine, and the ratio printed is the median of
those paired ratios.
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

NOT_INSTALLED = 3
"""Exit status of peers.py when its peer is not installed (a missing peer is a note, not a failure)."""

# Peak RSS must come from a process that is not the harness's own child: a child's ru_maxrss
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


@dataclass
class Sample:
    """One run of one command."""

    seconds: float
    cpu: float
    rss_mb: float


@dataclass
class Runs:
    """The runs of one command (one per round), or the note saying why it has none."""

    label: str
    cmd: list[str]
    samples: list[Sample] = field(default_factory=list)
    note: str = ""

    @property
    def ok(self) -> bool:
        return bool(self.samples) and not self.note

    @property
    def seconds(self) -> float | None:
        return statistics.median(s.seconds for s in self.samples) if self.ok else None

    @property
    def cpu(self) -> float | None:
        return statistics.median(s.cpu for s in self.samples) if self.ok else None

    @property
    def rss_mb(self) -> float | None:
        """The largest peak RSS of the runs (memory is a bound, not a typical value)."""
        return max(s.rss_mb for s in self.samples) if self.ok else None


def run_once(cmd: list[str]) -> tuple[int, Sample, str]:
    """Run cmd in its own process: (exit code, its sample, the last line of its stderr)."""
    with tempfile.TemporaryDirectory() as tmp:
        result, err = Path(tmp, "result"), Path(tmp, "stderr")
        with open(err, "wb") as err_file:
            subprocess.run([sys.executable, "-S", "-c", SPAWN, str(result), *cmd], cwd=ROOT,
                           stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                           stderr=err_file, check=True)
        code, seconds, cpu, rss_kb = result.read_text().split()
        lines = err.read_text(errors="replace").strip().splitlines()
    tail = lines[-1].removeprefix(f"{cmd[0]}: ") if lines else ""
    return int(code), Sample(float(seconds), float(cpu), int(rss_kb) / 1024), tail


def rounds(commands: dict[str, list[str]], runs: int,
           check: Callable[[str], str] | None = None) -> dict[str, Runs]:
    """Run every command once a round, `runs` rounds; a command that fails is not run again.

    `check(label)`, when given, is called after each successful run and returns "" or why the
    run's output is wrong (a benchmark of a wrong translation measures nothing)."""
    results = {label: Runs(label, cmd) for label, cmd in commands.items()}
    for _ in range(runs):
        for label, entry in results.items():
            if entry.note:
                continue
            code, sample, err = run_once(entry.cmd)
            if code == NOT_INSTALLED and str(HERE / "peers.py") in entry.cmd:
                entry.note = "not installed"
            elif code != 0:
                entry.note = f"failed (exit {code}): {err[:90]}"
            elif check is not None and (wrong := check(label)):
                entry.note = f"wrong output: {wrong}"
            else:
                entry.samples.append(sample)
    return results


def paired_ratio(ours: Runs, base: Runs, our_units: float = 1.0,
                 base_units: float = 1.0) -> float | None:
    """Median over rounds of (our rate / base rate), each rate = units / seconds of that round."""
    if not (ours.ok and base.ok):
        return None
    pairs = zip(ours.samples, base.samples)
    return statistics.median((our_units / o.seconds) / (base_units / b.seconds) for o, b in pairs)


def rate(runs: Runs, units: float = 1.0) -> float | None:
    """Units per second from the median run (None when the command has no run)."""
    seconds = runs.seconds
    return units / seconds if seconds else None
