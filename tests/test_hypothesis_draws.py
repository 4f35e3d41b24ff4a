"""Derandomized (CI, ``tests/conftest.py``), does each parametrization of a hypothesis test draw its own examples?

A ``@given`` test under ``@pytest.mark.parametrize`` does: hypothesis's pytest plugin adds the item's node id to
the test's digest, which seeds a derandomized run [V: ``_hypothesis_pytestplugin.py``, "Give every parametrized
test invocation a unique database key", and ``function_digest`` reading ``_hypothesis_internal_add_digest``;
hypothesis 6.170 here, and in the plugin since before the 6.100 that ``pyproject.toml`` asks for]. Measured on
``tests/test_isg_fuzz.py`` derandomized: its 9 targets drew 9 different series (only the first example, the
simplest, is the same). A ``@given`` test made inside a parametrized test (``tests/test_fuzz_all_dialects.py``)
does not: the plugin sees no hypothesis test, and every parametrization draws the same series unless seeded per
case (``each_its_own``). Both run here in a child pytest, derandomized, so a change of either shows.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

PROGRAM = '''
import json, os, pytest
from hypothesis import given, settings, strategies as st
from tests.test_fuzz_all_dialects import each_its_own

settings.register_profile("ci", derandomize=True, database=None)
settings.load_profile("ci")
DRAWN = {}


@pytest.mark.parametrize("case", ["a", "b", "c"])
@settings(max_examples=5)
@given(n=st.integers(0, 10**9))
def test_decorated(case, n):
    DRAWN.setdefault("decorated " + case, []).append(n)


@pytest.mark.parametrize("seeded", [False, True])
@pytest.mark.parametrize("case", ["a", "b", "c"])
def test_inner(case, seeded):
    @settings(max_examples=5)
    @given(n=st.integers(0, 10**9))
    def inner(n):
        DRAWN.setdefault(f"inner {seeded} {case}", []).append(n)

    (each_its_own((case,), inner) if seeded else inner)()


def test_zz_write():
    with open(os.environ["DRAWN_FILE"], "w") as f:
        json.dump(DRAWN, f)
'''


def test_each_parametrization_draws_its_own_examples_when_derandomized(tmp_path: Path) -> None:
    test_file = tmp_path / "test_draws.py"
    test_file.write_text(PROGRAM)
    drawn_file = tmp_path / "drawn.json"
    root = Path(__file__).resolve().parents[1]
    env = {**os.environ, "DRAWN_FILE": str(drawn_file), "PYTHONPATH": str(root)}
    env.pop("CI", None)  # (the child's own profile: the suite's conftest is not on its path)
    run = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "-p", "no:xdist",
                          "-p", "no:randomly", str(test_file)], cwd=tmp_path, env=env, capture_output=True,
                         text=True, timeout=300)
    assert run.returncode == 0, run.stdout + run.stderr
    drawn = {key: tuple(values[1:]) for key, values in json.loads(drawn_file.read_text()).items()}

    def series(prefix: str) -> set[tuple[int, ...]]:
        return {values for key, values in drawn.items() if key.startswith(prefix)}

    assert len(series("decorated ")) == 3, drawn
    assert len(series("inner False ")) == 1, drawn  # why test_fuzz_all_dialects seeds each pair
    assert len(series("inner True ")) == 3, drawn
