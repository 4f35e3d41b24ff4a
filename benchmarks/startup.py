"""Start-up of a one-line translation and of ``postproc dialects``, as whole processes, against a bare
interpreter measured in the same run (issue 13: < 120 ms). Runs are interleaved (bare, translate,
dialects, bare, ...) so that a machine whose load drifts moves all three alike; medians are printed with
the spread. Each run gets the same HOME (the entry-point cache lives there): the first, warm-up round is
not counted.

    .venv/bin/python benchmarks/startup.py [RUNS]
"""

from __future__ import annotations

import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BIN = Path(sys.executable).parent


def _once(cmd: list[str], env: dict[str, str]) -> tuple[float, float]:
    """Wall and CPU (user + system) seconds of one run of ``cmd``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(cmd, stdout=subprocess.DEVNULL, env=env, check=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main(runs: int) -> None:
    with tempfile.TemporaryDirectory() as home:
        program = Path(home) / "one.nc"
        program.write_text("G0 X1. Y2.\n")
        env = dict(os.environ, HOME=home)
        env.pop("XDG_CACHE_HOME", None)
        commands = {
            "python -c pass": [str(BIN / "python"), "-c", "pass"],
            "translate (1 line)": [str(BIN / "postproc"), "translate", str(program), "--from", "fanuc",
                                   "--to", "linuxcnc"],
            "dialects": [str(BIN / "postproc"), "dialects"],
        }
        for cmd in commands.values():  # warm-up: the entry-point cache, the file system cache
            _once(cmd, env)
        time.sleep(2.5)  # the cache is written once what it observes has settled (postproc.entry_points)
        for cmd in commands.values():
            _once(cmd, env)
        samples: dict[str, list[tuple[float, float]]] = {name: [] for name in commands}
        for _ in range(runs):
            for name, cmd in commands.items():
                samples[name].append(_once(cmd, env))
    bare = statistics.median(w for w, _ in samples["python -c pass"])
    print(f"{'command':20s} {'wall median':>11s} {'min':>7s} {'max':>7s} {'cpu median':>10s} {'x bare':>7s}")
    for name, got in samples.items():
        walls = [w for w, _ in got]
        wall = statistics.median(walls)
        cpu = statistics.median(c for _, c in got)
        print(f"{name:20s} {wall * 1e3:8.1f} ms {min(walls) * 1e3:7.1f} {max(walls) * 1e3:7.1f} "
              f"{cpu * 1e3:7.1f} ms {wall / bare:7.2f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 11)
