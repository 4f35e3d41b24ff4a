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
