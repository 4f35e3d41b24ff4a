"""SINUMERIK programs against LinuxCNC's interpreter: each is translated to LinuxCNC (flattened: its R
parameters, DEF variables, loops and jumps evaluated here), the translation is run by ``rs274``, and its moves
must be the moves postproc's own SINUMERIK toolpath gives (the issue's "LinuxCNC outputs give the same moves
in rs274 as postproc's Siemens toolpath"). The examples and seeded random programs (expressions, FOR/WHILE,
IF/ELSE, arcs by CR= and by I/J) are checked.
"""

from __future__ import annotations

import io
import math
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples" / "siemens").glob("*.mpf"))
ZERO_TOOLS = ROOT / "tests" / "support" / "zero_tools.xml"
TOOL_TABLE = "".join(f"T{n} P{n} Z0 D0\n" for n in range(1, 10))
"""The tools of ``zero_tools.xml`` (zero length and diameter), as rs274 reads a table."""
TOLERANCE_MM = 2e-4
"""rs274 prints 4 decimals (mm programs)."""


def _compare(text: str, file: str) -> None:
    setup = load_setup(str(ZERO_TOOLS))
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file=file, source="siemens", target="linuxcnc", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    theirs = [e for e in canonical_moves(run_rs274(out.getvalue(), tool_table=TOOL_TABLE), start=(0.0, 0.0, 0.0))
              if "move" in e]
    ours: list[dict[str, Any]] = [e for e in toolpath_events(io.StringIO(text), file=file, dialect="siemens",
                                                             setup=setup) if "move" in e]
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274\n{text}\n{out.getvalue()}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b, text)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b, text)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_an_example_moves_in_rs274_as_its_siemens_toolpath(path: Path) -> None:
    _compare(path.read_text(encoding="utf-8"), str(path))


_FUNCTIONS = ("SIN({})", "COS({})", "POT({})", "ABS({})", "TRUNC({})", "ROUND({})", "SQRT(ABS({}))",
              "ATAN2({}, 3)")


def _expression(rng: random.Random, depth: int = 0) -> str:
    leaf = rng.choice(["R1", "R2", "LEN", str(rng.randint(-9, 9)), f"{rng.uniform(-5, 5):.3f}", "1.5EX1"])
    if depth > 2 or rng.random() < 0.3:
        return leaf
    kind = rng.random()
    if kind < 0.5:
        return f"{_expression(rng, depth + 1)}{rng.choice('+-*')}{_expression(rng, depth + 1)}"
    if kind < 0.8:
        return rng.choice(_FUNCTIONS).format(_expression(rng, depth + 1))
    return f"({_expression(rng, depth + 1)})"


def _program(seed: int) -> str:
    rng = random.Random(seed)
    lines = ["%_N_RANDOM_MPF", "G710 G90 G17 G94", "G0 X0 Y0 Z5", "DEF REAL LEN",
             f"R1={rng.randint(1, 9)} R2={rng.uniform(-3, 3):.3f}", f"LEN={rng.uniform(1, 4):.2f}", "T1 D1 M6",
             "S1000 M3"]
    x, y = 0.0, 0.0
    for _ in range(rng.randint(3, 7)):
        kind = rng.choice(["expr", "for", "while", "cr", "ij", "if"])
        if kind == "expr":
            lines.append(f"G1 X={_expression(rng)} Y={_expression(rng)} F{rng.randint(50, 500)}")
        elif kind == "for":
            lines += [f"FOR R3=1 TO {rng.randint(1, 3)}", f"G1 X=R3*{rng.randint(1, 5)} Y={_expression(rng)} F200",
                      "ENDFOR"]
        elif kind == "while":
            lines += ["R4=0", f"WHILE R4<{rng.randint(1, 3)}", "R4=R4+1", "G1 Z=-R4*0.5 F100", "ENDWHILE"]
        elif kind == "if":
            lines += [f"IF (R1>{rng.randint(0, 9)}) OR (R2<0)", f"G1 Y={_expression(rng)} F150", "ELSE",
                      f"G0 Z={rng.randint(1, 9)}", "ENDIF"]
        x, y = rng.randint(-20, 20), rng.randint(-20, 20)
        lines.append(f"G1 X{x} Y{y} F300")  # a known point for the arcs
        if kind == "cr":
            ex, ey = x + rng.randint(-15, 15), y + rng.randint(1, 15)
            chord = math.hypot(ex - x, ey - y)
            radius = chord / 2 * rng.uniform(1.05, 3.0)
            sign = rng.choice(["", "-"])
            lines.append(f"G{rng.choice('23')} X{ex} Y{ey} CR={sign}{radius:.4f}")
        elif kind == "ij":
            i, j = rng.randint(-9, 9) or 3, rng.randint(-9, 9)
            cx, cy = x + i, y + j
            turn = math.radians(rng.uniform(20, 300))
            ex = cx + (x - cx) * math.cos(turn) - (y - cy) * math.sin(turn)
            ey = cy + (x - cx) * math.sin(turn) + (y - cy) * math.cos(turn)
            lines.append(f"G3 X{ex:.4f} Y{ey:.4f} I{i} J{j}")
    lines += ["G0 Z50", "M30"]
    return "\n".join(lines) + "\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(12))
def test_a_random_program_moves_in_rs274_as_its_siemens_toolpath(seed: int) -> None:
    _compare(_program(seed), f"random{seed}.mpf")
