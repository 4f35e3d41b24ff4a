"""LinuxCNC's own interpreter tests (shared/conformance/linuxcnc) against our linuxcnc reader's toolpath.

Each case's ``.ngc`` is read with the linuxcnc dialect and simulated; its ``expected`` canonical calls
(printed by LinuxCNC's interpreter) are parsed by ``tests/support/rs274.canonical_moves``; the two are
compared move by move, within 1.5e-4 program units (the ``expected`` files print 4 decimals).

* G81 in G17/G18/G19 with G98 and G99, incremental rows with L: every move (rapid and feed).
* G84 in G17 with G98 and G99: every move, tapping feeds included.
* G84 in G18/G19: the **rapids only** (all three axes). The conformance README says the upstream
  G18/G19 tapping feeds are wrong, so those feed moves are not trusted; the rapids still check
  positioning, the rise to R and the return to the clear level.
* M98/M99: Fanuc-style numbered subprograms (``O1`` ... ``M99`` after the main program, ``M98 P1 L3``,
  ``L0``, ``#1`` shared with the caller): every move.
* G76 (the threading cycle, inch, exit taper, spring passes, degression 2, compound angle 29.5): every move,
  read on a lathe set-up. The G71/G72 lathe cases are out (``SKIPPED`` says why).
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import pytest

from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import canonical_moves, motions

CONFORMANCE = Path(os.environ.get("POSTPROC_CONFORMANCE", "/work/shared/conformance")) / "linuxcnc"
"""The shared conformance cases (POSTPROC_CONFORMANCE names their folder elsewhere)."""
MM_PER_INCH = 25.4
TOLERANCE = 1.5e-4
"""In program units (the cases are inch programs: converted to mm before comparing)."""

_G7X = ("LinuxCNC's own lathe cycles (G70/G71.x/G72.x with an O-word profile and D/I/R words) are not read by "
        "the linuxcnc dialect; the Fanuc T/GSK cycles are modelled, and tests/test_turning_* compare their geometry "
        "with these cases' moves where the cut is the same")
SKIPPED = {"g71": _G7X, "g72": _G7X}
LATHE_CASES = ("g76",)
"""Cases run on a lathe (G76 is the threading cycle there, ``postproc_linuxcnc.threading``): read with a lathe
set-up in radius mode, as the standalone interpreter starts (no G7 in the program)."""
LATHE = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"))
RAPIDS_ONLY = ("g84-g18", "g84-g19")
"""Cases whose tapping feeds are wrong upstream (conformance README: G84 in G18/G19): rapids only."""


def _cases() -> list[Any]:
    if not CONFORMANCE.is_dir():
        return [pytest.param(None, marks=pytest.mark.skip(reason=f"{CONFORMANCE} is not available"))]
    params = []
    for case in sorted(p for p in CONFORMANCE.iterdir() if p.is_dir()):
        reason = next((why for prefix, why in SKIPPED.items() if case.name.startswith(prefix)), None)
        marks = [pytest.mark.skip(reason=reason)] if reason else []
        params.append(pytest.param(case, id=case.name, marks=marks))
    return params


def _program(case: Path) -> Path:
    programs = sorted(case.glob("*.ngc"))
    assert len(programs) == 1, f"{case.name}: expected one .ngc, found {programs}"
    return programs[0]


def _ours(program: Path, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    with open(program, encoding="utf-8", newline="") as src:
        events = list(toolpath_events(src, file=str(program), dialect="linuxcnc", setup=setup))
    return [e for e in events[1:] if "move" in e]


def _units(program: Path) -> float:
    """mm per program unit: the cases switch to G20 before their first move."""
    text = program.read_text(encoding="utf-8").lower()
    return MM_PER_INCH if "g20" in text else 1.0


def _mismatch(ours: list[dict[str, Any]], theirs: list[dict[str, Any]], tol_mm: float) -> str | None:
    for i, (a, b) in enumerate(zip(ours, theirs)):
        if a["move"] != b["move"]:
            return f"move {i}: ours {a}, LinuxCNC {b}"
        dev = math.dist((a["x"], a["y"], a["z"]), (b["x"], b["y"], b["z"]))
        if dev > tol_mm:
            return f"move {i} (line {a['line']}): {dev:.6f} mm apart: ours {a}, LinuxCNC {b}"
    if len(ours) != len(theirs):
        longer, name = (ours, "ours") if len(ours) > len(theirs) else (theirs, "LinuxCNC")
        first = longer[min(len(ours), len(theirs))]
        return f"{name} has {abs(len(ours) - len(theirs))} more move(s), the first: {first}"
    return None


@pytest.mark.parametrize("case", _cases())
def test_conformance_case(case: Path) -> None:
    program = _program(case)
    expected = motions(canonical_moves((case / "expected").read_text(encoding="utf-8")))
    ours = _ours(program, LATHE if case.name.startswith(LATHE_CASES) else None)
    if case.name.startswith(RAPIDS_ONLY):
        expected = [m for m in expected if m["move"] == "rapid"]
        ours = [m for m in ours if m["move"] == "rapid"]
    assert expected, f"{case.name}: no moves in the expected file"
    problem = _mismatch(ours, expected, TOLERANCE * _units(program))
    assert problem is None, f"{case.name}: {problem}"
