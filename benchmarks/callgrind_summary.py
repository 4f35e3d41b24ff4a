"""``make callgrind``: every row of ``make bench`` in instructions (``benchmarks/callgrind.sh``, one row at a
time, niced), with its baseline's instructions, the ratio and PASS/MISS against the targets of ``make bench``
(``summary.py``, ``translations.py``: one table of targets). Instructions counted by callgrind do not move
with the machine's load as wall time does.

Usage: python benchmarks/callgrind_summary.py [--rows ROW ...] [--reuse]
   (sizes: CALLGRIND_SMALL / CALLGRIND_LARGE, thousand blocks or hundred holes, as callgrind.sh reads them)

The ratio of a throughput row is the baseline's instructions a unit over the row's (higher is faster: a
rate ratio, as ``make bench``'s x); of a start-up row the row's instructions over the bare interpreter's
(``make bench``'s "x = times its ms"). A target on a rate or a duration (holes/s, ms) is wall-clock only:
printed with ``n/a``; each is judged on the line below it as restated against a peer (``summary.py``:
gcode-lib's instructions a block over ours a hole, ours a start over the bare interpreter's). ``--reuse`` takes a row already measured at the same sizes and build (its line is kept
under ``$TMPDIR/postproc-callgrind/summary``) instead of measuring it again.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from summary import (HOLES_TARGET, HOLES_TIMES_GCODE_LIB, PLAIN_TARGET, STARTUP_TARGET_MS,  # noqa: E402
                     STARTUP_TIMES_BARE, TOOLPATH_TARGET, VERIFY_TARGET, Target, at_least_x, fmt)
from translations import TRANSLATIONS  # noqa: E402


@dataclass(frozen=True)
class Measure:
    """One ``callgrind.sh`` run: ``--program PROGRAM SRC TGT NORMALIZE``."""

    program: str
    tgt: str
    normalize: str = "0"
    src: str = "fanuc"

    @property
    def key(self) -> str:
        return f"{self.program}-{self.src}-{self.tgt}-{self.normalize}".replace(":", "_").replace("+", "_")


@dataclass(frozen=True)
class Row:
    """One line of the table: a measure, the baseline it is compared with, the target."""

    what: str
    ours: Measure
    baseline_label: str
    baseline: Measure
    target: Target | None
    unit: str
    rows: str
    """The ``--rows`` name that selects it (``make bench``'s)."""

    @property
    def judged(self) -> bool:
        """Whether instructions can judge the target: a ratio can; a rate or a duration (holes/s, ms) cannot."""
        return self.target is not None and self.target.on == "ratio"

    def ratio(self, ours: int | None, base: int | None) -> float | None:
        """A throughput row: the baseline's instructions a unit over ours (a rate ratio: higher is faster);
        a start: ours over the bare interpreter's (times its instructions)."""
        if not ours or not base:
            return None
        return ours / base if self.unit == "start" else base / ours

    def verdict(self, ours: int | None, base: int | None) -> str:
        """PASS/MISS on a ratio target, n/a on a wall-clock one or a row not measured, "" without a target."""
        if self.target is None:
            return ""
        return self.target.verdict(ours, self.ratio(ours, base)) if self.judged else "n/a"


GCODE_LIB = Measure("cam", "peer:gcode-lib")
STATE = Measure("cam", "peer:gcode-lib-state")
STATE_BOTH = Measure("cam", "peer:gcode-lib-state+linuxcnc")
PLAIN = Measure("cam", "plainloop")
BARE = Measure("startup", "bare")


def table() -> list[Row]:
    """Every row of ``make bench`` that counts work (not memory, not batch), in its order."""
    rows = []
    for name, t in TRANSLATIONS.items():
        ours = Measure("cam", t.target, "1" if t.normalize else "0")
        rows.append(Row(t.label, ours, "gcode-lib parse", GCODE_LIB, at_least_x(t.times_gcode_lib), "block", name))
        if name == "normalize":
            rows.append(Row(t.label, ours, "plain loop", PLAIN, at_least_x(PLAIN_TARGET), "block", name))
    rows.append(Row("toolpath --format jsonl", Measure("cam", "toolpath"), "gcode-lib-state (position only)",
                    STATE, at_least_x(TOOLPATH_TARGET), "block", "toolpath"))
    rows.append(Row("verify fanuc / linuxcnc", Measure("cam", "verify:linuxcnc"),
                    "gcode-lib-state x 2 files (position only)", STATE_BOTH, at_least_x(VERIFY_TARGET), "block",
                    "verify"))
    for target in ("grbl", "linuxcnc"):
        rows.append(Row(f"cycles fanuc->{target}", Measure("cycles", target), "plain loop over its output",
                        Measure("cycles", f"plainloop:{target}"),
                        Target("figure", ">=", HOLES_TARGET, ">= 100,000/s"), "hole", "cycles"))
        rows.append(Row(f"cycles fanuc->{target}", Measure("cycles", target), "gcode-lib parse (its block / our hole)",
                        GCODE_LIB, at_least_x(HOLES_TIMES_GCODE_LIB), "hole", "cycles"))
    rows.append(Row("macro WHILE loop fanuc->grbl", Measure("macro", "grbl"), "plain loop over its output",
                    Measure("macro", "plainloop:grbl"), None, "block", "macro"))
    for what, tgt in (("translate a one-line program", "grbl"), ("postproc dialects", "dialects")):
        rows.append(Row(f"start-up: {what}", Measure("startup", tgt), "'python -c pass' (x = times its instr)",
                        BARE, Target("figure", "<", STARTUP_TARGET_MS, "< 120 ms"), "start", "startup"))
        rows.append(Row(f"start-up: {what}", Measure("startup", tgt), "'python -c pass' (x = times its instr)",
                        BARE, Target("ratio", "<=", STARTUP_TIMES_BARE, f"<= {STARTUP_TIMES_BARE:g}x bare"),
                        "start", "startup"))
    return rows


ROW_NAMES = [*TRANSLATIONS, "toolpath", "verify", "cycles", "macro", "startup"]


def cost(m: Measure) -> tuple[int, str]:
    """Measuring order: the cheap runs first (peers, starts, then translations; cycles and verify, the
    longest under valgrind, last), so that an interrupted run has measured the most rows."""
    rank = 0 if m.tgt.startswith(("peer:", "plainloop")) and m.program == "cam" else \
        {"startup": 1, "cam": 2, "macro": 3, "cycles": 4}[m.program]
    return (5 if m.tgt.startswith("verify:") else rank, m.tgt)


def measure(m: Measure, store: Path, reuse: bool) -> tuple[int | None, str]:
    """Instructions a unit of one measure (None: it failed, said on stderr) and the fixed cost its two runs
    imply ("": a start, or not printed), from ``callgrind.sh``."""
    sizes = f"{os.environ.get('CALLGRIND_SMALL', '-')}-{os.environ.get('CALLGRIND_LARGE', '-')}"
    kept = store / f"{m.key}.{sizes}{'.pure' if os.environ.get('POSTPROC_PURE') == '1' else ''}.txt"
    if not (reuse and kept.exists()):
        print(f"measuring {m.program} {m.src} {m.tgt} {m.normalize} ...", file=sys.stderr, flush=True)
        done = subprocess.run(["nice", str(HERE / "callgrind.sh"), "--program", m.program, m.src, m.tgt,
                               m.normalize], capture_output=True, text=True)
        if done.returncode != 0:
            print(f"callgrind.sh {m.program} {m.tgt}: failed\n{done.stderr}", file=sys.stderr)
            return None, ""
        kept.write_text(done.stdout.strip().splitlines()[-1] + "\n")
    line = kept.read_text()
    print(f"  {line.strip()}", file=sys.stderr)
    found, fixed = re.search(r" (-?\d+) instr/", line), re.search(r"fixed (-?\d+) M", line)
    return (int(found.group(1)) if found else None), (f"{fixed.group(1)} M" if fixed else "")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", nargs="+", choices=ROW_NAMES, metavar="ROW",
                        help=f"only these rows, with their baselines ({', '.join(ROW_NAMES)}; default all)")
    parser.add_argument("--reuse", action="store_true", help="take rows measured before at these sizes")
    args = parser.parse_args()
    rows = [r for r in table() if args.rows is None or r.rows in args.rows]
    store = Path(os.environ.get("TMPDIR", "/tmp")) / "postproc-callgrind" / "summary"
    store.mkdir(parents=True, exist_ok=True)
    figures: dict[Measure, int | None] = {}
    fixed: dict[Measure, str] = {}
    for m in sorted({m for row in rows for m in (row.ours, row.baseline)}, key=cost):
        figures[m], fixed[m] = measure(m, store, args.reuse)  # one at a time: each a niced valgrind process
    version = subprocess.run([str(HERE.parent / ".venv" / "bin" / "postproc"), "--version"], capture_output=True,
                             text=True).stdout.strip()
    small, large = os.environ.get("CALLGRIND_SMALL", "default"), os.environ.get("CALLGRIND_LARGE", "default")
    print(f"callgrind instructions ({version}); CALLGRIND_SMALL={small} CALLGRIND_LARGE={large} (thousand "
          "blocks, hundred holes of the cycles and macro programs): a unit's instructions are the "
          "large run's minus the small run's over the units between them; a start's are the whole process's")
    head = (f"{'row':<40} {'instr':>18} {'baseline':<42} {'its instr':>18} {'x':>6} {'target':<14} {'':<4}  "
            "fixed cost (row / baseline)")
    print(head)
    print("-" * len(head))
    verdicts = []
    for row in rows:
        ours, base = figures[row.ours], figures[row.baseline]
        ratio, verdict = row.ratio(ours, base), row.verdict(ours, base)
        if verdict:
            verdicts.append(verdict)
        print(f"{row.what:<40} {fmt(ours, ',d'):>12}/{row.unit:<5} {row.baseline_label:<42} "
              f"{fmt(base, ',d'):>12}/{row.unit:<5} {fmt(ratio, '.2f'):>6} "
              f"{row.target.text if row.target else '-':<14} {verdict:<4}  "
              f"{fixed[row.ours] or '-'} / {fixed[row.baseline] or '-'}")
    print(f"targets: {verdicts.count('PASS')} PASS, {verdicts.count('MISS')} MISS, {verdicts.count('n/a')} not "
          "judged in instructions (a wall-clock target) or not measured")
    print("fixed cost: the small run's instructions less its units at the row's figure (start-up, imports); "
          "one far from its neighbours' means a run did something once that the other did not")


if __name__ == "__main__":
    main()
