"""A lathe's tool offsets written into the coordinates (``postproc.cycles.lathe_offsets``) in the units and the
distance mode in force, which the step takes from the one tracker the lowering steps follow
(``postproc.lowering.units_and_distance``): a G20 or a G91 before the block the step changes, in it, and back.

The set-up (``tests.test_lathe_same_station``): offset 2 is X 5.08 mm (a diameter: 2.54 mm = 0.1 in as grbl's
radius) and Z 5.08 mm (0.2 in). grbl programs X as a radius, so a source X diameter d is written d / 2 plus the
offset's X. Each expected line is worked out by hand in its comment; ``verify`` runs both programs too.
"""

from __future__ import annotations

import io
from typing import Callable

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines
from tests.test_lathe_same_station import _setup


def _system_b() -> MachineSetup:
    """The same machine read as Fanuc T system B (G90/G91 are distance modes there)."""
    setup = _setup()
    setup.input.gcode_system = "B"
    return setup


def _to_grbl(program: str, setup: MachineSetup) -> list[str]:
    out = io.StringIO()
    translate(io.StringIO(program), out, file="l.nc", source="fanuc", target="grbl", setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()), on_unsupported="error")
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="l.nc", file_out="out",
                          source="fanuc", target="grbl", setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    return out.getvalue().splitlines()


@pytest.mark.parametrize(("program", "setup", "written"), [
    # G20 before the first block the step changes: X2. (diameter, in) -> 1. + 0.1 = 1.1, Z 0.2 + 0.2 = 0.4;
    # X1.5 -> 0.75 + 0.1 = 0.85 (in millimetres the offset would add 2.54 and 5.08)
    ("O0001\nG20 G18 G98\nG0 X4. Z2.\nT0202\nG0 X2. Z0.2\nG1 X1.5 F4.\nM30\n", _setup,
     ["G0 X1.1 Z0.4", "G1 X0.85 F4."]),
    # millimetres, then inches: X50. -> 25. + 2.54 = 27.54, Z 5. + 5.08 = 10.08; after G20 X1. -> 0.5 + 0.1 = 0.6,
    # Z 0.1 + 0.2 = 0.3
    ("O0001\nG21 G18 G98\nT0202\nG0 X50. Z5.\nG20\nG0 X1. Z0.1\nM30\n", _setup,
     ["G18 G0 X27.54 Z10.08", "G20", "G0 X0.6 Z0.3"]),
    # G91 under a steady offset: the increment is the same (X-2. diameter -> -1.); after G90 the offset again:
    # X40. -> 20. + 2.54 = 22.54, Z 2. + 5.08 = 7.08
    ("O0001\nG21 G18 G94\nT0202\nG0 X50. Z5.\nG91\nG0 X-2. Z-1.\nG90\nG0 X40. Z2.\nM30\n", _system_b,
     ["G91", "G0 X-1. Z-1.", "G90", "G0 X22.54 Z7.08"]),
    # the block's own G90 ends the G91 before its move takes the new offset
    ("O0001\nG21 G18 G94\nG91 T0202\nG90 G0 X50. Z5.\nM30\n", _system_b, ["G18 G90 G0 X27.54 Z10.08"]),
    # an inch increment before G90 and the offset: X1.1 Z0.4 as in the first case
    ("O0001\nG20 G18 G94\nG91\nG0 X-0.1\nG90\nT0202\nG0 X2. Z0.2\nM30\n", _system_b,
     ["G18 G0 X-0.05", "G90", "T2 M0 (TOOL CHANGE: LOAD T2, THEN CYCLE START)", "G0 X1.1 Z0.4"]),
])
def test_the_offset_is_added_in_the_units_and_distance_mode_in_force(
        program: str, setup: Callable[[], MachineSetup], written: list[str]) -> None:
    lines = _to_grbl(program, setup())
    at = lines.index(written[0])
    assert lines[at:at + len(written)] == written, lines


def test_an_incremental_move_that_takes_a_new_offset_is_refused() -> None:
    program = "O0001\nG21 G18 G94\nG0 X50. Z5.\nG91\nT0202\nG0 X-2. Z-1.\nM30\n"
    with pytest.raises(ErrorList) as caught:
        _to_grbl(program, _system_b())
    assert [str(e) for e in caught.value.errors] == [
        "l.nc:6:1: error: an incremental move takes a new lathe tool offset here, which the target has no way to "
        "apply: program X and Z absolutely"]


@pytest.mark.parametrize(("target", "written"), [
    # X50. (diameter) -> 25. + 2.54 = 27.54, Z 5. + 5.08 = 10.08; X40. -> 20. + 2.54 = 22.54
    ("grbl", ["G18 G91 G28 X0. Z0.", "G90", "T2 M0 (TOOL CHANGE: LOAD T2, THEN CYCLE START)", "G0 X27.54 Z10.08",
              "G1 X22.54 F200."]),
    ("mach3", ["G18 G91 G28 X0.0000 Z0.0000", "G90", "T2 M6", "G0 X27.5400 Z10.0800", "G1 X22.5400 F200."]),
])
def test_the_offset_after_a_reference_return_through_the_present_point(target: str, written: list[str]) -> None:
    """``G28 U0. W0.`` is written ``G91 G28 X0. Z0.`` and a ``G90`` block after it: the offsets follow that block
    too, so the absolute move that takes ``T0202`` is one (was: refused as "an incremental move takes a new lathe
    tool offset", the step never saw the G90)."""
    program = "O0001\nG21 G18 G98\nG28 U0. W0.\nT0202\nG0 X50. Z5.\nG1 X40. F200.\nM30\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="l.nc", source="fanuc", target=target, setup=_setup(),
              diagnostics=Diagnostics(warn_stream=io.StringIO()), on_unsupported="error")
    lines = out.getvalue().splitlines()
    at = lines.index(written[0])
    assert lines[at:at + len(written)] == written, lines
    report = verify_lines(io.StringIO(program), io.StringIO(out.getvalue()), file_in="l.nc", file_out="out",
                          source="fanuc", target=target, setup=_setup(), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    if target == "grbl":
        from tests.support.grbl_rules import grbl_problems
        assert grbl_problems(out.getvalue()) == []
