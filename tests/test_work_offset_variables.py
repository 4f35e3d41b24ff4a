"""A work offset set from the program (Fanuc/RS274 ``G10 L2``, issue 26) towards every target: native on
Mach3 (``G10 L2``), the zero offset table's variables on ISG (``V.G.NP[n].V.X=``) and Fagor 8070
(``V.A.ORGT[n].X=``), which those controllers take at the work system's next selection, so the active system
is selected again after the setting.

Independent checks: rs274 (the NGC/Fanuc meaning: an active system's new offset acts at once), outputs and
toolpaths derived by hand from the manuals' rules, seeded programs whose translations must verify against the
source (the offsets are never zero, so a setting lost or applied at the wrong time moves a point), and
refusals by name."""

from __future__ import annotations

import io
import random
import re
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available, run_rs274

TARGETS = ("isg", "fagor", "siemens", "mach3", "linuxcnc", "grbl")


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def translated(text: str, target: str, source: str = "fanuc") -> str:
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.nc", source=source, target=target,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


_CALL = re.compile(r"(SET_G5X_OFFSET|STRAIGHT_TRAVERSE|STRAIGHT_FEED)\(([^)]*)\)")


def rs274_points(text: str) -> list[tuple[float, float, float]]:
    """rs274's moves where the machine goes: its canonical points are program coordinates, each plus the
    work offset of the last ``SET_G5X_OFFSET`` (no G92, rotation or tool offset in these programs)."""
    offset = (0.0, 0.0, 0.0)
    out = []
    for line in run_rs274(text):
        m = _CALL.search(line)
        if m is None:
            continue
        args = [float(a) for a in m.group(2).split(",")]
        if m.group(1) == "SET_G5X_OFFSET":
            offset = (args[1], args[2], args[3])
        else:
            out.append(tuple(round(args[i] + offset[i], 4) for i in range(3)))
    return out  # type: ignore[return-value]


def points(text: str, dialect: str) -> list[tuple[float, float, float]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="t.nc", dialect=dialect)
    return [(e["x"], e["y"], e["z"]) for e in events if "move" in e]


# The active system's offset changed, then an absolute move: the move lands in the new offset at once.
ACTIVE = """G21 G90 G17
G10 L2 P2 X10. Y5. Z-2.
G55
G0 X1. Y1. Z5.
G1 Z0. F100.
G10 L2 P2 X20.
G1 X2.
G54
G0 X3. Y3.
M30
"""
ACTIVE_POINTS = [(11, 6, 3), (11, 6, -2), (22, 6, -2), (3, 3, -2)]
"""By hand: G55 is X10 Y5 Z-2, so X1 Y1 Z5 is 11 6 3; the new X20 acts at once: X2 is 22; G54 is zero."""


def test_the_fanuc_meaning_is_rs274s() -> None:
    assert points(ACTIVE, "fanuc") == ACTIVE_POINTS
    if not available():
        pytest.skip("rs274 not installed")
    assert rs274_points(ACTIVE) == [tuple(float(v) for v in p) for p in ACTIVE_POINTS]


EXPECTED = {
    "isg": """G17 G71 G90
V.G.NP[2].V.X=10. V.G.NP[2].V.Y=5. V.G.NP[2].V.Z=-2.
G55
G00 X1. Y1. Z5.
G01 Z0. F100.
V.G.NP[2].V.X=20.
G55
G01 X2.
G54
G00 X3. Y3.
M30
""",
    "fagor": """G17 G71 G90
V.A.ORGT[2].X=10. V.A.ORGT[2].Y=5. V.A.ORGT[2].Z=-2.
G55
G00 X1. Y1. Z5.
G01 Z0. F100.
V.A.ORGT[2].X=20.
G55
G01 X2.
G54
G00 X3. Y3.
M30
""",
    "siemens": """G17 G710 G90
$P_UIFR[2,X,TR]=10. $P_UIFR[2,Y,TR]=5. $P_UIFR[2,Z,TR]=-2.
G55
G0 X1. Y1. Z5.
G1 Z0. F100.
$P_UIFR[2,X,TR]=20.
G55
G1 X2.
G54
G0 X3. Y3.
M30
""",
    "mach3": """G17 G21 G90
G10 L2 P2 X10. Y5. Z-2.
G55
G0 X1.0000 Y1.0000 Z5.0000
G1 Z0.0000 F100.
G10 L2 P2 X20.
G1 X2.0000
G54
G0 X3.0000 Y3.0000
M30
""",
}
"""By hand from each manual's spelling (the writers' docstrings cite them): ISG and Fagor write the table and
take it at the selection, so the G55 in force is selected again after the second setting (and the first
setting's block is followed by the block's own G55 only: the system was not active when it was set)."""


@pytest.mark.parametrize("target", sorted(EXPECTED))
def test_the_hand_derived_translation(target: str) -> None:
    text = translated(ACTIVE, target)
    assert text == EXPECTED[target]
    assert points(text, target) == ACTIVE_POINTS


STORED = [("isg", "V.G.NP[2].V.X=10"), ("fagor", "V.A.ORGT[2].X=10"), ("siemens", "$P_UIFR[2,X,TR]=10")]


@pytest.mark.parametrize("dialect,setting", STORED)
def test_a_table_entry_of_the_active_system_acts_at_its_next_selection(dialect: str, setting: str) -> None:
    """By hand, the stored meaning: X1 is still in the old G55 (zero), X2 after G55 again is 12; set for a
    system not active (G56), the entry is there when it is selected."""
    units, move = ("G710", "G1") if dialect == "siemens" else ("G71", "G01")
    other = setting.replace("[2]", "[3]").replace("X=10", "Y=5").replace("[2,X,", "[3,Y,").replace("]=10", "]=5")
    program = f"{units} G90\nG55\n{setting}\n{move} X1 Y0 Z0 F100\nG55\n{move} X2\n{other}\nG56\n{move} X0 Y1\nM30\n"
    assert points(program, dialect) == [(1, 0, 0), (12, 0, 0), (0, 6, 0)]
    assert translated(program, dialect, source=dialect) == program  # read back byte for byte


@pytest.mark.parametrize("dialect,setting", STORED)
def test_the_stored_entry_of_the_active_system_waits_for_the_selection_towards_g10(dialect: str, setting: str) -> None:
    """By hand: G10 L2 would act at once, so it is written right before the next selection (``G55``), where
    rs274 takes it as the source's controller takes its table entry; a setting of a system not active is
    G10 L2 where it stands; one never selected again changed nothing and is left out (a comment says so)."""
    units, move = ("G710", "G1") if dialect == "siemens" else ("G71", "G01")
    # SINUMERIK powers on in exact stop (G60), LinuxCNC in blending: its first move selects G61 (path_at_start)
    exact = "G61 " if dialect == "siemens" else ""
    program = f"{units} G90\nG55\n{setting}\n{move} X1 Y0 Z0 F100\nG55\n{move} X2\n{setting}\n{move} X3\nM30\n"
    out = translated(program, "linuxcnc", source=dialect)
    assert out == ("G21 G90\nG55\n"
                   f"({setting}: written before the next work system selection)\n"
                   f"{exact}G1 X1. Y0. Z0. F100.\nG10 L2 P2 X10.\nG55\nG1 X2.\n"
                   f"({setting}: written before the next work system selection)\n"
                   "G1 X3.\nM30\n")
    assert points(out, "linuxcnc") == points(program, dialect) == [(1, 0, 0), (12, 0, 0), (13, 0, 0)]
    for target in ("fanuc", "grbl", "mach3", "isg", "fagor", "siemens"):
        text = translated(program, target, source=dialect)
        report = verify_lines(_lines(program), _lines(text), file_in="t", file_out="out", source=dialect,
                              target=target)
        assert report.ok, (target, report.summary(), text)
    program = f"{units} G90\nG54\n{setting}\nG55\n{move} X1 Y0 Z0 F100\nM30\n"
    assert "G10 L2 P2 X10" in translated(program, "linuxcnc", source=dialect)


def test_a_units_change_while_a_setting_waits_is_refused_by_name() -> None:
    program = "G71 G90\nG55\nV.G.NP[2].V.X=10\nG70\nG55\nG01 X1 Y0 Z0 F100\nM30\n"
    with pytest.raises(ErrorList, match="a units change while a work offset setting waits"):
        translated(program, "linuxcnc", source="isg")


def test_mach3_reads_g10_l2_and_gives_it_to_linuxcnc() -> None:
    text = translated(ACTIVE, "mach3")
    assert points(text, "mach3") == ACTIVE_POINTS
    back = translated(text, "linuxcnc", source="mach3")
    assert "G10 L2 P2 X20." in back and points(back, "linuxcnc") == ACTIVE_POINTS


@pytest.mark.parametrize("target", ["isg", "fagor", "siemens", "mach3"])
@pytest.mark.parametrize("source,setting,why", [
    ("linuxcnc", "G10 L2 P7 X1. A3.", "its work systems are (P)?1-(P)?6|it sets axes"),  # G59.1; an A axis
    ("fanuc", "G91 G10 L2 P1 X1.", "sets offsets absolutely only"),  # Fanuc adds to the offset under G91
    ("fanuc", "G10 L2 P0 X1.", "P0 here is not the offset common to all work systems"),
])
def test_what_has_no_spelling_is_refused_by_name(target: str, source: str, setting: str, why: str) -> None:
    if target == "siemens" and "P7" in setting:  # SINUMERIK has it: work system 7 is G507, $P_UIFR[7]
        assert "$P_UIFR[7,X,TR]=1. $P_UIFR[7,A,TR]=3." in translated(
            f"G21 G90\n{setting}\nG0 X0 Y0 Z0\nM30\n", target, source=source)
        return
    with pytest.raises(ErrorList, match=why):
        translated(f"G21 G90\n{setting}\nG0 X0 Y0 Z0\nM30\n", target, source=source)


def _program(rng: random.Random) -> str:
    """Work offsets of systems 1-6 set before and while they are active (never zero: a setting lost or
    applied late moves a point), selections, absolute and incremental moves."""
    lines = ["G21 G90 G17 G94 F500", "G0 X0. Y0. Z10."]
    for _ in range(rng.randint(4, 10)):
        r = rng.random()
        if r < 0.35:
            axes = rng.sample("XYZ", rng.randint(1, 3))
            values = " ".join(f"{a}{rng.choice((-1, 1)) * rng.randint(1, 4000) / 100:.2f}" for a in axes)
            lines.append(f"G10 L2 P{rng.randint(1, 6)} {values}")
        elif r < 0.55:
            lines.append(f"G{rng.randint(54, 59)}")
        elif r < 0.8:
            lines.append(f"G90 G1 X{rng.randint(-500, 500) / 10:.1f} Y{rng.randint(-500, 500) / 10:.1f} "
                         f"Z{rng.randint(-50, 50) / 10:.1f}")
        else:
            lines.append(f"G91 G1 X{rng.randint(-100, 100) / 10:.1f} Y{rng.randint(-100, 100) / 10:.1f}")
            lines.append("G90")
    lines.append("G90 G0 X0. Y0. Z10.")
    lines.append("M30")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("seed", range(40))
def test_seeded_programs_verify_on_every_target(seed: int) -> None:
    program = _program(random.Random(seed))
    for target in TARGETS:
        out = translated(program, target)
        report = verify_lines(_lines(program), _lines(out), file_in="t.nc", file_out="out", source="fanuc",
                              target=target)
        assert report.ok, (target, report.summary(), program, out)


@pytest.mark.parametrize("seed", range(10))
def test_seeded_programs_run_as_rs274_runs_them(seed: int) -> None:
    """The simulator's meaning of G10 L2 (Fanuc and LinuxCNC read it alike in absolute mode) against rs274's."""
    if not available():
        pytest.skip("rs274 not installed")
    program = _program(random.Random(1000 + seed))
    ours = [(round(x, 4), round(y, 4), round(z, 4)) for x, y, z in points(program, "fanuc")]
    theirs: list[Any] = rs274_points(program)
    assert theirs[-len(ours):] == ours, program


_SPELLINGS = {"isg": ("G71", "V.G.NP[{n}].V.{a}={v}"), "fagor": ("G71", "V.A.ORGT[{n}].{a}={v}"),
              "siemens": ("G710", "$P_UIFR[{n},{a},TR]={v}")}


def _family_program(rng: random.Random, dialect: str) -> str:
    """Table entries written for the active system and others (never zero), selections (or none after an
    entry of the active one), absolute and incremental moves, in the dialect's own spelling."""
    units, spelling = _SPELLINGS[dialect]
    lines = [f"{units} G90 G17 G94 F500", "G0 X0 Y0 Z10"]
    for _ in range(rng.randint(4, 10)):
        r = rng.random()
        if r < 0.35:
            n = rng.randint(1, 6)
            lines.append(" ".join(spelling.format(n=n, a=a, v=f"{rng.choice((-1, 1)) * rng.randint(1, 4000) / 100:.2f}")
                                  for a in rng.sample("XYZ", rng.randint(1, 3))))
        elif r < 0.55:
            lines.append(f"G{rng.randint(54, 59)}" if dialect != "siemens" else
                         rng.choice(("G54", "G55", "G56", "G57", "G505", "G506")))
        elif r < 0.8:
            lines.append(f"G90 G1 X{rng.randint(-500, 500) / 10:.1f} Y{rng.randint(-500, 500) / 10:.1f} "
                         f"Z{rng.randint(-50, 50) / 10:.1f}")
        else:
            lines.append(f"G91 G1 X{rng.randint(-100, 100) / 10:.1f} Y{rng.randint(-100, 100) / 10:.1f}")
            lines.append("G90")
    lines.append("G90 G0 X0 Y0 Z10")
    lines.append("M30")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("dialect", sorted(_SPELLINGS))
@pytest.mark.parametrize("seed", range(15))
def test_seeded_table_entry_programs_verify_on_every_target(dialect: str, seed: int) -> None:
    """The stored meaning read, and written for every target: its own table (no selection added for an entry
    the source takes at the selection) or G10 L2 moved to the next selection."""
    program = _family_program(random.Random(seed), dialect)
    for target in ("linuxcnc", "fanuc", "grbl", "mach3", "isg", "fagor", "siemens"):
        out = translated(program, target, source=dialect)
        report = verify_lines(_lines(program), _lines(out), file_in="t", file_out="out", source=dialect,
                              target=target)
        assert report.ok, (target, report.summary(), program, out)
