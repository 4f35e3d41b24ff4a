"""Fagor 8070: a ``G53`` move while a fixed cycle is active (issue 26, defects).

What the 8070 does then (end the cycle, keep it, drill at the machine position) is not confirmed [?: the
8070 programming manual's fixed-cycle and G53 pages were not reached; DIALECTS.md 4.2], so the reader
refuses it by name, as it refuses a motion code there (``dialects/fagor/block_syntax.py``). Before, a
``G53 Z0`` without a motion code in a cycle was refused as "G while a fixed cycle is active" (no code
named, column 1), and after a ``G01`` as "G53 with a motion other than G00 in force" (the cycle was not
the motion in force). The Fanuc -> Fagor direction writes ``G80`` before the move (tests/test_fagor_cycle_end.py).
"""

from __future__ import annotations

import pytest

from postproc.setup.machine import AxisTravel
from postproc.setup.machine_setup import MachineSetup
from tests.support.pair_checks import PairChecks

SETUP = MachineSetup()
SETUP.travel = {a: AxisTravel(name=a, home=h) for a, h in {"X": -400.0, "Y": -250.0, "Z": -12.5}.items()}  # type: ignore[arg-type]
CHECK = PairChecks(SETUP)
MESSAGE = ("G53 while a fixed cycle is active: whether the 8070 ends the cycle, keeps it or runs it at the machine "
           "position is not confirmed (write G80 before it)")


@pytest.mark.parametrize(("before", "line", "column"), [
    ("G00 X0 Y0 Z10", "G53 Z0", 1), ("G01 X0 Y0 Z10 F100", "N4 G53 Z0", 4), ("G00 X0 Y0 Z10", "G53 X-10 Y-10", 1),
])
def test_a_g53_move_in_a_fixed_cycle_is_refused_by_name(before: str, line: str, column: int) -> None:
    program = f"G71 G90\n{before}\nG81 X5 Y5 Z2 I-3 F100\n{line}\nX7\nG80\nM30\n"
    assert CHECK.errors(program, "fagor", "fanuc") == [f"in.nc:4:{column}: error: {MESSAGE}"]


@pytest.mark.parametrize("text", ["G80\nG53 Z0\n", "G80 G53 Z0\n", "G53 G80 Z0\n"])
def test_a_g53_move_after_or_with_g80_is_read(text: str) -> None:
    program = "G71 G90\nG00 X0 Y0 Z10\nG81 X5 Y5 Z2 I-3 F100\n" + text + "M30\n"
    out = CHECK.translate(program, "fagor", "fanuc")
    assert out.splitlines()[-2].endswith("G00 Z0."), out
    CHECK.verify(program, out, "fagor", "fanuc")
