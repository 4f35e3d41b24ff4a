"""Issue 29: real Haas lathe programs (tests/heldout/haas/cadekiely_*, a student's handwritten programs for a Haas
lathe, CadeKiely/Hass-CNC-Programs @8aff8b8a "CNC LATHE/", whose README says "Anyone is welcome to copy"):
they round-trip byte for byte, simulate, and translate to GSK and LinuxCNC, or are refused where they stand,
naming what is missing.

Expected values come from outside the tool: the roughing and grooving passes of ``cadekiely_l8_ex1_lathe.nc`` and
the finishing pass of ``cadekiely_l5_lathe.nc`` derived here by hand from the cycles' rules (DIALECTS.md 2.2: G71
passes Δd deeper each, retracted at 45 degrees by e and back to the start Z; G75 pecks I deep, retracted by e, K
apart; G70 the blocks P..Q from where the tool stands, then a rapid back to it), and the LinuxCNC translations run
in rs274, whose moves must be the simulation's of the source.

The machine (tests/heldout/setups/haas_lathe.xml) runs in inch at power-on (Haas Setting 9 [K]): these programs
program no G20, and their numbers are inches (``G00 X2.0 Z0.1``, ``F0.01`` per revolution), so the set-up says
``<Controller startUnits="inch"/>`` and the translations get ``G20``. A Haas G70 with U, W or D (three of the
programs copy them from their G71 line) is kept verbatim for a Haas and refused elsewhere: what the Haas does with
them is not in our sources [?] (``postproc.rs274.lathe_cycles._haas_finishing_extras``); the tests that run those
programs further take the words out, saying so.
"""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList, PostprocError
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.corpus_harness import harness
from tests.support.linuxcnc_rules import _user_m_files
from tests.support.rs274 import available
from tests.test_lathe_rs274 import INCH_TOLERANCE, difference, ours, theirs

ROOT = Path(__file__).resolve().parents[1]
PROGRAMS = {p.path.split("/")[-1]: p for p in harness.load_manifest(ROOT / "tests" / "heldout" / "corpus.toml")
            if p.path.startswith("haas/cadekiely_")}
IN = 25.4
R = 1.0 / IN
"""The set-up's G71 retract e and G74/G75 peck retract (``<LatheCycles>`` defaults, 1 mm), in inches."""
G70_L5 = ("G70 P46 Q55 U0.001 W0 D0.0005 F0.0002", "G70 P46 Q55 F0.0002")
G70_O58214 = ("G70 P45 Q49 U0.009 D0.01 F0.005", "G70 P45 Q49 F0.005")


def source(name: str, *edits: tuple[str, str]) -> str:
    text = harness._source(PROGRAMS[name])
    for old, new in edits:
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return text


def setup(name: str, target: str = "") -> Any:
    return harness._setup(PROGRAMS[name], target)


def write(text: str, name: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target=target, setup=setup(name, target))
    return out.getvalue()


def moves(text: str, name: str, line: int | None = None) -> list[tuple[str, float, float]]:
    """The simulation's moves (of one source line), X as a diameter, in inches."""
    events = toolpath_events(io.StringIO(text, newline=""), file="in.nc", dialect="fanuc", setup=setup(name))
    return [(e["move"], e["x"] / IN, e["z"] / IN) for e in events
            if "move" in e and (line is None or e["line"] == line)]


def close(got: list[tuple[str, float, float]], expected: list[tuple[str, float, float]]) -> None:
    assert len(got) == len(expected), (len(got), len(expected))
    for n, (a, b) in enumerate(zip(got, expected)):
        assert a[0] == b[0] and math.isclose(a[1], b[1], abs_tol=1e-9) and math.isclose(a[2], b[2], abs_tol=1e-9), \
            (n, a, b)


@pytest.mark.parametrize("name", ["cadekiely_l8_ex1_lathe.nc", "cadekiely_l5_lathe.nc",
                                  "cadekiely_o58214_bored_lathe.nc"])
def test_the_programs_round_trip_byte_for_byte(name: str) -> None:
    """Published bytes (a '%' without a line end, blank lines, trailing blanks), the G70 with U/W/D included."""
    text = source(name)
    assert write(text, name, "fanuc") == text


@pytest.mark.parametrize("name, where, message", [
    ("cadekiely_o58213_thumbscrew_lathe.nc", "in.nc:59:1", "G76: multiple threading cycle: the start point's X lies "
     "within the thread height"),
    ("cadekiely_o58215_snowman_lathe.nc", "in.nc:15:1", "G71: the profile's last block N58 is not in the program"),
])
def test_the_two_programs_no_haas_could_run_are_refused_where_they_stand(name: str, where: str, message: str) -> None:
    """The thumbscrew's G76 starts at X0.25, inside the thread it cuts (root X0.2 + 2 x K0.044 = X0.288); the
    snowman's first G71 names Q58, which the file lacks (an unfinished draft)."""
    with pytest.raises(ErrorList) as caught:
        write(source(name), name, "fanuc")
    assert f"{where}: error: {message}" in str(caught.value)


def test_a_haas_g70_with_u_w_d_is_kept_for_a_haas_and_refused_elsewhere_by_name() -> None:
    name = "cadekiely_o58214_bored_lathe.nc"
    text = source(name)
    with pytest.raises(PostprocError) as simulated:
        moves(text, name)
    assert "in.nc:31:1: error: a Haas finishing cycle with D, U (the roughing cycle's finishing allowances" \
        in str(simulated.value) and "[?]" in str(simulated.value)
    for target in ("gsk", "linuxcnc"):
        with pytest.raises(ErrorList) as caught:
            write(text, name, target)
        assert f"in.nc:31:1: error: a Haas finishing cycle with D, U" in str(caught.value)
        assert f"has no equivalent in {target}" in str(caught.value)


def test_the_programs_run_in_the_machines_power_on_inches() -> None:
    """No G20 in the program: the first move X2.0 is 2 inches on the Haas of the set-up, the translations say
    G20 in the first block that reads a length, and a copy for the Haas adds nothing (above)."""
    name = "cadekiely_l8_ex1_lathe.nc"
    text = source(name)
    first = next(e for e in toolpath_events(io.StringIO(text), file="in.nc", dialect="fanuc", setup=setup(name))
                 if "move" in e)
    assert (first["x"], first["z"]) == (50.8, 2.54)
    assert "N5 G18 G20 G54 G95 G40 G80 (SAFE START BLOCK LATHE)" in write(text, name, "linuxcnc").splitlines()
    mm = setup(name, "linuxcnc")
    mm.controller.start_units = None  # the machine's setting unknown: read in millimetres, and G21 written
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target="linuxcnc", setup=mm)
    assert any("G21" in line for line in out.getvalue().splitlines()[:8])


def test_power_on_units_give_way_to_the_programs_own() -> None:
    name = "cadekiely_l8_ex1_lathe.nc"
    text = source(name, ("N5 G18 G40 G54 G80 G99", "N5 G18 G21 G40 G54 G80 G99"))
    first = next(m for m in moves(text, name))
    assert first[1:] == pytest.approx((2.0 / IN, 0.1 / IN))  # X2 mm: the program's G21 wins


def test_l8_roughing_passes_by_hand() -> None:
    """``G71 P45 Q60 U0 W0 D.025 F0.01`` from X2.0 Z0.1 over N45 X1.1 / Z0. / Z-1.35 / X1.25 (type I: N45 names X
    only): passes 0.025 deeper (0.05 on the diameter) from X1.95 down to X1.15, each cut to the profile's Z-1.35,
    retracted 45 degrees by e and rapid back to Z0.1; then the profile itself (no allowance) and the return to the
    start point, X first."""
    name = "cadekiely_l8_ex1_lathe.nc"
    expected: list[tuple[str, float, float]] = []
    for k in range(1, 18):
        d = 2.0 - 0.05 * k
        expected += [("rapid", d, 0.1), ("feed", d, -1.35), ("rapid", d + 2 * R, -1.35 + R), ("rapid", d + 2 * R, 0.1)]
    expected += [("rapid", 1.1, 0.1), ("feed", 1.1, 0.0), ("feed", 1.1, -1.35), ("feed", 1.25, -1.35),
                 ("rapid", 2.0, -1.35), ("rapid", 2.0, 0.1)]
    close(moves(source(name), name, 13), expected)


def test_l8_grooves_by_hand() -> None:
    """``G75 X.800 Z-.325 I0.1 K0.2`` from X1.3 Z-.125: pecks 0.1 deep (radius) to X1.1, X0.9 and the bottom X0.8,
    each retracted by e, out to X1.3, the next groove K0.2 along at Z-.325, and back to Z-.125."""
    name = "cadekiely_l8_ex1_lathe.nc"
    expected: list[tuple[str, float, float]] = []
    for z in (-0.125, -0.325):
        if z != -0.125:
            expected.append(("rapid", 1.3, z))
        expected += [("feed", 1.1, z), ("rapid", 1.1 + 2 * R, z), ("feed", 0.9, z), ("rapid", 0.9 + 2 * R, z),
                     ("feed", 0.8, z), ("rapid", 1.3, z)]
    expected.append(("rapid", 1.3, -0.125))
    close(moves(source(name), name, 30), expected)


def test_l5_finishes_from_where_its_g70_starts() -> None:
    """Between its G71 (from X2.0 Z0.1) and its G70 the program chamfers (``U.1 W-.1`` ends at Z-0.1) and goes to
    X2.0: the G70 runs N46..N55 from X2.0 Z-0.1 (rapid to N46's X1.55 Z0.10) and rapids back there."""
    name = "cadekiely_l5_lathe.nc"
    got = moves(source(name, G70_L5), name, 40)
    close(got, [("rapid", 1.55, 0.1), ("feed", 1.55, 0.0), ("feed", 0.5, 0.0), ("feed", 0.5, -0.375),
                ("feed", 0.875, -0.375), ("feed", 0.875, -0.875), ("feed", 1.0, -1.5), ("feed", 1.0, -1.75),
                ("feed", 1.45, -1.75), ("feed", 1.45, -2.0), ("rapid", 2.0, -0.1)])
    chamfer = moves(source(name, G70_L5), name, 33)
    close(chamfer, [("feed", 0.4687 + 0.1, -0.1)])  # U.1 W-.1 from X.4687 Z0.


RUNNABLE = [("cadekiely_l8_ex1_lathe.nc", ()), ("cadekiely_l5_lathe.nc", (G70_L5,)),
            ("cadekiely_o58214_bored_lathe.nc", (G70_O58214,))]


@pytest.mark.parametrize("name, edits", RUNNABLE, ids=[n for n, _ in RUNNABLE])
def test_the_linuxcnc_translation_verifies_and_rs274_moves_as_the_source(name: str, edits: tuple[Any, ...]) -> None:
    text = source(name, *edits)
    ngc = write(text, name, "linuxcnc")
    report = verify_lines(io.StringIO(text), io.StringIO(ngc), file_in="in.nc", file_out="out.ngc", source="fanuc",
                          target="linuxcnc", setup=setup(name, "linuxcnc"), tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()
    if "M21" in text:
        assert "M121" in ngc and "M122" in ngc  # the tailstock, on the retrofit's user M codes
    if available():  # the user M codes' files are the machine's (tests/support/linuxcnc_rules.py)
        assert difference(ours(text, "fanuc", setup(name, "linuxcnc")), theirs(_user_m_files(ngc)),
                          INCH_TOLERANCE) is None


def placed(machine: Any) -> Any:
    """The set-up with the Haas's work offset 1 and tool offsets 1 and 2 declared (mm, X a diameter): G54 X-254.
    Z-508. (-10 and -20 inches), T0101 X-50.8 Z-127. (-2 and -5 inches), T0202 X-101.6 Z-76.2 (-4 and -3 inches)."""
    from dataclasses import replace
    from postproc.setup.machine import ToolData, WorkOffsetData
    machine.work_offsets = {**machine.work_offsets, "1": WorkOffsetData(number=1, x=-254.0, z=-508.0)}
    tools = dict(machine.tools)
    for number, x, z in ((1, -50.8, -127.0), (2, -101.6, -76.2)):
        tool = tools.get(str(number))
        tools[str(number)] = ToolData(number=number, x=x, z=z) if tool is None else replace(tool, x=x, z=z)
    machine.tools = tools
    return machine


def write_placed(text: str, name: str, target: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source="fanuc", target=target,
              setup=placed(setup(name, target)))
    return out.getvalue()


WORK_HOME = {"cadekiely_l8_ex1_lathe.nc": (14.0, 23.0), "cadekiely_l5_lathe.nc": (12.0, 25.0),
             "cadekiely_o58214_bored_lathe.nc": (14.0, 21.0)}
"""Each program's ``G00 G53 X0 Z..`` return in work coordinates, by hand (``placed``): machine minus work offset
minus the tool offset in force. L5 (T0101, G53 X0 Z0): X 0 + 10 + 2 = 12, Z 0 + 20 + 5 = 25; L8 (T0202 last, G53
X0 Z0): X 0 + 10 + 4 = 14, Z 0 + 20 + 3 = 23; O58214 (T0202 last, G53 X0 Z-2.): X 14, Z -2 + 23 = 21."""


@pytest.mark.parametrize("name, edits", RUNNABLE, ids=[n for n, _ in RUNNABLE])
def test_gsk_writes_the_machine_coordinate_return_in_work_coordinates(name: str, edits: tuple[Any, ...]) -> None:
    """The GSK dialect has no G53 (the 980TDc G-code list was not reached [?]): the program's ``G00 G53 X0 Z..``
    return is written as the same move in work coordinates, machine minus work offset minus the tool offset in
    force (``WORK_HOME``, by hand). Where the set-up does not say where G54 is (the shipped Haas set-up), the line is a located error naming
    the ``<Offset>`` to declare, never the machine's zero taken as the part's. The rest translates (G71 one block
    -> two, G75 native, the tailstock M21/M22) and verifies against the source with its G53."""
    text = source(name, *edits)
    line = next(i for i, t in enumerate(text.splitlines(), 1) if "G53" in t)
    with pytest.raises(ErrorList) as caught:
        write(text, name, "gsk")
    assert [str(e) for e in caught.value.errors] == [
        f"in.nc:{line}:1: error: the gsk dialect has no motion in machine coordinates, and this move cannot be put "
        "in work coordinates: the set-up gives work system 1 no offset for X (<WorkOffsets><Offset number=\"1\" "
        "x=...>) and the program sets none"]
    gsk = write_placed(text, name, "gsk")
    number = text.splitlines()[line - 1].split()[0]
    written = next(t for t in gsk.splitlines() if t.startswith(number + " ")).split("(")[0].split()
    assert "G53" not in written and written[-3] == "G00", written
    x, z = WORK_HOME[name]
    assert written[-2][0] == "X" and float(written[-2][1:]) == pytest.approx(x, abs=1e-12)
    assert written[-1][0] == "Z" and float(written[-1][1:]) == pytest.approx(z, abs=1e-12)
    assert any("G71 P" in t for t in gsk.splitlines()) and "G20" in gsk
    report = verify_lines(io.StringIO(text), io.StringIO(gsk), file_in="in.nc", file_out="out.nc", source="fanuc",
                          target="gsk", setup=placed(setup(name, "gsk")), tolerance=1e-5)
    assert report.ok, report.summary()


def test_gsk_refuses_the_machine_coordinate_return_without_the_tool_offset() -> None:
    """G54 declared but not tool offset 2, which T202 put in force: the offset the machine's point carries is not
    known, so neither is the work position of G53 X0 Z0."""
    name = "cadekiely_l8_ex1_lathe.nc"
    text = source(name)
    machine = placed(setup(name, "gsk"))
    machine.tools = {k: v for k, v in machine.tools.items() if k != "2"}
    with pytest.raises(ErrorList) as caught:
        translate(io.StringIO(text), io.StringIO(), file="in.nc", source="fanuc", target="gsk", setup=machine)
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:49:1: error: the gsk dialect has no motion in machine coordinates, and this move cannot be put in work "
        "coordinates: the set-up gives tool offset 2 no X and Z (<Tools><Tool number=\"2\" x=... z=...>)"]


def test_o58214_type_2_roughing_by_hand() -> None:
    """``G71 P45 Q49 U0.01 W0 D0.025 F0.02`` from X2.0 Z0.1 over N45 ``G00 X1.250 Z0.100`` (X and Z in the P block:
    Haas type 2 [V]), Z0., X1.0, Z-5.2, X1.25. The finishing allowance U0.01 (a diameter) moves the profile and the
    levels' top 0.01 out: levels from X2.01, 0.05 apart; the 15 above the profile's top (X1.26 with the allowance)
    cut from Z0.1 to its end Z-5.2 as a type 1 cycle would, retracted 45 degrees by e. The last pass runs the profile
    0.01 out (X1.26 Z0.1, Z0., X1.01, Z-5.2, X1.26) and the tool returns to the start. (How the levels inside the
    profile's step are entered is the engine's, ``postproc.cycles.turning.roughing``, not derived here.) The tailstock
    waits ``G04 P3.``: 3 seconds on a Haas (P with a decimal point)."""
    name = "cadekiely_o58214_bored_lathe.nc"
    text = source(name, G70_O58214)
    got = moves(text, name, 14)
    expected: list[tuple[str, float, float]] = [("rapid", 2.01, 0.1)]
    for k in range(1, 16):
        d = 2.01 - 0.05 * k
        if k > 1:  # back to the start's Z at the retracted X of the pass before
            expected.append(("rapid", d + 0.05 + 2 * R, 0.1))
        expected += [("rapid", d, 0.1), ("feed", d, -5.2), ("rapid", d + 2 * R, -5.2 + R)]
    close(got[:len(expected)], expected)
    close(got[-8:], [("rapid", 1.26, 0.1), ("feed", 1.26, 0.0), ("feed", 1.01, 0.0), ("feed", 1.01, -5.2),
                     ("feed", 1.26, -5.2), ("rapid", 2.01, -5.2), ("rapid", 2.01, 0.1), ("rapid", 2.0, 0.1)])
    events = list(toolpath_events(io.StringIO(text), file="in.nc", dialect="fanuc", setup=setup(name)))
    assert {"line": 11, "event": "dwell", "seconds": 3} in events
