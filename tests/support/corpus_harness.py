"""``benchmarks/corpus.py`` loaded once, and the check tests/test_corpus.py and tests/test_heldout.py run on
every program of their manifests.

The harness is a script, not a package module, so each test file loaded it by its path. Two loads under the
one name ``corpus_harness`` made two modules: the pair processes pickle an ``Outcome`` by that name, and the
first module's class was no longer the one the name found (running tests/test_heldout.py before
tests/test_corpus.py in one pytest call failed every held-out pair). Loading it here, in a module Python
imports once, makes one harness for every test file."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

ROOT = Path(__file__).resolve().parents[2]
NAME = "corpus_harness"


def _load() -> ModuleType:
    spec = importlib.util.spec_from_file_location(NAME, ROOT / "benchmarks" / "corpus.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[NAME] = module  # before running it: its dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


harness = _load()


def check_program(program: object, known_failures: dict[tuple[str, str], str],
                  source_refused: frozenset[str] = frozenset()) -> None:
    """Runs ``program``'s source check and every pair: no internal error and no timeout; a failure only
    where ``known_failures`` lists it, and every listed one still failing; a refusal located, naming its
    capability. A program in ``source_refused`` (its reader refuses it, a known failure) fails its pairs
    with 'translation refused the source' too."""
    sources, pairs = harness.run_corpus([program], jobs=1)
    assert sources[0].kind != harness.EXCUSED or program.excused  # type: ignore[attr-defined]
    for outcome in sources + pairs:
        key = (outcome.program, outcome.target)
        known = key in known_failures or outcome.program in source_refused and (
            outcome.category == "translation refused the source")
        assert outcome.category not in ("internal error", "timeout"), outcome.detail
        if outcome.kind == harness.FAILURE:
            assert known, f"{key}: {outcome.category}\n{outcome.detail}"
        else:
            assert key not in known_failures, f"{key} no longer fails ({outcome.kind}): remove it from KNOWN_FAILURES"
        if outcome.kind == harness.REFUSED:
            assert outcome.detail.count(":") >= 3 and outcome.blockers, outcome.detail  # located, capability named
