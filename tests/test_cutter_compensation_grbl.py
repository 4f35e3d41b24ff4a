"""Cutter compensation resolved for grbl (``postproc.lowering.cutter_compensation``), against LinuxCNC's own
interpreter: the seeded LinuxCNC programs of ``test_cutter_compensation_rs274`` (G41/G42 in the XY and ZX
planes, over lines and arcs, both sides, entry and exit moves, inside and outside corners, rapids, Z moves, coolant and dwell
waiting behind a held move, G91 blocks, several radii) are translated to grbl, whose output has no G41/G42
left; the moves grbl then runs (its program simulated plainly) must be rs274's compensated moves, within
the output's rounding. A program rs274 refuses must fail to translate at the same block; one whose
compensated arc starts off its circle (LinuxCNC runs it; grbl refuses such an arc) fails at that arc.

``POSTPROC_COMPENSATION_PROGRAMS`` sets the number of programs (200 by default), as for the other test.
"""

from __future__ import annotations

import io
import math
import re
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import RS274Error, available, run_rs274
from tests.test_cutter_compensation_rs274 import BATCH, PROGRAMS, generate, rs274_path

pytestmark = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")

TOLERANCE = 2e-3
"""mm: the grbl output is written to the output's places (never rounded by more than half a micrometre
in mm, 0.00002 in in inches), and an arc's centre is written from the rounded start."""


def _grbl_path(text: str, setup: Any) -> list[dict[str, Any]]:
    events = list(toolpath_events(io.StringIO(text).readlines(), file="out.gcode", dialect="grbl", setup=setup))[1:]
    out: list[dict[str, Any]] = []
    flood = False
    for ev in events:
        if "move" in ev:
            point = {**ev, **ev.get("controlled", {})}
            out.append({k: point[k] for k in ("move", "x", "y", "z", "cx", "cy", "cz", "f") if k in point})
        elif ev.get("event") == "dwell" or (ev.get("event") == "coolant" and ev["on"] != flood):
            flood = ev.get("on", flood)
            out.append({k: v for k, v in ev.items() if k != "line"})
    return out


def check(seed: int) -> str:
    p = generate(seed)
    try:
        theirs: list[dict[str, Any]] | None = rs274_path(run_rs274(p.text(p.scale), tool_table=p.tool_table()),
                                                       len(p.blocks), p.scale, p.unit, p.plane)
        refused_at = None
    except RS274Error as err:
        theirs = None
        found = re.findall(r"^N(\d+)\b", err.stderr, re.M)
        refused_at = int(found[-1]) if found else -1
    listing = f"seed {seed}:\n{p.text()}\ntool table (mm): radii {p.radii}, lengths {p.lengths}"
    out = io.StringIO()
    try:
        translate(io.StringIO(p.text()).readlines(), out, file="p.ngc", source="linuxcnc", target="grbl",
                  setup=p.setup(), diagnostics=Diagnostics(max_errors=100, warn_stream=io.StringIO()))
    except ErrorList as errs:
        lines = [e.location.line for e in errs.errors if e.location is not None]
        if theirs is not None and "mm off its circle" in str(errs.errors[0]):
            # LinuxCNC joins a nearly tangent move to an arc without moving the arc's start onto its
            # compensated circle; grbl refuses such an arc (error 33), so the translation refuses it at its
            # line, with the distance (checked against the rs274 arc's own start and centre)
            arc = theirs_arc_at(theirs, errs.errors[0].message)
            assert arc, f"{errs.errors[0]}\n{listing}"
            return "not expressible"
        assert theirs is None, f"translation refused lines {lines}, rs274 ran it: {errs.errors[0]}\n{listing}"
        assert lines and lines[0] == refused_at, f"rs274 refused line {refused_at}, translation: {lines}\n{listing}"
        return "refused"
    assert theirs is not None, f"rs274 refused line {refused_at}, the translation did not\n{listing}\n{out.getvalue()}"
    text = out.getvalue()
    assert not re.search(r"\bG4[12]\b", text), text
    ours = _grbl_path(text, p.setup())
    shown = "\n".join(map(str, ours)) + "\n--- rs274:\n" + "\n".join(map(str, theirs)) + f"\n{listing}\n{text}"
    assert [e.get("move", e.get("event")) for e in ours] == [e.get("move", e.get("event")) for e in theirs], shown
    for n, (a, b) in enumerate(zip(ours, theirs)):
        for key in set(a) | set(b):
            if key in ("move", "event"):
                continue
            x, y = a.get(key), b.get(key)
            assert isinstance(x, (int, float)) and isinstance(y, (int, float)) and abs(x - y) <= TOLERANCE, (
                f"item {n} {key}: grbl {x}, rs274 {y}\n{shown}")
    return "ran"


def theirs_arc_at(theirs: list[dict[str, Any]], message: str) -> bool:
    """rs274 ran an arc whose start lies the message's distance off the circle through its end."""
    off = float(re.search(r"starts (\d+\.\d+) mm off", message).group(1))  # type: ignore[union-attr]
    start = (0.0, 0.0)
    for e in theirs:
        if "move" not in e:
            continue
        if e["move"] in ("cw", "ccw"):
            r0 = math.hypot(start[0] - e["cx"], start[1] - e["cy"])
            r1 = math.hypot(e["x"] - e["cx"], e["y"] - e["cy"])
            if abs(abs(r0 - r1) - off) < 1e-3:
                return True
        start = (e["x"], e["y"])
    return False


@pytest.mark.parametrize("batch", range(math.ceil(PROGRAMS / BATCH)))
def test_grbl_runs_the_compensated_path_rs274_runs(batch: int) -> None:
    for seed in range(batch * BATCH, min(PROGRAMS, (batch + 1) * BATCH)):
        check(seed)
