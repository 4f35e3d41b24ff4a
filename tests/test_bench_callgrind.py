"""The instruction-count companion of ``make bench`` (benchmarks/callgrind.sh, callgrind_once.py,
callgrind_summary.py): it has every row ``make bench`` prints a work figure for, with the same targets, and
each kind of run it makes runs the command ``make bench`` runs. Valgrind is not run here (minutes a row);
what is counted is never asserted."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks"))

import callgrind_summary  # noqa: E402
import generate  # noqa: E402
import summary  # noqa: E402
from translations import TRANSLATIONS  # noqa: E402

ONCE = ROOT / "benchmarks" / "callgrind_once.py"


def once(*args: str, prepare: bool = False) -> subprocess.CompletedProcess[str]:
    env = {"PREPARE": "1"} if prepare else {}
    done = subprocess.run([sys.executable, str(ONCE), *args], capture_output=True, text=True, timeout=300,
                          env={**os.environ, **env}, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    return done


def test_every_work_row_of_make_bench_has_an_instruction_row() -> None:
    # make bench's summary lines that count work (not memory, not batch), as tests/test_bench_harness.py
    # lists them, plus grblHAL's
    bench = {t.label for t in TRANSLATIONS.values()} | {
        "toolpath --format jsonl", "verify fanuc / linuxcnc", "cycles fanuc->grbl", "cycles fanuc->linuxcnc",
        "macro WHILE loop fanuc->grbl", "start-up: translate a one-line program", "start-up: postproc dialects"}
    assert "translate fanuc->grblhal" in bench
    assert {row.what for row in callgrind_summary.table()} == bench


def test_targets_are_make_bench_targets() -> None:
    rows = {(row.what, row.baseline_label): row for row in callgrind_summary.table()}
    for t in TRANSLATIONS.values():
        assert rows[(t.label, "gcode-lib parse")].target.value == t.times_gcode_lib
    assert rows[("translate fanuc->fanuc --normalize", "plain loop")].target.value == summary.PLAIN_TARGET
    by_what = {row.what: row for row in callgrind_summary.table()}
    assert by_what["toolpath --format jsonl"].target.value == summary.TOOLPATH_TARGET
    assert by_what["verify fanuc / linuxcnc"].target.value == summary.VERIFY_TARGET
    assert rows[("cycles fanuc->grbl", "plain loop over its output")].target.value == summary.HOLES_TARGET
    assert rows[("cycles fanuc->grbl", "gcode-lib parse (its block / our hole)")].target.value == \
        summary.HOLES_TIMES_GCODE_LIB
    starts = [row for row in callgrind_summary.table() if row.what == "start-up: postproc dialects"]
    assert [row.target.value for row in starts] == [summary.STARTUP_TARGET_MS, summary.STARTUP_TIMES_BARE]


def test_ratio_and_verdicts() -> None:
    by_what = {row.what: row for row in callgrind_summary.table()}
    linuxcnc = by_what["translate fanuc->linuxcnc"]  # >= 1.5x gcode-lib's parse: its instructions / ours
    assert linuxcnc.ratio(20_000, 30_000) == 1.5 and linuxcnc.verdict(20_000, 30_000) == "PASS"
    assert linuxcnc.verdict(20_001, 30_000) == "MISS"
    assert linuxcnc.verdict(None, 30_000) == "n/a" and linuxcnc.ratio(20_000, None) is None
    rows = {(row.what, row.target.text if row.target else ""): row for row in callgrind_summary.table()}
    start = rows[("start-up: postproc dialects", "< 120 ms")]  # times the bare interpreter's instructions
    assert start.ratio(400, 100) == 4.0
    assert start.verdict(1, 100) == "n/a"  # < 120 ms is a duration: instructions cannot judge it
    bare = rows[("start-up: postproc dialects", "<= 12x bare")]  # the same restated on the bare start
    assert bare.verdict(1200, 100) == "PASS" and bare.verdict(1201, 100) == "MISS"
    assert rows[("cycles fanuc->grbl", ">= 100,000/s")].verdict(10**9, 1) == "n/a"
    holes = rows[("cycles fanuc->grbl", ">= 0.32x")]  # gcode-lib's instructions a block over ours a hole
    assert holes.verdict(100_000, 32_000) == "PASS" and holes.verdict(100_001, 32_000) == "MISS"
    assert by_what["macro WHILE loop fanuc->grbl"].verdict(1, 1) == ""


def test_verify_baseline_reads_both_files_and_plain_loop_the_translation(tmp_path: Path) -> None:
    program = tmp_path / "b.nc"
    program.write_text("".join(generate.blocks(300)), encoding="ascii")
    once("fanuc", "verify:linuxcnc", "0", str(program), prepare=True)
    translation = tmp_path / "b.nc.linuxcnc"
    assert translation.exists()
    # the plain loop prints the blocks it rewrote: over FILE, then over FILE.linuxcnc
    assert once("fanuc", "plainloop", "0", str(program)).stdout.split() == ["300"]
    lines = sum(1 for _ in translation.open())
    assert once("fanuc", "plainloop:linuxcnc", "0", str(program)).stdout.split() == [str(lines)]
    pytest.importorskip("gcode_lib")
    one = json.loads(once("fanuc", "peer:gcode-lib-state", "0", str(program)).stdout)
    both = json.loads(once("fanuc", "peer:gcode-lib-state+linuxcnc", "0", str(program)).stdout)
    assert one["tool"] == both["tool"] == "gcode-lib-state" and both["items"] > one["items"] > 0


def test_grblhal_row_translates_the_bench_program(tmp_path: Path) -> None:
    # without the bench machine's tools grblHAL refuses the program's G43 H01 (callgrind.sh fanuc grblhal 0
    # failed before its row took --machine)
    program = tmp_path / "b.nc"
    program.write_text("".join(generate.blocks(300)), encoding="ascii")
    done = once("fanuc", "grblhal", "0", str(program))
    assert "error" not in done.stderr
