"""``postproc info``: a small program whose every figure is worked out by hand below."""

from __future__ import annotations

import json
import math

import pytest

from postproc.commands.info import program_info

PROGRAM = """\
G21 G90 G17 G98
T1 M6
G0 X0 Y0 Z5
G1 Z0 F100
G1 X30 F300
G3 X30 Y20 I0 J10
G4 P2
G0 Z5
T2 M6
G0 X0 Y0
G81 X10 Y10 Z-3 R2 F60
X20
G80
M2
"""
SETUP = """\
<MachineSetup>
  <Axes>
    <Axis name="X" rapid="6000"/>
    <Axis name="Y" rapid="6000"/>
    <Axis name="Z" rapid="3000"/>
  </Axes>
  <WorkOffsets>
    <Offset number="1" x="-100" y="-50" z="-200"/>
  </WorkOffsets>
</MachineSetup>
"""

# By hand, from the start point X0 Y0 Z0 (the set-up's default):
# tool 1: feeds Z5->Z0 5 mm at F100 (3 s), X0->X30 30 mm at F300 (6 s), the ccw half circle about X30 Y10,
#   radius 10: pi * 10 mm at F300 (2 pi s); rapids Z0->Z5 and Z0->Z5: 10 mm, 5 / 3000 min = 0.1 s each.
# tool 2: rapid X30 Y20 -> X0 Y0: sqrt(30^2 + 20^2) mm, X the slowest: 30 / 6000 min = 0.3 s; each hole (G98:
#   back to the initial Z5): rapid over to it at Z5 (sqrt(200) mm for the first, 10 for the second; 0.1 s
#   each), down to R2 (3 mm, 0.06 s), feed to Z-3 (5 mm at F60: 5 s), rapid back to Z5 (8 mm, 0.16 s).
# The half circle bulges to X40 (its quadrant point at angle 0 about X30 Y10).
FEED_1 = 5 + 30 + math.pi * 10
FEED_1_S = 3 + 6 + 2 * math.pi
RAPID_2 = math.hypot(30, 20) + math.sqrt(200) + 3 + 8 + 10 + 3 + 8
RAPID_S = 0.1 + 0.1 + 0.3 + (0.1 + 0.06 + 0.16) * 2


@pytest.fixture
def setup_file(tmp_path):
    path = tmp_path / "m.xml"
    path.write_text(SETUP)
    return path


def _report(setup=None, targets=False):
    from postproc.setup.machine_setup import load_setup
    from postproc.plugins import default_registry
    loaded = None if setup is None else load_setup(str(setup), groups=default_registry().setup_groups)
    return program_info(PROGRAM.splitlines(True), file="p.ngc", dialect="linuxcnc", setup=loaded, targets=targets)


def test_extent_tools_and_time_by_hand(setup_file) -> None:
    report = _report(setup_file)
    assert report["extent"]["work"] == {"X": {"min": 0, "max": 40}, "Y": {"min": 0, "max": 20},
                                        "Z": {"min": -3, "max": 5}}
    assert report["extent"]["machine"] == {"X": {"min": -100, "max": -60}, "Y": {"min": -50, "max": -30},
                                           "Z": {"min": -203, "max": -195}}
    (one, two) = report["tools"]
    assert (one["number"], one["line"], two["number"], two["line"]) == (1, 2, 2, 9)
    assert one["feed_mm"] == pytest.approx(FEED_1, abs=1e-4) and one["feed_s"] == pytest.approx(FEED_1_S, abs=1e-4)
    assert one["rapid_mm"] == pytest.approx(10, abs=1e-4)
    assert (two["feed_mm"], two["feed_s"]) == (10, 10)
    assert two["rapid_mm"] == pytest.approx(RAPID_2, abs=1e-4)
    time = report["time"]
    assert time["complete"] and time["rapid_s"] == pytest.approx(RAPID_S, abs=1e-4)
    assert time["dwell_s"] == 2
    assert time["total_s"] == pytest.approx(FEED_1_S + 10 + RAPID_S + 2, abs=1e-3)
    assert report["holes"] == 2 and report["cycles"] == {"drill": 1}
    assert {"arcs", "canned cycle: drill", "dwells"} <= set(report["features"])


def test_without_rates_the_rapids_are_not_timed_and_it_says_so() -> None:
    report = _report()
    time = report["time"]
    assert not time["complete"] and time["rapid_s"] == 0
    assert time["untimed_rapid_mm"] == pytest.approx(10 + RAPID_2, abs=1e-4)
    assert any("no rapid rate" in said for said in report["assumed"])
    assert report["extent"]["machine"] is None


def test_machine_extent_unknown_without_the_work_offset(tmp_path) -> None:
    path = tmp_path / "m.xml"
    path.write_text("<MachineSetup><WorkOffsets><Offset number=\"1\" x=\"-100\"/></WorkOffsets></MachineSetup>")
    machine = _report(path)["extent"]["machine"]
    assert machine["X"] == {"min": -100, "max": -60}
    assert "no offset for Y" in machine["Y"]["unknown"]


def test_targets_are_tried_and_refusals_located(root) -> None:
    from postproc.setup.machine_setup import load_setup
    from postproc.plugins import default_registry
    setup = load_setup(str(root / "examples/setups/fanuc_0i_mf_vmc.xml"), groups=default_registry().setup_groups)
    path = root / "examples/fanuc/o1001_plate_drill_tap.nc"
    report = program_info(path.read_text().splitlines(True), file="o1001.nc", dialect="fanuc", setup=setup)
    targets = report["targets"]
    assert targets["fanuc"]["ok"] and targets["linuxcnc"]["ok"]
    # line 37 is "/N370 ...": grbl has no block delete
    assert not targets["grbl"]["ok"] and targets["grbl"]["errors"][0].startswith("o1001.nc:37:")
    assert "block delete" in targets["grbl"]["errors"][0]
    assert report["holes"] == 18  # 6 holes for each of its three cycles


def test_the_command_prints_text_and_json(cli, tmp_path, setup_file) -> None:
    program = tmp_path / "p.ngc"
    program.write_text(PROGRAM)
    text = cli("info", program, "--dialect", "linuxcnc", "--machine", setup_file)
    assert text.status == 0
    out = text.out.decode()
    assert "  X       0.0000 .. 40.0000" in out and "tool 2 (line 9)" in out and "holes: 2; cycles: drill 1" in out
    assert "run time: 0:00:28" in out and "linuxcnc     ok" in out
    as_json = cli("info", program, "--dialect", "linuxcnc", "--format", "json")
    report = json.loads(as_json.out)
    assert report["info"] == 1 and report["dialect"] == "linuxcnc" and report["targets"]["linuxcnc"]["ok"]


def test_a_program_that_cannot_run_is_a_located_error(cli, tmp_path) -> None:
    program = tmp_path / "p.ngc"
    program.write_text("G21 G90\nG1 X10\nM2\n")  # a feed move with no feed rate
    result = cli("info", program, "--dialect", "linuxcnc")
    assert result.status == 1 and result.err.startswith(f"{program}:2:")


def test_a_lathe_program_in_diameters(root) -> None:
    from postproc.setup.machine_setup import load_setup
    from postproc.plugins import default_registry
    setup = load_setup(str(root / "examples/setups/gsk_980tdc.xml"), groups=default_registry().setup_groups)
    path = root / "examples/gsk/o0101_stepped_shaft.nc"
    report = program_info(path.read_text().splitlines(True), file="o0101.nc", dialect="gsk", setup=setup,
                          targets=False)
    # the G70 finish pass reaches the profile's X18 (N10) and the arc's end Z-55; the last rapid X100 Z50
    assert report["x_mode"] == "diameter"
    assert report["extent"]["work"] == {"X": {"min": 18, "max": 100}, "Z": {"min": -55, "max": 50}}
    # one G71 (its two blocks: the first holds data only) and one G70; no hole
    assert report["cycles"] == {"turn_finish": 1, "turn_rough": 1} and report["holes"] == 0
    assert {"lathe cycles", "diameter programming", "arcs in radius form"} <= set(report["features"])
