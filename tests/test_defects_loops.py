"""Defects: a damaged Fanuc WHILE loop ran to the work bound (a million blocks: > 5 s, ``make fuzz``'s
limit per case) before its error. A while loop whose end runs with every variable (and the modal call)
as at its previous end can never end - the interpreter is deterministic in what it reads, a Custom Macro B
program reads no machine state (``MACHINE_ONLY``) - so it is refused at its second end.
A loop that ends is never refused: the tests run loops whose iterations repeat the same variables in
separate calls and separate entries, and the seed's bolt circle."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.tools import with_tools

BOLT_CIRCLE = (Path(__file__).resolve().parent.parent / "examples" / "fanuc" / "o1005_bolt_circle_macro.nc"
               ).read_text(encoding="utf-8")
SETUP = with_tools(lengths={2: 100.0})
SMALL = MachineSetup(limits=Limits(repeated_work=20_000))
NEVER = ("loop 'END1' never ends: it runs again with every variable as the time before, so nothing can change "
         "(does the program count its variable?)")


def errors(text: str, setup: MachineSetup, target: str = "grbl") -> list[str]:
    with pytest.raises(ErrorList) as caught:
        if target == "toolpath":
            list(toolpath_events(io.StringIO(text), file="in.nc", dialect="fanuc", setup=setup,
                                 diagnostics=Diagnostics(warn_stream=io.StringIO())))
        else:
            translate(io.StringIO(text), io.StringIO(), file="in.nc", source="fanuc", target=target, setup=setup,
                      diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return [str(e) for e in caught.value.errors]


@pytest.mark.parametrize("target", ["grbl", "toolpath"])
def test_the_bolt_circle_without_its_counter_is_refused_at_its_head(target: str) -> None:
    damaged = BOLT_CIRCLE.replace("#10=#10+1\n", "")
    # nothing in the loop sets #10 or #1 once the counter's line 18 is gone: its test (line 16) cannot change
    # (``postproc.interp.fixed_condition``); the first G65 call (line 8) runs it
    assert errors(damaged, SETUP, target) == [
        "in.nc:16:1: error: loop 'WHILE [#10 LT #1] DO1' never ends: its test reads no variable the loop sets and "
        "nothing in the loop leaves it (does the program count the variable it tests?) (in O9010, called from "
        "in.nc line 8)"]


@pytest.mark.parametrize("target", ["grbl", "toolpath"])
def test_an_endless_loop_of_moves_is_refused_long_before_the_work_bound(target: str) -> None:
    # the loop sets the variable it tests (so its test may change), to the value it had
    program = "G21 G90 G0 X0 Y0 Z5.\n#1=0\nWHILE [#1 LT 10] DO1\nG01 X1. F100.\nX0.\n#1=#1\nEND1\nM30\n"
    assert errors(program, SMALL, target) == [f"in.nc:7:1: error: {NEVER}"]


def test_a_loop_that_counts_a_variable_it_never_tests_is_refused_at_its_head() -> None:
    """It met the work bound (seconds); now its test is seen to be fixed (tests/test_defects_fixed_conditions.py)."""
    program = "#1=0\nWHILE [#1 LT 10] DO1\n#2=#2+1\nEND1\nM30\n"
    assert errors(program, SMALL) == [
        "in.nc:2:1: error: loop 'WHILE [#1 LT 10] DO1' never ends: its test reads no variable the loop sets and "
        "nothing in the loop leaves it (does the program count the variable it tests?)"]


def test_loops_that_repeat_their_variables_across_calls_and_entries_run() -> None:
    # the subprogram's loop runs 2 iterations in each of 3 calls with the same variables, and the main
    # program's inner loop is entered again by its outer loop: 3 x 2 + 2 x 2 holes = 10 feed moves down
    program = ("G21 G90 G0 X0 Y0 Z5.\nM98 P9011 L3\n#1=0\nWHILE [#1 LT 2] DO1\n#2=0\nWHILE [#2 LT 2] DO2\n"
               "G01 Z-1. F100.\nG00 Z5.\n#2=#2+1\nEND2\n#1=#1+1\nEND1\nM30\n"
               "O9011\n#10=0\nWHILE [#10 LT 2] DO1\nG01 Z-1. F100.\nG00 Z5.\n#10=#10+1\nEND1\nM99\n")
    events = list(toolpath_events(io.StringIO(program), file="in.nc", dialect="fanuc", setup=SMALL,
                                  diagnostics=Diagnostics(warn_stream=io.StringIO())))
    assert sum(1 for e in events if e.get("move") == "feed") == 10


def test_the_bolt_circle_itself_runs() -> None:
    out = io.StringIO()
    translate(io.StringIO(BOLT_CIRCLE), out, file="in.nc", source="fanuc", target="grbl", setup=SETUP,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    assert out.getvalue().count("G1 Z-12.") + out.getvalue().count("Z-12.") >= 8


def test_a_main_program_that_returns_to_its_start_unchanged_is_refused_at_its_second_return() -> None:
    # found by make fuzz (malformed fanuc: the bolt circle with its WHILE line moved to the top); the
    # loop never runs (#10 and #1 vacant), M99 returns to the start again and again
    program = "WHILE [#10 LT #1] DO1\nEND1\nM99\n"
    assert errors(program, SMALL, "toolpath") == errors(program, SMALL, "grbl") == [
        "in.nc:3:1: error: return 'M99' never ends: it runs again with every variable as the time before, so "
        "nothing can change (does the program count its variable?)"]
    counting = "#1=#1+1\nG0 X#1\nM99\n"  # counts: runs to the work bound
    assert errors(counting, SMALL, "toolpath")[0].startswith("in.nc:3:1: error: return 'M99' repeats more than")
