"""Every reader x writer pair either succeeds or reports located errors, and what it writes holds up:
no inf/nan, the target's own reader accepts it, and its toolpath equals the source's (verify at zero
tolerance). The cases and checks live in ``tests/support/fuzzing.py``; ``make fuzz`` runs the same
checks for as long as you like. CI derandomizes hypothesis (see conftest.py).

Derandomized, hypothesis draws from a seed made from the test function, the same for every
parametrization: the 81 pairs all translated the same 250 programs (20,250 translations, ~100 s of CPU
pure), so a reader saw 250 programs (read nine times each) and a writer 250. Each pair now draws from
its own seed (``pair_seed``): 60 programs a pair, 4,860 translations, and each reader and each writer
sees 540 different programs, each read once: more programs for every reader and writer for a quarter
of the work; what a pair alone sees is 60 programs instead of 250. Not derandomized (a local run),
every run draws new ones, as before.
"""

from __future__ import annotations

import zlib

import pytest
from hypothesis import HealthCheck, given, seed, settings
from hypothesis import strategies as st

from postproc.setup.machine_setup import MachineSetup
from tests.support.generators.isg_fragments import same_run_error
from tests.support.fuzzing import (PAIRS, READERS, check_toolpath, check_translation, known_defect, programs,
                                   setups)

CASES_PER_PAIR = 60
"""81 pairs: 4,860 translations, each also read back and verified, of as many programs (see above)."""


def pair_seed(*case: str) -> int:
    """A derandomized run's seed for one parametrization: its own examples, the same every run."""
    return zlib.crc32("->".join(case).encode())


def each_its_own(case: tuple[str, ...], test):  # type: ignore[no-untyped-def]
    """``test`` (a hypothesis test) seeded for ``case`` where the run is derandomized (CI)."""
    return seed(pair_seed(*case))(test) if settings.default.derandomize else test


@pytest.mark.parametrize("source, target", PAIRS, ids=[f"{a}-{b}" for a, b in PAIRS])
def test_translate_holds_up(source: str, target: str) -> None:
    @settings(max_examples=CASES_PER_PAIR, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(program=programs(), setup=setups(), warn=st.booleans())
    def holds_up(program: str, setup: MachineSetup, warn: bool) -> None:
        try:
            check_translation(source, target, program, setup, warn)
        except AssertionError as exc:
            if known_defect(target, str(exc)) is None and not (source == target and same_run_error(target, str(exc))):
                raise

    each_its_own((source, target), holds_up)()


@pytest.mark.parametrize("dialect", READERS)
def test_toolpath_succeeds_or_reports_located_errors(dialect: str) -> None:
    @settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
    @given(program=programs(), setup=setups())
    def succeeds_or_reports(program: str, setup: MachineSetup) -> None:
        check_toolpath(dialect, program, setup)

    each_its_own((dialect,), succeeds_or_reports)()
