"""Every reader x writer pair either succeeds or reports located errors, and what it writes holds up:
no inf/nan, the target's own reader accepts it, and its toolpath equals the source's (verify at zero
tolerance). The cases and checks live in ``tests/support/fuzzing.py``; ``make fuzz`` runs the same
checks for as long as you like. CI derandomizes hypothesis (see conftest.py)."""

from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from postproc.setup.machine_setup import MachineSetup
from tests.support.generators.isg_fragments import same_run_error
from tests.support.fuzzing import (PAIRS, READERS, check_toolpath, check_translation, known_defect, programs,
                                   setups)

CASES_PER_PAIR = 250
"""12 pairs: 3000 translations, each also read back and verified (about 30 s)."""


@pytest.mark.parametrize("source, target", PAIRS, ids=[f"{a}-{b}" for a, b in PAIRS])
@settings(max_examples=CASES_PER_PAIR, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs(), setup=setups(), warn=st.booleans())
def test_translate_holds_up(source: str, target: str, program: str, setup: MachineSetup, warn: bool) -> None:
    try:
        check_translation(source, target, program, setup, warn)
    except AssertionError as exc:
        if known_defect(target, str(exc)) is None and not (source == target and same_run_error(target, str(exc))):
            raise


@pytest.mark.parametrize("dialect", READERS)
@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs(), setup=setups())
def test_toolpath_succeeds_or_reports_located_errors(dialect: str, program: str, setup: MachineSetup) -> None:
    check_toolpath(dialect, program, setup)
