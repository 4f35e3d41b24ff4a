"""``<Controller startUnits>``: the units a controller is in at power-on (Fanuc parameter 0000#2 INI [K], Haas
Setting 9 [K]) carried by a program that programs none (``postproc.syntaxes.power_on_units``). Expected values by
hand: an inch is 25.4 mm."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList, PostprocError
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events

PROGRAM = "%\nO1000\n(NO UNITS)\nG90 G54 G00 X1. Y2.\nG01 Z-0.5 F10.\nM30\n%\n"


def machine(units: str | None) -> MachineSetup:
    setup = MachineSetup()
    setup.controller.start_units = units  # type: ignore[assignment]
    return setup


def points(text: str, setup: MachineSetup) -> list[tuple[float, float, float]]:
    return [(e["x"], e["y"], e["z"]) for e in toolpath_events(io.StringIO(text), file="p.nc", dialect="fanuc",
                                                               setup=setup) if "move" in e]


def write(text: str, target: str, setup: MachineSetup) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="p.nc", source="fanuc", target=target, setup=setup)
    return out.getvalue()


def test_an_inch_machine_runs_a_program_without_units_in_inches() -> None:
    assert points(PROGRAM, machine("inch")) == [(25.4, 50.8, 0), (25.4, 50.8, -12.7)]
    assert points(PROGRAM, machine(None)) == [(1, 2, 0), (1, 2, -0.5)]
    assert write(PROGRAM, "fanuc", machine("inch")) == PROGRAM  # the controller's own copy: as written
    ngc = write(PROGRAM, "linuxcnc", machine("inch")).splitlines()
    assert any(line.startswith("G90 G54 G20") or "G20" in line.split("(")[0] for line in ngc[:5]), ngc
    assert not any("G21" in line for line in ngc)


def test_a_metric_setting_and_a_programmed_unit_change_nothing() -> None:
    assert points(PROGRAM, machine("mm")) == [(1, 2, 0), (1, 2, -0.5)]
    metric = PROGRAM.replace("G90 G54 G00", "G21 G90 G54 G00")
    assert points(metric, machine("inch")) == [(1, 2, 0), (1, 2, -0.5)]
    assert write(metric, "linuxcnc", machine("inch")).count("G20") == 0


def test_a_statement_before_the_first_length_leaves_the_units_to_the_block_after_it() -> None:
    """``#100=1.`` reads no length: the move after it carries the units, run or kept as written."""
    text = PROGRAM.replace("(NO UNITS)\n", "(NO UNITS)\n#100=1.\n").replace("X1. Y2.", "X#100 Y2.")
    assert points(text, machine("inch")) == [(25.4, 50.8, 0), (25.4, 50.8, -12.7)]
    assert write(text, "fanuc", machine("inch")) == text
    ngc = write(text, "linuxcnc", machine("inch"))
    assert "G20" in ngc and "G21" not in ngc


def test_a_subprogram_defined_first_runs_in_the_units_and_is_flattened_to_carry_them() -> None:
    """Its blocks run where it is called, after the program's first move, which carries the units (run: inches
    throughout); kept as written they would land in the definition, so a translation is flattened, saying why."""
    text = "o<sq> sub\nG1 X1 F10\no<sq> endsub\nG0 X2\no<sq> call\nM2\n"
    assert [e["x"] for e in toolpath_events(io.StringIO(text), file="p.ngc", dialect="linuxcnc", setup=machine("inch"))
            if "move" in e] == [50.8, 25.4]
    warnings = io.StringIO()
    from postproc.errors import Diagnostics, ErrorLevel
    out = io.StringIO()
    translate(io.StringIO(text), out, file="p.ngc", source="linuxcnc", target="fanuc", setup=machine("inch"),
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=warnings))
    assert out.getvalue().splitlines()[0] == "G20 G00 X2."
    assert "would go into a subprogram defined before the program" in warnings.getvalue()
