"""A few cases of every targeted fuzz generator (``tests/support/generators/``) in the suite; ``make fuzz``
draws many more. A case either succeeds, is refused with located errors, or matches a listed known defect."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests.support.fuzzing import known_defect
from tests.support.generators import Case, strategies

STRATEGIES = strategies()


@pytest.mark.parametrize("kind", sorted(STRATEGIES))
@settings(max_examples=40, deadline=None, suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_generated_case_holds_up(kind: str, data: st.DataObject) -> None:
    case: Case = data.draw(STRATEGIES[kind])
    try:
        case.run(case.program)
    except AssertionError as exc:
        if known_defect(case.target, str(exc)) is None:
            raise


def test_every_generator_is_found() -> None:
    """The package finds its modules by file; a kind that vanished from the list would go unfuzzed."""
    assert all(isinstance(kind, str) and kind for kind in STRATEGIES)


def test_a_case_is_limited_by_its_cpu_time_not_the_clock() -> None:
    """``make fuzz``'s time limit per case (``fuzz_main.time_limit``) counts CPU: a case that waits 0.3 s (a loaded
    machine's wait, as far as this process sees it) passes a 0.1 s limit, one that computes endlessly is stopped
    near its limit of CPU (before, the clock: a 0.5 s case on a machine at load 15 was saved as a hang)."""
    import time

    from tests.support.fuzz_main import CaseTimeout, time_limit

    with time_limit(0.1):
        time.sleep(0.3)
    start = time.process_time()
    with pytest.raises(CaseTimeout, match="of CPU"):
        with time_limit(0.1):
            while time.process_time() - start < 5:
                pass
    assert time.process_time() - start < 1


def test_grblhal_calls_run_by_rs274_get_the_arguments_grblhal_hands_the_sub() -> None:
    """The "grblhal targets" fuzz runs a grblHAL text with o-words in rs274; grblHAL hands a sub the caller's
    ``#k`` for each argument a call leaves out, rs274 reads 0, so each such call is given them as ``[#k]`` first
    (hand-written expectations; a comment after the arguments stays last, a call of 30 is as written)."""
    from tests.support.generators.grblhal_targets import as_grblhal_runs

    rest = "".join(f" [#{k}]" for k in range(3, 31))
    assert as_grblhal_runs("o100 call [1] [[#2+1]*2]\n") == f"o100 call [1] [[#2+1]*2]{rest}\n"
    assert as_grblhal_runs("O<a> CALL (x)\r\n") == "O<a> CALL" + "".join(f" [#{k}]" for k in range(1, 31)) + " (x)\r\n"
    full = "o7 call" + "".join(" [0.]" for _ in range(30)) + "\n"
    assert as_grblhal_runs(full + "G1 X1\no7 sub\n") == full + "G1 X1\no7 sub\n"


@pytest.mark.skipif(not __import__("tests.support.rs274", fromlist=["available"]).available(),
                    reason="the LinuxCNC interpreter rs274 is not installed")
def test_the_grblhal_rs274_check_catches_a_call_that_relies_on_rs274s_zero() -> None:
    """A LinuxCNC program whose call gives no argument (its sub reads 0 for #1) written for grblHAL as it stands
    would move to X5 on grblHAL (the caller's #1): the check now fails it; with the argument written it passes."""
    from tests.support.generators.grblhal_targets import as_grblhal_runs
    from tests.support.generators.macros import moves_agree_with_rs274

    source = "G21 G90 G0 X0 Y0 Z5\n#1=5\no100 sub\nG1 X#1 F100\no100 endsub\no100 call\nM2\n"
    with pytest.raises(AssertionError, match="move"):
        moves_agree_with_rs274("linuxcnc", source, as_grblhal_runs(source))
    moves_agree_with_rs274("linuxcnc", source, as_grblhal_runs(source.replace("o100 call", "o100 call [0]")))
