"""The benchmark rows beyond straight translation: canned-cycle expansion (holes/s), a parametric
loop flattened (interpreted blocks/s) and start-up time, each against a baseline run in the same rounds.
"""
from __future__ import annotations

import hashlib
import sys
from collections.abc import Callable, Iterable
from pathlib import Path

import generate
from summary import (HOLES_TARGET, HOLES_TIMES_GCODE_LIB, STARTUP_TARGET_MS, STARTUP_TIMES_BARE, Line, Target,
                     at_least_x, fmt)
from timing import Runs, paired_ratio, rate, rounds

HERE = Path(__file__).resolve().parent
PY = sys.executable
PLAIN = [PY, str(HERE / "plainloop.py")]
GCODE_LIB = [PY, str(HERE / "peers.py"), "gcode-lib"]
CYCLE_TARGETS = ("grbl", "linuxcnc")


def postproc() -> list[str]:
    """The installed ``postproc`` command (what a user starts), else ``python -m postproc``."""
    script = Path(PY).with_name("postproc")
    return [str(script)] if script.exists() else [PY, "-m", "postproc"]


def translate(src: Path, out: Path, source: str, target: str, *options: str) -> list[str]:
    return [*postproc(), "translate", str(src), "-o", str(out), "--from", source, "--to", target, *options]


def prepare(cmd: list[str]) -> str:
    """Run cmd once, untimed (an output a baseline reads; also byte-compiles): "" or why it failed."""
    return rounds({"prepare": cmd}, 1)["prepare"].note


def cached(cache: Path, name: str, lines: Callable[[], Iterable[str]]) -> Path:
    """A generated program kept in `cache` (regenerated when generate.py changes)."""
    digest = hashlib.sha1(Path(generate.__file__).read_bytes()).hexdigest()[:10]
    path = cache / f"{name}-{digest}.nc"
    if not path.exists():
        for stale in cache.glob(f"{name}-*.nc"):
            stale.unlink()
        tmp = path.with_suffix(".tmp")
        with open(tmp, "w", encoding="ascii", newline="\n") as out:
            out.writelines(lines())
        tmp.replace(path)
    return path


def count_lines(path: Path) -> int:
    with open(path, "rb") as f:
        return sum(chunk.count(b"\n") for chunk in iter(lambda: f.read(1 << 20), b""))


def at_least_lines(outputs: dict[str, tuple[Path, int]]) -> Callable[[str], str]:
    """A check for `rounds`: the output of label has at least its minimum number of lines."""

    def check(label: str) -> str:
        if label not in outputs:
            return ""
        path, least = outputs[label]
        found = count_lines(path) if path.exists() else 0
        return "" if found >= least else f"{path.name} has {found} lines, expected >= {least}"

    return check


def print_runs(title: str, entries: Iterable[tuple[Runs, float, str]]) -> None:
    """A detail table: each command's median seconds, CPU, rate and peak RSS."""
    print(f"\n{title}")
    print(f"{'command':<34} {'units':>16} {'seconds':>8} {'cpu s':>6} {'units/s':>11} {'peak RSS MB':>11}  note")
    for runs, units, unit in entries:
        print(f"{runs.label:<34} {f'{units:,.0f} {unit}':>16} {fmt(runs.seconds, '.3f'):>8} "
              f"{fmt(runs.cpu, '.2f'):>6} {fmt(rate(runs, units), ',.0f'):>11} {fmt(runs.rss_mb, '.1f'):>11}  "
              f"{runs.note}")


def cycles(holes: int, cache: Path, work: Path, runs: int) -> list[Line]:
    """Rows of G81/G83 holes expanded for grbl and LinuxCNC (which runs Fanuc's cycles expanded),
    against the plain loop rewriting each expanded output (the least work to write those lines), and against
    gcode-lib parsing a CAM program of as many blocks (the target restated on a peer, ``HOLES_TIMES_GCODE_LIB``)."""
    src = cached(cache, f"cycles-{holes}", lambda: generate.cycle_rows(holes))
    cam = cached(cache, f"fanuc-{holes}", lambda: generate.blocks(holes))
    commands: dict[str, list[str]] = {}
    outputs: dict[str, tuple[Path, int]] = {}
    for target in CYCLE_TARGETS:
        out, prepared = work / f"cycles.{target}", work / f"cycles-prepared.{target}"
        prepare(translate(src, prepared, "fanuc", target))
        commands[f"fanuc->{target} (expands)"] = translate(src, out, "fanuc", target)
        outputs[f"fanuc->{target} (expands)"] = (out, 3 * holes)
        commands[f"plain loop over {target} output"] = [*PLAIN, str(prepared), str(work / "plain.out")]
    lib = f"gcode-lib parse ({holes:,} CAM blocks)"
    commands[lib] = [*GCODE_LIB, str(cam)]
    results = rounds(commands, runs, at_least_lines(outputs))
    lines = []
    detail = []
    for target in CYCLE_TARGETS:
        ours = results[f"fanuc->{target} (expands)"]
        base = results[f"plain loop over {target} output"]
        detail += [(ours, holes, "holes"), (base, holes, "holes")]
        lines.append(Line(f"cycles fanuc->{target}", f"{holes:,} holes", rate(ours, holes), "holes/s",
                          "plain loop over its output", paired_ratio(ours, base),
                          Target("figure", ">=", HOLES_TARGET, ">= 100,000/s"), ours.note or base.note))
        # holes/s over gcode-lib's blocks/s, round by round: as many holes as CAM blocks, so a rate ratio
        lines.append(Line(f"cycles fanuc->{target}", f"{holes:,} holes", rate(ours, holes), "holes/s",
                          "gcode-lib parse, as many blocks", paired_ratio(ours, results[lib]),
                          at_least_x(HOLES_TIMES_GCODE_LIB), ours.note or results[lib].note))
    detail.append((results[lib], holes, "blocks"))
    print_runs(f"canned cycles: {holes:,} holes in rows (G81, and G83 in 5 pecks), expanded", detail)
    return lines


def bolt_circle_size(holes: int) -> tuple[int, int]:
    """(circles, holes a circle) for about `holes` holes in circles of at most 100."""
    per = min(holes, generate.MACRO_HOLES)
    return -(-holes // per), per


def macro(holes: int, cache: Path, work: Path, runs: int) -> list[Line]:
    """A WHILE bolt-circle program flattened to grbl: interpreted blocks/s, against the plain
    loop rewriting the flattened output."""
    circles, per = bolt_circle_size(holes)
    executed = generate.bolt_circle_executed(circles, per)
    src = cached(cache, f"macro-{circles}x{per}", lambda: generate.bolt_circles(circles, per))
    out, prepared = work / "macro.grbl", work / "macro-prepared.grbl"
    prepare(translate(src, prepared, "fanuc", "grbl"))
    label = "fanuc->grbl (flattens)"
    results = rounds({label: translate(src, out, "fanuc", "grbl"), "plain loop over its output": [*PLAIN, str(prepared), str(work / "plain.out")]},
                     runs, at_least_lines({label: (out, 3 * circles * per)}))
    ours, base = results[label], results["plain loop over its output"]
    print_runs(f"parametric: {circles} x {per} holes of a nested WHILE bolt circle, {executed:,} "
               "interpreted blocks, flattened to grbl", [(ours, executed, "blocks"), (base, executed, "blocks")])
    return [Line("macro WHILE loop fanuc->grbl", f"{executed:,} blocks", rate(ours, executed),
                 "blocks/s", "plain loop over its output", paired_ratio(ours, base), None,
                 ours.note or base.note)]


def startup(work: Path, runs: int) -> list[Line]:
    """Start-up of a one-line translation and of ``postproc dialects``, against a bare interpreter."""
    one = work / "one-line.nc"
    one.write_text("G00 X1.\n", encoding="ascii")
    bare = "python -c pass"
    commands = {
        bare: [PY, "-c", "pass"],
        "translate a one-line program": translate(one, work / "one.out", "fanuc", "grbl"),
        "postproc dialects": [*postproc(), "dialects"],
    }
    results = rounds(commands, runs)
    print_runs("start-up (one process each; units = 1 start)", ((r, 1, "starts") for r in results.values()))
    lines = []
    for label in list(commands)[1:]:
        ours = results[label]
        ms = ours.seconds * 1000 if ours.seconds else None
        # a start-up is a duration: the ratio is our time over the bare interpreter's (lower is better)
        ratio = paired_ratio(results[bare], ours)
        lines.append(Line(f"start-up: {label}", "1 start", ms, "ms", f"'{bare}' (x = times its ms)", ratio,
                          Target("figure", "<", STARTUP_TARGET_MS, "< 120 ms"), ours.note or results[bare].note))
        lines.append(Line(f"start-up: {label}", "1 start", ms, "ms", f"'{bare}' (x = times its ms)", ratio,
                          Target("ratio", "<=", STARTUP_TIMES_BARE, f"<= {STARTUP_TIMES_BARE:g}x bare"),
                          ours.note or results[bare].note))
    return lines


