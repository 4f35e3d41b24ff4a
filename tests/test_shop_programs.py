"""Shop programs end to end (issue 12, "Done when"): CAM-posted and hand-written Fanuc-family milling
programs (tests/shop/, sources in its README) round-trip byte for byte, simulate, translate to LinuxCNC
and grbl, verify at zero deviation, and the LinuxCNC translations move in LinuxCNC's own interpreter as
the source does. A few simulated points per program are derived by hand below."""

from __future__ import annotations

import io
import math
import re
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274
from tests.support.tools import REGISTERS, with_tools

SHOP = Path(__file__).resolve().parent / "shop"
PROGRAMS: dict[str, tuple[str | None, bool]] = {
    "fusion_haas_vf2_plate.nc": ("haas_vf2.xml", True),
    "fusion_fanuc_bracket.nc": (None, True),
    "mastercam_fanuc_slot.nc": (None, True),
    "solidworks_cam_cover.nc": (None, True),
    "haas_two_vises.nc": ("haas_vf2.xml", True),
    "fanuc_0m_dos_profile.nc": ("fanuc_0m.xml", True),
    "four_axis_index.nc": ("four_axis.xml", False),
}
"""Program -> (its set-up, whether grbl can run it: a stock grbl has no 4th axis)."""
RIGID_TAPS = {"fusion_fanuc_bracket.nc": (60, 61, 62)}
"""Programs with a rigid tap, by the line of its M29 and of each tap block: LinuxCNC gets them as G33.1;
grbl cannot synchronise its feed with the spindle, and fed as a floating tap the tap breaks, so there
they are refused."""
TRANSLATED = list(PROGRAMS)
TOOL_TABLE = "".join(f"T{n} P{n} Z0 D0 ;\n" for n in range(1, 20))
"""Zero lengths and diameters: LinuxCNC applies both, the simulation neither (verify compares them)."""
TOLERANCE_MM = 3e-3
"""rs274 prints 4 decimals in program units: 1e-4 in = 0.00254 mm."""


def _machine(name: str) -> MachineSetup:
    setup_file = PROGRAMS[name][0]
    return load_setup(SHOP / setup_file) if setup_file else MachineSetup()


def _setup(name: str) -> MachineSetup:
    """The program's machine, its tools measured as zero (the tests here are not about tool lengths)."""
    return with_tools(_machine(name))


def _source(name: str) -> str:
    return (SHOP / name).read_bytes().decode("utf-8")


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def _translate(name: str, target: str, setup: MachineSetup | None = None) -> tuple[str, str]:
    out, warned = io.StringIO(newline=""), io.StringIO()
    translate(_lines(_source(name)), out, file=name, source="fanuc", target=target, setup=setup or _setup(name),
              on_unsupported="warn", diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=warned))
    return out.getvalue(), warned.getvalue()


def _events(name: str) -> list[dict[str, Any]]:
    return list(toolpath_events(_lines(_source(name)), file=name, dialect="fanuc", setup=_setup(name)))[1:]


def test_every_program_has_its_source_noted() -> None:
    readme = (SHOP / "README.md").read_text()
    assert set(PROGRAMS) == {p.name for p in SHOP.glob("*.nc")}
    assert all(f"`{name}`" in readme for name in PROGRAMS)


@pytest.mark.parametrize("name", PROGRAMS)
def test_round_trip_is_byte_for_byte_without_a_word(cli: Any, tmp_path: Path, name: str) -> None:
    out = tmp_path / name
    setup = PROGRAMS[name][0]
    args = ["--machine", SHOP / setup] if setup else []
    result = cli("translate", SHOP / name, "--from", "fanuc", "--to", "fanuc", "-o", out, *args)
    assert (result.status, result.err) == (0, "")
    assert out.read_bytes() == (SHOP / name).read_bytes()


@pytest.mark.parametrize("name", TRANSLATED)
def test_linuxcnc_translation_verifies_at_zero_deviation(name: str) -> None:
    out, _ = _translate(name, "linuxcnc")
    report = verify_lines(_lines(_source(name)), _lines(out), file_in=name, file_out="out.ngc", source="fanuc",
                          target="linuxcnc", setup=_setup(name))
    assert report.ok and report.max_deviation == 0 and not report.left_out_moves, report.summary()
    assert report.moves > 10


@pytest.mark.parametrize("name", [n for n in TRANSLATED if PROGRAMS[n][1] and n not in RIGID_TAPS])
def test_grbl_translation_writes_the_tool_lengths_and_verifies(name: str) -> None:
    lengths = {n: 100.0 + n for n in REGISTERS}
    long_tools = with_tools(_machine(name), lengths=lengths)
    out, _ = _translate(name, "grbl", long_tools)
    # grbl has no tool table: each G43 H<n> is written as G43.1 Z<100 + n> (in an inch program, over 25.4)
    inch = "G20" in _source(name)
    registers = [int(h) for h in re.findall(r"G43\b[^\n(]*?H0*(\d+)", _source(name))]
    written = [float(z) for z in re.findall(r"G43\.1 Z(\S+)", out)]
    assert registers and written == pytest.approx([(100 + n) / (25.4 if inch else 1) for n in registers], abs=1e-5)
    report = verify_lines(_lines(_source(name)), _lines(out), file_in=name, file_out="out.gcode", source="fanuc",
                          target="grbl", setup=long_tools)
    assert report.mismatch is None and report.max_deviation == 0, report.summary()
    # the cutter compensation is resolved for grbl (Fanuc's rules are modelled): nothing is left out
    assert not report.left_out_moves and not [note for note in report.ignored if note.startswith("cutter")]
    # the same output on a machine whose tools measure zero runs every move over 100 mm too high
    report = verify_lines(_lines(_source(name)), _lines(out), file_in=name, file_out="out.gcode", source="fanuc",
                          target="grbl", setup=_setup(name))
    report.allow_ignored = True
    assert not report.ok and report.max_deviation > 100, report.summary()


@pytest.mark.parametrize("name", RIGID_TAPS)
def test_a_rigid_tap_towards_grbl_is_refused_even_with_warn(name: str) -> None:
    from postproc.errors import ErrorList
    with pytest.raises(ErrorList) as info:
        _translate(name, "grbl")
    assert [(e.location.line if e.location else 0, "rigid" in str(e) or "follow the spindle" in str(e))
            for e in info.value.errors] == [(line, True) for line in RIGID_TAPS[name]]


@pytest.mark.parametrize("name", RIGID_TAPS)
def test_a_rigid_tap_reaches_linuxcnc_as_g33_1(name: str) -> None:
    out, _ = _translate(name, "linuxcnc")
    taps = re.findall(r"^G33\.1 .*$", out, re.M)
    assert len(taps) == len(RIGID_TAPS[name]) - 1 and not re.search(r"^[^(]*M29", out, re.M), out
    written_as_feeds = re.sub(r"^G33\.1 (Z\S+) K\S+$", r"G1 \1 F600.", out, flags=re.M)  # a floating tap
    report = verify_lines(_lines(_source(name)), _lines(written_as_feeds), file_in=name, file_out="out.ngc",
                          source="fanuc", target="linuxcnc", setup=_setup(name))
    assert not report.ok and "tap" in report.summary(), report.summary()


@pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("name", TRANSLATED)
def test_linuxcnc_translation_runs_in_linuxcnc_as_the_source_moves(name: str) -> None:
    out, _ = _translate(name, "linuxcnc")
    calls = rs274.run_rs274(out, tool_table=TOOL_TABLE)
    theirs = _machine_moves(calls) if re.search(r"^G10 L2 ", out, re.M) else [
        e for e in rs274.canonical_moves(calls, start=(0.0, 0.0, 0.0)) if "move" in e]
    ours = _xyz_moves(_events(name))
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in LinuxCNC\n{out}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        keys = ("x", "y", "z") + (("cx", "cy") if a["move"] in ("cw", "ccw") else ())
        dev = max(abs(float(a[k]) - float(b[k])) for k in keys)
        assert dev <= TOLERANCE_MM and not math.isnan(dev), (n, a, b)


def _xyz_moves(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The moves that change X, Y or Z (rs274's canonical calls, as read here, report those axes only)."""
    moves, last = [], (0.0, 0.0, 0.0)
    for e in events:
        if "move" in e:
            point = (float(e["x"]), float(e["y"]), float(e["z"]))
            if point != last or e["move"] in ("cw", "ccw"):
                moves.append(e)
            last = point
    return moves


def _machine_moves(calls: list[str]) -> list[dict[str, Any]]:
    """Straight moves of rs274's output in machine coordinates, mm: rs274 prints each point in the active
    work system and each offset as SET_G5X_OFFSET, both in the units in force (no arcs handled); a move
    that goes nowhere is dropped, as the simulation drops it."""
    scale, offset, moves = 1.0, [0.0, 0.0, 0.0], []
    last = [0.0, 0.0, 0.0]
    for call in calls:
        if "USE_LENGTH_UNITS" in call:
            scale = 25.4 if "INCHES" in call else 1.0
        m = re.search(r"SET_G5X_OFFSET\(\d+, ([^)]*)\)", call)
        if m:
            offset = [float(v) * scale for v in m.group(1).split(",")[:3]]
        m = re.search(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\(([^)]*)\)", call)
        if m:
            assert m.group(1) != "ARC_FEED", "arcs are not converted here"
            point = [float(v) * scale + o for v, o in zip(m.group(2).split(",")[:3], offset)]
            if max(abs(a - b) for a, b in zip(point, last)) < 1e-6:
                continue
            last = point
            moves.append({"move": "rapid" if "TRAVERSE" in m.group(1) else "feed", **dict(zip("xyz", point))})
    return moves


# -- hand-derived points --------------------------------------------------------------------------

def _find(events: list[dict[str, Any]], line: int) -> list[dict[str, Any]]:
    return [e for e in events if e["line"] == line]


def test_haas_plate_points() -> None:
    got = _events("fusion_haas_vf2_plate.nc")
    # the peck cycle at X20 Y20, already there at Z5 (the initial level): rapid to R3, feed 4 down, back to
    # R, rapid to 0.5 above the last bottom (the default clearance), feed 4 deeper, ... to Z-15, out to Z5
    peck = [e for e in _find(got, 39) if "move" in e]
    assert [(e["move"], e["z"]) for e in peck] == [
        ("rapid", 3), ("feed", -1), ("rapid", 3), ("rapid", -0.5), ("feed", -5), ("rapid", 3), ("rapid", -4.5),
        ("feed", -9), ("rapid", 3), ("rapid", -8.5), ("feed", -13), ("rapid", 3), ("rapid", -12.5), ("feed", -15),
        ("rapid", 5)]
    assert _find(got, 13) == [{"line": 13, "event": "machine", "code": "G187", "name": "smoothness and corner rounding"}]
    # the tap: feed to Z-12 at F625 (pitch 1.25 x S500), reverse, feed back to R5
    tap = _find(got, 57)
    assert [e.get("dir") for e in tap if e.get("event") == "spindle"] == ["ccw", "cw"]
    assert {"line": 57, "move": "feed", "x": 20, "y": 20, "z": -12, "f": 625} in tap


def test_bracket_rigid_tap_points() -> None:
    got = _events("fusion_fanuc_bracket.nc")
    # N250 M29 S600, N255 G98 G84 X10. Y10. Z-8. R3. F600. from Z5 (the initial level): rapid to R3, tap to
    # Z-8 and back to R3 in step with the spindle at F/S = 600/600 = 1 mm per revolution, rapid to Z5
    assert [(e["move"], e["x"], e["z"], e.get("f")) for e in _find(got, 61)] == [
        ("rapid", 10, 3, None), ("tap", 10, -8, 1), ("tap", 10, 3, 1), ("rapid", 10, 5, None)]
    assert [(e["move"], e["x"], e["z"]) for e in _find(got, 62)] == [
        ("rapid", 70, 5), ("rapid", 70, 3), ("tap", 70, -8), ("tap", 70, 3), ("rapid", 70, 5)]


def test_bracket_arc_centres() -> None:
    got = _events("fusion_fanuc_bracket.nc")
    arcs = [e for e in got if e.get("move") == "ccw"]
    # corner arcs of radius 10 around (50,30), (50,40), (30,40), (30,30)
    assert [(e["cx"], e["cy"], e["x"], e["y"]) for e in arcs] == [
        (50, 30, 60, 30), (50, 40, 50, 50), (30, 40, 20, 40), (30, 30, 30, 20)]


def test_inch_slot_is_converted_to_mm() -> None:
    got = _events("mastercam_fanuc_slot.nc")
    assert _find(got, 16) == [{"line": 16, "move": "ccw", "x": 88.9, "y": 19.05, "z": -3.175,
                                "cx": 82.55, "cy": 19.05, "cz": -3.175, "plane": "XY", "f": 762}]


def test_0m_profile_arcs_from_r() -> None:
    got = _events("fanuc_0m_dos_profile.nc")
    assert _find(got, 12) == [{"line": 12, "move": "cw", "x": 10, "y": 50, "z": -5, "cx": 10, "cy": 40,
                               "cz": -5, "plane": "XY", "f": 250}]


def test_four_axis_indexes_in_degrees() -> None:
    got = _events("four_axis_index.nc")
    assert _find(got, 10) == [{"line": 10, "move": "rapid", "x": 0, "y": 0, "z": 60, "a": 90}]
    assert _find(got, 9) == [{"line": 9, "event": "machine", "code": "M11", "name": "4th axis unclamp"}]


ISG_READY = ["mastercam_fanuc_slot.nc", "solidworks_cam_cover.nc"]
"""Programs ISG runs once its tool data and reference returns are resolved; the others stop at a machine's
own codes (G187, G5.1, M88, M10/M11), a rigid tap or a work offset set by G10 L2, which ISG has no spelling
for here."""


@pytest.mark.parametrize("name", ISG_READY)
def test_isg_translation_selects_d_and_returns_home_and_verifies(name: str) -> None:
    from postproc.setup.machine import AxisTravel
    setup = with_tools(_machine(name), lengths={n: 100.0 + n for n in REGISTERS})
    setup.travel = {a: AxisTravel(name=a, home=-5.0 if a == "Z" else 0.0) for a in "XYZ"}  # type: ignore[arg-type]
    out, _ = _translate(name, "isg", setup)
    source = _source(name)
    # every G43 H<n> is a D<n>, every G28 a #SUPPRESS OFFSETS to the home (Z-5 in the program's units)
    registers = [int(h) for h in re.findall(r"G43\b[^\n(]*?H0*(\d+)", source)]
    assert [int(d) for d in re.findall(r"\bD0*([1-9]\d*)\b", out)] == registers
    inch = "G20" in source
    homes = re.findall(r"^#SUPPRESS OFFSETS Z(\S+)$", out, re.M)
    assert homes and all(float(z) == pytest.approx(-5.0 / (25.4 if inch else 1.0), abs=1e-5) for z in homes)
    assert len(homes) == len(re.findall(r"G28[^\n]*Z", source))
    report = verify_lines(_lines(source), _lines(out), file_in=name, file_out="out.nc", source="fanuc",
                          target="isg", setup=setup)
    assert report.ok and report.max_deviation == 0, report.summary()
