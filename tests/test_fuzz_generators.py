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
