"""Defects: a loop that counts a variable it never tests (``WHILE [#1 LT 10] DO1`` whose body increments #2)
ran until the work bound (about ten seconds at the default million) before its error. Now a loop whose
test holds, reads only variables nothing in the loop sets, and has no other way out is refused at its
head when it is entered (``postproc.interp.fixed_condition``), in every dialect whose loops the interpreter
runs: Custom Macro B, LinuxCNC and grblHAL o-words, ISG and SINUMERIK. And the repeated-state check
(an iteration that ends as the one before can never end), which ran only at a while loop's end, runs at
the end of every kind of loop (do-while, repeat-until, counted) of ISG and SINUMERIK too. (It needs the
variables to say all the program can read: LinuxCNC's cannot where the run's frames answer its offset
parameters, the toolpath's case, so there a loop whose test may change still runs to the work bound.)

A loop that may end is never refused: the tests run loops left by a jump, a break, a return, a program
end, a call that sets the tested variable, a conditional or computed assignment to it, and one stopped
by the program's own alarm. (Fagor's loops are not simulated at all: "cannot be simulated" before they
run, so nothing of them can run long.)

The default set-up (a million blocks of work) is used: the work bound would name the loop's END line,
these errors name its head; no wall-clock is asserted."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.errors import Diagnostics, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events

FIXED = ("never ends: its test reads no variable the loop sets and nothing in the loop leaves it (does the "
         "program count the variable it tests?)")
REPEATS = ("never ends: it runs again with every variable as the time before, so nothing can change (does the "
           "program count its variable?)")


EXPRESSIONS = MachineSetup(controller=ControllerSettings(expressions=True))
"""grblHAL reads parameters and o-words only with its expressions option."""


def run(text: str, dialect: str) -> list[dict[str, Any]]:
    return list(toolpath_events(io.StringIO(text), file="in.nc", dialect=dialect,
                                setup=EXPRESSIONS if dialect == "grblhal" else None,
                                diagnostics=Diagnostics(warn_stream=io.StringIO())))


def errors(text: str, dialect: str) -> list[str]:
    with pytest.raises(ErrorList) as caught:
        run(text, dialect)
    return [str(e) for e in caught.value.errors]


FIXED_LOOPS = [
    # (dialect, program, the head's line and text)
    ("fanuc", "#1=0\n#2=0\nWHILE [#1 LT 10] DO1\nG0 X#2\n#2=#2+1\nEND1\nM30\n", "3:1: error: loop 'WHILE [#1 LT 10] DO1'"),
    ("fanuc", "#100=0\nWHILE [#100 LT 10] DO1\n#[#100+1]=5\nEND1\nM30\n", None),  # may set #100: runs
    ("linuxcnc", "#1=0\no1 while [#1 LT 10]\n#2=[#2+1]\nG0 X#2\no1 endwhile\nM2\n",
     "2:1: error: loop 'o1 while [#1 LT 10]'"),
    ("linuxcnc", "#<n>=0\no1 do\n#<m>=[#<m>+1]\no1 while [#<n> LT 10]\nM2\n", None),  # #<m> unset: an error first
    ("linuxcnc", "#<n>=0\n#<m>=0\no1 do\n#<m>=[#<m>+1]\no1 while [#<n> LT 10]\nM2\n",
     "5:1: error: loop 'o1 while [#<n> LT 10]'"),
    ("grblhal", "#1=0\no1 while [#1 LT 10]\n#2=[#2+1]\no1 endwhile\nM2\n", "2:1: error: loop 'o1 while [#1 LT 10]'"),
    ("isg", "%1\nP1=0\nP2=0\n$WHILE P1 < 10\nP2=P2+1\n$ENDWHILE\nM30\n", "4:1: error: loop '$WHILE P1 < 10'"),
    ("isg", "%1\nP1=0\nP2=0\n$DO\nP2=P2+1\n$ENDDO P1 < 10\nM30\n", "6:1: error: loop '$ENDDO P1 < 10'"),
    ("isg", "%1\nP1=0\nP2=0\n$REPEAT\nP2=P2+1\n$UNTIL P1 > 10\nM30\n", "6:1: error: loop '$UNTIL P1 > 10'"),
    ("siemens", "R1=0\nR2=0\nWHILE R1<10\nR2=R2+1\nENDWHILE\nM30\n", "3:1: error: loop 'WHILE R1<10'"),
    ("siemens", "R1=0\nR2=0\nREPEAT\nR2=R2+1\nUNTIL R1>10\nM30\n", "5:1: error: loop 'UNTIL R1>10'"),
    ("siemens", "R2=0\nLOOP\nR2=R2+1\nG0 X=R2\nENDLOOP\nM30\n", "2:1: error: loop 'LOOP'"),
]


@pytest.mark.parametrize("dialect, text, head", FIXED_LOOPS)
def test_a_loop_whose_test_cannot_change_is_refused_at_its_head(dialect: str, text: str, head: str | None) -> None:
    if head is None:  # the loop is not refused for its test: it meets another error or its bounds
        assert not any(FIXED in e for e in _errors_or_none(text, dialect))
        return
    assert errors(text, dialect) == [f"in.nc:{head} {FIXED}"]


def _errors_or_none(text: str, dialect: str) -> list[str]:
    try:
        run(text, dialect)
    except ErrorList as err:
        return [str(e) for e in err.errors]
    return []


LOOPS_THAT_END = [
    # (dialect, program, the X of the last move: what the loop's way out leaves)
    ("fanuc", "#1=0\n#2=0\nWHILE [#1 LT 10] DO1\n#2=#2+1\nG0 X#2\nIF [#2 GE 3] GOTO 9\nEND1\nN9 M30\n", 3.0),
    ("fanuc", "#1=0\n#2=0\nWHILE [#1 LT 10] DO1\n#2=#2+1\nG0 X#2\nIF [#2 GE 4] THEN #1=10\nEND1\nM30\n", 4.0),
    ("fanuc", "#1=0\n#2=0\n#3=1\nWHILE [#1 LT 10] DO1\n#2=#2+1\nG0 X#2\n#[#3]=10\nEND1\nM30\n", 1.0),
    ("fanuc", "#100=0\n#2=0\nWHILE [#100 LT 10] DO1\n#2=#2+1\nG0 X#2\nM98 P2000\nEND1\nM30\nO2000\n#100=#100+5\nM99\n",
     2.0),
    ("fanuc", "#1=0\n#2=0\nWHILE [#1 LT 10] DO1\n#2=#2+1\nG0 X#2\nM30\nEND1\n", 1.0),
    ("linuxcnc", "#1=0\n#2=0\no1 while [#1 LT 10]\n#2=[#2+1]\nG0 X#2\no2 if [#2 GE 2]\no1 break\no2 endif\n"
                 "o1 endwhile\nM2\n", 2.0),
    ("isg", "%1\nP1=0\nP2=0\n$WHILE P1 < 10\nP2=P2+1\nG0 X[P2]\n$IF P2 >= 2\n$BREAK\n$ENDIF\n$ENDWHILE\nM30\n", 2.0),
    ("siemens", "R1=0\nR2=0\nWHILE R1<10\nR2=R2+1\nG0 X=R2\nIF R2>=3 GOTOF OUT\nENDWHILE\nOUT:\nM30\n", 3.0),
    ("siemens", "R2=0\nLOOP\nR2=R2+1\nG0 X=R2\nIF R2>=2 GOTOF OUT\nENDLOOP\nOUT:\nM30\n", 2.0),
]


@pytest.mark.parametrize("dialect, text, last_x", LOOPS_THAT_END)
def test_a_loop_with_a_way_out_runs(dialect: str, text: str, last_x: float) -> None:
    moves = [ev for ev in run(text, dialect) if "move" in ev]
    assert moves[-1]["x"] == pytest.approx(last_x)


def test_the_programs_own_alarm_ends_a_loop_whose_test_is_fixed() -> None:
    text = "#1=0\n#2=0\nWHILE [#1 LT 10] DO1\n#2=#2+1\nIF [#2 GT 5] THEN #3000=1 (TOO MANY)\nEND1\nM30\n"
    found = errors(text, "fanuc")
    assert len(found) == 1 and found[0].startswith("in.nc:5:") and "#3000=1 (TOO MANY)" in found[0]


REPEATED = [
    # (dialect, program, the end that runs as before): each loop sets the variable it tests, to what it was
    ("isg", "%1\nP1=0\n$WHILE P1 < 10\nP1=P1*1\n$ENDWHILE\nM30\n", "5:1: error: loop '$ENDWHILE'"),
    ("isg", "%1\nP1=0\n$DO\nP1=0\n$ENDDO P1 < 10\nM30\n", "5:1: error: loop '$ENDDO P1 < 10'"),
    ("isg", "%1\nP1=0\n$REPEAT\nP1=0\n$UNTIL P1 > 10\nM30\n", "5:1: error: loop '$UNTIL P1 > 10'"),
    ("isg", "%1\n$FOR P1 = 0, 10, 0\nG0 X[P1]\n$ENDFOR\nM30\n", "4:1: error: loop '$ENDFOR'"),
    ("siemens", "R1=0\nWHILE R1<10\nR1=R1*1\nENDWHILE\nM30\n", "4:1: error: loop 'ENDWHILE'"),
    ("siemens", "R1=0\nREPEAT\nR1=0\nUNTIL R1>10\nM30\n", "4:1: error: loop 'UNTIL R1>10'"),
]


@pytest.mark.parametrize("dialect, text, end", REPEATED)
def test_an_iteration_that_ends_as_the_one_before_is_refused_at_its_second_end(dialect: str, text: str,
                                                                                 end: str) -> None:
    assert errors(text, dialect) == [f"in.nc:{end} {REPEATS}"]


@pytest.mark.parametrize("dialect, text", [
    ("isg", "%1\n$FOR P1 = 1, 3, 1\n$FOR P2 = 1, 2, 1\nG0 X[P1] Y[P2]\n$ENDFOR\n$ENDFOR\nM30\n"),
    ("siemens", "R1=0\nREPEAT\nR1=R1+1\nG0 X=R1\nUNTIL R1>=3\nREPEAT\nR1=R1-1\nG0 Y=R1\nUNTIL R1<=0\nM30\n"),
])
def test_loops_entered_again_with_the_same_variables_run(dialect: str, text: str) -> None:
    """The inner counted loop starts from the same variables on each entry: an entry is not a repetition."""
    assert len([ev for ev in run(text, dialect) if "move" in ev]) == 6


JUMPS = [
    # (dialect, program, the jump back that runs as before): a loop made of a label and a jump back
    ("fanuc", "#1=0\nN1 G0 X#1\nGOTO 1\nM30\n", "3:1: error: jump 'GOTO 1'"),
    ("siemens", "L1:\nG0 X1\nGOTOB L1\nM30\n", "3:1: error: jump 'GOTOB L1'"),
    ("isg", "%1\nP1=0\nN10 G0 X[P1]\n$GOTO N10\nM30\n", "4:1: error: jump '$GOTO N10'"),
]


@pytest.mark.parametrize("dialect, text, jump", JUMPS)
def test_a_jump_back_with_every_variable_as_before_is_refused_at_its_second_run(dialect: str, text: str,
                                                                                 jump: str) -> None:
    """It ran to the work bound: more than a minute of wall time on a busy machine (a SINUMERIK GOTOB loop)."""
    assert errors(text, dialect) == [f"in.nc:{jump} {REPEATS}"]


def test_a_jump_back_that_counts_runs() -> None:
    moves = [ev for ev in run("#1=0\nN1 G0 X#1\n#1=#1+1\nIF [#1 LT 5] GOTO 1\nM30\n", "fanuc") if "move" in ev]
    assert [m["x"] for m in moves] == [1, 2, 3, 4]  # X0 is where the tool starts: no move
