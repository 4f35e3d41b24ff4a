"""``--transform`` on lathe programs (issue #27, frames3 item 1): a shift along Z (the spindle's axis) is the one
map that keeps an XZ lathe program valid; every other map is refused by what it does. A reference return stays
where the machine has it (machine coordinates), and so does the start; everything programmed in work
coordinates moves, U/W increments and thread moves included.

Checked three ways: hand-derived words and toolpath points, ``verify`` with the same transform (and failing
with another), and the LinuxCNC translation run in rs274 against the source's toolpath moved by the shift,
its reference returns left in place (on the bundled Fanuc T and GSK examples and on seeded random programs).
"""

from __future__ import annotations

import io
import random
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, UsageError
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from postproc.transforms import parse_transform
from postproc.transforms.events import moved_events
from tests.support.rs274 import available
from tests.test_lathe_rs274 import difference, fanuc_program, theirs

ROOT = Path(__file__).resolve().parents[1]
FANUC_T = load_setup(str(ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"))
GSK = load_setup(str(ROOT / "examples" / "setups" / "gsk_980tdc.xml"))
SHIFT = "translate 0,0,-5"

PROGRAM = """%
O3002
G21 G99
G28 U0. W0.
T0101
G97 S800 M03
G00 X40. Z2.
G01 Z-20. F0.2
U10. W-5.
G02 X60. Z-30. R5.
G32 Z-40. F1.5
G00 X80.
G28 U0. W0.
G00 X30. Z5.
M30
%
"""


def _translate(text: str, target: str, transform: str, setup: MachineSetup = FANUC_T, source: str = "fanuc") -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target, setup=setup,
              transform=transform, diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _verify(text: str, out: str, target: str, transform: str, setup: MachineSetup = FANUC_T,
            source: str = "fanuc") -> Any:
    return verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source=source,
                        target=target, setup=setup, tolerance=1e-3, transform=parse_transform(transform))


def _points(text: str, dialect: str, setup: MachineSetup = FANUC_T) -> list[tuple[str, float, float]]:
    return [(e["move"], float(e["x"]), float(e["z"]))
            for e in toolpath_events(io.StringIO(text), file="t.nc", dialect=dialect, setup=setup) if "move" in e]


# -- by hand ---------------------------------------------------------------------------------------------

def test_a_shift_along_z_moves_work_coordinates_and_keeps_reference_returns() -> None:
    out = _translate(PROGRAM, "fanuc", SHIFT)
    body = [line for line in out.splitlines() if line[:1] in "GU"]
    assert body == ["G21 G99", "G28 U0. W0.", "G97 S800 M03", "G00 X40. Z-3.", "G01 Z-25. F0.2", "G01 U10. W-5.",
                    "G02 X60. Z-35. R5.", "G32 Z-45. F1.5", "G00 X80.", "G28 U0. W0.", "G00 X30. Z0."], out
    # by hand: every Z 5 lower, the increments as they were; the second reference return from (80, -45)
    # goes to the reference point (0, 0: a lathe's, machine coordinates), as the source's went from (80, -40)
    assert _points(out, "fanuc") == [("rapid", 40, -3), ("feed", 40, -25), ("feed", 50, -30), ("cw", 60, -35),
                                     ("feed", 60, -45), ("rapid", 80, -45), ("rapid", 0, 0), ("rapid", 30, 0)]
    assert _points(PROGRAM, "fanuc")[6] == ("rapid", 0, 0)
    assert _verify(PROGRAM, out, "fanuc", SHIFT).ok


def test_verify_fails_with_another_shift_and_so_would_a_moved_reference_return() -> None:
    out = _translate(PROGRAM, "fanuc", SHIFT)
    assert not _verify(PROGRAM, out, "fanuc", "translate 0,0,-4").ok
    # an output whose reference return were moved with the program (G28 to Z-5 by its intermediate point and
    # back to the reference point would still be at 0): only a return kept as written passes
    moved = out.replace("G00 X80.\nG28 U0. W0.", "G00 X80.\nG00 X0. Z-5.")
    assert not _verify(PROGRAM, moved, "fanuc", SHIFT).ok


def test_linuxcnc_gets_the_shift_and_its_own_reference_return() -> None:
    out = _translate(PROGRAM, "linuxcnc", SHIFT)
    assert out.count("G91 G28 X0. Z0.") == 2 and "G33 Z-45. K1.5" in out and "G0 X30. Z0." in out, out
    assert _verify(PROGRAM, out, "linuxcnc", SHIFT).ok


@pytest.mark.parametrize("how, says", [
    ("rotate 10 in zx", "it rotates the program"),
    ("mirror x", "it mirrors X, which puts the tool past the spindle's centre line"),
    ("rotate 180 in zx", "it turns X and Z over (a half turn in the ZX plane)"),
    ("mirror z about -25", "it mirrors Z, which turns the cut end for end"),
    ("scale 2", "it scales the program"),
    ("translate 5,0,0", "it shifts X, which moves the part off the spindle's centre line"),
    ("translate 0,0,-5; translate 0,1", "it shifts Y"),
])
def test_every_other_map_is_refused_by_what_it_does(how: str, says: str) -> None:
    with pytest.raises(UsageError) as caught:
        _translate(PROGRAM, "linuxcnc", how)
    assert f"--transform {how!r} on a lathe program: {says}" in caught.value.message
    assert "only 'translate 0,0,DZ' keeps a lathe program valid" in caught.value.message


@pytest.mark.parametrize("lines, line, says", [
    (["G01 W-5. F100."], 4, "this move starts from a machine position on Z"),  # the start is held
    (["G00 X40. Z2.", "G28 W0.", "G01 W-2. F100."], 6, "this move starts from a machine position on Z"),
    (["G00 X40. Z2.", "G28 W0.", "G02 X50. R5. F100."], 6, "an arc from a machine position on Z"),
    (["G28 W5."], 4, "this reference return's intermediate point is an increment from a machine position on Z"),
    (["G00 X40. Z2.", "G28 W0.", "G28 W3."], 6, "this reference return's intermediate point is an increment"),
    (["G50 X100. Z50."], 4, "a coordinate setting (the tool's point given new coordinates) cannot be transformed"),
])
def test_what_cannot_be_moved_is_a_located_error(lines: list[str], line: int, says: str) -> None:
    text = "%\nO3003\nG21 G98\n" + "\n".join(lines) + "\nM30\n%\n"
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc", SHIFT)
    assert f"t.nc:{line}:1: error: {says}" in str(caught.value.errors[0]), caught.value.errors


def test_a_move_that_leaves_z_alone_leaves_it_at_the_reference_point() -> None:
    # after G28 W0. the tool stands at the reference point on Z (0, machine coordinates): G00 X20. moves X only, in
    # the source and the output alike; Z is a point of the program again from Z10. on (written Z5.)
    text = "%\nO3004\nG21 G98\nG00 X40. Z2.\nG28 W0.\nG00 X20.\nG00 Z10.\nM30\n%\n"
    out = _translate(text, "fanuc", SHIFT)
    assert "G28 W0.\nG00 X20.\nG00 Z5." in out, out
    assert _points(out, "fanuc") == [("rapid", 40, -3), ("rapid", 40, 0), ("rapid", 20, 0), ("rapid", 20, 5)]
    assert _verify(text, out, "fanuc", SHIFT).ok


def test_a_lathe_cycle_kept_for_the_target_is_refused() -> None:
    text = (ROOT / "examples" / "fanuc-lathe" / "o2001_stepped_shaft.nc").read_text(encoding="utf-8")
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc", SHIFT)
    assert "t.nc:10:1: error: a lathe cycle kept for the target (turn rough) cannot be transformed" in \
        str(caught.value.errors[0])


# -- against rs274 -------------------------------------------------------------------------------------------

def _moved_source(text: str, dialect: str, setup: MachineSetup, transform: str) -> list[dict[str, Any]]:
    """The source's toolpath moved by ``transform`` (reference returns held), X and centres as radii."""
    events = toolpath_events(io.StringIO(text), file="t.nc", dialect=dialect, setup=setup, mark_held=True)
    moves = []
    for ev in moved_events(events, parse_transform(transform), {"X": 0.0, "Z": 0.0}):
        if "move" in ev:
            moves.append({k: float(v) / 2.0 if k in ("x", "cx") else v for k, v in ev.items()})
    return moves


EXAMPLES = [*[(p, "fanuc", FANUC_T) for p in sorted((ROOT / "examples" / "fanuc-lathe").glob("*.nc"))],
            *[(p, "gsk", GSK) for p in sorted((ROOT / "examples" / "gsk").glob("*.nc"))]]


@pytest.mark.parametrize("path, source, setup", EXAMPLES, ids=[p.stem for p, _, _ in EXAMPLES])
def test_the_lathe_examples_shift_for_linuxcnc_verify_and_run_in_rs274(path: Path, source: str,
                                                                       setup: MachineSetup) -> None:
    text = path.read_text(encoding="utf-8")
    out = _translate(text, "linuxcnc", SHIFT, setup, source)
    report = _verify(text, out, "linuxcnc", SHIFT, setup, source)
    assert report.ok, report.summary() + "\n" + out
    if available():
        problem = difference(_moved_source(text, source, setup, SHIFT), theirs(out))
        assert problem is None, f"{problem}\n\n{out}"


@pytest.mark.parametrize("seed", range(30))
def test_random_lathe_programs_shift_verify_and_run_in_rs274(seed: int) -> None:
    gsk = seed % 3 == 2
    text = fanuc_program(seed, gsk)
    how = f"translate 0,0,{random.Random(seed).randint(-80, 80) / 4:g}"
    source, setup = ("gsk", GSK) if gsk else ("fanuc", FANUC_T)
    out = _translate(text, "linuxcnc", how, setup, source)
    report = _verify(text, out, "linuxcnc", how, setup, source)
    assert report.ok, report.summary() + "\n" + text + "\n" + out
    if available():
        problem = difference(_moved_source(text, source, setup, how), theirs(out))
        assert problem is None, f"{problem}\n\n{text}\n{out}"
