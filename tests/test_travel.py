"""Travel limits: hand-derived overruns of expanded cycles, arcs and flattened loops, in machine
coordinates (work offsets, tool lengths, G53, home), for ``toolpath`` and ``translate``."""

from __future__ import annotations

from pathlib import Path

import pytest

DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"

MILL = """<MachineSetup name="travel test" dialect="fanuc">
  <Input decimalPoint="calculator"/>
  <Machine axes="XYZ"{units}/>
  <Axes>
    <Axis name="X" min="-500.0" max="500.0" home="0.0"/>
    <Axis name="Y" min="-300.0" max="300.0"/>
    <Axis name="Z" min="-400.0" max="0.0"{zhome}/>
  </Axes>
  <WorkOffsets>
    <Offset number="1" x="0.0" y="0.0" z="-200.0"/>
    <Offset number="2" x="-100.0" y="0.0"/>
  </WorkOffsets>
  <Tools>
    <Tool number="1" length="100.0"/>
  </Tools>
</MachineSetup>
"""


def _files(tmp_path: Path, program: str, units: str = "", zhome: str = ' home="0.0"') -> tuple[Path, Path]:
    machine = tmp_path / "m.xml"
    machine.write_text(DECLARATION + MILL.format(units=units, zhome=zhome))
    nc = tmp_path / "p.nc"
    nc.write_text(program)
    return machine, nc


def _toolpath(cli, tmp_path, program, *extra, **setup):
    machine, nc = _files(tmp_path, program, **setup)
    result = cli("toolpath", nc, "--dialect", "fanuc", "--machine", machine, *extra)
    return result, nc


# Holes at X100..X500 step 100 then one at X512.5: only the last overruns, by 12.5 mm; G54 X is 0.
HOLES = ("G90 G54 G0 X0 Y0 Z50\n"
         "G81 X100 Y0 Z-5 R2 F100\n"
         "X200\nX300\nX400\nX500\n"
         "X512.5\n"
         "G80\nM30\n")


def test_the_last_hole_of_a_pattern_overruns(cli, tmp_path):
    result, nc = _toolpath(cli, tmp_path, HOLES)
    assert result.status == 1
    assert result.err_lines == [f"{nc}:7:1: error: X+12.500 mm beyond the limit 500.000 (machine X 512.500)"]


def test_with_warn_the_overrun_is_a_warning_and_the_path_is_complete(cli, tmp_path):
    result, nc = _toolpath(cli, tmp_path, HOLES, "--on-unsupported", "warn")
    assert result.status == 0
    assert result.err_lines == [f"{nc}:7:1: warning: X+12.500 mm beyond the limit 500.000 (machine X 512.500)"]
    assert b'"x": 512.5' in result.out


def test_translate_reports_the_overrun_at_the_source_block(cli, tmp_path):
    machine, nc = _files(tmp_path, HOLES)
    result = cli("translate", nc, "--from", "fanuc", "--to", "linuxcnc", "--machine", machine)
    assert (result.status, result.out) == (1, b"")
    assert result.err_lines == [f"{nc}:7:1: error: X+12.500 mm beyond the limit 500.000 (machine X 512.500)"]
    warned = cli("translate", nc, "--from", "fanuc", "--to", "linuxcnc", "--machine", machine,
                 "--on-unsupported", "warn")
    assert warned.status == 0
    assert warned.err_lines == [f"{nc}:7:1: warning: X+12.500 mm beyond the limit 500.000 (machine X 512.500)"]
    assert b"X512.5" in warned.out


# An arc centred at X490 Y0, radius 20, from (490,-20) to (490,20): counter-clockwise it passes (510,0),
# 10 mm beyond X500 while both end points are at X490; clockwise it passes (470,0), inside.
ARC = "G90 G54 G0 X490 Y-20 Z50\nG1 Z10 F200\n{g} X490 Y20 R20\nM30\n"


def test_an_arc_bulging_past_a_limit_between_its_end_points(cli, tmp_path):
    result, nc = _toolpath(cli, tmp_path, ARC.format(g="G3"))
    assert result.status == 1
    assert result.err_lines == [f"{nc}:3:4: error: X+10.000 mm beyond the limit 500.000 between the arc's end "
                                "points (machine X 510.000)"]


def test_the_same_arc_the_other_way_round_stays_inside(cli, tmp_path):
    result, _ = _toolpath(cli, tmp_path, ARC.format(g="G2"))
    assert (result.status, result.err) == (0, "")


def test_a_full_circle_reaches_all_four_quadrant_points(cli, tmp_path):
    # centre (0, 280) radius 30: Y reaches 310, 10 beyond 300; X +-30 is inside
    result, nc = _toolpath(cli, tmp_path, "G90 G54 G0 X30 Y280 Z50\nG2 X30 Y280 I-30 J0 F100\nM30\n")
    assert result.err_lines == [f"{nc}:2:8: error: Y+10.000 mm beyond the limit 300.000 between the arc's end "
                                "points (machine Y 310.000)"]


# A WHILE loop's pass n (#1 = n-1) rapids to X = 100 + 70 (n-1): pass 7 reaches X520, 20 mm beyond X500.
LOOP = ("G90 G54 G0 X0 Y0 Z50\n"
        "#1=0\n"
        "WHILE[#1LT7]DO1\n"
        "G0 X[100+#1*70]\n"
        "#1=#1+1\n"
        "END1\n"
        "M30\n")


def test_the_seventh_pass_of_a_loop_overruns(cli, tmp_path):
    """A computed word has no number to point at: the error points at the block (column 1)."""
    result, nc = _toolpath(cli, tmp_path, LOOP)
    assert result.status == 1
    [error] = result.err_lines
    assert error.startswith(f"{nc}:4:1: error: X+20.000 mm beyond the limit 500.000 (machine X 520.000)")


def test_a_loop_overrun_fails_its_translation_to_a_controller_without_loops(cli, tmp_path):
    machine, nc = _files(tmp_path, LOOP)
    result = cli("translate", nc, "--from", "fanuc", "--to", "grbl", "--machine", machine)
    assert result.status == 1
    assert result.err_lines[0].startswith(f"{nc}:4:1: error: X+20.000 mm beyond the limit 500.000")


# -- machine coordinates -----------------------------------------------------------------------------

def test_the_work_offset_is_added(cli, tmp_path):
    # G55 X is -100: X-450 is machine X-550, 50 beyond -500; the same point in G54 is inside (the program gives
    # G55 the Z the set-up lacks: where the tool stands in G55 is then known on every axis)
    result, nc = _toolpath(cli, tmp_path, "G90 G54 G0 X-450 Y0 Z50\nG10 L2 P2 Z-200\nG55 G0 X-450\nM30\n")
    assert result.err_lines == [f"{nc}:3:8: error: X-50.000 mm beyond the limit -500.000 (machine X -550.000)"]


def test_a_g10_offset_replaces_the_declared_one(cli, tmp_path):
    # G10 sets G54 X to +100: X450 is machine X550
    result, nc = _toolpath(cli, tmp_path, "G10 L2 P1 X100\nG90 G54 G0 X450 Y0 Z50\nM30\n")
    assert result.err_lines == [f"{nc}:2:12: error: X+50.000 mm beyond the limit 500.000 (machine X 550.000)"]


def test_an_offset_the_setup_does_not_give_is_refused_once(cli, tmp_path):
    # G55 declares no Z; G56 nothing at all (selected after a move: where the tool then stands in G56 is unknown,
    # which the simulation itself refuses)
    result, nc = _toolpath(cli, tmp_path, "G90 G55 G0 X0 Y0\nZ10\nZ20\nG56 X0\nM30\n")
    assert result.err_lines == [
        f"{nc}:2:1: error: the travel of Z cannot be checked: the set-up gives work system 2 no offset for Z "
        '(<WorkOffsets><Offset number="2" z=...>) and the program sets none',
        f"{nc}:4:1: error: where the tool stands in the new work coordinates is unknown: the set-up gives work "
        'system 3 no offset for X (<WorkOffsets><Offset number="3" x=...>) and the program sets none']
    result, nc = _toolpath(cli, tmp_path, "G90 G56 G0 Y0\nX10\nX20\nM30\n")
    assert result.err_lines == [
        f"{nc}:1:12: error: the travel of Y cannot be checked: the set-up gives work system 3 no offset for Y "
        '(<WorkOffsets><Offset number="3" y=...>) and the program sets none',
        f"{nc}:2:1: error: the travel of X cannot be checked: the set-up gives work system 3 no offset for X "
        '(<WorkOffsets><Offset number="3" x=...>) and the program sets none']


def test_the_tool_length_is_added_to_z(cli, tmp_path):
    # G54 Z is -200, H1 is 100: Z150 under G43 is machine Z50, 50 beyond 0; under G44 it is -150, inside
    result, nc = _toolpath(cli, tmp_path, "G90 G54 G0 X0 Y0 Z50\nG43 H1 Z150\nG44 H1 Z150\nM30\n")
    assert result.err_lines == [f"{nc}:2:8: error: Z+50.000 mm beyond the limit 0.000 (machine Z 50.000)"]


def test_an_unknown_tool_length_is_refused(cli, tmp_path):
    result, nc = _toolpath(cli, tmp_path, "G90 G54 G0 X0 Y0 Z50\nG43 H2 Z100\nM30\n")
    # the simulation itself refuses the unknown length, at its register (the travel check never gets there)
    assert result.err_lines == [
        f"{nc}:2:5: error: the set-up gives tool length register 2 no value: add <Tool number=\"2\" "
        'length=".."/> to its <Tools>, or write the register in the program']


def test_a_g10_tool_length_counts(cli, tmp_path):
    # G10 L10 P2 R150: Z100 under G43 H2 is machine Z 100 - 200 + 150 = 50
    result, nc = _toolpath(cli, tmp_path, "G10 L10 P2 R150\nG90 G54 G0 X0 Y0 Z50\nG43 H2 Z100\nM30\n")
    assert result.err_lines == [f"{nc}:3:8: error: Z+50.000 mm beyond the limit 0.000 (machine Z 50.000)"]


def test_g53_is_machine_coordinates_under_a_tool_length_too(cli, tmp_path):
    # G53 suppresses the tool length on its axis (Fanuc: the offset vector is cancelled for the move): G53 Z-10
    # is machine Z -10 under G43 H1, G53 Z3 is 3 beyond; the next absolute Z50 is 50 - 200 + 100 = -50 again
    result, nc = _toolpath(cli, tmp_path, "G90 G54 G0 X0 Y0 Z50\nG53 G0 Z5\nG43 H1 Z50\nG53 G0 Z-10\n"
                                          "G53 G0 Z3\nG0 Z50\nZ251\nM30\n")
    assert result.err_lines == [
        f"{nc}:2:8: error: Z+5.000 mm beyond the limit 0.000 (machine Z 5.000)",
        f"{nc}:5:8: error: Z+3.000 mm beyond the limit 0.000 (machine Z 3.000)",
        f"{nc}:7:1: error: Z+151.000 mm beyond the limit 0.000 (machine Z 151.000)"]


def test_the_reference_return_needs_a_home(cli, tmp_path):
    result, nc = _toolpath(cli, tmp_path, "G90 G54 G0 X0 Y0 Z50\nG91 G28 Z0\nG90 G0 X10\nG91 G0 Z-10\nM30\n",
                           zhome="")
    assert result.err_lines == [
        f"{nc}:2:9: error: the travel of Z cannot be checked: the set-up gives axis Z no home "
        '(<Axis name="Z" home=...>) for the reference return']


def test_inch_machine_units(cli, tmp_path):
    # limits in inch (X 500 in): X 13000 mm is 511.811 in
    result, nc = _toolpath(cli, tmp_path, "G21 G90 G54 G0 X13000 Y0 Z50\nM30\n", units=' units="inch"')
    assert result.err_lines[0] == f"{nc}:1:16: error: X+11.811 inch beyond the limit 500.000 (machine X 511.811)"


LATHE = """<MachineSetup name="lathe" dialect="fanuc">
  <Input decimalPoint="calculator" machineType="lathe"/>
  <Machine axes="XZ" startX="100.0" startZ="100.0"/>
  <Axes>
    <Axis name="X" min="-10.0" max="400.0"/>
    <Axis name="Z" min="-600.0" max="300.0"/>
  </Axes>
  <WorkOffsets>
    <Offset number="1" x="0.0" z="0.0"/>
  </WorkOffsets>
  <Tools>
    <Tool number="1" x="0.0" z="-50.0"/>
  </Tools>
</MachineSetup>
"""


def test_a_lathe_checks_x_as_a_diameter_and_its_tool_offset(cli, tmp_path):
    machine = tmp_path / "lathe.xml"
    machine.write_text(DECLARATION + LATHE)
    nc = tmp_path / "t.nc"
    # X420 (diameter) is 20 beyond 400; T0101 adds Z-50: Z-560 is machine Z-610, 10 beyond -600; T0202's
    # offset is not in the set-up
    nc.write_text("G0 X100 Z50\nG0 X420\nT0101\nG0 X100 Z-560\nT0202\nG0 Z10\nM30\n")
    result = cli("toolpath", nc, "--dialect", "fanuc", "--machine", machine)
    assert result.err_lines == [
        f"{nc}:2:4: error: X+20.000 mm beyond the limit 400.000 (machine X 420.000)",
        f"{nc}:4:9: error: Z-10.000 mm beyond the limit -600.000 (machine Z -610.000)",
        f"{nc}:6:4: error: the travel of Z cannot be checked: the set-up gives tool offset 2 no z "
        '(<Tools><Tool number="2" z=...>)']


def test_no_limits_no_check(cli, tmp_path):
    nc = tmp_path / "p.nc"
    nc.write_text("G90 G0 X99999\nM30\n")
    assert cli("toolpath", nc, "--dialect", "fanuc").status == 0


@pytest.mark.parametrize("program", [HOLES.replace("X512.5", "X500"), ARC.format(g="G2")])
def test_programs_inside_the_travel_pass(cli, tmp_path, program):
    result, _ = _toolpath(cli, tmp_path, program)
    assert (result.status, result.err) == (0, "")


def test_a_lathe_coordinate_setting_moves_the_frame_not_the_machine(cli, tmp_path):
    # X100 Z50 (G54 X0 Z0) is machine X100 Z50; G50 X0 Z0 makes that point the new zero: X310 is
    # machine X410 (diameter), 10 beyond 400; Z-640 is machine Z-590, inside -600
    machine = tmp_path / "lathe.xml"
    machine.write_text(DECLARATION + LATHE)
    nc = tmp_path / "t.nc"
    nc.write_text("G0 X100 Z60\nG0 Z50\nG50 X0 Z0\nG0 Z-640\nG0 X310\nM30\n")
    result = cli("toolpath", nc, "--dialect", "fanuc", "--machine", machine)
    assert result.err_lines == [f"{nc}:5:4: error: X+10.000 mm beyond the limit 400.000 (machine X 410.000)"]


def test_translate_says_where_the_travel_can_no_longer_be_checked(cli, tmp_path):
    # the simulation cannot run a skip function (G31): from there the machine position is not known
    machine, nc = _files(tmp_path, "G90 G54 G0 X0 Y0 Z50\nG31 X1.\nG0 X600\nM30\n")
    result = cli("translate", nc, "--from", "fanuc", "--to", "fanuc", "--machine", machine)
    assert result.status == 1
    assert result.err_lines == [f"{nc}:2:1: error: the travel cannot be checked from here on: G31 (skip "
                                "function) cannot be simulated"]
    assert cli("translate", nc, "--from", "fanuc", "--to", "fanuc").status == 0  # no limits, no check


def test_the_travel_is_checked_through_a_coordinate_setting(cli, tmp_path):
    # G92 X100 at machine X0 (G54 zero here): X500 in the new frame is machine X400, inside; X600 is 500, beyond
    machine, nc = _files(tmp_path, "G90 G54 G0 X0 Y0 Z50\nG92 X100 Y0\nG0 X500\nG0 X601\nM30\n")
    result = cli("translate", nc, "--from", "fanuc", "--to", "fanuc", "--machine", machine)
    assert result.status == 1
    assert result.err_lines == [f"{nc}:4:4: error: X+1.000 mm beyond the limit 500.000 (machine X 501.000)"]


@pytest.mark.parametrize("code, errors", [("G3", 1), ("G2", 0)])
def test_a_lathe_arc_bulges_in_x_as_a_diameter(cli, tmp_path, code, errors):
    # ZX plane, X as a radius: from (Z0, X190) to (Z-40, X190) with R20, centre (Z-20, X190). Counter-
    # clockwise in (Z, X) the arc passes X radius 210 = diameter 420, 20 beyond 400; clockwise it passes 170
    machine = tmp_path / "lathe.xml"
    machine.write_text(DECLARATION + LATHE)
    nc = tmp_path / "t.nc"
    nc.write_text(f"G0 X100 Z10 S500 M03\nG0 X380 Z0\n{code} X380 Z-40 R20 F0.2\nM30\n")
    result = cli("toolpath", nc, "--dialect", "fanuc", "--machine", machine)
    expected = [f"{nc}:3:4: error: X+20.000 mm beyond the limit 400.000 between the arc's end points "
                "(machine X 420.000)"]
    assert result.err_lines == expected[:errors]
