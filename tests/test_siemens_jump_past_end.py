"""SINUMERIK: a jump in the main program to a label or block number after its M30 runs on from there (issue 26,
the held-back ``cead_goto.mpf``). With jumps, the end of program need not be the program's last block [K:
SINUMERIK ONE NC programming manual 4.1.5.2 "Program jumps to jump markers", as cited by CEAD-group's
nc-gcode-interpreter, whose ``examples/goto.mpf`` runs the label after M30 (``examples/goto.csv``)]; the run
ends where a program end runs (``SubprogramRules.jumps_past_end``). Another family's jump past its end stays a
located error (``tests/test_fuzz_regressions.py``).

SINUMERIK starts in G1 (the standard reset value of G group 1, MD20150 [V: ONE NC programming manual 12/2019
p.1247]): the held-back program, which programs no motion code and no feed rate, cannot run as published (alarm
10860). Its jumps are checked here on a machine set to start in G0 (``<Controller startMotion="rapid"/>``).
"""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

GOTO = (Path(__file__).parent / "heldout" / "siemens" / "cead_goto.mpf").read_text()
KEPT = GOTO.replace("N90 GOTOC NOWHERE ; destination missing: alarm suppressed, fall through", "N90 R5=1")
"""The same jumps without the GOTOC to a missing label (which alone makes a translation flatten the program):
what a target could otherwise keep as its own jumps."""
TARGETS = ("fanuc", "linuxcnc", "grbl", "grblhal", "isg", "fagor", "mach3")


def _rapid_start() -> MachineSetup:
    setup = MachineSetup()
    setup.controller = ControllerSettings(start_motion="rapid")
    return setup


def _events(text: str, setup: MachineSetup) -> list[dict[str, Any]]:
    return list(toolpath_events(io.StringIO(text), file="goto.mpf", dialect="siemens", setup=setup))


def _code(line: str) -> str:
    """A written line without its comments (parentheses, or from a semicolon on)."""
    out, depth = [], 0
    for ch in line.split(";")[0]:
        depth += ch == "("
        if not depth:
            out.append(ch)
        depth -= ch == ")" and depth > 0
    return "".join(out).strip()


def test_the_jump_past_m30_runs_the_blocks_there_and_returns() -> None:
    """By the manual's rules: N10 sets R1=30 R2=10 R4=3; GOTOF MIDDLE finds the label after N120 M30: Y=1 (line
    14); GOTOB REPEAT_HERE back to N40: X30, R4 2, jump back: X40, R4 1, back: X50, R4 0, on; GOTOF 90 skips
    N80; GOTOC NOWHERE falls through; GOTO FINISH finds N120 forward: M30 ends the run (line 13). No X999."""
    events = _events(GOTO, _rapid_start())
    moves = [(e["line"], e["x"], e["y"]) for e in events if "move" in e]
    assert moves == [(14, 0, 1), (5, 30, 1), (5, 40, 1), (5, 50, 1)]
    assert [e["line"] for e in events if e.get("event") == "end"] == [13]


def test_as_published_the_program_stops_for_its_missing_feed_rate() -> None:
    """In SINUMERIK's standard G1 its first move, Y=1 after the jump, has no feed rate: alarm 10860."""
    with pytest.raises(ErrorList) as info:
        _events(GOTO, MachineSetup())
    assert str(info.value.errors[0]).startswith("goto.mpf:14:1: error: a feed move with no feed rate")


@pytest.mark.parametrize("text", [GOTO, KEPT], ids=["published", "without-gotoc"])
@pytest.mark.parametrize("target", TARGETS)
def test_every_target_gets_the_run_flattened(target: str, text: str) -> None:
    """Each target's blocks after its end are comments (``postproc.lowering.program_end``), so a kept jump
    would go nowhere: the program is flattened, its moves as the run makes them, and verifies."""
    setup = _rapid_start()
    out = io.StringIO()
    translate(io.StringIO(text), out, file="goto.mpf", source="siemens", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    written = out.getvalue()
    code = [_code(line) for line in written.splitlines()]
    assert not [line for line in code if "999" in line or "GOTO" in line.upper()], written
    moved = [(word[0], float(word[1:])) for line in code if "X" in line or "Y" in line for word in [line.split()[-1]]]
    assert moved == [("Y", 1), ("X", 30), ("X", 40), ("X", 50)], written
    report = verify_lines(io.StringIO(text), io.StringIO(written), file_in="goto.mpf", file_out="out",
                          source="siemens", target=target, setup=setup, tolerance=0.0)
    assert report.ok, report.summary()


def test_the_reason_to_flatten_names_the_jump_past_the_end() -> None:
    warned = io.StringIO()
    translate(io.StringIO(KEPT), io.StringIO(), file="goto.mpf", source="siemens", target="fanuc",
              setup=_rapid_start(), diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=warned))
    assert "a jump to middle, after the program end, where fanuc's program keeps no blocks" in warned.getvalue()


def test_a_jump_past_the_end_that_runs_no_end_stops_at_the_files_end() -> None:
    """After the jump the run takes in the rest of the file: without another end it stops where the file does
    (the blocks after the label run, the ones before it do not)."""
    text = "G0 X1\nGOTOF AFTER\nX999\nM30\nX2\nAFTER: Y3\n"
    moves = [(e["x"], e["y"]) for e in _events(text, MachineSetup()) if "move" in e]
    assert moves == [(1, 0), (1, 3)]
