"""A Fanuc ``G28`` while a hole cycle is in force (issue 26, defects).

Fanuc cancels a canned cycle with ``G80`` or a group-01 code only; ``G28`` is group 00, one-shot, so the cycle
stays in force and the next block with a hole position drills [K: Fanuc 0i-MF operator's manual, canned cycles
("cancelled by G80 or a group 01 G code") and its G-code list (G28 in group 00); DIALECTS.md 3.1 item 10]. Each
hole is positioned "at the current level" and then goes to R [V: DIALECTS.md 2.1, Fanuc operations 1-2], so the
hole after the reference return rapids in X/Y where the return left Z (its reference point), then down to R. The
initial level of a G98 return stays the one the cycle started at.

Before, the reader took the reference return as leaving Z unknown and refused every later hole ("the Z position
before G81 is unknown") even with a home in the set-up. The expected toolpaths here are derived by hand from the
rules above and the set-up (home Z0 in machine coordinates, G54 Z-350: the reference point is Z350 in G54).
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from tests.support import rs274
from tests.support.pair_checks import PairChecks

VMC = Path(__file__).resolve().parents[1] / "examples" / "setups" / "fanuc_0i_mf_vmc.xml"


def _program(level: str) -> str:
    return ("O1000\nG21 G17 G90 G54\nG00 X0. Y0. Z50.\nS1000 M03\n"
            f"{level} G81 X10. Y10. Z-5. R2. F100.\nG91 G28 Z0.\nG90 X20. Y10.\nX30.\nG80\nM30\n")


def _moves(text: str, setup: MachineSetup | None) -> list[tuple[int, str, float, float, float]]:
    events = toolpath_events(io.StringIO(text), file="in.nc", dialect="fanuc", setup=setup)
    return [(e["line"], e["move"], e["x"], e["y"], e["z"]) for e in events if "move" in e]


@pytest.mark.parametrize(("level", "back"), [("G99", 2), ("G98", 50)])
def test_the_holes_after_the_reference_return_are_drilled(level: str, back: float) -> None:
    setup = load_setup(str(VMC))
    assert _moves(_program(level), setup) == [
        (3, "rapid", 0, 0, 50),
        (5, "rapid", 10, 10, 50), (5, "rapid", 10, 10, 2), (5, "feed", 10, 10, -5), (5, "rapid", 10, 10, back),
        (6, "rapid", 10, 10, 350),  # G91 G28 Z0: through the present point to the reference point
        (7, "rapid", 20, 10, 350), (7, "rapid", 20, 10, 2), (7, "feed", 20, 10, -5), (7, "rapid", 20, 10, back),
        (8, "rapid", 30, 10, back)] + ([(8, "rapid", 30, 10, 2)] if back != 2 else []) + [
        (8, "feed", 30, 10, -5), (8, "rapid", 30, 10, back)]


@pytest.mark.parametrize("target", ["fanuc", "grbl", "linuxcnc", "isg"])
@pytest.mark.parametrize("level", ["G98", "G99"])
def test_the_translations_drill_them_too(target: str, level: str) -> None:
    check = PairChecks(load_setup(str(VMC)))
    out = check.translate(_program(level), "fanuc", target)
    check.verify(_program(level), out, "fanuc", target)


def test_the_linuxcnc_translation_runs_so_in_rs274() -> None:
    """Without a set-up the reference point is machine zero, which rs274's G28 goes to too (its #5161-#5163 are 0
    in a fresh parameter file), and G54 is zero in both."""
    if not rs274.available():
        pytest.skip("rs274 is not installed")
    text = _program("G98")
    out = PairChecks(MachineSetup()).translate(text, "fanuc", "linuxcnc")
    theirs = rs274.motions(rs274.canonical_moves(rs274.run_rs274(out, tool_table="T1 P1 Z0 D0\n")))
    ours = [dict(move=m, x=x, y=y, z=z) for _, m, x, y, z in _moves(text, None)]
    rs274.assert_same_moves(ours, theirs, out)
