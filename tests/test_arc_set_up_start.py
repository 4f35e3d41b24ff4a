"""An arc after a reference return, a move in machine coordinates or a change of work system, whose start the
set-up places (``ModalState.places``: ``postproc.ir.state.SetUpPlaces``).

Before, the reading left the start unknown after ``G28``/``G53``/``G55`` and a translation to another dialect
refused every such arc with an absolute end in its plane ("a start whose X is unknown"), even where the set-up
declares the machine's reference positions and work offsets, which the simulator (and so ``verify``) takes the
tool to. Where the set-up declares them the start is known, and the arc is translated and verified, or refused by
the ordinary arc check when it does not fit that start; where it does not (or the program sets an offset itself),
the refusal stays, located.

The expected points are derived by hand from the set-up below: X home -100, G54 X-150, G55 X-95 (machine
coordinates, mm), so G28 X.. ends at work X50 under G54, G53 X-100 likewise, and X0 under G54 (machine -150) is
X-55 under G55. LinuxCNC's rs274 runs each LinuxCNC translation with the same values as its parameters (#5161,
the G28 position, in its machine unit, inches; G10 L2 for the offsets) and moves as the source's toolpath does.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274
from tests.support.pair_checks import PairChecks

SETUP = """<?xml version="1.0" encoding="UTF-8"?>
<MachineSetup name="t">
  <Axes>
    <Axis name="X" home="-100."/>
    <Axis name="Y" home="0."/>
    <Axis name="Z" home="0."/>
  </Axes>
  <WorkOffsets>
    <Offset number="1" x="-150." y="0." z="0."/>
    <Offset number="2" x="-95." y="0." z="0."/>
  </WorkOffsets>
</MachineSetup>
"""
RS274_MACHINE = "#5161=[-100/25.4]\n#5162=0\n#5163=0\nG21 G10 L2 P1 X-150 Y0 Z0\nG10 L2 P2 X-95 Y0 Z0\n"
"""The set-up as rs274's parameters, before the program (its G28 position is in its machine unit, inches)."""

PLACED = {
    "reference return": "G21 G90 G17\nG28 X0. Y0.\nG1 Z-1. F100.\nG2 X60. Y0. I5. J0.\nG0 Z5.\nM30\n",
    "machine move": "G21 G90 G17\nG53 G0 X-100. Y0.\nG1 Z-1. F100.\nG2 X60. Y0. I5. J0.\nG0 Z5.\nM30\n",
    "work system": "G21 G90 G17 G54\nG0 X0. Y0.\nG55\nG1 Z-1. F100.\nG2 X-45. Y0. I5. J0.\nG0 Z5.\nM30\n",
    "inch": "G20 G90 G17\nG28 X0. Y0.\nG1 Z-0.04 F4.\nG3 X1.7685 Y0. I-0.1 J0.\nG0 Z0.2\nM30\n",
}
"""Each arc starts where the set-up puts the tool (X50, X50, X-55, X50 mm = 1.9685 in) and ends on its circle."""


@pytest.fixture(scope="module")
def setup(tmp_path_factory: pytest.TempPathFactory) -> MachineSetup:
    path = tmp_path_factory.mktemp("setup") / "m.xml"
    path.write_text(SETUP)
    return load_setup(path)


@pytest.mark.parametrize("case", sorted(PLACED))
@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "grblhal", "isg"])
def test_an_arc_the_set_up_places_is_translated_and_verified(setup: MachineSetup, case: str, target: str) -> None:
    check = PairChecks(setup)
    out = check.translate(PLACED[case], "fanuc", target)
    if target == "isg" and case == "inch":  # ISG writes the home as an inch move at 8 places (-3.93700787 for
        # -100 mm): its arc starts that rounding away, 1e-5 mm at most here; PairChecks wants no deviation at all
        report = verify_lines(io.StringIO(PLACED[case]), io.StringIO(out), file_in="a.nc", file_out="b.nc",
                              source="fanuc", target=target, tolerance=1e-4, setup=setup)
        assert report.ok and report.max_deviation < 1e-4, report.summary()
        return
    check.verify(PLACED[case], out, "fanuc", target)


@pytest.mark.parametrize("case", sorted(PLACED))
def test_rs274_runs_the_linuxcnc_translation_as_the_source_moves(setup: MachineSetup, case: str) -> None:
    if not rs274.available():
        pytest.skip("rs274 is not installed")
    out = PairChecks(setup).translate(PLACED[case], "fanuc", "linuxcnc")
    theirs = rs274.motions(rs274.canonical_moves(rs274.run_rs274(RS274_MACHINE + out, tool_table="T1 P1 Z0 D0\n")))
    ours = [dict(move=e["move"], x=e["x"], y=e["y"], z=e["z"])
            for e in toolpath_events(io.StringIO(PLACED[case]), file="in.nc", dialect="fanuc", setup=setup)
            if "move" in e]
    # rs274 starts at machine zero (work X150 here), the simulation at the work origin: a first move to X0 is one
    # more move there, none here (a zero-length move is dropped); from the placed point on, every move is the same
    assert len(theirs) - len(ours) in (0, 1)
    rs274.assert_same_moves(ours, theirs[-len(ours):], out)


def test_an_arc_off_the_placed_start_is_refused_as_any_arc(setup: MachineSetup) -> None:
    program = PLACED["reference return"].replace("X60.", "X61.")
    (error,) = PairChecks(setup).errors(program, "fanuc", "linuxcnc")
    assert error.startswith("in.nc:4:") and "radius 5.0000 mm at the start, 6.0000 mm at the end" in error


@pytest.mark.parametrize(("program", "axis"), [
    ("G21 G90 G17\nG0 X0. Y0.\nG10 L2 P1 X5.\nG2 X10. Y0. I5. J0. F100.\nM30\n", "X"),  # the program's offset
    ("G21 G90 G17\nG30 X0. Y0.\nG2 X60. Y0. I5. J0. F100.\nM30\n", "X"),  # a second reference: no element for it
    ("G21 G90 G17\nG0 X0. Y0.\nG56\nG2 X10. Y0. I5. J0. F100.\nM30\n", "X"),  # G56: no offset in the set-up
])
def test_where_the_set_up_does_not_place_it_the_refusal_stays(setup: MachineSetup, program: str, axis: str) -> None:
    errors = PairChecks(setup).errors(program, "fanuc", "linuxcnc")
    assert len(errors) == 1 and f"from a start whose {axis} is unknown" in errors[0]


def test_without_a_home_in_the_set_up_the_refusal_stays() -> None:
    errors = PairChecks(MachineSetup()).errors(PLACED["reference return"], "fanuc", "linuxcnc")
    assert len(errors) == 1 and errors[0].startswith("in.nc:4:4: error: the arc ends at an absolute X from a start")
    assert errors[0].endswith("declare the machine's home and work offsets in the set-up: <Axes><Axis home>, "
                              "<WorkOffsets>)")
