"""What the two compensation differentials against rs274 share (``tests/test_cutter_compensation_rs274.py``,
mill cutter radius and tool length; ``tests/test_nose_compensation_rs274.py``, lathe tool nose radius):
postproc's controlled path of a LinuxCNC program, the block rs274 refused, and the comparison of both runs
move by move. Each test reads rs274's canonical calls itself (the planes and offsets it compares differ)."""

from __future__ import annotations

import re
from typing import Any, Iterator

from postproc.errors import Diagnostics
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import RS274Error

CALL = re.compile(r"^N(\d+|\.+)\s+([A-Z_]+)\((.*)\)\s*$")
"""One canonical call line of ``rs274 -g``: its block number, name and arguments."""


def calls_before(calls: list[str], end: int) -> Iterator[tuple[str, str, list[float]]]:
    """Each canonical call before block ``end`` (the program's M2: what it resets is no part of the path):
    its name, its arguments and the numbers among them."""
    for line in calls:
        m = CALL.match(line.strip())
        if not m:
            continue
        if m.group(1) == str(end):
            return
        args = m.group(3)
        yield m.group(2), args, [float(t) for t in re.split(r"[,\s]+", args.strip())
                                 if re.fullmatch(r"-?\d+(\.\d*)?", t)]


def refused_line(err: RS274Error) -> int:
    """The block number rs274 refused (-1: none named)."""
    found = re.findall(r"^N(\d+)\b", err.stderr, re.M)
    return int(found[-1]) if found else -1


def postproc_path(text: str, setup: MachineSetup, keys: tuple[str, ...],
                  radius_x: bool = False) -> tuple[list[dict[str, Any]], list[int]]:
    """postproc's controlled moves (their ``keys``; with ``radius_x``, X and its centre halved from a
    diameter), dwells and coolant changes (as rs274 reports them); and the lines of its errors."""
    diagnostics = Diagnostics(max_errors=100)
    events = list(toolpath_events(text.splitlines(keepends=True), file="p.ngc", dialect="linuxcnc",
                                  setup=setup, diagnostics=diagnostics, check=False))[1:]
    out = []
    flood = False
    for ev in events:
        if "move" in ev:
            point = {**ev, **ev.get("controlled", {})}
            out.append({k: (point[k] / 2.0 if radius_x and k in ("x", "cx") else point[k])
                        for k in keys if k in point})
        elif ev.get("event") == "dwell" or (ev.get("event") == "coolant" and ev["on"] != flood):
            flood = ev.get("on", flood)
            out.append({k: v for k, v in ev.items() if k != "line"})
    return out, [e.location.line for e in diagnostics.errors if e.location is not None]


def assert_same(ours: list[dict[str, Any]], errors: list[int], theirs: list[dict[str, Any]] | None,
                refused_at: int | None, tolerance: float, listing: str) -> str:
    """postproc's run equals rs274's: the same first refused block, or the same moves and events with every
    number within ``tolerance``. What happened: "refused" or "moves"."""
    if theirs is None:
        assert errors and errors[0] == refused_at, f"rs274 refused line {refused_at}, postproc: {errors}\n{listing}"
        return "refused"
    assert not errors, f"postproc refused lines {errors}, rs274 ran it\n{listing}"
    show = _show(ours) + "\n--- rs274:\n" + _show(theirs)
    assert [e.get("move", e.get("event")) for e in ours] == [e.get("move", e.get("event")) for e in theirs], (
        f"{show}\n{listing}")
    for n, (a, b) in enumerate(zip(ours, theirs)):
        for key in set(a) | set(b):
            if key in ("move", "event"):
                continue
            x, y = a.get(key), b.get(key)
            assert isinstance(x, (int, float)) and isinstance(y, (int, float)) and abs(x - y) <= tolerance, (
                f"item {n} {key}: postproc {x}, rs274 {y}\n{show}\n{listing}")
    return "moves"


def _show(path: list[dict[str, Any]]) -> str:
    return "\n".join(str(e) for e in path)


def compensated_moves(rng: Any, p: Any, line: Any, arc: Any, other: Any, count: tuple[int, int],
                      arc_share: float) -> None:
    """The moves of one compensated stretch of a random program, after its G41/G42 block: the entry move (an
    arc one time in five, else a G1 or G0), in the G41/G42 block half the time, then ``count`` moves: a line
    (45 %), an arc (up to ``arc_share``) or something else. ``line(rng, p, code)``, ``arc(rng, p)`` and
    ``other(rng, p)`` add the test's own blocks to ``p`` (``p.blocks``: the blocks, each a list of words)."""
    joined = rng.random() < 0.5  # the entry move in the G41/G42 block, or in the block after it
    entry = len(p.blocks)
    if rng.random() < 0.2:
        arc(rng, p)
    else:
        line(rng, p, rng.choice(["G1", "G1", "G0"]))
    if joined:
        p.blocks[entry - 1].extend(p.blocks.pop(entry))
    for _ in range(rng.randint(*count)):
        r = rng.random()
        if r < 0.45:
            line(rng, p)
        elif r < arc_share:
            arc(rng, p)
        else:
            other(rng, p)
