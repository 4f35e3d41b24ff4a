"""A lathe cycle that would cut at F0 is refused where it is read, as a G01 at F0 is: Fanuc alarms on a
cutting feed of zero (PS0011, "FEED ZERO"), rs274 ("Cannot do g1 with zero feed rate") and grbl (error 22)
refuse every move it expands to. ``translate`` to any target, and ``toolpath``, refuse it alike."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events

LATHE = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"))
MESSAGE = "a feed move at a zero feed rate (F0 is in force: program a feed rate above 0 first)"
PROFILE = "N10 G00 X20.\nG01 Z-15. F0.12\nN20 X48.\n"

CYCLES = [  # (cycle lines; line and column of the refusal: the F0 word, or the cycle's G when F0 came earlier)
    ("G90 X40. Z-20. F0\n", 5, 16),
    ("G94 X20. Z-2. F0\n", 5, 15),
    ("G01 F0\nG90 X40. Z-20.\n", 6, 1),
    ("G75 R0.3\nG75 X40. Z-28. P1000 Q8000 F0\n", 6, 28),
    ("G74 R0.3\nG74 X0 Z-20. P1000 Q8000 F0\n", 6, 26),
    ("G71 U2. R0.5\nG71 P10 Q20 U0.5 W0. F0\n" + PROFILE, 6, 22),
    ("G72 W2. R0.5\nG72 P10 Q20 U0.5 W0. F0\nN10 G00 Z-15.\nG01 X20. F0.12\nN20 Z2.\n", 6, 22),
    ("G73 U2. W0. R2\nG73 P10 Q20 U0.5 W0. F0\n" + PROFILE, 6, 22),
]


def program(cycle: str) -> str:
    return "G21 G99\nT0101\nG97 S500 M03\nG00 X50. Z2.\n" + cycle + "G00 X100. Z100.\nM30\n"


@pytest.mark.parametrize("dialect", ["fanuc", "gsk"])
@pytest.mark.parametrize("target", ["same", "linuxcnc"])
@pytest.mark.parametrize("cycle, line, col", CYCLES)
def test_a_cycle_at_f0_is_a_located_error(dialect: str, target: str, cycle: str, line: int, col: int) -> None:
    code = cycle.splitlines()[-1][:3] if cycle.startswith("G01") else cycle[:3]
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(program(cycle)), io.StringIO(), file="in.nc", source=dialect,
                  target=dialect if target == "same" else target, setup=LATHE)
    assert f"in.nc:{line}:{col}: error: {code}: {MESSAGE}" in [str(e) for e in caught.value.errors]


@pytest.mark.parametrize("cycle, line, col", CYCLES[:2])
def test_the_toolpath_refuses_it_too(cycle: str, line: int, col: int) -> None:
    with pytest.raises(ErrorList) as caught:
        list(toolpath_events(io.StringIO(program(cycle)), file="in.nc", dialect="fanuc", setup=LATHE))
    assert [str(e) for e in caught.value.errors] == [f"in.nc:{line}:{col}: error: {cycle[:3]}: {MESSAGE}"]


def test_a_first_block_and_a_g70_with_fed_profile_blocks_need_no_cycle_feed() -> None:
    """G71's first block moves nothing, and G70 cuts at the profile's own feed rates (F0.12 here):
    an F0 in force around them is no refusal. ``G01 F0`` alone only sets the mode and the feed rate:
    LinuxCNC refuses ``G1 F0`` ("Cannot do g1 with zero feed rate"), so its G1 is left out."""
    text = program("G01 F0\nG71 U2. R0.5\nG71 P10 Q20 U0.5 W0. F0.25\n" + PROFILE + "G01 F0\nG70 P10 Q20\n")
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="linuxcnc", setup=LATHE)
    assert "F0.12" in out.getvalue() and "G1 F0." not in out.getvalue() and "\nF0.\n" in out.getvalue()


STALLED = [  # (spindle words, cut; line and column of the refusal; what the spindle does)
    ("G97 S0 M03", "G01 Z-20. F0.2", 5, 5, "at spindle speed S0"),
    ("G97 S0 M03", "G90 X40. Z-20. F0.2", 5, 1, "at spindle speed S0"),
    ("G97 S500 M05", "G90 X40. Z-20. F0.2", 5, 1, "with the spindle stopped"),
    ("G97 S0 M03", "G74 R0.3\nG74 X0 Z-20. P1000 Q8000 F0.2", 6, 1, "at spindle speed S0"),
]


@pytest.mark.parametrize("spindle, cut, line, col, what", STALLED)
@pytest.mark.parametrize("target", ["fanuc", "linuxcnc"])
def test_a_cut_per_revolution_with_the_spindle_at_s0_or_stopped_is_a_located_error(
        spindle: str, cut: str, line: int, col: int, what: str, target: str) -> None:
    """In G99 the axes wait for revolutions: at S0 (or stopped) they never come. A Fanuc waits forever;
    rs274 refuses the LinuxCNC spelling ("Cannot feed with zero spindle speed in feed per rev mode"), which
    the plain G01 at S0 was written as, and a cycle's cuts too (found by the fuzz generator)."""
    text = f"G21 G99\nT0101\n{spindle}\nG00 X50. Z2.\n{cut}\nG00 X100. Z100.\nM30\n"
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(text), io.StringIO(), file="in.nc", source="fanuc", target=target, setup=LATHE)
    code = "" if cut.startswith("G01") else cut.splitlines()[-1][:3] + ": "
    assert [str(e) for e in caught.value.errors] == [
        f"in.nc:{line}:{col}: error: {code}a feed-per-revolution move {what}: the axes would wait for revolutions "
        f"that never come ({'start the spindle first' if 'stopped' in what else 'program a speed above 0 first'}, "
        "or feed per minute)"]


def test_rs274_refuses_a_feed_per_revolution_at_s0() -> None:
    from tests.support.rs274 import RS274Error, available, run_rs274
    if not available():
        pytest.skip("rs274 is not installed")
    with pytest.raises(RS274Error, match="Cannot feed with zero spindle speed in feed per rev mode"):
        run_rs274("G21 G95\nS0 M3\nG18 G0 X25. Z2.\nG1 Z-20. F0.2\nM2\n")
