"""A canned-cycle block's machine actions keep the simulator's order when the cycle is written expanded:
what the motion needs (tool change, spindle start, coolant on) before it, what ends it (spindle stop,
coolant off, program stop or end) after. Every combination of S, M3/M4/M5, M8/M9, T M6 and M0/M30 in
the block, translated with the cycle expanded to three targets, must give the source's toolpath: the
same moves and the same machine events in the same order (``verify`` compares both)."""

from __future__ import annotations

import io
import itertools

import pytest

from postproc.api import translate
from postproc.setup.machine_setup import CycleSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

SPINDLE = ("", "M3", "M4", "M5")
COOLANT = ("", "M8", "M9")
TOOL = ("", "T2 M6")
CONTROL = ("", "M0", "M30")
SPEED = ("", "S1000")
COMBINATIONS = [c for c in itertools.product(SPEED, SPINDLE, COOLANT, TOOL, CONTROL) if any(c)]
TARGETS = {
    "fanuc": MachineSetup(cycles=CycleSettings(expand="all")),  # forced expansion back into Fanuc
    "grbl": MachineSetup(),  # no canned cycles: always expanded
    "linuxcnc": MachineSetup(cycles=CycleSettings(expand="all")),
}


def _program(words: tuple[str, ...]) -> str:
    extra = " ".join(w for w in words if w)
    tail = "" if "M30" in words else "X8.\nG80\nM5 M9\nM30\n"  # nothing live after the end
    return ("G21 G17 G90\nT1 M6\nS800 M3 M8\nG0 X0. Y0. Z10.\n"
            f"G98 G81 X5. Y5. Z-1. R2. F100. {extra}\n{tail}")


def _events(program: str, dialect: str, setup: MachineSetup) -> list[dict[str, object]]:
    """The machine events (no moves) of a program, with how many moves came before each."""
    events: list[dict[str, object]] = []
    moves = 0
    for ev in toolpath_events(io.StringIO(program), file="p.nc", dialect=dialect, setup=setup):
        if "move" in ev:
            moves += 1
        elif "event" in ev:
            events.append({**{k: v for k, v in ev.items() if k != "line"}, "after_moves": moves})
    return events


@pytest.mark.parametrize("target", sorted(TARGETS))
@pytest.mark.parametrize("words", COMBINATIONS, ids=lambda c: "_".join(w.replace(" ", "") for w in c if w))
def test_expanded_cycle_keeps_the_simulators_event_order(target: str, words: tuple[str, ...]) -> None:
    setup = TARGETS[target]
    program = _program(words)
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="fanuc", target=target, setup=setup)
    text = out.getvalue()
    assert "(drill from line 5" in text  # the cycle was written expanded
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                          source="fanuc", target=target, setup=setup, tolerance=1e-6)
    assert report.ok, report.summary() + "\n--- in\n" + program + "--- out\n" + text
    assert _events(text, target, setup) == _events(program, "fanuc", setup)


def test_spindle_start_and_tool_change_precede_the_expanded_hole() -> None:
    """The issue's case, by hand: the feed into the hole comes after M3 and the tool change."""
    program = "G21 G17 G90\nT1 M6\nG0 X0. Y0. Z10.\nG98 G81 X5. Y5. Z-1. R2. F100. S1000 M3 T2 M6\nM30\n"
    kinds = [ev.get("event") or ev.get("move") for ev in
             toolpath_events(io.StringIO(_translated(program)), file="o.nc", dialect="fanuc",
                             setup=TARGETS["fanuc"]) if "toolpath" not in ev]
    assert kinds == ["tool", "rapid", "tool", "spindle", "rapid", "rapid", "feed", "rapid", "end"]


def _translated(program: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.nc", source="fanuc", target="fanuc", setup=TARGETS["fanuc"])
    return out.getvalue()
