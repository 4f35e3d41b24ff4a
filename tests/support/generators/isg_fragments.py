"""ISG programs built from ISG fragments ($ statements, P parameters, # commands, comments, the codes that
collide with Fanuc's), translated to every writer: the inputs of ``tests/test_isg_fuzz.py``, which the
suite draws derandomized, drawn here for as long as ``make fuzz`` runs (random drawing found an arc off
its circle kept symbolically for LinuxCNC that the suite's examples never reached).

A failure of the program's run that the source and the output share (``same_run_error``) is no defect: a
program kept symbolically, or copied ISG to ISG, is run only by verify, which then fails on both sides.
"""

from __future__ import annotations

import io
import re
from typing import Callable

from hypothesis import strategies as st

from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.fuzzing import WRITERS, check_translation

from . import Case

KIND = "isg fragments"

LINES = [
    "G00 X10 Y5", "G01 X[P1*2] F100", "G01 XP1 Y-P2 F200", "G02 X0 Y10 I-5 J5", "G03 X5 Y5 R5", "G04 X0.5",
    "G70", "G71", "G90", "G91", "G17", "G18", "G162", "G161", "G20", "G21", "G98", "G99", "G74 X0", "G92 X0",
    "G81", "G261", "G260", "M03 S1000", "M05", "M08", "M09", "M30", "P1=2", "P2=P1+1.5", "P1=P1*-1",
    "P3=10/P1", "P4=SQRT[P2]", "P5=INT[P2]+FRACT[P2]", "V.L.X=3", "G01 X[V.L.X] F50", "$IF P1 > 1",
    "$ELSEIF P1 == 0", "$ELSE", "$ENDIF", "$WHILE P1 < 4", "P1=P1+1", "$ENDWHILE", "$FOR P6 = 0, 2, 1",
    "$ENDFOR", "$REPEAT", "$UNTIL P1 > 2", "$DO", "$ENDDO P1 < 1", "$SWITCH P1", "$CASE 2", "$DEFAULT",
    "$BREAK", "$ENDSWITCH", "$CONTINUE", "N[10+P1] G01 Y1 F10", "N20: G00 Z5", "$GOTO N20", "#CYL OFF",
    "#SLOPE [TYPE=STEP]", "( comment ( nested ) )", "; comment", "/1 G00 X1", "N5 G01X1Y2Z3F100",
    "LL SUB", "%L SUB", "M17", "G01 X10 \\", "#COMMENT BEGIN", "#COMMENT END", "#VAR", "#ENDVAR", "X", "$FOO",
    "P0=1", "G01 X[1+", "'16#FF'", "P1='16#1F'", "P100[2]=5", "G01 X[P100[1]]", "[LOOP] G01 X1 F10",
    "$GOTO [LOOP]", "$IF P1 > 3 $GOTO [OUT]", "[OUT]",
]
"""ISG fragments, valid and not: the reader's and the interpreter's located errors are exercised too."""


def programs() -> st.SearchStrategy[str]:
    return st.lists(st.sampled_from(LINES), min_size=1, max_size=12).map(
        lambda lines: "G71 G90 G00 X0 Y0 Z10 F100\nP1=1\n" + "\n".join(lines) + "\n")
# F in the first line: without it most programs would be refused for a feed move before any feed rate
# (translate finds it in a program kept symbolically too: the run before keeping passes check_blocks)


SETUP = MachineSetup(limits=Limits(loop_iterations=2000, call_depth=8))


def same_run_error(target: str, message: str) -> bool:
    """ISG to ISG copies the program's text, which ``translate`` does not run: a program that fails when
    run (a jump to a missing label, a feed move with no feed rate) fails the same way, at the same place, on
    both sides of verify. (A program kept symbolically for another dialect is run first, and what fails in
    that run fails translation.)

    Verify runs both sides in step and stops when one side reaches the error cap: a failure repeated by a
    loop then fills the cap with the source's errors before the output's are read (the example CI found:
    ``P100[2]=5`` in a ``$REPEAT``). The output is then run alone, and the two sides' distinct errors compared."""
    prefix = "translated, but verify fails: "
    if not message.startswith(prefix):
        return False
    found: dict[str, list[str]] = {"in.nc": [], "out.nc": []}
    lines = message[len(prefix):].splitlines()
    while lines:
        match = _ERROR.match(lines[0])
        if match is None:
            break  # the output program follows the errors
        found[match.group(1)].append(match.group(2).replace("out.nc", "in.nc"))
        del lines[0]
    if len(found["in.nc"]) >= Diagnostics().max_errors and not found["out.nc"]:
        source, output = _distinct(found["in.nc"]), _distinct(_run_errors(target, "\n".join(lines) + "\n"))
        return source == output
    return bool(found["in.nc"]) and found["in.nc"] == found["out.nc"]


_ERROR = re.compile(r"(in\.nc|out\.nc):\d+:\d+: error: (.*)$")


def _run_errors(dialect: str, text: str) -> list[str]:
    """The messages of the errors a run of ``text`` alone reports (up to the cap)."""
    try:
        for _ in toolpath_events(io.StringIO(text), file="out.nc", dialect=dialect, setup=SETUP,
                                 diagnostics=Diagnostics(warn_stream=io.StringIO())):
            pass
    except ErrorList as errs:
        return [err.message for err in errs.errors]
    except PostprocError as err:
        return [err.message]
    return []


def _distinct(messages: list[str]) -> list[str]:
    return list(dict.fromkeys(messages))


def _run(target: str, warn: bool) -> Callable[[str], object]:
    def run(program: str) -> object:
        try:
            return check_translation("isg", target, program, SETUP, warn)
        except AssertionError as exc:
            if same_run_error(target, str(exc)):
                return "refused"  # the run fails alike on both sides (see the module's docstring)
            raise
    return run


def cases() -> st.SearchStrategy[Case]:
    return st.builds(lambda program, target, warn: Case(f"isg fragments isg-{target}", target, program,
                                                        _run(target, warn), SETUP),
                     programs(), st.sampled_from(WRITERS), st.booleans())
