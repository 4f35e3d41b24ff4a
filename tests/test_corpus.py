"""Third-party programs x targets (issue 26, "Done when"; tests/corpus/, sources in its README): every
program of the manifest runs through ``benchmarks/corpus.py``, each pair in a process of its own with
the issue's two-minute limit. No internal error and no timeout anywhere; no pair whose translation
verify rejects or its controller refuses; no reader refusing a source the manifest calls valid, except
the failures listed below, each a known defect routed to its owner, which must go on failing until it
is fixed (then its entry goes). The share of pairs translated and verified is printed by the harness,
not asserted here."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.support.corpus_harness import check_program, harness

ROOT = Path(__file__).resolve().parents[1]

PROGRAMS = harness.load_manifest()

KNOWN_FAILURES: dict[tuple[str, str], str] = {}
"""(program, target or '' for the source check) -> the defect, as found by this corpus."""


@pytest.mark.parametrize("program", PROGRAMS, ids=[p.path for p in PROGRAMS])
def test_program_translates_or_fails_as_known(program: object) -> None:
    check_program(program, KNOWN_FAILURES)


def test_every_program_is_in_the_manifest_and_its_source_noted() -> None:
    corpus = ROOT / "tests" / "corpus"
    files = {str(p.relative_to(corpus)) for p in corpus.rglob("*") if p.is_file()
             and p.parent.name not in ("setups",) and p.name not in ("README.md", "corpus.toml")}
    assert files == {p.path for p in PROGRAMS}
    readme = (corpus / "README.md").read_text()
    assert all(f"`{p.path}`" in readme for p in PROGRAMS)
    assert {k[0] for k in KNOWN_FAILURES} <= files


def test_a_refusal_names_its_capability_without_particulars() -> None:
    message = "the grbl dialect cannot express a tool length offset from a table (G43 H13; grbl has only G43.1)"
    assert harness.capability(message, "grbl") == (
        "the target cannot express a tool length offset from a table (G43 Hn; grbl has only G43.1)")
    assert harness.capability("G33.1 (rigid tapping) from linuxcnc has no equivalent in fanuc", "fanuc") == (
        "G33.1 (rigid tapping) from linuxcnc has no equivalent in the target")


def test_a_pair_past_its_time_limit_is_a_timeout_failure() -> None:
    program = next(p for p in PROGRAMS if p.path == "linuxcnc/arcspiral_trimmed.ngc")
    outcomes = harness.run_tasks([(program, "fanuc")], jobs=1, timeout=0.0)
    assert [(o.kind, o.category) for o in outcomes] == [(harness.FAILURE, "timeout")]


def test_the_held_out_set_and_the_corpus_share_one_harness() -> None:
    """Collected in either order (tests/test_heldout.py first, as ``pytest tests/test_heldout.py
    tests/test_corpus.py`` does), both test files use one harness module, so an ``Outcome`` a pair process
    sends back pickles by its module's name; two loads of ``benchmarks/corpus.py`` under one name made the
    held-out set's outcomes unpicklable ("not the same object as corpus_harness.Outcome")."""
    import subprocess
    import sys
    script = ("import pickle, sys; sys.path[:0] = ['tests', '.']\n"
              "import test_heldout, test_corpus\n"
              "assert test_heldout.harness is test_corpus.harness\n"
              "pickle.dumps(test_heldout.harness.Outcome('p.nc', 'fanuc', test_heldout.harness.FAILURE))\n")
    done = subprocess.run([sys.executable, "-c", script], cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
