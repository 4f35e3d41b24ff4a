"""Random ISG programs built from ISG fragments ($ statements, P parameters, # commands, comments, the
codes that collide with Fanuc's): every translation to every writer succeeds and verifies at zero
deviation, or fails with located errors only; the toolpath likewise (``tests/support/fuzzing.py``)."""

from __future__ import annotations

import io
import re

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.setup.machine_setup import Limits, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.fuzzing import WRITERS, check_toolpath, check_translation, known_defect

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


@pytest.mark.parametrize("target", WRITERS)
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs(), warn=st.booleans())
def test_isg_program_translates_or_reports_located_errors(target: str, program: str, warn: bool) -> None:
    try:
        check_translation("isg", target, program, SETUP, warn)
    except AssertionError as exc:
        if known_defect(target, str(exc)) is None and not _same_run_error(target, str(exc)):
            raise


def _same_run_error(target: str, message: str) -> bool:
    """A program kept symbolically is not run by ``translate`` (``postproc.block_rules``: from a program's
    first construct on, a feed move before any feed rate is left to the run; ISG to ISG copies the text): one
    that fails when run (a jump to a missing label, a feed move with no feed rate) fails the same way, at the
    same place, on both sides of verify. (A failure only ISG has, an unset P parameter, fails translation.)

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


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs())
def test_isg_toolpath_succeeds_or_reports_located_errors(program: str) -> None:
    check_toolpath("isg", program, SETUP)


# The example the ISG fuzz reached in CI: the loop never ends before the set-up's bound, so the source's
# run repeats its error until verify's cap, and the output's errors are never read.
LOOPED_RUN_ERROR = "G71 G90 G00 X0 Y0 Z10 F100\nP1=1\n$REPEAT\nP1=2\nP100[2]=5\n$UNTIL P1 > 2\n"


def test_a_run_error_a_loop_repeats_to_the_cap_is_compared_with_the_output_run_alone() -> None:
    with pytest.raises(AssertionError) as caught:
        check_translation("isg", "isg", LOOPED_RUN_ERROR, SETUP, False)
    assert _same_run_error("isg", str(caught.value))


def test_an_output_that_runs_without_that_error_is_no_same_run_error() -> None:
    errors = "".join("in.nc:5:1: error: P parameter arrays (not modelled) cannot be simulated\n" for _ in range(50))
    assert not _same_run_error("isg", "translated, but verify fails: " + errors + "G71\nG01 X1 F100\nM30\n")
