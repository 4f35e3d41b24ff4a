"""LinuxCNC (and grblHAL) lathe programs that switch between G7 (X a diameter) and G8 (X a radius) inside one program
(``postproc.rs274.ngc_lathe.program_x_mode``, the ``XProgramming`` section, ``NgcLatheWriting``).

The oracle is rs274 2.9 (``tests/support/rs274.py``), its lathe mode run on the same text: a seeded random
differential of whole programs (moves, G91 stretches, arcs, G33 straight and tapered, G76) with switches alone
on a line or beside a move, read with a set-up in either mode, move by move. The rules it rests on were read
from rs274 runs first (module docstring of ``ngc_lathe``): a block's own G7/G8 applies to its X; X (absolute
and G91) is a diameter in G7; an arc's I stays a radius; G33's K is a lead; G76's I, J, K are halved in G7;
``#5420`` reads the radius in both modes (``test_rs274_reads_the_position_as_a_radius_in_both_modes``).

Translations are checked independently of our writer: the LinuxCNC text we write (copied, normalised, in
inches) is run by rs274 again and must move as the source does; a Fanuc T / GSK translation (diameter
programmed [K], no G7/G8: the switches go, every X a diameter) must verify at zero deviation and move as
rs274 runs the source.
"""

from __future__ import annotations

import io
import math
import os
import random
import re
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.ir import Block
from postproc.ir.lathe_sections import XProgramming
from postproc.reading import read_blocks
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup, load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.test_lathe_rs274 import INCH_TOLERANCE, TOLERANCE, difference, theirs

ROOT = Path(__file__).resolve().parents[1]
SEEDS = int(os.environ.get("POSTPROC_X_MODE_DIFFERENTIAL", "40"))
needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _setup(radius: bool) -> MachineSetup:
    setup = load_setup(str(ROOT / "examples" / "setups" / "linuxcnc_lathe.xml"))
    if radius:
        setup.input.x_programming = "radius"
    return setup


def _ours(text: str, setup: MachineSetup, dialect: str = "linuxcnc") -> list[dict[str, Any]]:
    """Our moves with X and an arc centre's X as radii, whichever mode the toolpath reports X in."""
    events = list(toolpath_events(io.StringIO(text), file="prog", dialect=dialect, setup=setup))
    half = 0.5 if events[0].get("x_mode") == "diameter" else 1.0
    return [{k: float(v) * half if k in ("x", "cx") else v for k, v in ev.items()} for ev in events[1:]
            if "move" in ev]


def _translate(text: str, target: str, setup: MachineSetup, **options: Any) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="prog", source="linuxcnc", target=target, setup=setup,
              on_unsupported="error", **options)
    return out.getvalue()


def _n(value: float) -> str:
    text = f"{value:.4f}".rstrip("0")
    return "0." if text in ("-0.", "0.") else text


def program(seed: int, g76: bool = True) -> tuple[str, bool, bool]:
    """(text, set-up in radius mode, inch): a random lathe program on grid values that switches between G7
    and G8 (``radius`` below is the true distance from the axis; ``k`` scales it to the program's X: 2 in G7, 1
    in G8, whichever the set-up says)."""
    rng = random.Random(seed)
    setup_radius, inch = rng.random() < 0.4, rng.random() < 0.25
    diameter = rng.random() < 0.5  # the program's first mode: the set-up's or the other
    s = 0.04 if inch else 1.0
    per_rev = rng.random() < 0.6
    lines = ["G18 " + ("G7" if diameter else "G8") + (" G20" if inch else " G21") + " G90 " +
             ("G95" if per_rev else "G94")]
    lines.append(rng.choice(("S600 M3", f"G96 S{120 if not inch else 400} D2500 M3", "G97 S800 M4")))
    r, z = rng.randint(18, 30), rng.randint(1, 4)
    pending = ""
    """A switch written beside the next move."""

    def k() -> float:
        return 2.0 if diameter else 1.0

    def feed() -> str:
        return _n(rng.choice((0.05, 0.1, 0.2)) * (s if inch else 1.0)) if per_rev else _n(rng.choice((60, 150)) * s)

    def xz(radius: float, zz: float) -> str:
        return f"X{_n(radius * k() * s)} Z{_n(zz * s)}"

    def add(line: str) -> None:
        nonlocal pending
        lines.append((pending + " " + line).strip())
        pending = ""

    add("G0 " + xz(r, z))
    incremental = False
    ops = ["switch"] + [rng.choice(("feed", "feed", "rapid", "arc", "thread", "taper", "g76", "switch", "switch",
                                    "g91")) for _ in range(rng.randint(6, 11))]
    rng.shuffle(ops)
    for op in ops:
        if op == "g76" and not g76:
            op = "taper"
        if op == "switch":
            diameter = not diameter
            code = "G7" if diameter else "G8"
            if pending:
                lines.append(pending)  # (two switches in a row: the first on a line of its own)
                pending = ""
            if rng.random() < 0.5:
                lines.append(code)
            else:
                pending = code  # beside the next move: it applies to that move's X
            continue
        if op == "g91":
            incremental = not incremental
            add("G91" if incremental else "G90")
            continue
        if incremental and op in ("g76", "arc"):
            incremental = False
            add("G90")
        if op in ("feed", "rapid"):
            r1, z1 = rng.randint(8, 32), rng.randint(-30, 3)
            words = (f"X{_n((r1 - r) * k() * s)} Z{_n((z1 - z) * s)}" if incremental else xz(r1, z1))
            add(("G1 " if op == "feed" else "G0 ") + words + (f" F{feed()}" if op == "feed" else ""))
            r, z = r1, z1
        elif op == "arc":
            q = rng.choice((1, 2, 3))
            if r <= 2 * q + 1:
                continue
            out = rng.choice((-1, 1))
            i, kk = (0.0, -q) if rng.random() < 0.5 else (out * q, 0.0)  # I a radius in both modes
            r1, z1 = r + out * q, z - q
            assert abs(math.hypot(z1 - (z + kk), r1 - (r + i)) - q) < 1e-9
            add(f"{rng.choice(('G2', 'G3'))} {xz(r1, z1)} I{_n(i * s)} K{_n(kk * s)} F{feed()}")
            r, z = r1, z1
        elif op == "thread":
            z1 = rng.randint(-30, z - 2) if z > -28 else z - 2
            words = f"Z{_n((z1 - z) * s)}" if incremental else f"Z{_n(z1 * s)}"
            add(f"G33 {words} K{_n(rng.choice((1.0, 1.5, 2.0)) * s)}")
            z = z1
        elif op == "taper":
            dz = rng.randint(4, 12)
            dr = rng.randint(-2, 2) if r > 12 else rng.randint(0, 2)
            words = (f"X{_n(dr * k() * s)} Z{_n(-dz * s)}" if incremental else xz(r + dr, z - dz))
            add(f"G33 {words} K{_n(rng.choice((1.0, 2.0)) * s)}")
            r, z = r + dr, z - dz
        else:  # g76: I, J, K diameters in G7
            r0, z0 = rng.randint(14, 26), rng.randint(1, 4)
            add("G0 " + xz(r0 + 3, z0))
            depth, j = rng.choice((0.6, 1.0)), rng.choice((0.1, 0.2))
            end = rng.randint(-25, -8)
            words = [f"P{_n(rng.choice((1.0, 1.5)) * s)}", f"Z{_n(end * s)}", f"I{_n(-3 * k() * s)}",
                     f"J{_n(j * k() * s)}", f"K{_n((j + depth) * k() * s)}"]
            if rng.random() < 0.5:
                words.append(f"R{rng.choice((1.5, 2.))}")
            if rng.random() < 0.4:
                words.append(f"H{rng.choice((0, 1))}")
            add("G76 " + " ".join(words))
            r, z = r0 + 3, end
            add("G0 " + xz(r, z))
    if pending:
        lines.append(pending)
    if incremental:
        lines.append("G90")
    lines += ["M5", "M2"]
    return "\n".join(line.rstrip() for line in lines) + "\n", setup_radius, inch


def _switches(text: str) -> bool:
    return bool(re.search(r"\bG7\b", text)) and bool(re.search(r"\bG8\b", text))


# -- reading and simulating, against rs274 ---------------------------------------------------------------

@needs_rs274
@pytest.mark.parametrize("seed", range(SEEDS))
def test_switching_programs_move_as_rs274_runs_them(seed: int) -> None:
    text, setup_radius, inch = program(seed)
    assert _switches(text)
    problem = difference(_ours(text, _setup(setup_radius)), theirs(text), INCH_TOLERANCE if inch else TOLERANCE)
    assert problem is None, f"{problem}\n\n{text}"


@needs_rs274
@pytest.mark.parametrize("seed", range(0, SEEDS, 3))
def test_switching_programs_translated_move_as_rs274_runs_the_source(seed: int) -> None:
    """LinuxCNC copied (byte for byte), normalised and in inches (rs274 runs what we wrote), Fanuc T and GSK
    (diameters, no switch left; verify at zero deviation, and our simulation of the output against rs274's run
    of the source)."""
    text, setup_radius, inch = program(seed, g76=seed % 2 == 0)
    setup = _setup(setup_radius)
    tolerance = INCH_TOLERANCE if inch else TOLERANCE
    source = theirs(text)
    assert _translate(text, "linuxcnc", setup) == text
    normalising = _setup(setup_radius)
    normalising.output.normalize = True
    bare = re.sub(r"(\d)\.(?=\s|$)", r"\1", text, flags=re.M)  # X50 for X50.: the normaliser rewrites the line
    normalised = _translate(bare, "linuxcnc", normalising)
    assert normalised != bare
    problem = difference(theirs(normalised), source, tolerance)
    assert problem is None, f"normalised: {problem}\n\n{normalised}"
    if "G76" not in text:  # (a G76 rewritten in the switched mode is refused: ``test_refusals``)
        units = "mm" if inch else "inch"
        converted = _translate(text, "linuxcnc", setup, units=units)
        problem = difference(theirs(converted), source, INCH_TOLERANCE)
        assert problem is None, f"{units}: {problem}\n\n{converted}"
    for target in ("fanuc", "gsk"):
        written = _translate(text, target, setup)
        assert not re.search(r"\bG0?[78]\b", written), written
        report = verify_lines(io.StringIO(text), io.StringIO(written), file_in="prog", file_out="out",
                              source="linuxcnc", target=target, setup=setup, tolerance=0.0)
        assert report.ok and report.max_deviation == 0.0, report.summary()
        problem = difference(_ours(written, setup, target), source, tolerance)
        assert problem is None, f"{target}: {problem}\n\n{written}"


# -- by hand -----------------------------------------------------------------------------------------------

def test_hand_program_reads_each_x_in_its_own_mode() -> None:
    """By hand, as radii: X40 in G7 is 20; G8 on the move's own line: 25; G91 X-2 in G8: 23; G7 X-2 (still G91), a
    diameter: 22; G90 G8 G2 X24 Z-9 I0 K-2 from (22, -7): centre (22, -9), end 24, 2 from it."""
    text = "G18 G7 G21 G90 G94 F100\nG0 X40 Z0\nG8 G1 X25 Z-5\nG91 X-2 Z-1\nG7 X-2 Z-1\nG90 G8 G2 X24 Z-9 I0 K-2\nM2\n"
    moves = _ours(text, _setup(False))
    assert [(m["move"], m["x"], m["z"]) for m in moves] == [
        ("rapid", 20.0, 0.0), ("feed", 25.0, -5.0), ("feed", 23.0, -6.0), ("feed", 22.0, -7.0), ("cw", 24.0, -9.0)]
    assert (moves[-1]["cx"], moves[-1]["cz"]) == (22.0, -9.0)
    radius_setup = _ours(text, _setup(True))  # the same program read with a radius set-up moves the same
    assert [(m["x"], m["z"]) for m in radius_setup] == [(m["x"], m["z"]) for m in moves]


def test_every_g7_and_g8_is_a_section_and_the_ir_keeps_the_set_ups_mode() -> None:
    """A G7 that repeats the mode is a section too: a LinuxCNC line written again (``--units``) keeps its code
    (rs274 starts in radius mode unless the ini's start-up code says otherwise [K])."""
    text = "G18 G7 G21\nG7 G0 X40 Z0\nG8\nG8 G1 X25 F100\nG7 X30\nM2\n"
    _, stream = read_blocks(text.splitlines(keepends=True), "prog", default_registry().dialect("linuxcnc"),
                            _setup(False), Diagnostics())
    blocks = list(stream)
    modes = [(b.line, b.sections["XProgramming"].mode) for b in blocks if "XProgramming" in b.sections]
    assert modes == [(1, "diameter"), (2, "diameter"), (3, "radius"), (4, "radius"), (5, "diameter")]
    x = [b.sections["Motion"].axes.get("X") for b in blocks if "Motion" in b.sections]
    assert x == [40.0, 50.0, 30.0]  # the IR keeps diameters: G8 X25 is 50


def test_the_section_round_trips_through_xml() -> None:
    block = Block(3, "G8", "\n", [("G", "8")])
    block.add(XProgramming("radius"))
    again = Block.from_xml(block.make_xml_source())  # (through the factory registry)
    assert again == block and again.sections["XProgramming"].mode == "radius"
    assert XProgramming("radius") != XProgramming("diameter")


REFUSED = [
    ("G18 G7 F100\nG0 X20 Z0\nG8\no100 sub\nG1 X1\no100 endsub\nM2\n", "prog:4:1: error: an o-word line while"),
    ("G18 G7 F100\nG0 X20 Z0\nG8 G1 X[#1+2] Z-1\nM2\n", "a computed X while the program writes X as a radius"),
    ("G18 G7 F100\nO100 SUB\nG1 X2 Z0\nG1 X6 Z-4\nG1 X12\nO100 ENDSUB\nG8 G0 X6 Z1\nG71 Q100 X6 Z1 D0.5 I1 R0.5\nM2\n",
     "prog:8:1: error: G71 while the program writes X in the mode other than the set-up's"),
    ("G18 G7 F100\nO100 SUB\nG1 X2 Z0\nG8 G1 X3 Z-4\nG7\nG1 X12\nO100 ENDSUB\nG0 X12 Z1\nG71 Q100 X12 Z1 D0.5 I1 R0.5\n"
     "M2\n", "G8 in a profile"),
]


@pytest.mark.parametrize("text, message", REFUSED)
def test_refusals(text: str, message: str) -> None:
    with pytest.raises(ErrorList) as err:
        _translate(text, "linuxcnc", _setup(False))
    assert message in str(err.value)


def test_a_thread_cycle_rewritten_in_the_switched_mode_is_refused_by_line() -> None:
    text = "G18 G7 G21 G95 F0.1\nS500 M3\nG8 G0 X15 Z2\nG76 P1.5 Z-10 I-1 J0.1 K0.8\nG7\nM2\n"
    with pytest.raises(ErrorList) as err:
        _translate(text, "linuxcnc", _setup(False), units="inch")
    assert "prog:4:1: error:" in str(err.value) and "CompoundMotion while the program writes X" in str(err.value)


def _grblhal_setup(radius: bool) -> MachineSetup:
    setup = load_setup(str(ROOT / "tests" / "heldout" / "setups" / "grblhal_lathe.xml"))  # encoder, tool table
    if radius:
        setup.input.x_programming = "radius"
    return setup


@needs_rs274
@pytest.mark.parametrize("seed", range(1, SEEDS, 4))
def test_grblhal_reads_the_switches_as_rs274_and_linuxcnc_runs_its_translation(seed: int) -> None:
    """grblHAL's rules are rs274's [V: grblHAL/core f80fc34 ``gcode.c``: the block's G7/G8 sets ``diameter_mode``,
    then the X word is halved]: the same text (no G76: grblHAL's passes differ) moves as rs274 runs it; the
    LinuxCNC translation of the grblHAL program, run by rs274, moves alike; a grblHAL copy is the text itself."""
    text, setup_radius, inch = program(seed, g76=False)
    setup = _grblhal_setup(setup_radius)
    tolerance = INCH_TOLERANCE if inch else TOLERANCE
    source = theirs(text)
    problem = difference(_ours(text, setup, "grblhal"), source, tolerance)
    assert problem is None, f"{problem}\n\n{text}"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="prog", source="grblhal", target="linuxcnc", setup=setup,
              on_unsupported="error")
    problem = difference(theirs(out.getvalue()), source, tolerance)
    assert problem is None, f"{problem}\n\n{out.getvalue()}"
    copy = io.StringIO()
    translate(io.StringIO(text), copy, file="prog", source="grblhal", target="grblhal", setup=setup,
              on_unsupported="error")
    assert copy.getvalue() == text


@needs_rs274
def test_rs274_reads_the_position_as_a_radius_in_both_modes() -> None:
    """[V] The fact the module docstring states (our lathe reading refuses position reads outside a G70-G72
    profile, so only rs274 is asked)."""
    from tests.support.rs274 import run_rs274
    calls = run_rs274("G18 G8 G21\nG0 X10 Z0\nG7 G1 X30 Z-5 F100\n(debug, a=#5420)\nG8 G1 X20\n(debug, b=#5420)\nM2\n",
                      tool_table="T1 P1 X0 Z0 D0\n")
    said = " ".join(line for line in calls if "MESSAGE" in line)
    assert "a=15.000000" in said and "b=20.000000" in said


LOOP = ("G18 G7 G21 F100\nG0 X40 Z0\n#1=0\no1 while [#1 lt 2]\nG8 G1 X[10+#1] Z[-1-#1]\nG7\n#1=[#1+1]\no1 endwhile\n"
        "G8\no2 if [1]\nG1 X5\no2 endif\nM2\n")
"""Run, a loop body that switches to G8 and back reads each X in the mode it runs in (the interpreter feeds the
block syntax in execution order). Kept as written (LinuxCNC), the switched computed X and the o-word line under G8
are refused."""


@needs_rs274
def test_a_loop_that_switches_runs_as_rs274_runs_it_and_flattens_for_fanuc() -> None:
    setup = _setup(False)
    source = theirs(LOOP)
    assert [(m["x"], m["z"]) for m in source] == [(20.0, 0.0), (10.0, -1.0), (11.0, -2.0), (5.0, -2.0)]
    assert difference(_ours(LOOP, setup), source) is None
    written = _translate(LOOP, "fanuc", setup)
    assert difference(_ours(written, setup, "fanuc"), source) is None, written
    with pytest.raises(ErrorList) as err:
        _translate(LOOP, "linuxcnc", setup)
    assert "prog:5:1: error: a computed X while the program writes X as a radius" in str(err.value)
