"""A LinuxCNC program reads its current position (issue 26: the held-back ``pcb2gcode_outline_tiled.ngc`` tiles
its outline by ``G92 X[#5420-[2.174016]]``): #5420-#5428 and ``#<_x>``..``#<_w>`` are the current point in the
active coordinate system with every offset (G5x, G52/G92, tool offset) in the program's units [V:
``rs274ngc_pre.cc`` ``Interp::read`` copies ``current_x``.. into #5420.. as each block is read;
``interp_namedparams.cc``; LinuxCNC docs "Parameters"]. The translation knows it where the simulation does
(``postproc.frames.parameters``): every axis read programmed absolutely since the start, no move in machine
coordinates, reference return, cycle or work system change since. Elsewhere, a located error.

Checked by hand-derived points, and by seeded programs mixing G92, G52, G92.1-G92.3, G10 L2 work offsets and a
second work system, G91, arcs, G20/G21, G43/G49 with reads of the position, run through our simulation and
translated to grbl (flattened), against rs274 run with the same tool table.
"""

from __future__ import annotations

import io
import math
import os
import random
import re
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup, MachineSettings
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import available, run_rs274
from tests.test_frames import _segments

SEEDS = range(int(os.environ.get("POSTPROC_POSITION_READ_PROGRAMS", "100")))
"""Random programs per run (``POSTPROC_POSITION_READ_PROGRAMS=2000`` for a long run)."""
BATCH = 25
TOLERANCE_MM = 4e-3
"""rs274 prints 4 decimals in program units: in inches each of a point's three terms (the move, the G5x and the
G92 offset) is within 0.00127 mm; a wrong read is off by a length, an offset or a unit factor (0.25 mm and up)."""
LENGTHS = {1: 1.0, 2: 0.375, 3: 2.25}
"""Tool lengths in inches: rs274 reads a standalone tool table in inches, and so does the inch set-up."""
TOOL_TABLE = "".join(f"T{n} P{n} Z{z} D0.1\n" for n, z in LENGTHS.items())


def _setup() -> MachineSetup:
    setup = MachineSetup()
    setup.machine = MachineSettings(units="inch")
    setup.tools = {str(n): ToolData(number=n, length=z, radius=0.05) for n, z in LENGTHS.items()}
    return setup


def moves(text: str) -> list[dict[str, Any]]:
    events = toolpath_events(io.StringIO(text, newline=""), file="t.ngc", dialect="linuxcnc", setup=_setup())
    return [e for e in events if "move" in e]


def points(text: str) -> list[tuple[float, float, float]]:
    return [(round(e["x"], 6), round(e["y"], 6), round(e["z"], 6)) for e in moves(text)]


# -- by hand ----------------------------------------------------------------------------------------------

TILES = """G21 G90 G0 X10 Y5 Z3
G92 X[#5420-2] Y[#5421+1]
G1 X#5420 Y[#5421+1] Z[#5422] F100
G20
G1 X[#5420+1]
G21
G1 X0
M2
"""


def test_a_g92_from_the_current_point_tiles_as_by_hand() -> None:
    """At (10, 5, 3): G92 X8 Y6 shifts the offset by (2, -1); X8 Y7 Z3 there is work (10, 6, 3). In G20
    #5420 reads 8 / 25.4 in: X[8/25.4 + 1] is 8 + 25.4 mm, work 35.4; X0 is work 2."""
    assert points(TILES) == [(10, 5, 3), (10, 6, 3), (35.4, 6, 3), (2, 6, 3)]


AFTER_LENGTH = "G21 G90 G0 X0 Y0 Z10\nG43 H1\nG1 X[#5422] F100\nG92 Z0\nG1 Z-5\nG49\nG0 Z50\nM2\n"


def test_a_length_offset_moves_the_current_point_as_by_hand() -> None:
    """G43 H1 (1 in) keeps the machine point: the current Z reads 10 - 25.4 = -15.4 [V: rs274 prints
    SET_G92_OFFSET(.., -15.4) for the G92 Z0 below], so X-15.4, and the tip's point, unmoved on the machine, is
    Z-15.4 too. G92 Z0 there puts the offset at -15.4: Z-5 is work -20.4 (the controlled point 5); after G49, Z50
    is work 34.6."""
    assert points(AFTER_LENGTH) == [(0, 0, 10), (-15.4, 0, -15.4), (-15.4, 0, -20.4), (-15.4, 0, 34.6)]


NAMED = "G21 G90 G0 X4 Y-2 Z1\nG91 G1 X1.5 F100\nG90 G1 X[#<_x>*2] Y[#<_y>-1] Z[#<_z>]\nM2\n"


def test_the_named_position_parameters_read_the_same_point() -> None:
    """After G91 X1.5 from X4: #<_x> = 5.5, so X11 Y-3 Z1."""
    assert points(NAMED)[-1] == (11, -3, 1)


@pytest.mark.parametrize("text, named", [
    ("G21 G90 G0 X1 Y2\nG1 Z[#5422] F100\nM2\n", "#5422 (current position)"),  # Z never programmed
    ("G21 G90 G0 X1 Y2 Z3\nG55\nG0 X#5420\nM2\n", "#5420 (current position)"),  # the set-up's G55
    ("G21 G90 G0 X1 Y2 Z3\nG53 G0 X0\nG0 Y#5420\nM2\n", "#5420 (current position)"),  # machine coordinates
    ("G21 G90 G0 X1 Y2 Z3\nG28 X1\nG0 X#<_x>\nM2\n", "#<_x> (current position)"),  # a reference return
    ("G21 G90 G0 X1 Y2 Z3\nG81 X4 Y4 Z-1 R1 F100\nG80\nG0 X#5421\nM2\n", "#5421 (current position)"),  # a cycle
])
def test_a_position_the_simulation_does_not_know_is_the_machines(text: str, named: str) -> None:
    with pytest.raises(ErrorList) as info:
        moves(text)
    message = str(info.value.errors[0])
    assert named in message and "known only to the machine" in message, message


def test_a_position_read_with_cutter_compensation_on_is_refused_as_rs274_does() -> None:
    text = "G21 G90 G0 X0 Y0 Z1\nG41 D1\nG1 X10 F100\nG1 Y#5421\nG40\nG0 X0\nM2\n"
    with pytest.raises(ErrorList) as info:
        moves(text)
    assert "#5421 (current position) cannot be read with cutter radius compensation on" in str(info.value.errors[0])
    if available():
        with pytest.raises(Exception, match="Cannot read current position with cutter radius compensation on"):
            run_rs274(text, tool_table=TOOL_TABLE)


def test_a_translation_reads_the_position_where_it_flattens() -> None:
    """Towards grbl the program is flattened: G92 X8 Y6 (the values read) is evaluated into the coordinates
    (offset (2, -1)), and the inch move reads 8 / 25.4: X[8/25.4 + 1] + 2/25.4 = 10/25.4 + 1 = 1.39370079 in."""
    out = io.StringIO()
    translate(io.StringIO(TILES), out, file="t.ngc", source="linuxcnc", target="grbl", setup=_setup())
    assert out.getvalue().splitlines() == ["G21 G90 G0 X10. Y5. Z3.", "(G92 X8. Y6. evaluated)", "G1 X10. Y6. Z3. F100.",
                                           "G20", "G1 X1.39370079", "G21", "G1 X2.", "M2"]


# -- against rs274 ----------------------------------------------------------------------------------------

class _Gen:
    """Random LinuxCNC programs that read their position among frame, unit and tool offset changes. The
    generator follows which axes the simulation knows (programmed absolutely since the start, a change of work
    system or a cycle) and reads only those: every program must run on both sides."""

    def __init__(self, seed: int) -> None:
        self.r = random.Random(seed)
        self.inch = False
        self.length = False
        """A tool length offset is in force."""

    def num(self, lo: int = -40, hi: int = 40) -> str:
        value = self.r.randint(lo * 4, hi * 4) / 4
        return f"{value / 25.4:.5f}" if self.inch else f"{value:g}"

    def full(self) -> str:
        return f"G90 G0 X{self.num()} Y{self.num()} Z{self.num(2, 20)}"

    def read(self, axis: str) -> str:
        number = {"X": 5420, "Y": 5421, "Z": 5422}[axis]
        return f"#<_{axis.lower()}>" if self.r.random() < 0.2 else f"#{number}"

    def program(self) -> str:
        r = self.r
        lines = ["G21 G17 G90 G94 G40 G49 F200", "G0 X0 Y0 Z10"]
        for _ in range(r.randint(6, 14)):
            kind = r.choice(["move", "inc", "arc", "g52", "g92", "g92read", "g92x", "g10", "work", "units",
                             "length", "length", "cycle", "readmove", "readmove", "store"])
            if kind == "move":
                lines.append(f"G90 G1 X{self.num()} Y{self.num()} Z{self.num(0, 10)} F200")
            elif kind == "inc":
                lines.append(f"G91 G1 X{self.num(-10, 10)} Z{self.num(-3, 3)} F150")
                lines.append("G90")
            elif kind == "arc":
                i, j = self.num(-15, 15), self.num(-15, 15)
                if float(i) == 0 and float(j) == 0:
                    i = "5" if not self.inch else "0.2"
                lines.append(f"G90 G{r.choice([2, 3])} I{i} J{j} F100")  # a full circle: back where it starts
            elif kind == "g52":
                lines.append(f"G52 X{self.num(-20, 20)} Y{self.num(-20, 20)}")
            elif kind == "g92":
                lines.append(f"G92 X{self.num(-20, 20)} Z{self.num(0, 10)}")
            elif kind == "g92read":  # pcb2gcode's tiling: the offset from where the tool stands
                axis = r.choice("XYZ")
                lines.append(f"G92 {axis}[{self.read(axis)}-[{self.num(-5, 5)}]]")
            elif kind == "g92x":
                lines.append(r.choice(["G92.1", "G92.2", "G92.3"]))
            elif kind == "g10":  # the active system's offset: the set-up's before it is the machine's
                lines.append(f"G10 L2 P1 X{self.num(-30, 30)} Y{self.num(-30, 30)} Z{self.num(-5, 5)}")
                lines.append(self.full())
            elif kind == "work":  # the set-up's own offsets are the machine's: programmed again before a read
                lines.append(f"G10 L2 P2 X{self.num(-30, 30)} Y{self.num(-30, 30)}")
                lines.append(r.choice(["G55", "G54"]))
                lines.append(self.full())
            elif kind == "units":
                if self.length:
                    # a standalone rs274 keeps the offset in force in the units it was set in across G20/G21
                    # (sai's GET_EXTERNAL_TOOL_LENGTH_ZOFFSET returns it unconverted; the machine's emccanon
                    # converts it: TO_PROG_LEN [V: src/emc/sai/saicanon.cc, src/emc/task/emccanon.cc]), so
                    # the offset goes before a change of units
                    lines.append("G49")
                    self.length = False
                self.inch = not self.inch
                lines.append("G20" if self.inch else "G21")
            elif kind == "length":
                code = r.choice(["G43 H1", "G43 H2", "G43 H3", "G49"])
                self.length = code != "G49"
                lines.append(code + (f" G0 Z{self.num(2, 10)}" if r.random() < 0.3 else ""))
            elif kind == "cycle":  # from a known initial level (a length change leaves the cycle's unknown)
                lines.append(self.full())
                lines.append(f"G90 G98 G81 X{self.num()} Y{self.num()} Z-{self.num(1, 5)} R{self.num(1, 3)} F100")
                lines.append("G80")
                lines.append(self.full())
            elif kind == "readmove":
                lines.append(f"G90 G1 X[{self.read('X')}+{self.num(-5, 5)}] Y[{self.read('Y')}*0.5] "
                             f"Z[{self.read('Z')}] F120")
            else:
                lines.append(f"#1=[{self.read('Z')}] #2=[{self.read('X')}]")
                lines.append(f"G90 G1 X{self.num()} Y{self.num()} Z{self.num(0, 10)}")
                lines.append("G90 G1 X#2 Z#1")
        lines.append("G49 G92.1")
        lines.append("M2")
        return "\n".join(lines) + "\n"


RESET = ["G90 G80 G17 G21 G94 G40 G49 G54", "G92.1", "G10 L2 P1 X0 Y0 Z0 R0", "G10 L2 P2 X0 Y0 Z0 R0"]
"""Between two programs of one rs274 run: no offset, no length, G54 at zero."""


def _batch(texts: list[str]) -> str:
    body: list[str] = []
    for n, text in enumerate(texts):
        lines = [line for line in text.splitlines() if line.strip() not in ("M2", "M30", "%")]
        body += [*RESET, f"(SEGMENT {n})", *lines]
    return "\n".join(body + ["M2"]) + "\n"


_CALL = re.compile(r"^\s*(?:\d+\s+)?N\.+\s+([A-Z_0-9]+)\((.*)\)\s*$")


def _work_points(calls: list[str]) -> list[dict[str, Any]]:
    """rs274's moves at their work points (the canonical point plus the G5x and G92 offsets in force; the tool
    offset not added: the tool tip, as our ``x, y, z``), in mm. rs274 prints every length in the units in
    force when it prints it (``USE_LENGTH_UNITS``), an offset too, so each is taken in its own."""
    scale, g5x, g92, tlo = 1.0, [0.0] * 3, [0.0] * 3, [0.0] * 3
    out: list[dict[str, Any]] = []
    for line in calls:
        m = _CALL.match(line)
        if m is None:
            continue
        name, text = m.group(1), m.group(2)
        if name == "USE_LENGTH_UNITS":
            scale = 25.4 if "INCHES" in text else 1.0
            continue
        args = [float(v) for v in re.split(r"[,\s]+", text.strip()) if re.fullmatch(r"-?[\d.]+", v)]
        if name == "SET_G5X_OFFSET":
            g5x = [v * scale for v in args[1:4]]
        elif name == "SET_G92_OFFSET":
            g92 = [v * scale for v in args[0:3]]
        elif name == "USE_TOOL_LENGTH_OFFSET":
            tlo = [v * scale for v in args[0:3]]
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "ARC_FEED"):
            end = (args[0], args[1], args[5]) if name == "ARC_FEED" else tuple(args[0:3])
            move = {"STRAIGHT_TRAVERSE": "rapid", "STRAIGHT_FEED": "feed"}.get(name, "arc")
            point = {k: v * scale + g5x[i] + g92[i] for i, (k, v) in enumerate(zip("xyz", end))}
            out.append({"move": move, **point, "controlled": {k: v + tlo[i] for i, (k, v) in enumerate(point.items())}})
    return out


def _same(ours: list[dict[str, Any]], theirs: list[dict[str, Any]], text: str, seed: int) -> None:
    ours, theirs = _moved(ours), _moved(theirs)
    assert len(ours) == len(theirs), f"seed {seed}: {len(ours)} moves here, {len(theirs)} in rs274\n{text}"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"] or a["move"] in ("cw", "ccw") and b["move"] == "arc", (seed, n, a, b, text)
        dev = max(abs(float(a[k]) - float(b[k])) for k in ("x", "y", "z"))
        assert dev <= TOLERANCE_MM, (seed, n, a, b, text)


def _moved(events: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Moves whose controlled point ends away from where it starts (rs274 prints a move to the point it stands
    on, and one whose tip point alone changes, a length change taken up without motion)."""
    out: list[dict[str, Any]] = []
    here = (0.0, 0.0, 0.0)
    for e in events:
        at = e.get("controlled", e)
        end = (at["x"], at["y"], at["z"])
        if e["move"] in ("rapid", "feed") and all(abs(a - b) <= TOLERANCE_MM for a, b in zip(end, here)):
            continue
        out.append(e)
        here = end
    return out


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("batch", range(math.ceil(len(SEEDS) / BATCH)))
def test_random_programs_reading_their_position_run_as_in_rs274(batch: int) -> None:
    seeds = list(SEEDS)[batch * BATCH:(batch + 1) * BATCH]
    texts = [_Gen(seed).program() for seed in seeds]
    grbls = []
    for text in texts:
        out = io.StringIO()
        translate(io.StringIO(text), out, file="gen.ngc", source="linuxcnc", target="grbl", setup=_setup())
        grbls.append(out.getvalue())
    source_runs = _segments(run_rs274(_batch(texts), timeout=120, tool_table=TOOL_TABLE), len(texts))
    grbl_runs = _segments(run_rs274(_batch(grbls), timeout=120, tool_table=TOOL_TABLE), len(texts))
    for seed, text, grbl, theirs, evaluated in zip(seeds, texts, grbls, source_runs, grbl_runs):
        want = _work_points(theirs)
        _same(moves(text), want, text, seed)
        _same(_work_points(evaluated), want, text + "\n--- grbl ---\n" + grbl, seed)


def test_the_generator_reads_every_kind_of_position_among_every_change() -> None:
    text = "".join(_Gen(seed).program() for seed in SEEDS)
    for word in ("#5420", "#5421", "#5422", "#<_x>", "#<_z>", "G43 H", "G49", "G92 Z[", "G52", "G20", "G55",
                 "G92.3", "G81"):
        assert word in text, word
    assert re.search(r"G43 H\d\n(?!G90 G1 X\S+ Y\S+ Z)", text), "a read must follow a length change unmoved"
