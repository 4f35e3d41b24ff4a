"""The SVG backplot draws in memory that does not grow with the program (issue 13).

Each size runs in a fresh interpreter with ``tracemalloc`` (allocations counted by Python, so the figure
does not depend on the allocator or on other processes, unlike RSS), started once the toolpath has begun:
reading the set-up and the dialect's base XML comes before the first event and has its own bounds. The
interpreter keeps the last ``Limits.kept_prefix`` blocks for backward jumps (100,000 by default, so it
grows up to there by design); the set-up here keeps 100, leaving the backplot as the only thing that
could grow. The in-memory backplot this replaced grew by 5.1 MB from 20k to 80k blocks here (25 bytes
a point), the streamed one by nothing.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

MEASURE = r"""
import os, sys, tracemalloc
from itertools import chain
from postproc.commands.export import write_backplot
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import start_position, toolpath_events

setup = load_setup(sys.argv[2])  # tools measured as zero: the simulation needs the lengths G43 reads
setup.limits.kept_prefix = 100
with open(sys.argv[1]) as src, open(os.devnull, "w") as out:
    events = toolpath_events(src, file="g.nc", dialect="fanuc", setup=setup)
    first = next(events)
    tracemalloc.start(1)
    write_backplot(chain([first], events), out, "svg", start_position(setup), False)
print(tracemalloc.get_traced_memory()[1])
"""

MARGIN = 1 << 20
"""Largest growth of the peak from 20k to 80k blocks, in bytes (the in-memory backplot grew 5.1 MB)."""


def peak(blocks: int, tmp: Path) -> int:
    program = tmp / f"g{blocks}.nc"
    subprocess.run([sys.executable, str(ROOT / "benchmarks" / "generate.py"), str(blocks), str(program)],
                   check=True)
    done = subprocess.run([sys.executable, "-c", MEASURE, str(program), str(ROOT / "tests/support/zero_tools.xml")],
                          capture_output=True, text=True,
                          check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    return int(done.stdout.split()[-1])


def test_the_backplot_peak_does_not_grow_with_the_program(tmp_path: Path) -> None:
    small, large = peak(20_000, tmp_path), peak(80_000, tmp_path)
    assert large - small < MARGIN, (small, large)
    assert small < 16 << 20, small  # a few MB: one spill chunk and one <path> of PATH_POINTS points
