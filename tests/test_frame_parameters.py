"""A program reads its own frame (issue #27): LinuxCNC's offset parameters #5210-#5219 (the shared G52/G92
offset) and a work system's #5221.. (offsets and R set by G10 L2 in the program), in the machine's length
units, derived by hand and against rs274 (simulated, and again after translation to grbl, flattened).

rs274 stores these parameters in its external (INI) length units ([V] ``interp_convert.cc``
``PROGRAM_TO_USER_LEN``, ``units.h``); standalone, without an INI file, that is inches: the oracle runs
compare with a set-up whose machine is in inches.
"""

from __future__ import annotations

import io
import math
import os
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine_setup import MachineSetup, MachineSettings
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, run_rs274
from tests.test_frames import _batch, _Gen, _machine, _same, _segments

SEEDS = range(int(os.environ.get("POSTPROC_FRAME_PARAMETER_PROGRAMS", "100")))
BATCH = 25


def _setup(units: str) -> MachineSetup:
    setup = MachineSetup()
    setup.machine = MachineSettings(units=units)
    return setup


def moves(text: str, units: str = "mm") -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="t.ngc", dialect="linuxcnc", setup=_setup(units))
    return [e for e in events if "move" in e]


OFFSETS = """G21 G90 G0 X10 Y5
G92 X0 Y0
G1 X#5211 Y#5212 F100
G52 X3
G1 X#5211 Z#5210
G92.2
G1 X#5211 Y#5210
G92.1
G1 X[#5211+1] Y[#5210+2]
M2
"""


def test_the_shared_offset_parameters_read_what_g52_and_g92_left() -> None:
    """By hand: G92 X0 Y0 at (10, 5) makes the offset (10, 5), #5210 = 1; G1 X10 Y5 goes to (20, 10). G52 X3
    replaces X only: (3, 5); X3 Z1 -> (6, 10, 1). G92.2 clears the offset (#5210 = 0) but keeps #5211 = 3:
    X3 Y0 -> (3, 0, 1). G92.1 clears the parameters too: X1 Y2 -> (1, 2, 1)."""
    got = [(e["x"], e["y"], e["z"]) for e in moves(OFFSETS)]
    assert got == [(10, 5, 0), (20, 10, 0), (6, 10, 1), (3, 0, 1), (1, 2, 1)]


def test_the_parameters_are_in_the_machines_units() -> None:
    """The same program on an inch machine: #5211 = 10 mm = 0.3937 in, read as a mm word."""
    got = [(round(e["x"], 6), round(e["y"], 6)) for e in moves(OFFSETS, "inch")]
    assert got[1] == (round(10 + 10 / 25.4, 6), round(5 + 5 / 25.4, 6))


def test_a_work_systems_parameters_read_what_g10_set_in_the_program() -> None:
    """G10 L2 P1 X7 Y-3 R30: #5221 = 7, #5222 = -3, #5230 = 30 (read before R0 takes the rotation away); at
    X7 Y-3 in G54 the tool is at (14, -6)."""
    got = moves("G21 G90 G10 L2 P1 X7 Y-3 R30\n#1=#5230\nG10 L2 P1 R0\nG0 X#5221 Y#5222 Z#1\nM2\n")
    assert [(e["x"], e["y"], e["z"]) for e in got] == [(14, -6, 30)]


INCH_READING = ("G20\nG90 G10 L2 P1 X1. Y0\nG54\no1 if [#5221 LT 1]\nG0 X2. Y0\no1 else\nG0 X3. Y0\no1 endif\n"
                "M2\n")


def test_an_inch_machine_reads_an_offset_as_linuxcnc_stores_it() -> None:
    """G10 L2 P1 X1 in G20 on an inch machine: LinuxCNC stores PROGRAM_TO_USER_LEN(1) = (1 * 25.4) * (1/25.4),
    the INI's inch being 1/25.4 mm per unit [V: units.h, inifile.cc, emccanon.cc GET_EXTERNAL_LENGTH_UNITS]:
    0.9999999999999999, not 1 (what dividing by 25.4 gave). So [#5221 LT 1] holds: X2 in G54 at X1 is 3 in,
    76.2 mm (the old reading went to X3, 101.6 mm). (A standalone rs274 multiplies by 0.03937007874016 and
    reads 1.000000000000064 [V: sai/driver.cc]: not the machine's arithmetic.)"""
    assert 1.0 * 25.4 * (1.0 / 25.4) < 1.0  # the machine's double arithmetic, as its source spells it
    assert [round(e["x"], 6) for e in moves(INCH_READING, "inch")] == [76.2]


SAME_BLOCK = "G21\nG20 G90 G10 L2 P1 X1. Y0\nG54\nG0 X[#5221] Y0\nM2\n"


@pytest.mark.parametrize("units, x", [("mm", 25.4 + 25.4 * 25.4), ("inch", 2 * 25.4)])
def test_a_g10_in_the_block_that_selects_inches_stores_inches(units: str, x: float) -> None:
    """rs274 sets the units before G10 in one block [V: LinuxCNC order of execution; rs274 prints
    SET_G5X_OFFSET(1, 1.0000, ..) in inches]: the offset is 1 in, and #5221 reads 25.4 on a mm machine (X25.4
    in G20: 645.16 mm from the 25.4 mm offset), 1 on an inch machine (2 in). The readback took the X1 as mm
    (26.4 mm on the inch machine)."""
    assert [round(e["x"], 6) for e in moves(SAME_BLOCK, units)] == [round(x, 6)]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_a_g10_in_the_block_that_selects_inches_as_rs274_runs_it() -> None:
    theirs = [e for e in _machine(run_rs274(SAME_BLOCK)) if e["move"] == "rapid"]  # in inches after G20
    ours = moves(SAME_BLOCK, "inch")
    assert [round(e["x"] * 25.4, 6) for e in theirs] == [round(e["x"], 6) for e in ours] == [50.8]


WORK_SYSTEM = "G21 G90 G0 X0 Y0\nG59.1\n#1=#5220\nG55\nG0 X#1 Y#5220\nG54\nG0 X#5220\nM2\n"


def test_the_active_work_system_number_reads_the_last_selection() -> None:
    """#5220 is 1 (G54) to 9 (G59.3) [V: interp_parameter_def.hh]: G59.1 makes it 7, G55 2: X7 Y2; G54: X1. The
    work offsets are the set-up's (none: zero), so the points are the words."""
    assert [(e["x"], e["y"]) for e in moves(WORK_SYSTEM)] == [(7, 2), (1, 2)]


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_active_work_system_number_as_rs274_reads_it() -> None:
    theirs = [(e["x"], e["y"]) for e in _machine(run_rs274(WORK_SYSTEM)) if e["move"] == "rapid"]
    assert theirs[1:] == [(7, 2), (1, 2)]


@pytest.mark.parametrize("text, named", [
    ("G21 G0 X#5221\nM2\n", "#5221 (work offset)"),  # the set-up's G54, not set by the program
    ("G21 G0 X#5220\nM2\n", "#5220 (active coordinate system)"),
])
def test_a_parameter_the_program_did_not_set_is_the_machines(text: str, named: str) -> None:
    with pytest.raises(ErrorList) as info:
        moves(text)
    assert named in str(info.value.errors[0])


def test_a_translation_to_a_target_without_variables_reads_them_when_flattened() -> None:
    out = io.StringIO()
    translate(io.StringIO(OFFSETS), out, file="t.ngc", source="linuxcnc", target="grbl")
    lines = [line for line in out.getvalue().splitlines() if line.startswith(("G1", "X", "Y", "Z"))]
    assert lines[:4] == ["G1 X20. Y10. F100.", "G1 X6. Z1.", "G1 X3. Y0.", "G1 X1. Y2."]


class _ParameterGen(_Gen):
    """The frame generator, and moves whose words read the offset parameters (in inches: rs274's external
    units without an INI file; ``* 25.4`` makes them mm words on both sides)."""

    def program(self) -> str:
        lines = super().program().splitlines()
        out: list[str] = []
        work_set = False
        for line in lines:
            out.append(line)
            if line.startswith("G10 L2"):
                work_set = True
            if line.startswith("G90 G0 X") and self.r.random() < 0.7:
                out.append(self._reading(work_set))
        return "\n".join(out) + "\n"

    def _reading(self, work_set: bool) -> str:
        r = self.r
        x = r.choice(["#5211*25.4", "#5212*25.4+1", "#5211*-25.4"])
        y = r.choice(["#5212*25.4", "#5210*7", "#5213*25.4"])
        if work_set and r.random() < 0.5:
            x = r.choice(["#5221*25.4", "#5222*25.4"])
            y = "#5230/10"
        return f"G90 G1 X[{x}] Y[{y}] Z{self.num(0, 10)} F200"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("batch", range(math.ceil(len(SEEDS) / BATCH)))
def test_random_programs_reading_the_offset_parameters_run_as_in_rs274(batch: int) -> None:
    seeds = list(SEEDS)[batch * BATCH:(batch + 1) * BATCH]
    texts = [_ParameterGen(seed).program() for seed in seeds]
    grbls = []
    for text in texts:
        out = io.StringIO()
        translate(io.StringIO(text), out, file="gen.ngc", source="linuxcnc", target="grbl", setup=_setup("inch"))
        grbls.append(out.getvalue())
    source_runs = _segments(run_rs274(_batch(texts), timeout=120), len(texts))
    grbl_runs = _segments(run_rs274(_batch(grbls), timeout=120), len(texts))
    for seed, text, grbl, theirs, evaluated in zip(seeds, texts, grbls, source_runs, grbl_runs):
        want = _machine(theirs)
        _same(moves(text, "inch"), want, text, seed)
        _same(_machine(evaluated), want, text + "\n--- grbl ---\n" + grbl, seed)


def test_the_generator_reads_every_kind_of_parameter() -> None:
    text = "".join(_ParameterGen(seed).program() for seed in SEEDS)
    for word in ("#5210", "#5211", "#5212", "#5213", "#5221", "#5222", "#5230"):
        assert word in text, word


READS = "G21 G90 G0 X10 Y5\nG92 X0 Y0\n#1=#5211\nG1 X#1 F100\nM2\n"
"""A program that computes and reads its G92 offset (#5211 = 10 mm): G1 X10 goes to work X20."""


def _translated(text: str, target: str, transform: str | None = None) -> tuple[str, str]:
    out, warned = io.StringIO(), io.StringIO()
    translate(io.StringIO(text), out, file="t.ngc", source="linuxcnc", target=target, transform=transform,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=warned))
    return out.getvalue(), warned.getvalue()


def test_a_program_reading_its_frame_is_flattened_where_the_frame_is_evaluated() -> None:
    """Fanuc's #5211 is an external work offset, and the evaluated G92 sets nothing there: kept symbolically
    the program would read another value. Flattened, it moves to X20."""
    out, warned = _translated(READS, "fanuc")
    assert "#" not in out and "G01 X20. F100." in out.splitlines()
    assert "it reads its coordinate frame (#5211)" in warned


def test_a_program_reading_its_frame_stays_symbolic_where_the_frame_stays_native() -> None:
    out, warned = _translated(READS, "linuxcnc")
    assert out == READS and warned == ""


def test_a_transform_evaluates_the_frame_back_to_its_own_dialect_so_the_program_is_flattened() -> None:
    out, warned = _translated(READS, "linuxcnc", transform="translate 1,0")
    assert "#" not in out and "G1 X21. F100." in out.splitlines()
