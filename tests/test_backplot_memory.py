"""The SVG backplot draws in memory that does not grow with the program (issue 13).

Each size runs in a fresh interpreter with ``tracemalloc`` (allocations counted by Python, so the figure
does not depend on the allocator or on other processes, unlike RSS), started once the toolpath has begun:
reading the set-up and the dialect's base XML comes before the first event and has its own bounds. The
interpreter keeps the last ``Limits.kept_prefix`` blocks for backward jumps (100,000 by default, so it
grows up to there by design); the set-up here keeps 100, leaving the backplot as the only thing that
could grow. The in-memory backplot this replaced grew by 5.1 MB from 20k to 80k blocks here (25 bytes
a point), the streamed one by nothing.

The flatness is measured with a spill chunk of 512 points and paths of 500 points (``pointstore.CHUNK``,
``backplot.PATH_POINTS``, as tests/test_backplot_stream.py sets them), so that both sizes are past the
point where the store and the paths stop growing by design: 2,500 and 10,000 blocks show what 20k and
80k blocks showed at the real sizes (16,384 and 20,000) for a quarter of the work (the test took ~57 s of
CPU, now ~9 s; tracemalloc makes the simulation several times slower). Its power (pure build, measured
once each): the streamed backplot grows 34 kB from 2,500 to 10,000 blocks; with nothing spilled (both
constants 10**9, the in-memory backplot) 2.7 MB; a leak injected into ``PointStore.append`` that keeps
every point's three coordinates (24 bytes) 426 kB, and one that keeps only its x (8 bytes) 166 kB: each
fails ``MARGIN``. The real constants keep their own bound at 20k blocks. The measuring process installs the
compiled hot path first (``native.install``), so the compiled pass measures the compiled build (before, its
first import of a hot module made both passes measure pure Python); compiled, the growth is 35 kB and the
8-byte leak +166 kB.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

MEASURE = r"""
import os, sys, tracemalloc
from postproc import native
native.install()  # the build under test: without it the first import of a hot module ran it as pure Python
from itertools import chain
import postproc.drawing.backplot as backplot
import postproc.drawing.pointstore as pointstore
from postproc.commands.export import write_backplot
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import start_position, toolpath_events

if sys.argv[3] != "real":
    pointstore.CHUNK, backplot.PATH_POINTS = map(int, sys.argv[3].split(","))
setup = load_setup(sys.argv[2])  # tools measured as zero: the simulation needs the lengths G43 reads
setup.limits.kept_prefix = 100
with open(sys.argv[1]) as src, open(os.devnull, "w") as out:
    events = toolpath_events(src, file="g.nc", dialect="fanuc", setup=setup)
    first = next(events)
    tracemalloc.start(1)
    write_backplot(chain([first], events), out, "svg", start_position(setup), False)
print(tracemalloc.get_traced_memory()[1])
"""

SMALL_STORE = "512,500"
"""The spill chunk and the points of a <path> for the flatness (``pointstore.CHUNK``, ``backplot.PATH_POINTS``)."""
MARGIN = 128 << 10
"""Largest growth of the peak from 2,500 to 10,000 blocks, in bytes: the allowance a block of the former
1 MB from 20k to 80k (17 bytes a block; the in-memory backplot grew 25 bytes a point, more than a point a
block)."""


def peak(blocks: int, tmp: Path, store: str = SMALL_STORE) -> int:
    program = tmp / f"g{blocks}.nc"
    if not program.exists():
        subprocess.run([sys.executable, str(ROOT / "benchmarks" / "generate.py"), str(blocks), str(program)],
                       check=True)
    done = subprocess.run([sys.executable, "-c", MEASURE, str(program), str(ROOT / "tests/support/zero_tools.xml"),
                           store], capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    return int(done.stdout.split()[-1])


def test_the_backplot_peak_does_not_grow_with_the_program(tmp_path: Path) -> None:
    small, large = peak(2_500, tmp_path), peak(10_000, tmp_path)
    assert large - small < MARGIN, (small, large)


def test_the_backplot_peak_at_the_real_sizes_is_a_few_mb(tmp_path: Path) -> None:
    """Past one spill chunk and one <path> (20k blocks), as the store is in use."""
    real = peak(20_000, tmp_path, "real")
    assert real < 16 << 20, real  # a few MB: one spill chunk and one <path> of PATH_POINTS points
