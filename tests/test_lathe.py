"""Lathes: the machine type decides what a code means; Fanuc T and GSK 980TDc read, keep native and expand
lathe cycles; the toolpath is in the XZ plane with X as a diameter.

Expected texts and toolpaths are derived by hand from DIALECTS.md 2.2 (and the seed's GSK G71), and each
translation is checked against its source by ``verify`` (both programs simulated by their own readers).
"""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList
from postproc.ir import Block
from postproc.ir.lathe_sections import LatheCycle
from postproc.setup.machine_setup import InputSettings, LatheCycleSettings, MachineSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

LATHE = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"))
MILL = MachineSetup()

SEED = """%
O0001
G00 X60. Z5.
G71 U2. R1.
G71 P10 Q20 U0.5 W0.1 F0.25 K1
N10 G00 X20.
G01 Z-20. F0.1
X40. Z-30.
Z-50.
N20 X56.
G70 P10 Q20
G00 X100. Z50.
M30
%
"""
"""The seed's GSK G71 two-block form (with its K1 monotonicity check) and a G70 finish."""


def lines(text: str) -> list[str]:
    return text.splitlines(keepends=True)


def write(text: str, source: str, target: str, setup: MachineSetup = LATHE) -> str:
    out = io.StringIO()
    translate(lines(text), out, file="in.nc", source=source, target=target, setup=setup)
    return out.getvalue()


def events(text: str, dialect: str, setup: MachineSetup = LATHE) -> list[dict[str, Any]]:
    return list(toolpath_events(lines(text), file="in.nc", dialect=dialect, setup=setup))


def blocks(text: str, dialect: str, setup: MachineSetup = LATHE) -> list[Block]:
    return read_program(lines(text), file="in.nc", dialect=dialect, setup=setup)


def deviation(source: str, out: str, src: str, dst: str, setup: MachineSetup = LATHE) -> float:
    report = verify_lines(lines(source), lines(out), file_in="in.nc", file_out="out.nc", source=src, target=dst,
                          setup=setup)
    assert report.ok, report.summary()
    return report.max_deviation


# -- the seed: kept native, expanded, verified ------------------------------------------------------

def test_seed_gsk_to_fanuc_keeps_the_cycles_native() -> None:
    # Fanuc T has no K (the monotonicity check: the translation has made it), every other word stays;
    # GSK starts in G98 (feed per minute), Fanuc T in G99: the first block says G98 (and the units the
    # translation read the program in, G21: postproc.lowering.units_at_start)
    assert write(SEED, "gsk", "fanuc") == (
        "%\nO0001\nG21 G98 G00 X60. Z5.\nG71 U2. R1.\nG71 P10 Q20 U0.5 W0.1 F0.25\nN10 G00 X20.\nG01 Z-20. F0.1\n"
        "G01 X40. Z-30.\nG01 Z-50.\nN20 G01 X56.\nG70 P10 Q20\nG00 X100. Z50.\nM30\n%\n")


def test_seed_round_trips_byte_for_byte() -> None:
    assert write(SEED, "gsk", "gsk") == SEED


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_seed_is_expanded_for_a_target_without_lathe_cycles(target: str) -> None:
    text = write(SEED, "gsk", target)
    code = [line for line in text.splitlines() if line[:1] not in ("(", "%", "O")]
    assert not any("G71" in line or "G70" in line for line in code)
    assert "(turn_rough from line 5: G71 P10 Q20 U0.5 W0.1 F0.25 K1)" in text
    assert "(turn_finish from line 11: G70 P10 Q20)" in text
    assert "(PROFILE LINE 6: N10 G00 X20.)" in text
    if target == "grbl":  # X is a radius there (no diameter mode): the first move to X60. is written X30.
        assert code[0].startswith("G18") and "X30." in code[0]
    else:  # a LinuxCNC lathe in diameter mode (G7): X60. stays
        assert code[0] == "G18 G7" and "X60." in code[1]
    assert deviation(SEED, text, "gsk", target) == 0.0


def test_verify_reports_zero_deviation_between_native_and_expanded() -> None:
    fanuc = write(SEED, "gsk", "fanuc")
    grbl = write(SEED, "gsk", "grbl")
    assert deviation(SEED, fanuc, "gsk", "fanuc") == 0.0
    assert deviation(fanuc, grbl, "fanuc", "grbl") == 0.0


def test_a_wrong_translation_is_caught_by_verify() -> None:
    """The comparison can fail: the same program with the allowance changed deviates by 0.25 mm radius."""
    fanuc = write(SEED, "gsk", "fanuc").replace("U0.5 W0.1", "U1. W0.1")
    report = verify_lines(lines(SEED), lines(fanuc), file_in="in.nc", file_out="out.nc", source="gsk",
                          target="fanuc", setup=LATHE)
    assert not report.ok


def test_seed_toolpath_finishing_pass_by_hand() -> None:
    """G70 from A (X60 Z5): the profile's own moves and feeds, then a rapid back to A; the profile blocks
    themselves never run where they stand (the controller skips to the block after N20)."""
    evs = events(SEED, "gsk")
    assert evs[0] == {"toolpath": 1, "units": "mm", "dialect": "gsk", "x_mode": "diameter"}
    assert not [e for e in evs[1:] if 6 <= e["line"] <= 10]
    finish = [e for e in evs if e.get("line") == 11]
    assert finish == [
        {"line": 11, "move": "rapid", "x": 20, "z": 5},
        {"line": 11, "move": "feed", "x": 20, "z": -20, "f": 0.1},
        {"line": 11, "move": "feed", "x": 40, "z": -30, "f": 0.1},
        {"line": 11, "move": "feed", "x": 40, "z": -50, "f": 0.1},
        {"line": 11, "move": "feed", "x": 56, "z": -50, "f": 0.1},
        {"line": 11, "move": "rapid", "x": 60, "z": 5},
    ]


def test_seed_roughing_by_hand() -> None:
    """G71 U2 R1, U0.5 W0.1: A' = (X60.5, Z5.1); the first level 2 mm (radius) in at X56.5 cuts to the
    offset profile's Z-49.9; the last pass follows the profile offset by 0.25 (radius) and 0.1."""
    rough = [e for e in events(SEED, "gsk") if e.get("line") == 5]
    assert rough[0] == {"line": 5, "move": "rapid", "x": 60.5, "z": 5.1}
    assert rough[1] == {"line": 5, "move": "rapid", "x": 56.5, "z": 5.1}
    assert rough[2] == {"line": 5, "move": "feed", "x": 56.5, "z": -49.9, "f": 0.25}
    contour = [(e["x"], e["z"]) for e in rough if e["move"] == "feed"][-4:]
    assert contour == [(20.5, -19.9), (40.5, -29.9), (40.5, -49.9), (56.5, -49.9)]
    assert (rough[-1]["x"], rough[-1]["z"]) == (60, 5)  # back at A
    depths = sorted({e["x"] for e in rough if e["move"] == "feed" and e["z"] != -19.9 and e["x"] < 60})
    assert all(b - a <= 4.0 + 1e-9 for a, b in zip(depths, depths[1:]))  # 2 mm radius per pass


# -- single cycles ----------------------------------------------------------------------------------

SINGLE = """G00 X60. Z5.
G90 X50. Z-30. F0.2
X40. R-2.
G00 X100.
"""


def test_turning_single_cycle_by_hand() -> None:
    """G90: rapid X to the cut, feed Z, feed X out, rapid Z back; X40 repeats it, R-2 (radius) starts the
    cut 2 mm lower: X36 (diameter)."""
    evs = events(SINGLE, "gsk")[1:]
    assert [(e["line"], e["move"], e["x"], e["z"]) for e in evs] == [
        (1, "rapid", 60, 5),
        (2, "rapid", 50, 5), (2, "feed", 50, -30), (2, "feed", 60, -30), (2, "rapid", 60, 5),
        (3, "rapid", 36, 5), (3, "feed", 40, -30), (3, "feed", 60, -30), (3, "rapid", 60, 5),
        (4, "rapid", 100, 5),
    ]


def test_single_cycle_in_fanuc_system_b_is_g77() -> None:
    setup = MachineSetup(input=InputSettings(machine_type="lathe", gcode_system="B"), machine=MachineSettings(axes="XZ"))
    text = write(SINGLE, "gsk", "fanuc", setup)
    assert text == "G21 G94 G00 X60. Z5.\nG77 X50. Z-30. F0.2\nG77 X40. Z-30. R-2.\nG00 X100.\n"
    assert deviation(SINGLE, text, "gsk", "fanuc", setup) == 0.0


# -- words ------------------------------------------------------------------------------------------

def test_u_and_w_are_increments_of_x_and_z() -> None:
    evs = events("G00 X60. Z5.\nG01 U-10. W-5. F0.2\nX20. W-5.\n", "gsk")[1:]
    assert [(e["x"], e["z"]) for e in evs] == [(60, 5), (50, 0), (20, -5)]


def test_radius_programming_reads_x_as_a_radius() -> None:
    setup = MachineSetup(input=InputSettings(machine_type="lathe", x_programming="radius"),
                         machine=MachineSettings(axes="XZ"))
    evs = events("S500 M03\nG00 X30. Z5.\nG01 U-5. F0.2\n", "fanuc", setup)
    assert evs[0] == {"toolpath": 1, "units": "mm", "dialect": "fanuc", "feed_mode": "per_rev"}  # G99 at start
    assert [(e["x"], e["z"]) for e in evs[2:]] == [(30, 5), (25, 5)]


def test_coordinate_setting_and_spindle_clamp() -> None:
    bs = blocks("G50 X200. Z100.\nG50 S2500\nG96 S180\nG00 X60. Z5.\n", "gsk")
    assert bs[0].sections["CoordinateSet"].axes == {"X": 200.0, "Z": 100.0}
    assert bs[1].sections["SpindleClamp"].rpm == 2500.0
    assert bs[2].sections["SpindleMode"].mode == "css"
    assert write("G50 X200. Z100.\nG50 S2500\nG96 S180\nG00 X60. Z5.\n", "gsk", "fanuc") == (
        "G21\nG98 G50 X200. Z100.\nG50 S2500\nG96 S180\nG00 X60. Z5.\n")  # units before the setting's lengths
    # G50 X200 declares where the tool is: a move to X60 goes 140 (diameter) down from there
    evs = events("G50 X200. Z100.\nG00 X60. Z5.\n", "gsk")
    assert [(e["x"], e["z"]) for e in evs[1:]] == [(60, 5)]


def test_tool_and_offset_word() -> None:
    assert write("T0101\n", "gsk", "fanuc") == "G21 G98 T0101\n"  # GSK's start in G98 said for Fanuc T
    assert blocks("T0101\n", "gsk")[0].sections["ToolSelect"].number == 101


# -- the same number, another meaning ---------------------------------------------------------------

@pytest.mark.parametrize("text, setup, key, value", [
    ("G50", MILL, "FrameChange", "scale_off"),
    ("G50 X100. Z50.", LATHE, "CoordinateSet", {"X": 100.0, "Z": 50.0}),
    ("G98", MILL, "ReturnLevel", "initial"),
    ("G98", LATHE, "FeedMode", "per_min"),
    ("G99", LATHE, "FeedMode", "per_rev"),
    ("G90", MILL, "DistanceMode", "absolute"),
    ("G94", MILL, "FeedMode", "per_min"),
    ("G92 X10. Z0.", MILL, "FrameChange", "origin"),
])
def test_machine_type_decides_meaning(text: str, setup: MachineSetup, key: str, value: object) -> None:
    section = blocks(text + "\n", "fanuc", setup)[0].sections[key]
    got = {"NativeCode": "what", "FrameChange": "kind", "CoordinateSet": "axes", "ReturnLevel": "level", "FeedMode": "mode",
           "DistanceMode": "mode"}[key]
    assert getattr(section, got) == value


@pytest.mark.parametrize("code, kind", [("G90", "turn_single"), ("G92", "thread_single"), ("G94", "face_single")])
def test_system_a_single_cycles(code: str, kind: str) -> None:
    b = blocks(f"S500 M03 G00 X60. Z5.\n{code} X50. Z-30. F2.\n", "fanuc")[1]  # (G99: the spindle turns)
    assert b.sections["LatheCycle"].kind == kind


def test_system_b_and_c_renumber() -> None:
    b_setup = MachineSetup(input=InputSettings(machine_type="lathe", gcode_system="B"))
    c_setup = MachineSetup(input=InputSettings(machine_type="lathe", gcode_system="C"))
    assert blocks("G90\n", "fanuc", b_setup)[0].sections["DistanceMode"].mode == "absolute"
    assert blocks("G92 X10. Z0.\n", "fanuc", b_setup)[0].sections["CoordinateSet"].axes == {"X": 10.0, "Z": 0.0}
    assert blocks("G94\n", "fanuc", b_setup)[0].sections["FeedMode"].mode == "per_min"
    assert blocks("G98\n", "fanuc", b_setup)[0].sections["NativeCode"].what.startswith("G98 (drilling")
    assert blocks("G71\n", "fanuc", c_setup)[0].sections["Units"].system == "mm"
    assert blocks("G70\n", "fanuc", c_setup)[0].sections["Units"].system == "inch"


def test_a_mill_never_reads_lathe_cycles() -> None:
    with pytest.raises(ErrorList) as info:
        blocks("G71 U2. R1.\n", "fanuc", MILL)
    assert [str(e) for e in info.value.errors] == ["in.nc:1:1: error: unknown G code G71"]


def test_a_lathe_never_reads_mill_cycles() -> None:
    with pytest.raises(ErrorList) as info:
        blocks("G81 X0. Z-5. R1. F100.\n", "gsk")
    assert [str(e) for e in info.value.errors] == ["in.nc:1:1: error: unknown G code G81"]


# -- defaults and checks ------------------------------------------------------------------------------

TWO_CYCLES = """G00 X60. Z5.
G71 P10 Q20 U0.5 W0.1 F0.25
N10 G00 X20.
N20 G01 X56. Z-20.
G71 U2.5 R0.7
G71 P30 Q40 U0.5 W0.1 F0.25
N30 G00 X20.
N40 G01 X56. Z-20.
G71 P50 Q60 U0.5 W0.1 F0.25
N50 G00 X20.
N60 G01 X56. Z-20.
"""


def test_gsk_data_parameters_default_and_are_rewritten_by_a_programmed_value() -> None:
    """No.051/052 from the set-up until a first block programs U/R; from then on its values (the seed)."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe"),
                         lathe_cycles=LatheCycleSettings(rough_depth=1.5, rough_retract=0.4))
    cycles = [b.sections["LatheCycle"] for b in blocks(TWO_CYCLES, "gsk", setup) if "LatheCycle" in b.sections]
    assert [(c.form, c.params["depth"], c.params["retract"]) for c in cycles] == [
        ("second", 1.5, 0.4), ("first", 2.5, 0.7), ("second", 2.5, 0.7), ("second", 2.5, 0.7)]


def test_gsk_output_writes_every_word() -> None:
    """A Fanuc G71 without its first block: GSK gets one, with the values the source used."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe"),
                         lathe_cycles=LatheCycleSettings(rough_depth=1.5, rough_retract=0.4))
    text = write("S500 M03\nG00 X60. Z5.\nG71 P10 Q20 U0.5 W0.1 F0.25\nN10 G00 X20.\nN20 G01 X56. Z-20.\n", "fanuc", "gsk",
                 setup)
    assert text == ("G21 G99 S500 M03\nG00 X60. Z5.\nG71 U1.5 R0.4\nG71 P10 Q20 U0.5 W0.1 F0.25\nN10 G00 X20.\n"
                    "N20 G01 X56. Z-20.\n")


def test_gsk_k1_refuses_a_profile_that_is_not_monotonic_at_its_block() -> None:
    program = ("G00 X60. Z5.\nG71 U2. R1.\nG71 P10 Q20 U0.5 W0.1 F0.25 K1\nN10 G00 X20.\nG01 Z-20. F0.1\n"
               "X40. Z-30.\nX30. Z-40.\nN20 X56.\n")
    with pytest.raises(ErrorList) as info:
        blocks(program, "gsk")
    assert [str(e) for e in info.value.errors] == [
        "in.nc:7:1: error: G71 K1: the profile is not monotonic in X at line 7"]


def test_profile_with_a_missing_last_block_is_a_located_error() -> None:
    with pytest.raises(ErrorList) as info:
        blocks("G00 X60. Z5.\nG71 U2. R1.\nG71 P10 Q20 U0.5 F0.25\nN10 G00 X20.\nG01 Z-20.\n", "gsk")
    assert [str(e) for e in info.value.errors] == [
        "in.nc:3:1: error: G71: the profile's last block N20 is not in the program"]


def test_g70_without_a_roughing_profile_is_a_located_error() -> None:
    with pytest.raises(ErrorList) as info:
        blocks("G00 X60. Z5.\nG70 P10 Q20\n", "gsk")
    assert [str(e) for e in info.value.errors] == [
        "in.nc:2:1: error: G70 P10 Q20: no roughing cycle before it read the profile N10..N20"]


def test_one_block_form_written_and_read() -> None:
    """Fanuc 10/11/15-T: G71 P Q U W D F in one block; GSK gets it as two."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe", lathe_cycle_format="one-block"))
    program = "S500 M03\nG00 X60. Z5.\nG71 P10 Q20 U0.5 W0.1 D2. F0.25\nN10 G00 X20.\nN20 G01 X56. Z-20.\n"
    cycle = blocks(program, "fanuc", setup)[2].sections["LatheCycle"]
    assert isinstance(cycle, LatheCycle) and cycle.form == "one" and cycle.params["depth"] == 2.0
    gsk = write(program, "fanuc", "gsk", setup)
    assert gsk.splitlines()[2:4] == ["G71 U2. R1.", "G71 P10 Q20 U0.5 W0.1 F0.25"]
    assert write(SEED, "gsk", "fanuc", setup).splitlines()[3:5] == [
        "(G71 U2. R1.: in the next block)", "G71 P10 Q20 U0.5 W0.1 D2. F0.25"]
    assert deviation(SEED, write(SEED, "gsk", "fanuc", setup), "gsk", "fanuc", setup) == 0.0


# -- the other cycles: words read as the manuals give them, native both ways, verified --------------

CYCLES = """%
O0003
G98 G00 X60. Z5.
G73 U3. W0.5 R3
G73 P30 Q40 U0.4 W0.1 F80.
N30 G00 X20. Z2.
G01 Z-20. F60.
X40. Z-30.
N40 X56.
G70 P30 Q40
G00 X45. Z-10.
G75 R0.5
G75 X30. Z-20. P2000 Q3000 F40.
G00 X60. Z5.
G00 X0. Z3.
G74 R1.
G74 Z-20. Q5000 F30.
G00 X55. Z5.
G76 P011060 Q100 R0.05
G76 X44.376 Z-30. P1624 Q500 F2.
G00 X60. Z5.
G92 X47. Z-30. F2.
X46.
G94 X20. Z-2. F50.
Z-4.
G00 X100. Z50.
M30
%
"""


def _cycle(program: str, line: int) -> LatheCycle:
    block = next(b for b in blocks(program, "gsk") if b.line == line)
    cycle = block.sections["LatheCycle"]
    assert isinstance(cycle, LatheCycle)
    return cycle


@pytest.mark.parametrize("line, kind, form, params", [
    (4, "pattern_repeat", "first", {"relief_x": 3.0, "relief_z": 0.5, "passes": 3}),
    (5, "pattern_repeat", "second", {"ns": 30, "nf": 40, "allow_x": 0.4, "allow_z": 0.1, "relief_x": 3.0,
                                     "relief_z": 0.5, "passes": 3}),
    (13, "groove", "second", {"x": 30.0, "z": -20.0, "step_x": 2.0, "step_z": 3.0, "relief": 0.0, "retract": 0.5}),
    # G74 without X: a drill on the spot (X of the start); Q in least increments: 5000 = 5 mm
    (17, "face_peck", "second", {"z": -20.0, "step_z": 5.0, "x": 0.0, "step_x": 0.0, "relief": 0.0, "retract": 1.0}),
    # P011060: one finishing pass, chamfer 1.0 x lead, 60 degrees; Q100 = 0.1 mm; P1624 = 1.624 mm
    (19, "thread_multi", "first", {"finish_passes": 1, "chamfer": 10, "angle": 60, "min_depth": 0.1,
                                   "allowance": 0.05}),
    (20, "thread_multi", "second", {"x": 44.376, "z": -30.0, "height": 1.624, "first_depth": 0.5, "taper": 0.0,
                                    "finish_passes": 1, "chamfer": 10, "angle": 60, "min_depth": 0.1,
                                    "allowance": 0.05}),
    (23, "thread_single", "single", {"x": 46.0, "z": -30.0}),
    (25, "face_single", "single", {"x": 20.0, "z": -4.0}),
])
def test_cycle_words(line: int, kind: str, form: str, params: dict[str, float]) -> None:
    cycle = _cycle(CYCLES, line)
    assert (cycle.kind, cycle.form) == (kind, form)
    for name, value in params.items():
        assert cycle.params[name] == pytest.approx(value), name


def test_every_cycle_round_trips_through_fanuc_and_verifies() -> None:
    fanuc = write(CYCLES, "gsk", "fanuc")
    assert "G75 X30. Z-20. P2000 Q3000 R0. F40." in fanuc  # every word; P/Q back in least increments
    assert "G76 P011060 Q100 R0.05" in fanuc and "G76 X44.376 Z-30. P1624 Q500 F2." in fanuc
    assert deviation(CYCLES, fanuc, "gsk", "fanuc") == 0.0
    assert write(fanuc, "fanuc", "gsk") == fanuc  # GSK gets the same explicit words


def test_thread_passes_reach_the_root_from_the_first_depth() -> None:
    """G76 X44.376 P1624 Q500 from X55: the crest is the root plus the height, 44.376 + 2 x 1.624 =
    47.624 (diameter); the first pass cuts 0.5 (radius) below it, X46.624; the last reaches the root."""
    threads = [e for e in events(CYCLES, "gsk") if e.get("line") == 20 and e.get("move") == "feed"]
    assert threads[0]["x"] == pytest.approx(46.624)
    assert min(e["x"] for e in threads) == pytest.approx(44.376)


def test_grooving_pecks_stay_within_the_groove() -> None:
    evs = [e for e in events(CYCLES, "gsk") if e.get("line") == 13 and "move" in e]
    assert min(e["x"] for e in evs) == pytest.approx(30.0)
    assert {e["z"] for e in evs} <= {-10.0, -13.0, -16.0, -19.0, -20.0}
    assert (evs[-1]["x"], evs[-1]["z"]) == (45, -10)  # back at the start


def test_threading_has_no_spelling_where_the_spindle_is_not_synchronised() -> None:
    with pytest.raises(ErrorList) as info:
        write("G00 X60. Z5.\nG92 X47. Z-30. F2.\n", "gsk", "grbl")
    assert [str(e) for e in info.value.errors] == ["in.nc:2:1: error: the grbl dialect cannot express thread motion"]


def test_least_increment_words_take_no_decimal_point() -> None:
    with pytest.raises(ErrorList) as info:
        blocks("G00 X45. Z-10.\nG75 R0.5\nG75 X30. Z-20. P2. Q3000 F40.\n", "gsk")
    assert [str(e) for e in info.value.errors] == [
        "in.nc:3:16: error: address P of G75 takes no decimal point: it counts least input increments (P2.)"]


@pytest.mark.parametrize("target", ["grbl", "linuxcnc"])
def test_roughing_grooving_and_facing_expand_and_verify(target: str) -> None:
    program = "\n".join(line for line in CYCLES.splitlines()
                        if not any(code in line for code in ("G76", "G92", "X46."))) + "\n"
    text = write(program, "gsk", target)
    assert "(pattern_repeat from line 5: G73 P30 Q40 U0.4 W0.1 F80.)" in text
    assert deviation(program, text, "gsk", target) == 0.0


def test_lathe_backplot_draws_the_zx_plane_in_radii(tmp_path: Any) -> None:
    from postproc.commands.export import export_toolpath
    out = io.StringIO()
    export_toolpath(lines(SEED), out, file="in.nc", dialect="gsk", setup=LATHE, fmt="svg")
    svg = out.getvalue()
    assert "Turning (Z across, X radius up)" in svg
    # the diameters 20..100 (the profile's N10 X20., the last rapid's X100.) drawn as radii (true geometry,
    # arcs round); the set-up gives no start, so the drawing begins at the first move (X60. Z5.), not at X0
    assert "X 10..50 " in svg


def test_each_control_starts_in_its_own_feed_mode() -> None:
    """Fanuc T starts in G99 (per revolution), GSK in G98, grbl and LinuxCNC per minute: a program that
    relies on its control's start gets the mode written for a target that starts in another."""
    program = "G97 S500 M03\nG00 X60. Z5.\nG01 X50. F0.2\n"  # a spindle turning: LinuxCNC feeds per rev only then
    assert write(program, "fanuc", "linuxcnc").splitlines()[:2][0] == "G18 G7"  # the LinuxCNC lathe's modes
    assert write(program, "fanuc", "linuxcnc").splitlines()[2].startswith("G95 ")  # after the units (G21)
    assert events(program, "fanuc")[0]["feed_mode"] == "per_rev"
    assert "feed_mode" not in events(program, "gsk")[0]
    assert write(program, "fanuc", "fanuc") == program


def test_verify_reads_the_target_on_the_sources_lathe(cli: Any, tmp_path: Any) -> None:
    """GSK is a lathe whatever the set-up says; without --target-machine the Fanuc translation is read as
    running on the same lathe (not as a mill program, where G71 is unknown)."""
    src, out = tmp_path / "seed.nc", tmp_path / "seed.fanuc.nc"
    src.write_text(SEED)
    assert cli("translate", src, "--from", "gsk", "--to", "fanuc", "-o", out).status == 0
    result = cli("verify", src, out, "--from", "gsk", "--to", "fanuc")
    assert result.status == 0, result.err
    assert result.out.decode().startswith("max deviation 0.0000 mm")


def test_an_absolute_and_an_incremental_word_of_one_axis_are_refused() -> None:
    with pytest.raises(ErrorList) as info:
        blocks("G00 X60. Z5.\nZ-5. W0\n", "gsk")
    assert [str(e) for e in info.value.errors] == [
        "in.nc:2:6: error: Z and W in one block: the absolute and the incremental Z of one move"]


@pytest.mark.parametrize("line", ["X20. U2.", "N20 Z-5. W1.5", "G1 X20. U2."])
def test_a_cam_line_with_both_words_of_an_axis_is_refused_too(line: str) -> None:
    """A canonical CAM line (no G code) takes the plain-block lane (``postproc.fast.plain``), which once accepted ``X20. U2.``
    (run as X22) while ``G1 X20. U2.`` was refused: both are."""
    with pytest.raises(ErrorList) as info:
        blocks(f"G00 X60. Z5. S500 M03\nG01 X50. F0.2\n{line}\n", "fanuc")
    [error] = [str(e) for e in info.value.errors]
    assert error.startswith("in.nc:3:") and "in one block: the absolute and the incremental" in error


def test_g76_one_block_form_becomes_two_blocks_for_gsk() -> None:
    """Fanuc 15-T ``G76 X Z K D F A P``: K height, D first depth (decimal); GSK gets the two-block form
    with the set-up's m and r and the block's angle, P/Q in least increments."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe", lathe_cycle_format="one-block"))
    program = "S500 M03 G00 X55. Z5.\nG76 X44.376 Z-30. K1.624 D0.5 F2. A60 P1\nG00 X60.\n"
    gsk = write(program, "fanuc", "gsk", setup)
    assert gsk.splitlines()[1:3] == ["G76 P011060 Q100 R0.05", "G76 X44.376 Z-30. P1624 Q500 F2."]
    assert deviation(program, gsk, "fanuc", "gsk", setup) == 0.0


def test_g72_facing_expands_and_verifies() -> None:
    program = ("G00 X62. Z2.\nG72 W1.5 R0.5\nG72 P10 Q20 U0.4 W0.2 F100.\nN10 G00 Z-12.\nG01 X40. F50.\n"
               "X20. Z-4.\nN20 Z2.\nG70 P10 Q20\n")
    cycle = _cycle(program, 2)
    assert (cycle.kind, cycle.params["depth"], cycle.params["retract"]) == ("face_rough", 1.5, 0.5)
    for target in ("grbl", "fanuc"):
        assert deviation(program, write(program, "gsk", target), "gsk", target) == 0.0


def test_a_lathe_cycle_with_computed_words_is_flattened_or_refused() -> None:
    """Kept symbolically a cycle's computed words are refused (located); flattened they are numbers."""
    program = "G98 G00 X60. Z5.\n#1=50.\nG90 X[#1] Z-30. F100.\n"
    with pytest.raises(ErrorList) as info:
        blocks(program, "fanuc")
    assert [str(e) for e in info.value.errors] == [
        "in.nc:3:1: error: G90 with computed words cannot be read: a lathe cycle's words must be numbers"]
    grbl = write(program, "fanuc", "grbl")
    assert "(turn_single from line 3: G90 X50. Z-30. F100.)" in grbl
    assert deviation(program, grbl, "fanuc", "grbl") == 0.0


SUBPROGRAM_G71 = ("O1000\nG21 G18 G40 G99\nT0101\nG97 S500 M03\nG00 X62. Z2.\n{first}M98 P2000\nG00 X100. Z100.\n"
                  "M30\nO2000\n{second}G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.2\nN10 G00 X{x}\nG01 Z-20.\nX60.\n"
                  "N20 Z-40.\nM99\n")
"""A roughing cycle in an M98 subprogram, called from X62 Z2, the text after the call at X100 Z100."""


def _flattened(program: str, target: str) -> tuple[str, str]:
    warned = io.StringIO()
    out = io.StringIO()
    translate(lines(program), out, file="in.nc", source="fanuc", target=target, setup=LATHE,
              diagnostics=Diagnostics(warn_stream=warned))
    return out.getvalue(), warned.getvalue()


def test_a_lathe_cycle_in_a_subprogram_is_roughed_from_where_it_is_called() -> None:
    """Kept symbolically for LinuxCNC (the program computes: ``#5=1.``), the G71 in O2000 was expanded from where
    the text before it left the tool (X100 Z100, after the call), not where M98 runs it (X62 Z2): exit 0, verify
    105 mm off. As a hole cycle's, an expansion the control flow may run elsewhere flattens the program."""
    program = SUBPROGRAM_G71.format(first="#5=1.\n", second="", x="40.")
    written, warned = _flattened(program, "linuxcnc")
    assert deviation(program, written, "fanuc", "linuxcnc") < 1e-9
    assert warned == ("in.nc:6:1: warning: the program is flattened (its evaluated motion is written): line 12: the "
                      "lathe cycle in 'G71 P10 Q20 U0.4 W0.1 F0.2' would be written as the moves of one run, but the "
                      "program's control flow (a subprogram, a loop or a jump) runs it from other positions\n")


def test_a_flattened_computed_profile_says_why() -> None:
    """Its roughing profile computed (X[#1]), the program is flattened for LinuxCNC, and the warning says so: it
    said "M98 sharing its line with other words (FeedMode)", the source's feed mode put on the dry run's first block
    (the call) as if it were the program's start."""
    program = SUBPROGRAM_G71.format(first="", second="#1=40.\n", x="[#1]")
    written, warned = _flattened(program, "linuxcnc")
    assert deviation(program, written, "fanuc", "linuxcnc") < 1e-9
    assert warned == ("in.nc:6:1: warning: the program is flattened (its evaluated motion is written): line 13: "
                      "G71: a computed word in the profile cannot be expanded\n")


@pytest.mark.parametrize("word", ["X1.5", "U1.5", "P1500"])
def test_dwell_on_a_lathe(word: str) -> None:
    evs = events(f"G00 X60. Z5.\nG04 {word}\nG00 X70.\n", "gsk")[1:]
    assert evs == [{"line": 1, "move": "rapid", "x": 60, "z": 5}, {"line": 2, "event": "dwell", "seconds": 1.5},
                   {"line": 3, "move": "rapid", "x": 70, "z": 5}]


def test_data_parameters_are_millimetres_in_an_inch_program() -> None:
    """No.051 holds 1.5 mm: an inch program's G71 without U cuts 1.5 / 25.4 in a pass; a programmed
    U0.1 (inch) is kept as 2.54 mm for the next cycle."""
    setup = MachineSetup(input=InputSettings(machine_type="lathe"), lathe_cycles=LatheCycleSettings(rough_depth=1.5))
    program = ("G20\nG00 X2.4 Z0.2\nG71 P10 Q20 U0.02 F8.\nN10 G00 X0.8\nN20 G01 X2.2 Z-1.\n"
               "G71 U0.1 R0.02\nG71 P30 Q40 U0.02 F8.\nN30 G00 X0.8\nN40 G01 X2.2 Z-1.\nG21\n"
               "G71 P50 Q60 U0.5 F100.\nN50 G00 X20.\nN60 G01 X56. Z-25.\n")
    depths = [b.sections["LatheCycle"].params["depth"] for b in blocks(program, "gsk", setup)
              if "LatheCycle" in b.sections and b.sections["LatheCycle"].form == "second"]
    assert depths == pytest.approx([1.5 / 25.4, 0.1, 2.54])


def test_g32_thread_cutting_is_a_synchronised_move() -> None:
    program = "G99 S500 M03 G00 X30. Z5.\nG32 Z-20. F1.5\nG00 X40.\n"
    b_setup = MachineSetup(input=InputSettings(machine_type="lathe", gcode_system="B"))
    assert write(program, "gsk", "fanuc", b_setup) == "G21 G95 G00 X30. Z5. S500 M03\nG33 Z-20. F1.5\nG00 X40.\n"
    assert blocks(program, "gsk")[1].sections["Motion"].mode == "thread"
    evs = events(program, "gsk")
    assert evs[3] == {"line": 2, "move": "feed", "x": 30, "z": -20, "f": 1.5}
    with pytest.raises(ErrorList):
        write(program, "gsk", "grbl")


def test_system_b_incremental_moves_become_u_w_for_system_a() -> None:
    b_setup = MachineSetup(input=InputSettings(machine_type="lathe", gcode_system="B"))
    program = "G94 G90 G00 X60. Z5.\nG91 G01 X-10. Z-5. F100.\nG02 X10. Z-5. R5.\nG90 G00 X80.\n"
    gsk = write(program, "fanuc", "gsk", b_setup)
    assert gsk == "G21 G98 G00 X60. Z5.\nG01 U-10. W-5. F100.\nG02 U10. W-5. R5.\nG00 X80.\n"
    report = verify_lines(lines(program), lines(gsk), file_in="in.nc", file_out="out.nc", source="fanuc",
                          target="gsk", setup=b_setup, target_setup=LATHE)
    assert report.ok and report.max_deviation == 0.0
