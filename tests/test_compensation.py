"""Tool length and cutter radius compensation in the simulation (``postproc.compensation``): hand-derived
paths. LinuxCNC's own paths are the differential test's (``test_cutter_compensation_rs274.py``)."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.setup.machine import ToolData
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines


def machine(**tools: tuple[float | None, float | None]) -> MachineSetup:
    """A set-up whose ``<Tools>`` give register ``T<n>`` (length, radius)."""
    setup = MachineSetup()
    setup.tools = {name[1:]: ToolData(number=int(name[1:]), length=length, radius=radius)
                   for name, (length, radius) in tools.items()}
    return setup


def run(text: str, dialect: str = "fanuc", setup: MachineSetup | None = None) -> list[dict[str, Any]]:
    return list(toolpath_events(io.StringIO(text), file="p.nc", dialect=dialect,
                                setup=setup or machine(T1=(100.0, 5.0))))[1:]


def moves(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    return [e for e in events if "move" in e]


def errors(text: str, dialect: str = "fanuc", setup: MachineSetup | None = None) -> list[str]:
    with pytest.raises(ErrorList) as info:
        run(text, dialect, setup)
    return [str(e) for e in info.value.errors]


# -- tool length ---------------------------------------------------------------------------------------

def test_g43_adds_the_length_to_the_controlled_z_and_g49_cancels_it() -> None:
    got = moves(run("G21 G90 G0 X0 Y0 Z50.\nG43 H1 Z50.\nG1 Z-5. F100.\nG44 H1 Z0.\nG49 G0 Z60.\nM30\n"))
    assert got == [
        {"line": 1, "move": "rapid", "x": 0, "y": 0, "z": 50},
        # the programmed point stays; the machine moves by the length: no zero-length drop
        {"line": 2, "move": "rapid", "x": 0, "y": 0, "z": 50, "controlled": {"x": 0, "y": 0, "z": 150}},
        {"line": 3, "move": "feed", "x": 0, "y": 0, "z": -5, "f": 100, "controlled": {"x": 0, "y": 0, "z": 95}},
        {"line": 4, "move": "feed", "x": 0, "y": 0, "z": 0, "f": 100, "controlled": {"x": 0, "y": 0, "z": -100}},
        {"line": 5, "move": "rapid", "x": 0, "y": 0, "z": 60},
    ]


def test_an_arc_carries_the_length_in_its_controlled_centre() -> None:
    got = moves(run("G21 G90 G17 G0 X0 Y0 Z0\nG43 H1\nG2 X10. Y0 I5. J0 F100.\nM30\n"))
    assert got == [{"line": 3, "move": "cw", "x": 10, "y": 0, "z": 0, "cx": 5, "cy": 0, "cz": 0, "plane": "XY",
                    "f": 100, "controlled": {"x": 10, "y": 0, "z": 100, "cx": 5, "cy": 0, "cz": 100}}]


def test_the_programs_own_register_values_and_wear() -> None:
    # G10 L10 replaces the set-up's 100 by 40; L11 adds a wear of -0.5; an inch program's R is in inches
    got = moves(run("G21 G90\nG10 L10 P1 R40.\nG10 L11 P1 R-0.5\nG43 H1 G0 Z10.\nG20\nG10 L10 P1 R1.\n"
                    "G43 H1 Z1.\nM30\n"))
    assert [m["controlled"]["z"] for m in moves(got)] == [10 + 40 - 0.5, 25.4 + 25.4 - 0.5]


def test_a_length_register_the_set_up_lacks_is_a_located_error_naming_the_element() -> None:
    assert errors("G21 G90\nG0 Z10.\nG43 H7 Z5.\nM30\n") == [
        'p.nc:3:5: error: the set-up gives tool length register 7 no value: add <Tool number="7" length=".."/> '
        "to its <Tools>, or write the register in the program"]


def test_register_zero_is_no_offset() -> None:
    assert moves(run("G21 G90\nG43 H0 G0 Z10.\nM30\n", setup=MachineSetup())) == [
        {"line": 2, "move": "rapid", "x": 0, "y": 0, "z": 10}]


def test_a_reference_return_and_machine_coordinates_end_at_the_machine_point() -> None:
    # under a length of 100 the programmed point of machine Z0 is Z-100; the next incremental move starts there
    got = moves(run("G21 G90 G0 Z50.\nG43 H1 Z50.\nG91 G28 Z0.\nG90 G0 Z50.\nG53 Z0.\nG91 G0 Z-10.\nM30\n"))
    assert [(m["line"], m["z"], m.get("controlled", {}).get("z", m["z"])) for m in got] == [
        (1, 50, 50), (2, 50, 150), (3, -100, 0), (4, 50, 150), (5, -100, 0), (6, -110, -10)]


def test_verify_compares_controlled_points_so_a_written_length_equals_g43() -> None:
    setup = machine(T1=(100.0, None))
    source = "G21 G90\nG0 X0 Y0 Z200.\nG43 H1 Z10.\nG1 X10. F100.\nM30\n"
    written = "G21 G90\nG0 X0 Y0 Z200.\nG0 Z110.\nG1 X10. F100.\nM30\n"
    report = verify_lines(io.StringIO(source), io.StringIO(written), file_in="a.nc", file_out="b.nc",
                          source="fanuc", target="fanuc", setup=setup)
    assert report.ok and report.max_deviation == 0 and report.ignored == [], report.summary()
    lost = "G21 G90\nG0 X0 Y0 Z200.\nG0 Z10.\nG1 X10. F100.\nM30\n"
    report = verify_lines(io.StringIO(source), io.StringIO(lost), file_in="a.nc", file_out="b.nc",
                          source="fanuc", target="fanuc", setup=setup, allow_ignored=True)
    assert not report.ok and report.max_deviation == 100


# -- cutter radius (LinuxCNC's rules) ---------------------------------------------------------------------

def ngc(*blocks: str) -> list[dict[str, Any]]:
    return moves(run("G21 G17 G90 G40 G49\n" + "\n".join(blocks) + "\nM2\n", "linuxcnc", machine(T1=(0.0, 1.0))))


def ends(got: list[dict[str, Any]]) -> list[tuple[str, float, float]]:
    return [(m["move"], m.get("controlled", m)["x"], m.get("controlled", m)["y"]) for m in got]


def test_an_inside_corner_meets_at_the_offset_lines() -> None:
    # left of +X is +Y (entry ends at 10,1); turning to +Y is an inside corner: x = 9 meets y = 1 at (9, 1);
    # the G40 keeps the last move's compensated end (9, 10); the exit move goes to the programmed point
    got = ngc("G0 X0 Y0 Z0", "G41 D1 G1 X10 Y0 F100", "G1 X10 Y10", "G40 G1 X0 Y10")
    assert ends(got) == [("feed", 9, 1), ("feed", 9, 10), ("feed", 0, 10)]
    assert got[0]["x"] == 10 and got[0]["y"] == 0  # the programmed point stays in the usual keys


def test_an_outside_corner_is_an_arc_about_the_programmed_corner() -> None:
    # right of +X is -Y: the entry ends at (10, -1); turning to +Y is an outside corner: an arc about (10, 0)
    # from (10, -1) to (11, 0), counter-clockwise (the tool is on the right)
    got = ngc("G0 X0 Y0 Z0", "G42 D1 G1 X10 Y0 F100", "G1 X10 Y10", "G40 G1 X20 Y10")
    assert ends(got) == [("feed", 10, -1), ("ccw", 11, 0), ("feed", 11, 10), ("feed", 20, 10)]
    corner = got[1]
    assert (corner["x"], corner["y"], corner["cx"], corner["cy"]) == (10, 0, 10, 0)
    assert (corner["controlled"]["cx"], corner["controlled"]["cy"]) == (10, 0)


def test_an_arc_is_offset_along_its_radius() -> None:
    # a G3 half circle about (10, 5) from (10, 0) to (10, 10), the tool on the left (inside): radius 5 - 1
    got = ngc("G0 X0 Y0 Z0", "G41 D1 G1 X10 Y0 F100", "G3 X10 Y10 I0 J5", "G40 G1 X0 Y10")
    assert ends(got) == [("feed", 10, 1), ("ccw", 10, 9), ("feed", 0, 10)]
    assert (got[1]["controlled"]["cx"], got[1]["controlled"]["cy"]) == (10, 5)


def test_moves_along_z_wait_with_the_corner_and_take_its_point() -> None:
    # the Z move between the two lines is made at the inside corner (9, 1), after the first line
    got = ngc("G0 X0 Y0 Z0", "G41 D1 G1 X10 Y0 F100", "G1 Z-1", "G1 X10 Y10", "G40 G1 X0 Y10")
    assert [(m["move"], m["controlled"]["x"], m["controlled"]["y"], m["z"]) for m in got[:3]] == [
        ("feed", 9, 1, 0), ("feed", 9, 1, -1), ("feed", 9, 10, -1)]


@pytest.mark.parametrize("blocks, message", [
    (("G0 X0 Y0", "G41 D1 G1 X0.5 Y0 F100"),
     "p.nc:3:1: error: the entry move of cutter compensation is not longer than the tool radius"),
    (("G0 X0 Y0", "G41 D1 G1 X10 Y0 F100", "G3 X10 Y1.5 I0 J0.75"),
     "p.nc:4:1: error: the tool radius is not less than the radius of an arc it cuts inside"),
    (("G0 X0 Y0", "G41 D1 G1 X10 Y0 F100", "G1 X10 Y1", "G1 X0 Y1"),
     "p.nc:5:1: error: a straight feed in an inside corner cannot be reached by the tool without gouging"),
    (("G0 X0 Y0", "G41 D1 G1 X10 Y0 F100", "G40", "G2 X20 Y0 I5 J0"),
     "p.nc:5:1: error: the move after cutter compensation is cancelled must be straight, not an arc"),
    (("G41 D1", "G42 D1"), "p.nc:3:1: error: cutter compensation is turned on while it is on (cancel it first)"),
    (("G0 X0 Y0 Z5", "G41 D1 G1 X10 Y0 F100", "G81 X20 Y0 Z-1 R1"),
     "p.nc:4:1: error: a canned cycle with cutter compensation on cannot be run (cancel it first)"),
    (("G0 X0 Y0", "G41 G1 X10 Y0 F100"),
     "p.nc:3:1: error: cutter compensation without D takes the radius of the tool in the spindle, which is not "
     "known here (no tool change before it, no startTool in the set-up's <Machine>): program D"),
    (("G41 D9", "G1 X10 F100"),
     'p.nc:2:5: error: the set-up gives tool radius register 9 no value: add <Tool number="9" radius=".."/> '
     "to its <Tools>, or write the register in the program"),
])
def test_what_linuxcnc_refuses_is_a_located_error(blocks: tuple[str, ...], message: str) -> None:
    text = "G21 G17 G90 G40 G49\n" + "\n".join(blocks) + "\nM2\n"
    assert errors(text, "linuxcnc", machine(T1=(0.0, 1.0)))[0] == message


def test_a_dialect_without_rules_keeps_the_setting_for_verify() -> None:
    # ISG's start-up and corner rules are not modelled (Fanuc's are: tests/test_fanuc_comp.py): the path
    # stays the programmed one
    got = moves(run("G71 G90 G0 X0 Y0\nG41 D1 G1 X10 F100\nG40 G0 X0\nM30\n", "isg", machine(T1=(0.0, 5.0))))
    assert all("controlled" not in m for m in got)


def test_the_verify_picture_draws_the_controlled_paths_it_compares() -> None:
    from postproc.drawing.overlay import Overlay
    setup = machine(T1=(100.0, None))
    source = "G21 G90\nG0 X0 Y0 Z200.\nG43 H1 Z10.\nG1 X10. F100.\nM30\n"
    written = "G21 G90\nG0 X0 Y0 Z200.\nG0 Z110.\nG1 X10. F100.\nM30\n"
    overlay = Overlay()
    try:
        verify_lines(io.StringIO(source), io.StringIO(written), file_in="a.nc", file_out="b.nc", source="fanuc",
                     target="fanuc", setup=setup, overlay=overlay)
        assert list(overlay.source.all_points()) == list(overlay.target.all_points())
        assert max(z for _, _, z in overlay.source.all_points()) == 200
        assert (10.0, 0.0, 110.0) in list(overlay.source.all_points())  # the cut at the controlled Z
    finally:
        overlay.close()


def test_the_cutter_queue_is_bounded() -> None:
    # the compensated line (line 3) and 9,999 moves along Z wait for the next move in the plane; the
    # 10,000th (line 3 + 10,000) is refused rather than held
    from postproc.compensation.cutter_radius import QUEUE_LIMIT
    zs = "".join(f"G1 Z{-(k % 2)}\n" for k in range(QUEUE_LIMIT))
    text = f"G21 G17 G90 G40 G49\nG0 X0 Y0 Z0\nG41 D1 G1 X10 Y0 F100\n{zs}G40 G1 X0 Y0\nM2\n"
    assert errors(text, "linuxcnc", machine(T1=(0.0, 1.0))) == [
        f"p.nc:{3 + QUEUE_LIMIT}:1: error: cutter compensation waits for a move in the plane for more than "
        f"{QUEUE_LIMIT} moves and events (move in the plane, or cancel compensation, sooner)"]


def test_without_h_or_d_linuxcnc_takes_the_tool_in_the_spindle_not_the_one_selected_since() -> None:
    # [V] rs274: T1 M6 T2 G43 applies tool 1's length; G41 without D takes tool 1's radius
    setup = machine(T1=(10.0, 1.0), T2=(20.0, 2.0))
    got = moves(run("G21 G17 G90\nT1 M6\nT2\nG43\nG0 X0 Y0 Z5\nG41 G1 X10 Y0 F100\nG40 G1 X20 Y0\nM2\n",
                    "linuxcnc", setup))
    assert [(m["controlled"]["x"], m["controlled"]["y"], m["controlled"]["z"]) for m in got] == [
        (0, 0, 15), (10, 1, 15), (20, 0, 15)]
