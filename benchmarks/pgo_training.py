"""The training run of the profile-guided build (``make compile``; setup.py's ``POSTPROC_PGO``, docs/compiled.md).

Runs the instrumented hot path over the work ``make bench`` measures, one command after another (each adds its
counts to the profile): every translation row of a generated CAM program, its toolpath and its verification, the
canned-cycle holes and the parametric loop to grbl and LinuxCNC, then ``make run``'s examples (every reader and
lathe writer, so that no dialect's path is left out of the profile). The outputs go to a temporary folder
(the examples' to ``out/``, as ``make run``'s); a
command that fails fails the build, for the compiled code would then be trained on an error path.

Usage: python benchmarks/pgo_training.py
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
from collections.abc import Iterable
from pathlib import Path

import generate
from translations import TRANSLATIONS
from workloads import postproc, translate

HERE = Path(__file__).resolve().parent
MACHINE = HERE / "machine.xml"
CAM_BLOCKS = 20_000
"""Enough blocks that the per-block path outweighs the start (~0.3 s a row instrumented)."""
HOLES = 300
MACRO_HOLES = 200


def write(path: Path, lines: Iterable[str]) -> Path:
    with open(path, "w", encoding="ascii", newline="\n") as out:
        out.writelines(lines)
    return path


def commands(work: Path) -> list[list[str]]:
    """What to run: the bench's rows on programs of training size."""
    cam = write(work / "cam.nc", generate.blocks(CAM_BLOCKS))
    cycles = write(work / "cycles.nc", generate.cycle_rows(HOLES))
    macro = write(work / "macro.nc", generate.bolt_circles(-(-MACRO_HOLES // generate.MACRO_HOLES),
                                                          generate.MACRO_HOLES))
    lowered = work / "cam.ngc"
    runs = [translate(cam, work / f"cam-{row}.out", "fanuc", t.target, *t.options(MACHINE))
            for row, t in TRANSLATIONS.items()]
    runs.append(translate(cam, lowered, "fanuc", "linuxcnc"))
    runs.append([*postproc(), "toolpath", str(cam), "--dialect", "fanuc", "--machine", str(MACHINE),
                 "--format", "jsonl", "-o", str(work / "cam.jsonl")])
    runs.append([*postproc(), "verify", str(cam), str(lowered), "--from", "fanuc", "--to", "linuxcnc",
                 "--machine", str(MACHINE)])
    for target in ("linuxcnc", "grbl"):
        runs.append(translate(cycles, work / f"cycles-{target}.out", "fanuc", target))
        runs.append(translate(macro, work / f"macro-{target}.out", "fanuc", target))
    return runs


def main() -> int:
    with tempfile.TemporaryDirectory(prefix="postproc-pgo-") as tmp:
        work = Path(tmp)
        for cmd in commands(work):
            done = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if done.returncode != 0:
                print(f"pgo training: {' '.join(cmd)} failed ({done.returncode}):\n{done.stderr}", file=sys.stderr)
                return 1
        examples = subprocess.run([sys.executable, "examples/run.py"], cwd=HERE.parent,  # (as ``make run``)
                                  stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if examples.returncode != 0:
            print(f"pgo training: examples/run.py failed:\n{examples.stderr}", file=sys.stderr)
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
