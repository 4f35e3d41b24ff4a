"""The benchmark harness (benchmarks/): its programs are what they claim, its figures and ratios are
computed as documented, and ``run.py --quick`` runs end to end. Speed is never asserted here."""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import Any, Callable

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

import generate  # noqa: E402
import timing  # noqa: E402
from summary import Line, Target  # noqa: E402


def toolpath(cli: Callable[..., Any], path: Path) -> list[dict[str, Any]]:
    r = cli("toolpath", path, "--dialect", "fanuc", "--format", "jsonl")
    assert r.status == 0, r.err
    return [json.loads(line) for line in r.out.decode().splitlines()[1:]]


HARNESS = pytest.mark.one_build(
    reason="checks the benchmark harness's report (rows, figures, verdicts), not postproc's outputs, which the rest of the suite holds in both builds; the build changes only the speeds it prints")


def write(tmp_path: Path, name: str, lines: Iterator[str]) -> Path:
    path = tmp_path / name
    path.write_text("".join(lines), encoding="ascii")
    return path


@pytest.mark.parametrize("holes", [1, 25, 26, 57])
def test_cycle_rows_drill_exactly_the_holes_claimed(cli: Callable[..., Any], tmp_path: Path,
                                                    holes: int) -> None:
    # A G81 hole is one feed to Z-5.; a G83 hole pecks Q3. from R2. to Z-12. (-1, -4, -7, -10, then -12):
    # one feed reaches the bottom per hole.  Rows of 25 alternate G81 and G83.
    events = toolpath(cli, write(tmp_path, "cycles.nc", generate.cycle_rows(holes)))
    bottoms = [e for e in events if e.get("move") == "feed" and e["z"] in (-5.0, -12.0)]
    assert len(bottoms) == holes
    g83_holes = sum(min(25, holes - first) for first in range(0, holes, 25) if (first // 25) % 2 == 1)
    assert sum(1 for e in bottoms if e["z"] == -12.0) == g83_holes
    pecks = [e for e in events if e.get("move") == "feed" and e["z"] in (-1.0, -4.0, -7.0, -10.0)]
    assert len(pecks) == 4 * g83_holes


def test_bolt_circle_executed_blocks_hand_counted() -> None:
    # One circle of one hole, line by line: 6 straight lines; WHILE1 (true), #10=0, #21; WHILE2 (true),
    # #11, G00, G01, G00, #10=#10+1, END2; WHILE2 (false); #20=#20+1, END1; WHILE1 (false); G00, M05, M30.
    assert generate.bolt_circle_executed(1, 1) == 6 + 3 + 7 + 1 + 2 + 1 + 3
    # Two circles of three: each circle 3 + 3 x 7 + 1 + 2 = 27 lines.
    assert generate.bolt_circle_executed(2, 3) == 6 + 2 * 27 + 1 + 3


def test_bolt_circles_drill_every_hole_on_its_circle(cli: Callable[..., Any], tmp_path: Path) -> None:
    circles, per = 3, 8
    events = toolpath(cli, write(tmp_path, "macro.nc", generate.bolt_circles(circles, per)))
    plunges = [i for i, e in enumerate(events) if e.get("move") == "feed" and e["z"] == -3.0]
    assert len(plunges) == circles * per
    for n, i in enumerate(plunges):
        circle, hole = divmod(n, per)
        angle = math.radians(hole * 360.0 / per + circle)  # #11 = #10*360./#1 + #20, in degrees
        radius = 10.0 + circle * 0.5
        x, y = events[i]["x"], events[i]["y"]
        assert (x, y) == pytest.approx((60.0 + radius * math.cos(angle), 40.0 + radius * math.sin(angle)),
                                       abs=1e-3)


def test_cam_program_has_exactly_n_blocks() -> None:
    assert sum(1 for _ in generate.blocks(500)) == 500


def sample(seconds: float) -> timing.Sample:
    return timing.Sample(seconds, seconds, 10.0)


def test_paired_ratio_is_the_median_of_round_by_round_ratios() -> None:
    ours = timing.Runs("ours", [], [sample(1.0), sample(2.0), sample(4.0)])
    base = timing.Runs("base", [], [sample(2.0), sample(2.0), sample(2.0)])
    # rates per round: ours 1, 0.5, 0.25 units/s; base 0.5 each: ratios 2, 1, 0.5 -> median 1
    assert timing.paired_ratio(ours, base) == 1.0
    assert ours.seconds == 2.0
    # holes/s of ours over blocks/s of a baseline that did 4 times the units
    assert timing.paired_ratio(ours, base, 1.0, 4.0) == 0.25
    assert timing.paired_ratio(ours, timing.Runs("failed", [], note="failed (exit 1)")) is None


def test_targets_mark_pass_miss_and_unmeasured() -> None:
    at_least = Target("ratio", ">=", 1.5, ">= 1.5x")
    assert Line("t", "1", 10.0, "blocks/s", "b", 1.5, at_least).verdict == "PASS"
    assert Line("t", "1", 10.0, "blocks/s", "b", 1.49, at_least).verdict == "MISS"
    assert Line("t", "1", 10.0, "blocks/s", "b", None, at_least).verdict == "n/a"
    below = Target("figure", "<", 120.0, "< 120 ms")
    assert Line("s", "1", 119.9, "ms", "b", 9.0, below).verdict == "PASS"
    assert Line("s", "1", 120.0, "ms", "b", 1.0, below).verdict == "MISS"


def test_rounds_report_a_failing_command_and_a_wrong_output(tmp_path: Path) -> None:
    ok = [sys.executable, "-c", "pass"]
    results = timing.rounds({"fails": [sys.executable, "-c", "import sys; sys.exit(4)"], "ok": ok,
                             "wrong": ok}, 2, lambda label: "no output" if label == "wrong" else "")
    assert results["fails"].note.startswith("failed (exit 4)") and not results["fails"].samples
    assert results["wrong"].note == "wrong output: no output" and not results["wrong"].ok
    assert len(results["ok"].samples) == 2 and results["ok"].rss_mb and results["ok"].seconds


SUMMARY_ROWS = [
    "translate fanuc->fanuc --normalize", "translate fanuc->fanuc (copy)", "translate fanuc->grbl (warn)",
    "translate fanuc->linuxcnc", "translate fanuc->grblhal", "translate fanuc->isg", "translate fanuc->fagor",
    "toolpath --format jsonl", "verify fanuc / linuxcnc", "peak RSS verify fanuc / linuxcnc",
    "RSS growth toolpath --format jsonl", "RSS growth verify fanuc / linuxcnc", "cycles fanuc->grbl", "cycles fanuc->linuxcnc",
    "macro WHILE loop fanuc->grbl", "start-up: translate a one-line program", "start-up: postproc dialects",
    "peak RSS translate fanuc->fanuc --normalize", "RSS growth translate fanuc->linuxcnc",
    "batch --jobs 1", "batch --jobs 2",
]


@HARNESS
def test_quick_run_end_to_end(tmp_path: Path) -> None:
    """Tiny sizes, one round: every row is measured (a figure, a ratio, a verdict where a target is)."""
    done = subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / "run.py"), "--quick", "--sizes", "200", "300",
         "--holes", "30", "--macro-holes", "12", "--batch", "tiny", "--cache", str(tmp_path / "cache")],
        cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    out = done.stdout
    assert "failed" not in out and "wrong output" not in out, out
    table = out[out.index("\nsummary:"):].splitlines()
    summary = table[table.index(next(t for t in table if t.startswith("---"))) + 1:-1]
    assert summary and table[-1].startswith("targets:")
    for row in SUMMARY_ROWS:
        assert any(line.startswith(row) for line in summary), (row, out)
    for line in summary:
        figure = re.search(r"\s(-|-?[\d,.]+) (blocks/s|holes/s|files/s|ms|MB)\s", line)
        assert figure and figure.group(1) != "-", line
        if "peer" not in line and "gcode-lib" not in line:  # a peer may be missing; baselines never
            assert re.search(r"\s\d+\.\d\d\s", line), line
    for row in ("toolpath --format jsonl", "verify fanuc / linuxcnc", "translate fanuc->isg", "translate fanuc->fagor"):
        # issue 30's targets: every throughput row of the simulator and of a lowering translation has one
        assert all(re.search(r"\s>= [\d.]+x\s+(PASS|MISS|n/a)", line) for line in summary if line.startswith(row)), row
    verdicts = re.findall(r"\s(PASS|MISS|n/a)\s", "\n".join(summary) + "\n")
    assert len(verdicts) == sum(1 for line in summary if re.search(r"\s[<>]=? ", line))
    assert re.search(r"^targets: \d+ PASS, \d+ MISS, \d+ not measured$", out, re.M)


@HARNESS
def test_rows_measure_only_what_they_name(tmp_path: Path) -> None:
    """``--rows toolpath startup``: those rows and the baselines they are compared with, nothing else."""
    done = subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / "run.py"), "--quick", "--rows", "toolpath", "startup",
         "--sizes", "200", "--cache", str(tmp_path / "cache")],
        cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    out = done.stdout
    assert "failed" not in out and "wrong output" not in out, out
    detail = out[:out.index("\nsummary:")]
    for command in ("toolpath --format jsonl", "gcode-lib-state", "python -c pass", "postproc dialects"):
        assert re.search(rf"^{re.escape(command)}\s", detail, re.M), (command, out)
    for command in ("translate fanuc->", "verify fanuc", "plain loop", "gcode-lib ", "canned cycles", "batch"):
        assert not re.search(rf"^{re.escape(command)}", detail, re.M), (command, out)
    table = out[out.index("\nsummary:"):].splitlines()
    summary = table[table.index(next(t for t in table if t.startswith("---"))) + 1:-1]
    rows = sorted({re.split(r"\s{2,}", line)[0] for line in summary})
    assert rows == ["peak RSS toolpath --format jsonl", "start-up: postproc dialects",
                    "start-up: translate a one-line program", "toolpath --format jsonl"], out
