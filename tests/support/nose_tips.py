"""Tool nose radius compensation derived by hand: the imaginary tip's direction and the controlled points of a
simulated lathe program, shared by ``tests/test_nose_compensation.py`` (LinuxCNC's rules) and
``tests/test_fanuc_nose.py`` (Fanuc T's).

The machine positions the imaginary tool tip: the nose centre plus r times the tip's direction, from the Haas
lathe manual's table ("Imaginary Tool Tip and Direction": 1 X+Z+, 2 X+Z-, 3 X-Z-, 4 X-Z+, 5 Z+, 6 X+, 7 Z-,
8 X-, 0 and 9 none), written out here as its words, not taken from ``postproc.compensation.nose``.
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events

SETUPS = Path(__file__).resolve().parents[2] / "examples" / "setups"

FINISHING_UNDER_G42 = """G0 X62. Z2.
G71 U2. R0.5
G71 P10 Q20 U0.4 W0.1 F0.25
N10 G0 X20.
G1 Z-15.
X40. Z-25.
N20 G1 X60.
G42 G0 X62. Z2.
G70 P10 Q20
G40 G0 X100. Z50.
M30
"""
"""A Fanuc T program's end after its tool and spindle blocks: G71 (two blocks) over a turn, a taper and a face,
then G42 before G70 and G40 after it (compensation outside the profile, as Fanuc T wants [K])."""

MANUAL_TIPS = {0: "", 1: "X+Z+", 2: "X+Z-", 3: "X-Z-", 4: "X-Z+", 5: "Z+", 6: "X+", 7: "Z-", 8: "X-", 9: ""}
"""The Haas manual's table, as its words."""


def direction(tip: int) -> tuple[float, float]:
    """(Z, X) signs from the manual's words."""
    words = MANUAL_TIPS[tip]
    z = 1.0 if "Z+" in words else -1.0 if "Z-" in words else 0.0
    x = 1.0 if "X+" in words else -1.0 if "X-" in words else 0.0
    return z, x


def one_tool(setup_file: str, register: int, radius: float, tip: int | None) -> MachineSetup:
    """The example set-up ``setup_file`` whose only tool entry is ``register`` with a nose ``radius`` and ``tip``."""
    setup = load_setup(str(SETUPS / setup_file))
    setup.tools = {str(register): ToolData(number=register, radius=radius, tip=tip)}
    return setup


def controlled(text: str, dialect: str, setup: MachineSetup, file: str) -> list[dict[str, Any]]:
    """Every move of the simulated program at its controlled point (the programmed one where none is given):
    line, kind, X (a diameter), Z, and an arc's centre."""
    moves = []
    for ev in toolpath_events(io.StringIO(text), file=file, dialect=dialect, setup=setup):
        if "move" in ev:
            point = {**ev, **ev.get("controlled", {})}
            moves.append({k: point[k] for k in ("line", "move", "x", "z", "cx", "cz") if k in point})
    return moves


def at_tip(line: int, move: str, centre_end: tuple[float, float], tip: int | None, radius: float,
           arc_centre: tuple[float, float] | None = None) -> dict[str, Any]:
    """The expected move whose nose centre ends at ``centre_end`` (Z, X radius), moved to the imaginary tip;
    X (and an arc's centre X) a diameter, compared within 1e-6."""
    tz, tx = direction(tip or 0)
    z, x = centre_end
    point: dict[str, Any] = {"line": line, "move": move, "x": pytest.approx(2 * (x + tx * radius), abs=1e-6),
                             "z": pytest.approx(z + tz * radius, abs=1e-6)}
    if arc_centre is not None:
        point["cx"] = pytest.approx(2 * (arc_centre[1] + tx * radius), abs=1e-6)
        point["cz"] = pytest.approx(arc_centre[0] + tz * radius, abs=1e-6)
    return point
