"""The summary table of ``make bench``: one line per figure, its ratio to a peer or baseline
measured in the same run, and the issue's target for it marked PASS or MISS (printed, never asserted).
"""
from __future__ import annotations

from dataclasses import dataclass

# The targets of issue 30 beyond the translations' (``translations.Translation.times_gcode_lib``): one table,
# read by ``make bench`` (run.py, workloads.py) and by ``callgrind_summary.py``.
PLAIN_TARGET = 0.8
"""--normalize: at least 0.8x the plain loop (benchmarks/plainloop.py)."""
TOOLPATH_TARGET = 1.5
"""toolpath: at least 1.5x gcode-lib's parse plus state tracking (issue 30)."""
VERIFY_TARGET = 1.0
"""verify: at least gcode-lib's parse plus state tracking over both files (issue 30)."""
HOLES_TARGET = 100_000.0
"""Canned cycles: at least 100,000 holes/s expanded (a rate: judged on the wall clock as the issue set it)."""
HOLES_TIMES_GCODE_LIB = 0.32
"""The same target against a peer measured in the same run, so that it judges the code, not the machine: on
the machine where it was set (2026-11-24, docs/benchmarks.md) gcode-lib parsed the 100,000-block CAM program
at 308,050 blocks/s (477,477 blocks/s of ``--normalize``, 1.55x it), so 100,000 holes/s was a hole in at
most 308,050 / 100,000 = 3.1 of gcode-lib's blocks: holes/s over gcode-lib's blocks/s >= 0.32, and in
instructions (``make callgrind``) gcode-lib's a block over ours a hole >= 0.32. Today's machine is about 1.5
times slower for both (gcode-lib 210,673 blocks/s, quiet, 2026-12-01), where 100,000 holes/s asks 0.47."""
STARTUP_TARGET_MS = 120.0
"""Start-up: a one-line translation and ``postproc dialects`` under 120 ms (a duration: the wall clock)."""
STARTUP_TIMES_BARE = 12.0
"""The same target against a bare ``python -c pass`` started in the same run: 120 ms over its 23 ms on the
quiet development machine of 2026-12-01 (``make bench``'s start-up rows) was 5.2x. That bare start ran the
venv's editable-install hooks, which are gone (Makefile): they were 52.6M of its 92.7M instructions
(``benchmarks/callgrind.sh --program startup fanuc bare 0``, 2026-12-02), so the same machine's bare start is
now 23 x 40.0 / 92.7 = 9.9 ms, and 120 ms is 12.1x it; 12x is kept. Stricter than the issue's (set on a
machine about 1.5 times faster, where the bare start took less), and judged in instructions too."""
RSS_TARGET_MB = 64.0
FLAT_TARGET = 1.10
"""Peak RSS at the largest size over the smallest: "flat" allows 10 % for ten times the blocks."""


@dataclass(frozen=True)
class Target:
    """A bound on a line's figure or on its ratio: ``>= 1.5x``, ``< 120 ms``."""

    on: str  # "figure" or "ratio"
    op: str  # ">=" or "<" or "<="
    value: float
    text: str

    def verdict(self, figure: float | None, ratio: float | None) -> str:
        value = figure if self.on == "figure" else ratio
        if value is None:
            return "n/a"
        ok = {">=": value >= self.value, "<": value < self.value, "<=": value <= self.value}[self.op]
        return "PASS" if ok else "MISS"


def at_least_x(value: float) -> Target:
    return Target("ratio", ">=", value, f">= {value:g}x")


@dataclass
class Line:
    """One figure of the summary."""

    what: str
    size: str
    figure: float | None
    unit: str
    baseline: str
    ratio: float | None
    target: Target | None = None
    note: str = ""

    @property
    def verdict(self) -> str:
        return self.target.verdict(self.figure, self.ratio) if self.target else ""


def fmt(value: float | None, spec: str) -> str:
    return "-" if value is None else format(value, spec)


def figure_text(line: Line) -> str:
    spec = ",.1f" if line.unit in ("ms", "MB", "files/s") or (line.figure or 0) < 100 else ",.0f"
    return f"{fmt(line.figure, spec)} {line.unit}"


def print_summary(lines: list[Line], runs: int) -> None:
    """Print the summary table and a count of PASS / MISS."""
    print(f"summary: each figure the median of {runs} run(s); x = the median of paired ratios "
          "(this row's rate / the baseline's rate, round by round); PASS/MISS against the issue's target")
    head = (f"{'row':<44} {'size':<18} {'figure':>18} {'baseline':<40} {'x':>6} "
            f"{'target':<16} {'':<4}  note")
    print(head)
    print("-" * len(head))
    for line in lines:
        print(f"{line.what:<44} {line.size:<18} {figure_text(line):>18} {line.baseline:<40} "
              f"{fmt(line.ratio, '.2f'):>6} {line.target.text if line.target else '-':<16} "
              f"{line.verdict:<4}  {line.note}")
    verdicts = [line.verdict for line in lines if line.target]
    print(f"targets: {verdicts.count('PASS')} PASS, {verdicts.count('MISS')} MISS, "
          f"{verdicts.count('n/a')} not measured")
