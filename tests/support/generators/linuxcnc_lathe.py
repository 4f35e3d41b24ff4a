"""Fuzz kind "linuxcnc lathe": LinuxCNC lathe programs as the source (G7/G8 diameter and radius mode, G95
feed per revolution, G96 S D with its speed cap, G33 spindle-synchronised moves straight and tapered,
G2/G3 in ZX with I/K, G4), to every lathe writer and the grbl family.

The source is first run by ``rs274`` (lathe mode: ``G18 G7``): where both run, its moves (radii, centres,
feeds, leads) must be ours (``test_lathe_rs274.difference``); what rs274 refuses must not simulate here.
Then each translation passes ``fuzzing.check_translation`` (read back, target's rules, verify), or is
refused with located errors.
"""

from __future__ import annotations

import io
from pathlib import Path

from hypothesis import strategies as st

from postproc.errors import ErrorList
from postproc.setup.machine_setup import MachineSetup, load_setup

from ..fuzzing import check_translation, located
from ..rs274 import RS274Error, available
from ..tools import with_tools
from . import Case

KIND = "linuxcnc lathe"
TARGETS = ("linuxcnc", "fanuc", "gsk", "grbl", "grblhal")
SETUP_FILE = Path(__file__).resolve().parents[3] / "examples" / "setups" / "linuxcnc_lathe.xml"
_SETUP: list[MachineSetup] = []


def setup() -> MachineSetup:
    if not _SETUP:
        _SETUP.append(with_tools(load_setup(str(SETUP_FILE))))
    return _SETUP[0]


def _n(value: float) -> str:
    text = f"{value:.4f}".rstrip("0")
    return "0" if text in ("-0.", "0.") else text.rstrip(".")


def _d(lo: float, hi: float) -> st.SearchStrategy[float]:
    return st.integers(int(lo * 2), int(hi * 2)).map(lambda v: v / 2.0)


@st.composite
def programs(draw: st.DrawFn) -> str:
    per_rev = draw(st.booleans())
    radius_mode = draw(st.sampled_from([False, False, False, True]))
    lines = ["G18 G7 G21 G90 " + ("G95" if per_rev else "G94")]
    lines.append(draw(st.sampled_from(["S600 M3", "G96 S150 D2500 M3", "G96 S120 M4", "G97 S900 M3",
                                       "G96 S200 D500 M3"])))
    x, z = draw(_d(30, 60)), draw(_d(1, 5))
    lines.append(f"G0 X{_n(x)} Z{_n(z)}")

    def feed() -> str:
        return _n(draw(st.sampled_from([0.05, 0.1, 0.2] if per_rev else [60.0, 120.0, 250.0])))

    for op in draw(st.lists(st.sampled_from(["feed", "rapid", "arc", "thread", "taper", "mode", "dwell", "radius",
                                             "inc"]), min_size=2, max_size=8)):
        if op in ("feed", "rapid"):
            x, z = draw(_d(10, 70)), draw(_d(-60, 5))
            lines.append(("G1" if op == "feed" else "G0") + f" X{_n(x)} Z{_n(z)}"
                         + (f" F{feed()}" if op == "feed" else ""))
        elif op == "inc":
            u, w = draw(_d(-4, 4)), draw(_d(-6, 0))
            if x + u < 8:
                u = 0.0
            x, z = x + u, z + w
            lines += [f"G91 G1 X{_n(u)} Z{_n(w)} F{feed()}", "G90"]
        elif op == "arc":
            r = draw(st.sampled_from([1.0, 2.0, 2.5, 4.0]))
            out = draw(st.sampled_from([-1, 1])) if x / 2.0 > 2 * r + 1 else 1
            below = draw(st.booleans())
            i, k = (0.0, -r) if below else (out * r, 0.0)
            x, z = x + 2 * out * r, z - r
            lines.append(f"{draw(st.sampled_from(['G2', 'G3']))} X{_n(x)} Z{_n(z)} I{_n(i)} K{_n(k)} F{feed()}")
        elif op == "thread":
            z = draw(_d(min(-50, z - 11), z - 1))
            lines.append(f"G33 Z{_n(z)} K{_n(draw(st.sampled_from([0.75, 1.0, 1.5, 2.0])))}")
        elif op == "taper":
            dz = draw(_d(3, 20))
            x, z = x + 2.0, z - dz
            lines.append(f"G33 X{_n(x)} Z{_n(z)} K{_n(draw(st.sampled_from([1.0, 1.5, 2.5])))}")
        elif op == "mode":
            per_rev = not per_rev
            lines.append(("G95" if per_rev else "G94") + f" F{feed()} "
                         + draw(st.sampled_from(["G97 S800", "G96 S100 D1800", ""])))
        elif op == "dwell":
            lines.append("G4 P0.5")
        elif radius_mode:  # X as a radius from here on: the numbers halve
            lines.append(f"G8 G0 X{_n(x / 2)}")
            lines.append(f"G7 G0 X{_n(x)}")
    lines += ["M5", "M2"]
    return "\n".join(line.rstrip() for line in lines) + "\n"


def source_agrees_with_rs274(program: str) -> None:
    from tests.test_lathe_rs274 import difference, ours, theirs
    if not available():
        return
    try:
        rs274 = theirs(program)
    except RS274Error as err:
        try:
            ours(program, "linuxcnc", setup())
        except ErrorList as errs:
            for e in errs.errors:
                located(e)
            return
        raise AssertionError(f"rs274 refuses what postproc simulates: {err.stderr or err}\n{program}") from None
    try:
        here = ours(program, "linuxcnc", setup())
    except ErrorList:
        return  # stricter than rs274 by choice in places
    problem = difference(here, rs274)
    assert problem is None, f"the linuxcnc lathe source and rs274 differ: {problem}\n{program}"


def check(target: str, program: str) -> str:
    source_agrees_with_rs274(program)
    return check_translation("linuxcnc", target, program, setup(), False)


def _case(target: str, program: str) -> Case:
    return Case(f"linuxcnc lathe-{target}", target, program, lambda p: check(target, p), "linuxcnc_lathe.xml")


def cases() -> st.SearchStrategy[Case]:
    return st.builds(_case, st.sampled_from(TARGETS), programs())
