"""Differential test: our Fanuc reader's toolpath against the real LinuxCNC interpreter (``rs274``).

Hypothesis writes programs in the ground where Fanuc and LinuxCNC move alike (DIALECTS.md §2.1,
"LinuxCNC / RS274-NGC baseline", and RS274_NOTES.md beside ``tests/support/rs274.py``):

* metric (G21), G17, G94, explicit decimal points on every length and feed;
* G0/G1 and G2/G3 arcs with I/J (end points exactly on the circle), absolute and incremental;
* G4 dwells (Fanuc ``G04 X<s>`` or ``G04 P<ms>``, LinuxCNC ``G4 P<s>``);
* hole cycles G81, G82, G83, G73, G85, G89 and G86 (Fanuc without P; LinuxCNC needs ``P0``), each run
  started by a rapid to its initial level **above R** (LinuxCNC rises to R first, Fanuc does not);
* G98/G99 in absolute runs; G98 after a G99 hole only with a new R below the tool (both position at
  the current level then; with R at or above the tool LinuxCNC rapids diagonally to the clear level,
  Fanuc in the plane at the current level); G89 only with G99 (LinuxCNC feeds out to the clear
  level, Fanuc feeds to R and rapids on);
* incremental rows: ``G91 G98`` with Fanuc ``K`` = LinuxCNC ``L`` (R is measured from the level the
  tool stands at, which is the initial level in both while every hole returns there), and modal
  repetition of the row;
* G73/G83 clearances: the Fanuc set-up takes LinuxCNC's fixed 0.010 in = 0.254 mm;
* a switch to G20 and back to G21, each with F and a feed move in the same block: LinuxCNC reads
  that F in the old units, Fanuc in the new ones (``G20 F254.`` is Fanuc's ``G20 F10.``).

Each program is written once for LinuxCNC and once in Fanuc spelling, run through our fanuc dialect's
toolpath and through ``rs274``, and compared move by move (end points, arc centres, feed rates)
within ``TOLERANCE``; dwells of more than zero seconds must agree too. The LinuxCNC spelling also goes
through our linuxcnc reader, which must agree with ``rs274`` the same way. Skipped when ``rs274`` is
absent.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import Any, Callable, Iterator

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, canonical_moves, run_rs274

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed "
                                "(apt-get install linuxcnc-uspace, or .ci/install-oracle.sh)")

LINUXCNC_PECK_MM = 0.254
"""LinuxCNC's G73 retract and G83 clearance: 0.010 in, printed as 0.2540 in mm programs (RS274_NOTES.md)."""
TOLERANCE = 1.5e-4
"""mm: rs274 prints 4 decimals; every generated value lies on a 0.25 mm grid (or a 0.254 offset)."""
EXAMPLES = int(os.environ.get("POSTPROC_DIFFERENTIAL_EXAMPLES", "60"))
"""Generated programs per run; raise it locally to search harder (the suite keeps it modest)."""
FANUC_SETUP = MachineSetup(cycles=CycleSettings(peck_retract=LINUXCNC_PECK_MM, peck_clearance=LINUXCNC_PECK_MM))

RESULTS: dict[str, int] = {"programs": 0, "moves": 0}


@pytest.fixture(scope="module", autouse=True)
def _report(request: pytest.FixtureRequest) -> Iterator[None]:
    """Print how many generated programs agreed with rs274 (visible in the normal -q output)."""
    yield
    line = (f"differential rs274: {RESULTS['programs']} generated programs agreed with LinuxCNC "
            f"({RESULTS['moves']} moves compared)")
    capture = request.config.pluginmanager.get_plugin("capturemanager")
    reporter = request.config.pluginmanager.get_plugin("terminalreporter")
    if capture is None or reporter is None:
        print(line)
        return
    with capture.global_and_fixture_disabled():
        reporter.write_line("\n" + line)


# -- programs ----------------------------------------------------------------------------------------

def num(value: float) -> str:
    """A length with an explicit decimal point, as both dialects read it ('10.', '-2.5', '0.')."""
    text = f"{value:.4f}".rstrip("0")
    return "0." if text in ("-0.", "0.") else text


@dataclass
class Program:
    """One program in both spellings, built block by block; ``pos`` tracks the tool (absolute mm)."""

    ngc: list[str] = field(default_factory=list)
    fanuc: list[str] = field(default_factory=list)
    pos: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])

    def both(self, text: str) -> None:
        self.ngc.append(text)
        self.fanuc.append(text)

    def each(self, ngc: str, fanuc: str) -> None:
        self.ngc.append(ngc)
        self.fanuc.append(fanuc)

    def listing(self) -> str:
        return "LinuxCNC:\n" + "\n".join(self.ngc) + "\n\nFanuc:\n" + "\n".join(self.fanuc)


def grid(lo: float, hi: float, step: float = 0.5) -> st.SearchStrategy[float]:
    return st.integers(round(lo / step), round(hi / step)).map(lambda k: k * step)


Draw = Callable[[st.SearchStrategy[Any]], Any]


def straight(draw: Draw, p: Program) -> None:
    code = draw(st.sampled_from(["G0", "G1"]))
    target = [draw(grid(-40, 40)), draw(grid(-40, 40)), draw(grid(0, 30))]
    feed = f" F{num(draw(grid(50, 500, 25)))}" if code == "G1" else ""
    if draw(st.booleans()):
        words = " ".join(f"{a}{num(t - c)}" for a, t, c in zip("XYZ", target, p.pos))
        p.both(f"G91 {code} {words}{feed}")
        p.both("G90")
    else:
        words = " ".join(f"{a}{num(t)}" for a, t in zip("XYZ", target))
        p.both(f"G90 {code} {words}{feed}")
    p.pos = target


def arc(draw: Draw, p: Program) -> None:
    """An arc in G17 whose end lies exactly on its circle: the start vector turned by k quarter turns."""
    i, j = draw(grid(-20, 20)), draw(grid(-20, 20))
    if i == 0 and j == 0:
        i = 5.0
    quarters = draw(st.integers(1, 4))
    cx, cy = p.pos[0] + i, p.pos[1] + j
    vx, vy = -i, -j
    for _ in range(quarters):
        vx, vy = -vy, vx
    end = [cx + vx, cy + vy, p.pos[2]]
    code = draw(st.sampled_from(["G2", "G3"]))
    feed = num(draw(grid(50, 500, 25)))
    if draw(st.booleans()):
        p.both(f"G91 {code} X{num(end[0] - p.pos[0])} Y{num(end[1] - p.pos[1])} I{num(i)} J{num(j)} F{feed}")
        p.both("G90")
    else:
        p.both(f"G90 {code} X{num(end[0])} Y{num(end[1])} I{num(i)} J{num(j)} F{feed}")
    p.pos = end


def dwell(draw: Draw, p: Program) -> None:
    seconds = draw(st.sampled_from([0.25, 0.5, 1.0, 1.5]))
    fanuc = f"G04 X{num(seconds)}" if draw(st.booleans()) else f"G04 P{round(seconds * 1000)}"
    p.each(f"G4 P{num(seconds)}", fanuc)


def unit_switch(draw: Draw, p: Program) -> None:
    """G20 with F and a feed move, a move in inches, then G21 with F and a feed move (0.05 in grid)."""
    inch = [[draw(grid(-1.5, 1.5, 0.05)), draw(grid(-1.5, 1.5, 0.05)), draw(grid(0, 1.2, 0.05))] for _ in "ab"]
    rate = draw(st.integers(2, 20))  # in/min
    words = [" ".join(f"{a}{num(v)}" for a, v in zip("XYZ", t)) for t in inch]
    p.each(f"G20 F{num(rate * 25.4)} G1 {words[0]}", f"G20 F{num(rate)} G1 {words[0]}")
    p.both(f"G1 {words[1]}")
    target = [draw(grid(-40, 40)), draw(grid(-40, 40)), draw(grid(0, 30))]
    mm = draw(st.integers(2, 20))  # in/min again, written in mm for Fanuc
    p.each(f"G21 F{num(mm)} G1 " + " ".join(f"{a}{num(v)}" for a, v in zip("XYZ", target)),
           f"G21 F{num(mm * 25.4)} G1 " + " ".join(f"{a}{num(v)}" for a, v in zip("XYZ", target)))
    p.pos = target


CYCLES = (81, 82, 83, 73, 85, 89, 86)


def cycle_run(draw: Draw, p: Program) -> None:
    """Position at the initial level, one cycle block, modal repeats, G80."""
    code = draw(st.sampled_from(CYCLES))
    initial = draw(st.sampled_from([10.0, 15.0, 20.0, 25.0]))
    r = draw(st.sampled_from([0.0, 1.0, 2.0, 3.0, 5.0, 10.0]))
    bottom = r - draw(grid(0.5, 15))
    x, y = draw(grid(-30, 30)), draw(grid(-30, 30))
    feed = num(draw(grid(50, 300, 25)))
    extra_ngc = extra_fanuc = ""
    if code in (73, 83):
        q = num(draw(grid(0.5, 4)))
        extra_ngc = extra_fanuc = f" Q{q}"
    elif code in (82, 89):
        seconds = draw(st.sampled_from([0.25, 0.5, 1.0]))
        extra_ngc, extra_fanuc = f" P{num(seconds)}", f" P{round(seconds * 1000)}"
    elif code == 86:
        extra_ngc = " P0."  # LinuxCNC needs P in G86; Fanuc's G86 has none
    p.both(f"G90 G0 X{num(x)} Y{num(y)} Z{num(initial)}")
    p.pos = [x, y, initial]
    if code != 89 and draw(st.booleans()):
        _incremental_run(draw, p, code, initial, r, bottom, feed, extra_ngc, extra_fanuc)
    else:
        _absolute_run(draw, p, code, r, bottom, feed, extra_ngc, extra_fanuc)
    p.both("G80")


def _incremental_run(draw: Draw, p: Program, code: int, initial: float, r: float, bottom: float,
                     feed: str, extra_ngc: str, extra_fanuc: str) -> None:
    def row() -> tuple[str, int]:
        dx, dy = draw(grid(-10, 10)), draw(grid(-10, 10))
        count = draw(st.integers(1, 4))
        p.pos = [p.pos[0] + count * dx, p.pos[1] + count * dy, initial]
        return f"X{num(dx)} Y{num(dy)}", count

    words, count = row()
    levels = f"Z{num(bottom - r)} R{num(r - initial)}"
    p.each(f"G91 G98 G{code} {words} {levels}{extra_ngc} L{count} F{feed}",
           f"G91 G98 G{code} {words} {levels}{extra_fanuc} K{count} F{feed}")
    for _ in range(draw(st.integers(0, 2))):
        words, count = row()
        p.each(f"{words} L{count}", f"{words} K{count}")
    p.both("G90")


def _absolute_run(draw: Draw, p: Program, code: int, r: float, bottom: float, feed: str,
                  extra_ngc: str, extra_fanuc: str) -> None:
    holes = draw(st.integers(1, 4))
    switch = 0 if code == 89 else draw(st.integers(0, holes))
    """Holes before ``switch`` return with G98, the rest with G99."""
    initial = p.pos[2]
    for n in range(holes):
        x, y = draw(grid(-30, 30)), draw(grid(-30, 30))
        mode = 98 if n < switch else 99
        if n == 0:
            tail = f"Z{num(bottom)} R{num(r)}"
            p.each(f"G{mode} G{code} X{num(x)} Y{num(y)} {tail}{extra_ngc} F{feed}",
                   f"G{mode} G{code} X{num(x)} Y{num(y)} {tail}{extra_fanuc} F{feed}")
        else:
            switched = "G99 " if n == switch else ""
            p.both(f"{switched}X{num(x)} Y{num(y)}")
        p.pos = [x, y, p.pos[2] if mode == 98 else r]
    if code != 89 and switch < holes and r > bottom and draw(st.booleans()):
        lower = r - draw(grid(0.5, r - bottom))  # a G98 hole after G99 ones, its R below the tool (at R)
        x = draw(grid(-30, 30))
        p.both(f"G98 X{num(x)} R{num(lower)}")
        p.pos = [x, p.pos[1], initial]


STEPS = (straight, arc, dwell, cycle_run, unit_switch)


@st.composite
def programs(draw: Draw) -> Program:
    p = Program()
    p.both("G21 G17 G90 G94")
    p.both("G0 X0. Y0. Z50.")
    p.both("M3 S1000")
    p.pos = [0.0, 0.0, 50.0]
    for _ in range(draw(st.integers(1, 6))):
        draw(st.sampled_from(STEPS))(draw, p)
    p.both("G90 G0 Z50.")
    p.both("M5")
    p.both("M30")
    return p


# -- comparing ---------------------------------------------------------------------------------------

def ours(program: Program) -> list[dict[str, Any]]:
    lines = [line + "\n" for line in program.fanuc]
    return list(toolpath_events(lines, file="generated.nc", dialect="fanuc", setup=FANUC_SETUP))[1:]


def ours_linuxcnc(program: Program) -> list[dict[str, Any]]:
    """The LinuxCNC spelling through our own linuxcnc reader (a second check, of that reader)."""
    lines = [line + "\n" for line in program.ngc]
    return list(toolpath_events(lines, file="generated.ngc", dialect="linuxcnc"))[1:]


def linuxcnc(program: Program) -> list[dict[str, Any]]:
    calls = run_rs274("\n".join(program.ngc) + "\n")  # each run has its own HOME: no crash to retry
    return canonical_moves(calls, start=(0.0, 0.0, 0.0), feeds=True)


def comparable(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Moves, and dwells that last (LinuxCNC prints a zero dwell in G86 where Fanuc has none)."""
    return [e for e in events if "move" in e or (e.get("event") == "dwell" and e["seconds"] > 0)]


def first_difference(a: list[dict[str, Any]], b: list[dict[str, Any]]) -> str | None:
    for n, (x, y) in enumerate(zip(a, b)):
        if x.get("move") != y.get("move") or x.get("event") != y.get("event"):
            return f"item {n}: ours {x}, rs274 {y}"
        if "move" in x:
            keys = ["x", "y", "z"] + (["cx", "cy", "cz"] if x["move"] in ("cw", "ccw") else [])
            keys += ["f"] if x["move"] != "rapid" else []
            dev = max(abs(float(x[k]) - float(y[k])) for k in keys)
        else:
            dev = abs(float(x["seconds"]) - float(y["seconds"]))
        if dev > TOLERANCE or math.isnan(dev):
            return f"item {n}: {dev:.6f} apart: ours {x}, rs274 {y}"
    if len(a) != len(b):
        return f"ours has {len(a)} items, rs274 {len(b)}"
    return None


@settings(max_examples=EXAMPLES, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_fanuc_toolpath_matches_linuxcnc(program: Program) -> None:
    mine, theirs = comparable(ours(program)), comparable(linuxcnc(program))
    problem = first_difference(mine, theirs)
    assert problem is None, f"fanuc reader: {problem}\n\n{program.listing()}"
    problem = first_difference(comparable(ours_linuxcnc(program)), theirs)
    assert problem is None, f"linuxcnc reader: {problem}\n\n{program.listing()}"
    RESULTS["programs"] += 1
    RESULTS["moves"] += sum(1 for e in mine if "move" in e)


def test_one_known_program_matches() -> None:
    """A fixed program through the same comparison, so a failure here is easy to read."""
    p = Program()
    for text in ("G21 G17 G90 G94", "G0 X0. Y0. Z50.", "M3 S1000", "G90 G0 X10. Y10. Z20."):
        p.both(text)
    p.each("G91 G98 G83 X5. Y0. Z-8. R-17. Q2.5 L3 F100.", "G91 G98 G83 X5. Y0. Z-8. R-17. Q2.5 K3 F100.")
    p.both("G90 G80")
    p.both("G2 X30. Y15. I0. J5. F200.")
    p.each("G4 P0.5", "G04 P500")
    p.both("M30")
    mine, theirs = comparable(ours(p)), comparable(linuxcnc(p))
    assert first_difference(mine, theirs) is None, first_difference(mine, theirs)
    assert sum(1 for e in mine if e.get("move") == "feed") == 3 * 4  # 8 mm in pecks of 2.5: 4 per hole
