"""G92 on the frame model, for the grbl family (grbl and grblHAL read G92 as LinuxCNC does): a program of these
words is RS274/NGC that rs274 reads, so rs274 runs the program itself as the oracle, and again its translations
(the frame evaluated into their coordinates). ``tests/test_grbl_frames.py`` and ``tests/test_grblhal_frames.py``
hold the cases; this module what they share: reading, translating, the random programs and the comparison."""

from __future__ import annotations

import io
import random
from typing import Any

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import assert_same_moves, run_rs274
from tests.test_frames import _machine as machine_points

HEAD = "G21 G90 G17 G0 X0 Y0 Z0\n"


def translated(text: str, source: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def moves(text: str, dialect: str) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect) if "move" in e]


def assert_evaluated(text: str, source: str, target: str) -> None:
    """``target`` gets no G92 (the frame evaluated into its coordinates) and moves as ``text`` does."""
    out = translated(text, source, target)
    assert "G92" not in "".join(line.split("(")[0] for line in out.splitlines()), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source=source,
                          target=target, tolerance=1e-3)
    assert report.ok, report.summary()


def random_program(seed: int, kinds: tuple[str, ...], clears: dict[str, str]) -> str:
    """A random program of G92 (absolute or under G91), arcs, incremental moves and the codes ``clears`` gives
    for its kinds (``{"clear": "G92.1"}``), each followed by a rapid; ``kinds`` are drawn from in that order."""
    rng = random.Random(seed)
    lines = ["G21 G90 G17 G94", "G0 X0 Y0 Z0"]
    for _ in range(rng.randint(3, 7)):
        kind = rng.choice(kinds)
        if kind == "g92":
            axes = rng.sample("XYZ", rng.randint(1, 3))
            lines.append(f"{rng.choice(['G90', 'G91'])} G92 " + " ".join(f"{a}{rng.randint(-20, 20)}" for a in axes))
            lines.append("G90")
        elif kind in clears:
            lines.append(clears[kind])
        elif kind == "arc":
            x, y = rng.randint(-20, 20), rng.randint(-20, 20)
            lines.append(f"G1 X{x} Y{y} F{rng.randint(50, 500)}")
            lines.append(f"G{rng.choice('23')} X{x + 10} Y{y} I5 J0")
        else:
            lines.append(f"G91 G1 X{rng.randint(-5, 5)} Y{rng.randint(-5, 5)} Z{rng.randint(-2, 2)} F200\nG90")
        lines.append(f"G0 X{rng.randint(-20, 20)} Y{rng.randint(-20, 20)} Z{rng.randint(0, 5)}")
    lines += ["G92.1", "G0 X0 Y0 Z10", "M2"]
    return "\n".join(lines) + "\n"


def _machine_moves(text: str) -> list[dict[str, Any]]:
    """rs274's moves at machine points (its canonical calls leave the G92 offset out), straight moves that go
    nowhere left out as the toolpath leaves them."""
    out: list[dict[str, Any]] = []
    here = (0.0, 0.0, 0.0)
    for e in machine_points(run_rs274(text)):
        point = (e["x"], e["y"], e["z"])
        if e["move"] in ("rapid", "feed") and max(abs(a - b) for a, b in zip(point, here)) < 1e-9:
            continue
        out.append(e)
        here = point
    return out


def same_moves(ours: list[dict[str, Any]], text: str, program: str) -> None:
    """``ours`` (the toolpath of ``program``) are the moves rs274 makes running ``text``."""
    assert_same_moves(ours, _machine_moves(text), program, text)
