"""Tool data, machine coordinates and path modes between Fanuc and the ISG/Fagor family
(``postproc.isg_family.tool_data``, ``dialects/isg/writer.py``, ``dialects/fagor/writer.py``).

Expected texts are written out by hand from the manuals' spellings (TF5200: ``D<n>``, ``#SUPPRESS
OFFSETS``, ``G360``/``G359``/``G60``; Fagor 8070/8055: ``G43 D<n>``, ``G44`` cancel, ``G07``/``G60``);
expected points from the set-up's lengths below (H1 100, H2 25.5, H21 100, radii 3, 5, 4). Every number
that means one thing on Fanuc and another on the target is pinned in both directions."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.machine import AxisTravel, ToolData
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274


def _setup(home: float | None = 0.0) -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {"1": ToolData(number=1, length=100.0, radius=3.0), "2": ToolData(number=2, length=25.5, radius=5.0),
                   "21": ToolData(number=21, length=100.0, radius=4.0), "19": ToolData(number=19, length=7.0, radius=4.0)}
    if home is not None:
        setup.travel = {a: AxisTravel(name=a, home=home if a == "Z" else 0.0) for a in "XYZ"}  # type: ignore[arg-type]
    return setup


def _translate(text: str, source: str, target: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target=target,
              setup=setup or _setup(), diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _errors(text: str, source: str, target: str, setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        _translate(text, source, target, setup)
    return [str(e) for e in caught.value.errors]


def _verify(text: str, out: str, source: str, target: str, setup: MachineSetup | None = None) -> Any:
    return verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="in.nc",
                        file_out="out", source=source, target=target, setup=setup or _setup())


def _moves(text: str, dialect: str, setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect, setup=setup or _setup())
            if "move" in e]


FANUC = ("G21 G90 G17 G40 G49\nT1 M06\nG43 H01 Z50. M08\nG00 X-10. Y-10.\nG01 Z-2. F200.\n"
         "G41 D21 G01 X0. Y0.\nG01 X20.\nG40 G01 X30. Y-10.\nG49 G00 Z100.\nM30\n")


def test_fanuc_length_and_radius_registers_become_isg_d() -> None:
    out = _translate(FANUC, "fanuc", "isg")
    assert out.splitlines() == [
        "G17 G71 G90 G40 D0", "T1 M06", "D01 G00 Z50. M08", "G00 X-10. Y-10.", "G01 Z-2. F200.",
        # G41 D21: data block 21 carries radius 4 and the same length as H1 (100), so D21 keeps the length
        "G41 D21 G01 X0. Y0.", "G01 X20.",
        "G40 D01 G01 X30. Y-10.",  # compensation off: back to the length register's own data
        "D0 G00 Z100.", "M30"]
    report = _verify(FANUC, out, "fanuc", "isg")
    assert report.ok and report.max_deviation == 0, report.summary()


def test_fanuc_length_and_radius_become_fagor_g43_d_and_g44() -> None:
    out = _translate(FANUC, "fanuc", "fagor")
    assert out.splitlines() == [
        "G17 G71 G90 G40 G44", "T1 M06", "G43 D01 G00 Z50. M08", "G00 X-10. Y-10.", "G01 Z-2. F200.",
        "G41 D21 G01 X0. Y0.", "G01 X20.", "G40 G01 X30. Y-10.", "G44 G00 Z100.", "M30"]
    report = _verify(FANUC, out, "fanuc", "fagor")
    assert report.ok and report.max_deviation == 0, report.summary()


def test_isg_d_applies_the_length_of_its_data() -> None:
    moves = _moves("G71 G90\nD2 G00 Z50\nG00 X5\nD0 G00 Z80\nM30\n", "isg")
    # D2: 50 + 25.5; the X move keeps it; D0: none
    assert [(m["z"], m.get("controlled", {}).get("z")) for m in moves] == [(50, 75.5), (50, 75.5), (80, None)]


def test_fagor_d_selects_and_g43_applies_and_g44_cancels() -> None:
    moves = _moves("G71 G90\nD2\nG00 Z50\nG43 G00 Z50\nG44 G00 Z80\nM30\n", "fagor")
    # D2 alone selects (no length yet): Z50; G43: 50 + 25.5; G44 cancels
    assert [(m["z"], m.get("controlled", {}).get("z")) for m in moves] == [(50, None), (50, 75.5), (80, None)]
    # no D selected: the 8070 takes D1 (length 100)
    assert _moves("G71 G90\nG43 G00 Z50\nM30\n", "fagor")[0]["controlled"]["z"] == 150


@pytest.mark.parametrize("source, text, fanuc", [
    ("fagor", "G71 G90\nG43 D2 G00 Z50\nG44 G00 Z80\nM30\n", ["G21 G90", "G43 H02 G00 Z50.", "G49 G00 Z80.", "M30"]),
    ("isg", "G71 G90\nD2 G00 Z50\nD0 G00 Z80\nM30\n", ["G21 G90", "G43 H02 G00 Z50.", "G49 G00 Z80.", "M30"]),
])
def test_target_d_reads_back_as_fanuc_g43_h_and_its_cancel_as_g49(source: str, text: str, fanuc: list[str]) -> None:
    """Fagor's G44 is a cancel: it reaches Fanuc as G49, never as Fanuc's G44 (a negative offset)."""
    out = _translate(text, source, "fanuc")
    assert out.splitlines()[1:] == fanuc[1:] or out.splitlines() == fanuc
    assert "G44" not in out
    assert _verify(text, out, source, "fanuc").ok


@pytest.mark.parametrize("target, why", [
    ("fagor", "Fagor's G44 cancels the offset, and no code subtracts a length"),
    ("isg", "D adds the tool's length, and no code subtracts it")])
def test_fanuc_g44_negative_offset_is_refused_never_written_g44(target: str, why: str) -> None:
    assert _errors("G21 G90\nG44 H01 Z50.\nM30\n", "fanuc", target) == [
        f"in.nc:2:1: error: the {target} dialect cannot express a negative tool length offset (Fanuc G44): {why}"]


@pytest.mark.parametrize("target", ["fagor", "isg"])
def test_one_d_cannot_carry_two_registers_of_different_lengths(target: str) -> None:
    # H1 is 100 mm long, register 19 (the radius) 7 mm: one D cannot give the length of the one and the radius
    # of the other. ISG and Fagor (G43 on) resolve such a compensation into the path (Fanuc's rules are
    # modelled), which needs the start point
    errors = _errors("G21 G90\nG43 H01 Z50.\nG42 D19 G01 X0. Y0. F100.\nM30\n", "fanuc", target)
    assert errors == ["in.nc:3:1: error: the start point of a compensated move is not known (program X and Y "
                      "absolutely after the origin moved)"]


@pytest.mark.parametrize("target", ["isg", "fagor"])
def test_isg_writes_the_compensated_path_where_one_d_cannot_carry_both_registers(target: str) -> None:
    """Fanuc's start-up type A: the start-up move towards (0,0) ends square to the next move (+X), right of
    it by register 19's radius; the last move ends square to itself, then the cancel move."""
    text = "G21 G90\nG0 X-10. Y-10.\nG43 H01 Z50.\nG42 D19 G01 X0. Y0. F100.\nX20.\nG40 X30. Y-10.\nM30\n"
    radius = _setup().tools["19"].radius
    out = _translate(text, "fanuc", target)
    assert f"G01 X0. Y{-radius:g}. F100.\nG01 X20. Y{-radius:g}.\nG01 X30. Y-10.\n" in out, out
    assert _verify(text, out, "fanuc", target).ok


def test_isg_applies_a_new_length_only_at_an_absolute_z() -> None:
    """[V] TF5200 P-CHAN-00100 (default 0): a D's length reaches Z at the next absolute Z move only."""
    assert _errors("G21 G90\nG43 H01\nG91 G00 Z5.\nM30\n", "fanuc", "isg") == [
        "in.nc:2:5: error: this tool length change applies at the next move on the source's controller and only "
        "at the next absolute Z on the target's, and the programmed Z is not known where it applies: program Z "
        "beside the length change"]
    assert "D01 G00 Z50." in _translate("G21 G90\nG43 H01 Z50.\nM30\n", "fanuc", "isg").splitlines()
    alone = "G21 G90\nG43 H01\nG00 Z50.\nM30\n"  # the next move applies it on Fanuc: it goes there
    out = _translate(alone, "fanuc", "isg")
    assert "D01 G00 Z50." in out.splitlines() and _verify(alone, out, "fanuc", "isg").ok


LINUXCNC_LENGTH_ALONE = "G21 G90 G0 X0 Y0 Z50\nT1 M6\nG43 H1\nG0 X10\nG0 Z5\nG49\nG0 X20\nG0 Z50\nM2\n"
"""LinuxCNC changes the length in blocks without Z (as gmoccapy's and hk_ba20's programs in the corpus do)."""


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_linuxcnc_applies_a_length_change_only_at_the_next_z() -> None:
    """The premise, from rs274: canonical points are program points (the length not added), so the X10
    traverse at program Z 50 - 1 (inch table: length 1 inch = 25.4 mm) is the machine Z 50 unmoved; after
    G49 the X20 traverse is at program Z 5 + 25.4, again the machine Z unmoved."""
    calls = rs274.run_rs274(LINUXCNC_LENGTH_ALONE, tool_table="T1 P1 Z1.0 D0.1 ;\n")
    moves = [m for m in rs274.canonical_moves(calls) if "move" in m]
    assert [(m["x"], m["z"]) for m in moves] == [(0, 50), (10, 50 - 25.4), (10, 5), (20, 5 + 25.4), (20, 50)]


@pytest.mark.parametrize("target, lines", [
    ("isg", ["G71 G90 G00 X0. Y0. Z50.", "T1 M06", "D01", "G00 X10.", "G00 Z5.", "D0", "G00 X20.", "G00 Z50.", "M02"]),
    ("fagor", ["G71 G90 G00 X0. Y0. Z50.", "T1 M06", "G00 X10.", "G43 D01 G00 Z5.", "G00 X20.", "G44 G00 Z50.",
               "M02"])])
def test_a_linuxcnc_length_change_without_z_keeps_its_place(target: str, lines: list[str]) -> None:
    """LinuxCNC and ISG (P-CHAN-00100 = 0) both apply the new length at the next absolute Z, so the D
    goes where the G43 was; Fagor (simulated as applying it at the next move, [?] when Z moves) gets it
    at the next absolute Z (``postproc.lowering.length_timing``)."""
    out = _translate(LINUXCNC_LENGTH_ALONE, "linuxcnc", target)
    assert out.splitlines() == lines
    assert _verify(LINUXCNC_LENGTH_ALONE, out, "linuxcnc", target).ok


def test_a_linuxcnc_length_change_then_an_incremental_z_goes_to_the_absolute_z_towards_fagor() -> None:
    """The incremental Z moves the machine 5 down under either length (rs274: by its increment), so Fagor
    gets the change at the absolute Z, where LinuxCNC applies it, whichever Fagor rule holds."""
    text = "G21 G90 G0 X0 Y0 Z50\nT1 M6\nG43 H1\nG0 X10\nG91 G0 Z-5\nG90 G0 Z50\nM2\n"
    out = _translate(text, "linuxcnc", "fagor")
    assert out.splitlines() == ["G71 G90 G00 X0. Y0. Z50.", "T1 M06", "G00 X10.", "G91 G00 Z-5.",
                                "G90 G43 D01 G00 Z50.", "M02"]
    assert _verify(text, out, "linuxcnc", "fagor").ok
    assert "D01" in _translate(text, "linuxcnc", "isg").splitlines()  # ISG waits for an absolute Z too


LINUXCNC_RADIUS_ONLY = ("G21 G90 G0 X0 Y0 Z5\nT1 M6\nG41 D1\nG1 X20 Y0 F100\nG1 X20 Y20\nG1 X0 Y20\n"
                        "G40 G1 X-10 Y10\nM2\n")
"""G41 D1 with no length offset in force (the corpus's comp_g1, comp311): ISG's D1 would bring tool 1's
100 mm length with its radius."""


def test_a_radius_whose_d_brings_another_length_is_written_as_the_compensated_path_for_isg() -> None:
    """Radius 3 on the left of the square's sides: the entry move ends at the inside corner X17 Y3, then
    X17 Y17 and X0 Y17 (hand-derived, the points rs274 gives below); no D, so no length either."""
    out = _translate(LINUXCNC_RADIUS_ONLY, "linuxcnc", "isg")
    assert out.splitlines() == ["G71 G90 G00 X0. Y0. Z5.", "T1 M06", "G01 X17. Y3. F100.", "G01 X17. Y17.",
                                "G01 X0. Y17.", "G01 X-10. Y10.", "M02"]
    report = _verify(LINUXCNC_RADIUS_ONLY, out, "linuxcnc", "isg")
    assert report.ok and report.max_deviation == 0, report.summary()
    if rs274.available():
        calls = rs274.run_rs274(LINUXCNC_RADIUS_ONLY, tool_table=f"T1 P1 Z{100 / 25.4:.6f} D{6 / 25.4:.6f} ;\n")
        theirs = [(m["x"], m["y"]) for m in rs274.canonical_moves(calls) if "move" in m]
        assert theirs == [(m["x"], m["y"]) for m in _moves(out, "isg")]


def test_a_radius_whose_d_brings_the_length_in_force_stays_g41_for_isg() -> None:
    """Register 21 has H1's length (100): D21 carries both, so the target compensates itself."""
    text = LINUXCNC_RADIUS_ONLY.replace("G41 D1", "G43 H1 Z5\nG41 D21")
    lines = _translate(text, "linuxcnc", "isg").splitlines()
    assert "G41 D21" in lines and "G01 X20. Y0. F100." in lines, lines


def test_a_missing_length_names_the_element_to_add() -> None:
    assert _errors("G21 G90\nG43 H07 Z50.\nM30\n", "fanuc", "isg") == [
        'in.nc:2:5: error: the set-up gives tool length register 7 no value: add <Tool number="7" length=".."/> to '
        "its <Tools>, or write the register in the program"]


# -- machine coordinates and reference returns -----------------------------------------------------------------

REFERENCE = "G21 G90\nG43 H02 Z50.\nG01 X5. F100.\nG91 G28 Z0.\nG90 G53 G00 X-10. Y-20. M05\nG01 X1.\nM30\n"


def test_fanuc_g28_and_g53_become_isg_suppress_offsets() -> None:
    out = _translate(REFERENCE, "fanuc", "isg", _setup(home=-12.5))
    assert out.splitlines() == [
        "G71 G90", "D02 G00 Z50.", "G01 X5. F100.",
        # the intermediate point is where the tool is (G91 Z0): no move; then home, absolute, at rapid; the next
        # block programs its own G90, so no G91 is written back (postproc.isg_family.machine_moves)
        "G90 G00", "#SUPPRESS OFFSETS Z-12.5",
        "G90 G00", "#SUPPRESS OFFSETS X-10. Y-20.", "M05",
        "G01 X1.", "M30"]
    report = _verify(REFERENCE, out, "fanuc", "isg", _setup(home=-12.5))
    assert report.ok and report.max_deviation == 0, report.summary()
    moves = _moves(out, "isg", _setup(home=-12.5))
    # at home the controlled Z is the machine's -12.5 whatever tool length D2 (25.5) is in force
    assert (moves[2]["z"], moves[2]["controlled"]["z"]) == (-38, -12.5)


def test_isg_suppress_offsets_moves_in_the_mode_in_force() -> None:
    moves = _moves("G71 G90\nG01 X1 F100\n#SUPPRESS OFFSETS X-4\nM30\n", "isg")
    assert [(m["move"], m["x"]) for m in moves] == [("feed", 1), ("feed", -4)]
    text = "G71 G90\nG00 X1\n#SUPPRESS OFFSETS X-4\nM30\n"
    assert _translate(text, "isg", "isg") == text


def test_a_reference_return_needs_the_home_position() -> None:
    assert _errors("G21\nG91 G28 Z0.\nM30\n", "fanuc", "isg", _setup(home=None)) == [
        "in.nc:2:1: error: the isg dialect cannot express a reference return of axis Z: ISG writes it as a move "
        "to the home position in machine coordinates, which the set-up does not give (add <Axes><Axis name=\"Z\" "
        "home=\"..\"/>)"]
    assert "second reference position" in _errors("G21\nG91 G30 Z0.\nM30\n", "fanuc", "isg")[0]


def test_fanuc_g28_and_g53_become_fagor_g53_at_rapid_in_absolute_positions() -> None:
    """Hand-derived: the G28's intermediate point is where the tool is (G91 Z0), so only the G53 rapid to the
    set-up's home (-12.5) is written, with G90 for it; the next block gives its own G90, so no G91 is written
    back between them (``postproc.isg_family.machine_moves``)."""
    out = _translate(REFERENCE, "fanuc", "fagor", _setup(home=-12.5))
    assert out.splitlines() == [
        "G71 G90", "G43 D02 G00 Z50.", "G01 X5. F100.",
        "G53 G90 G00 Z-12.5",
        "G53 G90 G00 X-10. Y-20. M05",
        "G01 X1.", "M30"]
    report = _verify(REFERENCE, out, "fanuc", "fagor", _setup(home=-12.5))
    assert report.ok and report.max_deviation == 0, report.summary()
    moves = _moves(out, "fagor", _setup(home=-12.5))
    # G53 positions the controlled point, whatever tool length D2 (25.5) is in force
    assert [(m["move"], m["controlled"]["x"], m["controlled"]["z"]) for m in moves[2:4]] == [
        ("rapid", 5, -12.5), ("rapid", -10, -12.5)]
    assert _translate(out, "fagor", "fanuc", _setup(home=-12.5)).splitlines()[4] == "G53 G90 G00 X-10. Y-20. M05"


def test_fagor_g53_under_g91_is_written_absolute() -> None:
    """From grbl, whose G53 words are machine positions under G91 too [V: gcode.c]."""
    text = "G21 G91\nG00 X1.\nG53 G00 Z-3.\nX1.\nM30\n"
    out = _translate(text, "grbl", "fagor")
    assert out.splitlines()[2:4] == ["G53 G90 G00 Z-3.", "G91 G00 X1."]  # G91 again where it is next read
    assert _verify(text, out, "grbl", "fagor").ok


def test_fagor_reference_returns_it_cannot_place_are_located_errors() -> None:
    assert _errors("G21\nG91 G28 Z0.\nM30\n", "fanuc", "fagor", _setup(home=None)) == [
        "in.nc:2:1: error: the fagor dialect cannot express a reference return of axis Z: Fagor writes it as a G53 "
        "move to the home position, which the set-up does not give (add <Axes><Axis name=\"Z\" home=\"..\"/>)"]
    assert "second reference position" in _errors("G21\nG91 G30 Z0.\nM30\n", "fanuc", "fagor")[0]


# -- path modes ------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("fanuc, fagor", [("G61", "G07"), ("G09 G01 X2. F100.", "G60 G01 X2. F100.")])
def test_fanuc_exact_stop_is_fagor_square_corner_never_g61(fanuc: str, fagor: str) -> None:
    text = f"G21\n{fanuc}\nG00 X1.\nM30\n"
    out = _translate(text, "fanuc", "fagor")
    assert out.splitlines()[1] == fagor and "G61" not in out
    assert _translate(out, "fagor", "fanuc").splitlines()[1] == fanuc


def test_fanuc_cutting_mode_is_fagor_g05_and_back() -> None:
    """8070 REF 1709 p.197: G05 rounds the corners (modal) as the #ROUNDPAR in force says, G61 one block."""
    text = "G21\nG64\nG01 X1. F100.\nY1.\nG61\nX0.\nM30\n"
    out = _translate(text, "fanuc", "fagor")
    assert out.splitlines()[1:6] == ["G05", "G01 X1. F100.", "G01 Y1.", "G07", "G01 X0."]
    assert _verify(text, out, "fanuc", "fagor").ok
    assert _translate(out, "fagor", "fanuc").splitlines()[1] == "G64"


def test_fagor_corner_rounding_for_one_block_and_roundpar_are_not_fanuc() -> None:
    assert _errors("G71\nG61 G01 X1 F100\nM30\n", "fagor", "fanuc")[0].startswith(
        "in.nc:2:1: error: G61 (corner rounding for one block) from fagor has no equivalent in fanuc")
    assert _errors("G71\n#ROUNDPAR [4,0.1]\nG05\nG01 X1 F100\nM30\n", "fagor", "fanuc")[0].startswith(
        "in.nc:2:1: error: #ROUNDPAR")


def test_g53_means_two_things_and_is_pinned_both_ways() -> None:
    """Fanuc's G53 is one block in machine coordinates; ISG's deselects the zero offsets (modal): neither
    is ever written as the other's."""
    out = _translate("G21 G90\nG53 G00 Z0.\nM30\n", "fanuc", "isg")
    assert "G53" not in out and "#SUPPRESS OFFSETS Z0." in out.splitlines()
    assert _errors("G71 G90\nG53\nG00 X1\nM30\n", "isg", "fanuc") == [
        "in.nc:2:1: error: G53 (zero offset deselection) from isg has no equivalent in fanuc"]
