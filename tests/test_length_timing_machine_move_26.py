"""A tool length change without Z after a move in machine coordinates, translated towards a controller that
applies it at the next absolute Z (``postproc.lowering.length_timing``, ``length_point.MachineFrame``; issue 26, audit26).

The hand-written Haas pattern ``G53 Z0.`` (home), ``T1 M06``, ``G43 H01`` alone, ``G00 X.. Y..``: the source
(Fanuc rule: the length applies at the next move) keeps the programmed Z while its XY rapid takes the length, so
the target's move must name the Z the program stands at. That Z is the machine Z0 put in work coordinates: less
the active work system's offset. It was written as the machine's number (``Z0.``), a rapid down to the part's
zero wherever G55 is not at machine zero; verify saw it only where the set-up gave G55's offset (250 mm off).

Expected values are derived by hand: G55's Z offset -250 mm, so machine Z0 is work Z 0 - (-250) = 250; no
length is in force at the G53 move (G49 by default)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine import ToolData, WorkOffsetData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines

PROGRAM = "G21 G90 G55\nG53 Z0.\nT1 M06\nG43 H01\nG00 X-1.25 Y-0.25\nZ1.\nG01 X3. F100.\nM30\n"


def _setup(offset: bool = True) -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {"1": ToolData(number=1, length=101.0)}
    if offset:
        setup.work_offsets = {"2": WorkOffsetData(number=2, x=-300.0, y=-200.0, z=-250.0)}
    return setup


def _translate(text: str, target: str, setup: MachineSetup) -> list[str]:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target=target, setup=setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out.getvalue(), newline=""), file_in="in.nc",
                          file_out="out", source="fanuc", target=target, setup=setup)
    assert report.ok and report.max_deviation == 0.0, (out.getvalue(), report)
    return out.getvalue().splitlines()


@pytest.mark.parametrize("target, written", [
    ("linuxcnc", "G43 H01 G0 X-1.25 Y-0.25 Z250."),
    ("grbl", "G0 X-1.25 Y-0.25 Z250."),
    ("isg", "D01 G00 X-1.25 Y-0.25 Z250."),
])
def test_the_move_gets_the_machine_z_in_work_coordinates(target: str, written: str) -> None:
    assert written in _translate(PROGRAM, target, _setup())


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "isg"])
def test_without_the_work_offset_it_is_a_located_error_naming_it(target: str) -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(PROGRAM, target, _setup(offset=False))
    message = str(caught.value.errors[0])
    assert message.startswith("in.nc:4:5: error: ") and '<Offset number="2" z=...>' in message


def test_after_a_g92_the_translation_evaluates_the_move_is_in_the_targets_frame() -> None:
    """G92 Z0. at work Z10 is evaluated into the coordinates before this step (``(G92 Z0. evaluated)``, the later
    Z1. written Z11.): the target stays in G55, where machine Z0 is still work Z250."""
    shifted = PROGRAM.replace("G53 Z0.\n", "G0 X0 Y0 Z10.\nG92 Z0.\nG53 Z0.\n")
    lines = _translate(shifted, "linuxcnc", _setup())
    assert "G43 H01 G0 X-1.25 Y-0.25 Z250." in lines and "G0 Z11." in lines


def test_a_change_of_work_system_after_the_machine_move_reads_the_z_in_the_new_system() -> None:
    """G53 Z0. under G54 (Z offset -350 mm: work Z 350), then ``G55 G00 X Y`` beside the waiting length: the machine
    stays, so the Z the move must name is machine Z0 less G55's -250 mm: 250 (hand-derived)."""
    setup = _setup()
    setup.work_offsets["1"] = WorkOffsetData(number=1, x=-400.0, y=-250.0, z=-350.0)
    program = PROGRAM.replace("G21 G90 G55\n", "G21 G90 G54\n").replace("G00 X-1.25", "G55 G00 X-1.25")
    assert "G55 G43 H01 G0 X-1.25 Y-0.25 Z250." in _translate(program, "linuxcnc", setup)
