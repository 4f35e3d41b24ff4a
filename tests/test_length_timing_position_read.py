"""A Fanuc lathe offset (``G00 T0202``) or a mill's ``G43 H1`` whose next move leaves an axis the program never
placed, towards LinuxCNC (``postproc.lowering.length_timing``, issue 26).

Fanuc applies the new offset on every axis at the next move (the simulation's model); LinuxCNC's ``G43 H``
only where an axis is next programmed, so ``X86.`` alone would leave Z at the machine point of the old offset.
Where the program's Z is not known, the move gets ``Z#5422``: rs274 sets #5420-#5428 from the current point
when it reads a block, before the block's own ``G43`` [V: ``rs274ngc_pre.cc`` ``Interp::read``], so the move
ends at the old program Z under the new offset, as the Fanuc's does.

Expected values are hand-derived (program Z 0 at rs274's start; the offset's Z 12.7 mm = 0.5 in in rs274's tool
table) and checked against rs274 itself, whose canonical moves give the program point without the tool offset:
the read keeps Z at 0 where ``G43 H2 X86.`` alone would go to -12.7. verify compares the controlled points with a
set-up whose offsets are known; the same output without the read is shown to fail it.
"""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.setup.groups import MachineSettings
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, canonical_moves, motions, run_rs274

needs_rs274 = pytest.mark.skipif(not available(), reason="rs274 (LinuxCNC's interpreter) is not installed")
Z_OFFSET_MM = 12.7
RS274_TOOLS = "T2 P2 X0 Z0.5\nT1 P1 Z0.5\n"
"""rs274's table in inches: tool 2's (and 1's) Z offset is 12.7 mm, X none."""


def _lathe(start_z: float = 0.0) -> MachineSetup:
    setup = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ", start_z=start_z))
    setup.tools = {"2": ToolData(number=2, x=6.0, z=Z_OFFSET_MM), "3": ToolData(number=3, x=-4.0, z=3.0)}
    return setup


def _mill(start_z: float = 0.0) -> MachineSetup:
    setup = MachineSetup(machine=MachineSettings(start_z=start_z))
    setup.tools = {"1": ToolData(number=1, length=Z_OFFSET_MM)}
    return setup


def _translate(text: str, setup: MachineSetup, target: str = "linuxcnc") -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="p.nc", source="fanuc", target=target, setup=setup)
    return out.getvalue()


LATHE_PROGRAM = "O0001\nG00 T0202\nX86.\nZ0.25\nS500 M03\nG01 X80. F0.2\nM30\n"
MILL_PROGRAM = "O0001\nG43 H1\nG00 X10. Y10.\nZ5.\nM30\n"


def test_lathe_move_gets_the_z_read() -> None:
    out = _translate(LATHE_PROGRAM, _lathe())
    assert re.search(r"^G43 H02 G0 X86\. Z#5422$", out, re.M), out


def test_mill_move_gets_the_z_read() -> None:
    out = _translate(MILL_PROGRAM, _mill())
    # G21: the units the program was read in are written (tests/test_units_at_start.py)
    assert re.search(r"^G21 G43 H01 G0 X10\. Y10\. Z#5422$", out, re.M), out


@needs_rs274
def test_lathe_read_held_to_rs274() -> None:
    """By hand: X86. is radius 43 (G7); Z stays at the program's 0 under the new offset, then 0.25 (rs274 starts at 0;
    its ``G0 T2 M6`` moves to where it stands, a zero move left out)."""
    out = _translate(LATHE_PROGRAM, _lathe())
    moves = motions(canonical_moves(run_rs274(out, tool_table=RS274_TOOLS), start=(0.0, 0.0, 0.0)))
    assert [(m["move"], m["x"], m["z"]) for m in moves[:3]] == [("rapid", 43.0, 0.0), ("rapid", 43.0, 0.25),
                                                              ("feed", 40.0, 0.25)], (out, moves)


@needs_rs274
def test_without_the_read_rs274_moves_z_by_the_offset() -> None:
    """The property the read restores: without it rs274 keeps the machine Z, the program Z moving by -12.7."""
    out = _translate(LATHE_PROGRAM, _lathe()).replace(" Z#5422", "")
    moves = motions(canonical_moves(run_rs274(out, tool_table=RS274_TOOLS), start=(0.0, 0.0, 0.0)))
    assert (moves[0]["x"], moves[0]["z"]) == (43.0, -Z_OFFSET_MM), (out, moves)


@needs_rs274
def test_mill_read_held_to_rs274() -> None:
    out = _translate(MILL_PROGRAM, _mill())
    moves = motions(canonical_moves(run_rs274(out, tool_table=RS274_TOOLS), start=(0.0, 0.0, 0.0)))
    assert [(m["x"], m["y"], m["z"]) for m in moves[:2]] == [(10.0, 10.0, 0.0), (10.0, 10.0, 5.0)], (out, moves)


@pytest.mark.parametrize("start_z", [0.0, 50.0, -7.5])
def test_lathe_translation_verifies(start_z: float) -> None:
    setup = _lathe(start_z)
    out = _translate(LATHE_PROGRAM, setup)
    report = verify_lines(io.StringIO(LATHE_PROGRAM), io.StringIO(out), file_in="p.nc", file_out="p.ngc",
                          source="fanuc", target="linuxcnc", setup=setup)
    assert report.ok and report.moves >= 3, report.summary()
    broken = out.replace(" Z#5422", "")
    report = verify_lines(io.StringIO(LATHE_PROGRAM), io.StringIO(broken), file_in="p.nc", file_out="p.ngc",
                          source="fanuc", target="linuxcnc", setup=setup)
    assert not report.ok, report.summary()


def test_mill_translation_verifies() -> None:
    setup = _mill(30.0)
    out = _translate(MILL_PROGRAM, setup)
    report = verify_lines(io.StringIO(MILL_PROGRAM), io.StringIO(out), file_in="p.nc", file_out="p.ngc",
                          source="fanuc", target="linuxcnc", setup=setup)
    assert report.ok, report.summary()


def test_x_read_is_doubled_on_a_diameter_lathe() -> None:
    """``G00 T0202`` then ``Z5.``: X is not known, the read (a radius) is doubled for the diameter X word."""
    text = "O0001\nG00 T0202\nZ5.\nX20.\nM30\n"
    setup = _lathe()
    out = _translate(text, setup)
    assert re.search(r"^G43 H02 G0 (Z5\. X\[#5420\*2\.\]|X\[#5420\*2\.\] Z5\.)$", out, re.M), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="p.nc", file_out="p.ngc",
                          source="fanuc", target="linuxcnc", setup=setup)
    assert report.ok, report.summary()


def _refused(text: str, setup: MachineSetup, target: str = "linuxcnc") -> list[str]:
    with pytest.raises(ErrorList) as err:
        _translate(text, setup, target)
    return [str(e) for e in err.value.errors]


def test_target_without_reads_still_refuses() -> None:
    """grbl reads no parameter: the move stays a located error asking for Z."""
    messages = _refused(MILL_PROGRAM, _mill(), "grbl")
    assert any(m.startswith("p.nc:2:") and "not known where it applies" in m for m in messages), messages


def test_no_read_under_cutter_compensation() -> None:
    """rs274 refuses #5420-#5428 under cutter compensation ("Cannot read current position with cutter radius
    compensation on"): no read is written, the change stays a located error."""
    text = "O0001\nG42\nG00 T0202\nX86.\nZ0.25\nG40\nM30\n"
    messages = _refused(text, _lathe())
    assert any("not known where it applies" in m for m in messages), messages


def test_no_read_after_a_change_written_alone() -> None:
    """``T0202`` replaced by ``T0303`` before any move stays where it was written (it moves nothing there on
    LinuxCNC), but it moves LinuxCNC's program point: a read after it would not be the source's Z, so none."""
    text = "O0001\nG00 T0202\nT0303\nX86.\nZ0.25\nM30\n"
    messages = _refused(text, _lathe())
    assert any(m.startswith("p.nc:3:") and "not known where it applies" in m for m in messages), messages


def test_replaced_change_kept_and_verified() -> None:
    """A cancel replaced before any move (``T0200`` then ``T0303``, a Fanuc lathe's tool change) is written where
    the source has it, so the offsets verify compares come in the source's order."""
    text = "O0001\nG00 T0202\nX86. Z1.\nT0200\nT0303\nX50.\nZ2.\nM30\n"
    setup = _lathe()
    out = _translate(text, setup)
    assert re.search(r"^G49$", out, re.M), out
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="p.nc", file_out="p.ngc",
                          source="fanuc", target="linuxcnc", setup=setup)
    assert report.ok, report.summary()


@pytest.mark.parametrize("text, line", [
    ("O0001\nG00 T0202\nG55\nX86.\nZ0.25\nM30\n", 4),  # a work system selected since the start
    ("O0001\nG00 T0202\nG55 X86.\nZ0.25\nM30\n", 3),  # ... in the moving block itself (LinuxCNC reads before it)
    ("O0001\nG00 T0202\nG20 X3.\nZ0.25\nM30\n", 3),  # units changed in the moving block
])
def test_no_read_where_the_point_was_re_expressed(text: str, line: int) -> None:
    """The read is the start's point only while nothing but the start placed the axis: a work system or unit
    change leaves the Fanuc's programmed Z to what the run knows; a located error as before."""
    messages = _refused(text, _lathe())
    assert any(m.startswith(("p.nc:2:", f"p.nc:{line}:")) and "not known where it applies" in m
               for m in messages), messages
