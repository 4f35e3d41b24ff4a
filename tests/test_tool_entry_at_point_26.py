"""LinuxCNC ``G10 L10``/``L11`` (issue 26, task 3): a tool table entry measured where the tool stands, X, Y and Z
(``G10 L10``: the offsets that make the current point read the values in the active work system; ``L11``: in
G59.3), simulated as LinuxCNC's interpreter works them out ([V] ``interp_convert.cc`` ``convert_setup_tool``).

* Seeded programs (work offsets G54/G55 and G59.3, ``G10 L1`` entries, ``G10 L10``/``L11`` with any subset of
  X, Y, Z, ``G43``/``G49``, absolute and incremental moves, metric or inch) move the controlled point where rs274
  run with the same tool table (``-t``) moves it: its canonical point plus the work offset and the tool offset
  it prints.
* Hand-derived: the values of one program worked out from the rule.
* Under a coordinate shift or rotation of the program's own (``G92``, ``G52``, ``G10 L2 R``): checked against
  rs274 in ``test_measured_entry_rotated.py``.
* Towards Fanuc and grbl, ``G10 L10`` is worked out where the translation knows the point and the offset in
  force (``postproc.frames.measured_entries``): seeded programs translated move as rs274 and verify;
  where it does not (``L11``, after a change of work system), a located error: never a dropped entry.
"""

from __future__ import annotations

import io
import random
import re
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274

PROGRAMS = 40
TOLERANCE_MM = 3e-3
"""rs274 prints 4 decimals in program units (1e-4 in = 0.00254 mm)."""
TOOLS = (3, 4)
TOOL_TABLE = "".join(f"T{t} P{t} Z0 D0\n" for t in TOOLS)
"""rs274's table at the start: every entry zero (the programs write the values)."""
SETUP = MachineSetup()
SETUP.tools = {str(t): ToolData(number=t, length=0.0, radius=0.0) for t in TOOLS}

needs_rs274 = pytest.mark.skipif(not rs274.available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _lines(text: str) -> list[str]:
    return io.StringIO(text, newline="").readlines()


def controlled(text: str) -> list[tuple[float, float, float]]:
    """Our simulation's controlled point of each move, mm."""
    evs = toolpath_events(_lines(text), file="t.ngc", dialect="linuxcnc", setup=SETUP)
    return [(p["x"], p["y"], p["z"]) for e in evs if "move" in e for p in [e.get("controlled", e)]]


def machine_points(calls: list[str], scale: float) -> list[tuple[float, float, float]]:
    """rs274's controlled point of each straight move that moves, mm: the canonical point, plus the active work
    offset and the tool offset in force as it prints them (program units)."""
    g5x = tlo = (0.0, 0.0, 0.0)
    out = []
    for call in calls:
        if m := re.search(r"SET_G5X_OFFSET\(\d+, (\S+), (\S+), (\S+),", call):
            g5x = (float(m.group(1)), float(m.group(2)), float(m.group(3)))
        elif m := re.search(r"USE_TOOL_LENGTH_OFFSET\((\S+) (\S+) (\S+),", call):
            tlo = (float(m.group(1)), float(m.group(2)), float(m.group(3)))
        elif m := re.search(r"STRAIGHT_(?:TRAVERSE|FEED)\((\S+), (\S+), (\S+),", call):
            point = tuple((float(m.group(i + 1)) + g5x[i] + tlo[i]) * scale for i in range(3))
            if not out or max(abs(p - q) for p, q in zip(point, out[-1])) > 1e-9:
                out.append(point)  # (a move to where the tool stands moves nothing: no move of ours)
    return out  # type: ignore[return-value]


def _program(rng: random.Random, measured: tuple[int, ...] = (10, 11), systems: bool = True) -> str:
    """A seeded program; ``measured``: the L numbers it measures entries with; ``systems``: it switches
    between G54 and G55."""
    inch = rng.random() < 0.25
    u = 1 / 25.4 if inch else 1.0

    def n() -> str:
        return f"{rng.uniform(-20, 20) * u:.4f}"

    def axes(letters: str = "XYZ", least: int = 1) -> str:
        chosen = [a for a in letters if rng.random() < 0.6] or list(rng.sample(letters, least))
        return " ".join(a + n() for a in chosen)

    tool = rng.choice(TOOLS)
    systems_set = [f"G10 L2 P1 {axes()}", f"G10 L2 P2 {axes()}", f"G10 L2 P9 {axes()}"] if systems else []
    lines = [f"{'G20' if inch else 'G21'} G90 G17 G94", *systems_set, f"G10 L1 P{tool} {axes()}", f"T{tool} M6",
             f"G43 H{tool}", f"G0 X{n()} Y{n()} Z{n()}", f"F{200 * u:.4f}"]
    settle = [] if systems else [f"G0 Z{n()}"]  # (Fanuc applies a length change at its next move, rs274 at the
    # next Z: a translation refuses a setting between the two, so these programs program Z at once)
    for _ in range(rng.randint(6, 12)):
        kind = rng.random()
        if kind < 0.35:
            lines.append(f"G10 L{rng.choice(measured)} P{rng.choice(TOOLS)} {axes()}")
            if rng.random() < 0.7:
                lines += [f"G43 H{tool}", *settle]  # the entry applies where G43 reads it
        elif kind < 0.45:
            lines += [rng.choice(["G49", f"G43 H{rng.choice(TOOLS)}"]), *settle]
        elif kind < 0.5 and systems:
            lines.append(rng.choice(["G54", "G55"]))
        elif kind < 0.6:
            lines.append(f"G91 G1 {axes()}")
            lines.append("G90")
        else:
            lines.append(f"G{rng.choice((0, 1))} {axes()}")
    lines.append("M2")
    return "\n".join(lines) + "\n"


@needs_rs274
@pytest.mark.parametrize("seed", range(PROGRAMS))
def test_entries_measured_where_the_tool_stands_move_as_rs274(seed: int) -> None:
    text = _program(random.Random(2626 + seed))
    scale = 25.4 if "G20" in text else 1.0
    theirs = machine_points(rs274.run_rs274(text, tool_table=TOOL_TABLE), scale)
    ours = controlled(text)
    assert len(ours) == len(theirs), (text, ours, theirs)
    for a, b in zip(ours, theirs):
        assert max(abs(p - q) for p, q in zip(a, b)) <= TOLERANCE_MM, (text, a, b)


def test_the_rule_hand_derived() -> None:
    # G54 (1, 2, 3), G59.3 (-1, -2, -4); tool 3 entry (0.5, 0.25, 10). At (5, 6, 7) in G54 with the entry in force
    # the tool's point without its offset reads (5.5, 6.25, 17) in G54: L10 X2 makes entry X 3.5 (Y, Z kept). At
    # (1, 1, 1) with (3.5, 0.25, 10) in force the machine point is (5.5, 3.25, 14); in G59.3 it reads (6.5, 5.25,
    # 18): L11 Y3 Z2 makes entry Y 2.25 and Z 16 (X kept); G43 then moves the controlled point to
    # (0, 0, 0) + G54 + (3.5, 2.25, 16)
    text = ("G21 G90 G17\nG10 L2 P1 X1 Y2 Z3\nG10 L2 P9 X-1 Y-2 Z-4\nT3 M6\nG10 L1 P3 X0.5 Y0.25 Z10\nG43 H3\n"
            "G0 X5 Y6 Z7\nG10 L10 P3 X2\nG43 H3\nG1 X1 Y1 Z1 F100\nG10 L11 P3 Y3 Z2\nG43 H3\nG0 X0 Y0 Z0\nM2\n")
    points = [v for point in controlled(text) for v in point]
    assert points == pytest.approx([6.5, 8.25, 20, 5.5, 3.25, 14, 4.5, 4.25, 19])


@needs_rs274
@pytest.mark.parametrize("target", ["fanuc", "grbl"])
@pytest.mark.parametrize("seed", range(PROGRAMS // 2))
def test_entries_measured_in_the_active_system_translate_and_move_as_rs274(seed: int, target: str) -> None:
    text = _program(random.Random(2680 + seed), measured=(10,), systems=False)
    scale = 25.4 if "G20" in text else 1.0
    theirs = machine_points(rs274.run_rs274(text, tool_table=TOOL_TABLE), scale)
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target=target, setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    evs = toolpath_events(_lines(out.getvalue()), file="t.nc", dialect=target, setup=SETUP)
    ours = [(p["x"], p["y"], p["z"]) for e in evs if e.get("move") in ("rapid", "feed") for p in [e.get("controlled", e)]]
    assert len(ours) == len(theirs), (text, out.getvalue())
    for a, b in zip(ours, theirs):
        assert max(abs(p - q) for p, q in zip(a, b)) <= TOLERANCE_MM, (text, out.getvalue(), a, b)
    report = verify_lines(_lines(text), _lines(out.getvalue()), file_in="t.ngc", file_out="t.nc", source="linuxcnc",
                          target=target, setup=SETUP)
    assert report.ok, report.summary()


def test_a_measured_length_towards_fanuc_hand_derived() -> None:
    # tool 1 of length 10 (G10 L1) at Z5: the point without the offset reads 5 + 10 = 15, L10 Z3 sets 12
    text = "G21 G90\nG10 L1 P1 Z10\nT1 M6\nG43 H1\nG0 X1 Y2 Z5\nG10 L10 P1 Z3\nG43 H1\nG1 X5 Z0 F100\nM2\n"
    out = io.StringIO(newline="")
    translate(_lines(text), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=SETUP)
    assert "\nG10 L10 P1 R12.\n" in out.getvalue(), out.getvalue()


@pytest.mark.parametrize("target", ["fanuc", "grbl", "isg", "siemens"])
@pytest.mark.parametrize("mode", ["error", "warn"])
def test_an_entry_the_translation_cannot_work_out_is_refused_by_name(target: str, mode: str) -> None:
    text = "G21 G90\nT3 M6\nG0 X1 Y1 Z1\nG10 L11 P3 X0 Y0\nG43 H3\nG0 X2\nM2\n"
    warnings = io.StringIO()
    out = io.StringIO(newline="")
    try:
        translate(_lines(text), out, file="t.ngc", source="linuxcnc", target=target, setup=SETUP,
                  on_unsupported=mode, diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=warnings))
    except ErrorList as err:
        assert any(e.location is not None and e.location.line == 4 for e in err.errors), err
        return
    assert mode == "warn" and "t.ngc:4:" in warnings.getvalue(), warnings.getvalue()  # never silently dropped
