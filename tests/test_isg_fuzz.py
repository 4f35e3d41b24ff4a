"""Random ISG programs built from ISG fragments ($ statements, P parameters, # commands, comments, the
codes that collide with Fanuc's): every translation to every writer succeeds and verifies at zero
deviation, or fails with located errors only; the toolpath likewise (``tests/support/fuzzing.py``). The
fragments and the programs are ``tests/support/generators/isg_fragments.py``'s, which ``make fuzz`` draws."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.support.fuzzing import WRITERS, check_toolpath, check_translation, known_defect
from tests.support.generators.isg_fragments import SETUP, programs
from tests.support.generators.isg_fragments import same_run_error as _same_run_error


@pytest.mark.parametrize("target", WRITERS)
@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs(), warn=st.booleans())
def test_isg_program_translates_or_reports_located_errors(target: str, program: str, warn: bool) -> None:
    try:
        check_translation("isg", target, program, SETUP, warn)
    except AssertionError as exc:
        if known_defect(target, str(exc)) is None and not _same_run_error(target, str(exc)):
            raise


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
